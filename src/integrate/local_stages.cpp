#include "momenta/integrate/runge_kutta.hpp"

namespace momenta::integrate::detail {

void LocalStages::resize(int nq, int nv, int stages) {
  kq.assign(stages, VecX::Zero(nv));
  kv.assign(stages, VecX::Zero(nv));
  delta = VecX::Zero(nv);
  v = VecX::Zero(nv);
  q = VecX::Zero(nq);
}

void LocalStages::evaluate(SecondOrderSystem& system, const State& start, double h, int i,
                           const double* a, double c, long& evaluations) {
  // The stage point in local coordinates about the step's start.
  delta.setZero();
  v = start.v;
  for (int j = 0; j < i; ++j) {
    if (a[j] == 0.0) continue;
    delta.noalias() += (h * a[j]) * kq[j];
    v.noalias() += (h * a[j]) * kv[j];
  }
  system.integrate(start.q, delta, q);
  // Its rates: δ̇ through the inverse exponential Jacobian, v̇ from the dynamics.
  system.local_coordinate_rate(delta, v, kq[i]);
  system.acceleration(start.t + c * h, q, v, kv[i]);
  ++evaluations;
}

void LocalStages::combine(const State& start, double h, const double* b, int stages,
                          VecX& delta_out, VecX& v_out) const {
  delta_out.setZero();
  v_out = start.v;
  for (int j = 0; j < stages; ++j) {
    if (b[j] == 0.0) continue;
    delta_out.noalias() += (h * b[j]) * kq[j];
    v_out.noalias() += (h * b[j]) * kv[j];
  }
}

}  // namespace momenta::integrate::detail
