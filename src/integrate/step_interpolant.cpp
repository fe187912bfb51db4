#include "momenta/integrate/step_interpolant.hpp"

namespace momenta::integrate {

void StepInterpolant::resize(int nq, int nv) {
  start_ = State{0.0, VecX::Zero(nq), VecX::Zero(nv)};
  end_ = start_;
  a0_ = a1_ = delta1_ = rate1_ = delta_ = VecX::Zero(nv);
}

void StepInterpolant::set(SecondOrderSystem& system, const Integrator& integrator,
                          const State& start, const State& end) {
  integrator_ = &integrator;
  start_.t = start.t;
  start_.q = start.q;
  start_.v = start.v;
  end_.t = end.t;
  end_.q = end.q;
  end_.v = end.v;
  if (integrator.has_dense_output()) return;
  system.begin_step(start.t, end.t);
  system.acceleration(start.t, start.q, start.v, a0_);
  system.acceleration(end.t, end.q, end.v, a1_);
  system.difference(start.q, end.q, delta1_);
  system.local_coordinate_rate(delta1_, end.v, rate1_);
}

void StepInterpolant::evaluate(const SecondOrderSystem& system, double t, State& out) {
  // The ends exactly: what the run recorded there, projected.
  if (t <= start_.t || t >= end_.t) {
    const State& end = t <= start_.t ? start_ : end_;
    out.t = end.t;
    out.q = end.q;
    out.v = end.v;
    return;
  }
  if (integrator_->has_dense_output()) {
    integrator_->interpolate(system, t, out);
    out.t = t;
    return;
  }
  // Cubic Hermite on [0, 1]: h00 = (1 + 2s)(1 − s)², h10 = s (1 − s)², h01 = s² (3 − 2s),
  // h11 = s² (s − 1); derivatives scale by the step h.
  const double h = end_.t - start_.t;
  const double s = (t - start_.t) / h;
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s);
  const double h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s);
  const double h11 = s * s * (s - 1);
  delta_.noalias() = (h10 * h) * start_.v + h01 * delta1_ + (h11 * h) * rate1_;
  system.integrate(start_.q, delta_, out.q);
  out.v.noalias() = h00 * start_.v + (h10 * h) * a0_ + h01 * end_.v + (h11 * h) * a1_;
  out.t = t;
}

}  // namespace momenta::integrate
