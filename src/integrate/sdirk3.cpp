#include "momenta/integrate/sdirk3.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/math/portable_pow.hpp"

namespace momenta::integrate {

namespace {
// Alexander (1977): the L-stable, stiffly accurate 3-stage SDIRK of order 3.
constexpr double kGamma = 0.43586652150845899942;
constexpr double kB1 = -(6.0 * kGamma * kGamma - 16.0 * kGamma + 1.0) / 4.0;
constexpr double kB2 = (6.0 * kGamma * kGamma - 20.0 * kGamma + 5.0) / 4.0;
constexpr double kA[3][3] = {
    {kGamma, 0.0, 0.0}, {(1.0 - kGamma) / 2.0, kGamma, 0.0}, {kB1, kB2, kGamma}};
constexpr double kC[3] = {kGamma, (1.0 + kGamma) / 2.0, 1.0};

// Newton's method: at most this many iterations a stage, a contraction no slower than this, and
// the estimated remaining error at most this fraction of the tolerance (Hairer & Wanner §IV.8).
constexpr int kMaxIterations = 10;
constexpr double kSlowestContraction = 0.9;
constexpr double kNewtonFraction = 0.1;
// A contraction slower than this in a step renews the Jacobian before the next one.
constexpr double kRenewContraction = 0.1;
}  // namespace

Sdirk3::Sdirk3(const Tolerances& newton) : tolerances_(newton) { check_tolerances(name(), newton); }

void Sdirk3::initialize(SecondOrderSystem& system, const State& state) {
  const int nq = system.nq();
  const int nv = system.nv();
  for (int i = 0; i < 3; ++i) {
    kq_[i] = VecX::Zero(nv);
    kv_[i] = VecX::Zero(nv);
  }
  for (VecX* x : {&psi_delta_, &psi_v_, &z_delta_, &z_v_, &delta_rate_, &a_, &r_delta_, &r_v_,
                  &rhs_, &dv_, &scale_}) {
    *x = VecX::Zero(nv);
  }
  q_ = VecX::Zero(nq);
  probes_.resize(nq, nv);
  dadq_ = MatX::Zero(nv, nv);
  dadv_ = MatX::Zero(nv, nv);
  iteration_matrix_ = MatX::Identity(nv, nv);
  lu_ = Eigen::PartialPivLU<MatX>(nv);
  factored_h_ = 0.0;
  eta_ = 1.0;
  slowest_contraction_ = 0.0;
  jacobians_ = 0;
  statistics_ = {};
  system.begin_step(state.t, std::numeric_limits<double>::infinity());
  update_jacobian(system, state);
}

// ∂a/∂q and ∂a/∂v at `at` (acceleration_jacobian.hpp).
void Sdirk3::update_jacobian(SecondOrderSystem& system, const State& at) {
  system.acceleration(at.t, at.q, at.v, a_);
  acceleration_jacobian(system, at.t, at.q, at.v, a_, dadq_, dadv_, probes_);
  statistics_.evaluations += 2L * static_cast<long>(a_.size()) + 1;
  ++jacobians_;
  jacobian_fresh_ = true;
  factored_h_ = 0.0;
}

// S = I − h γ ∂a/∂v − (h γ)² ∂a/∂q, factored.
void Sdirk3::factor(double h) {
  const double hg = h * kGamma;
  iteration_matrix_.setIdentity();
  iteration_matrix_.noalias() -= hg * dadv_;
  iteration_matrix_.noalias() -= (hg * hg) * dadq_;
  lu_.compute(iteration_matrix_);
  factored_h_ = h;
}

// Stage i: Z = ψ + h γ f(Z), ψ = (0, v_n) + h Σ_{j<i} a_ij k_j; its slope k_i = (Z − ψ)/(h γ).
// True when Newton's method converged.
bool Sdirk3::solve_stage(SecondOrderSystem& system, const State& start, double h, int i) {
  const double hg = h * kGamma;
  psi_delta_.setZero();
  psi_v_ = start.v;
  for (int j = 0; j < i; ++j) {
    psi_delta_.noalias() += (h * kA[i][j]) * kq_[j];
    psi_v_.noalias() += (h * kA[i][j]) * kv_[j];
  }
  // Predictor: the last stage's slope carried on (the start's velocity for the first stage).
  z_delta_ = psi_delta_ + hg * (i == 0 ? start.v : kq_[i - 1]);
  z_v_ = psi_v_;
  if (i > 0) z_v_.noalias() += hg * kv_[i - 1];
  const double t_stage = start.t + kC[i] * h;
  double last_size = 0.0;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    // The residual r = Z − h γ f(Z) − ψ.
    system.integrate(start.q, z_delta_, q_);
    system.local_coordinate_rate(z_delta_, z_v_, delta_rate_);
    system.acceleration(t_stage, q_, z_v_, a_);
    ++statistics_.evaluations;
    r_delta_ = z_delta_ - hg * delta_rate_ - psi_delta_;
    r_v_ = z_v_ - hg * a_ - psi_v_;
    if (!r_delta_.allFinite() || !r_v_.allFinite()) {
      non_finite_at_ = t_stage;
      return false;
    }
    // The correction, reduced to the velocities: Δδ = h γ Δv − r_δ and
    // S Δv = −r_v − h γ ∂a/∂q r_δ.
    rhs_ = -r_v_;
    rhs_.noalias() -= hg * (dadq_ * r_delta_);
    dv_.noalias() = lu_.solve(rhs_);
    r_delta_ = hg * dv_ - r_delta_;  // now Δδ
    z_delta_ += r_delta_;
    z_v_ += dv_;
    // Its size against the tolerance, largest over the coordinates.
    system.configuration_scale(q_, scale_);
    double size = 0.0;
    for (int k = 0; k < static_cast<int>(dv_.size()); ++k) {
      const double sq = tolerances_.absolute + tolerances_.relative * scale_[k];
      const double sv = tolerances_.absolute + tolerances_.relative * std::abs(z_v_[k]);
      size = std::max({size, std::abs(r_delta_[k]) / sq, std::abs(dv_[k]) / sv});
    }
    if (!std::isfinite(size)) return false;
    if (iteration > 0) {
      const double theta = size / last_size;
      if (theta >= kSlowestContraction) return false;
      eta_ = theta / (1.0 - theta);
      slowest_contraction_ = std::max(slowest_contraction_, theta);
    }
    last_size = size;
    if (eta_ * size <= kNewtonFraction || size == 0.0) break;
    if (iteration + 1 == kMaxIterations) return false;
  }
  kq_[i] = (z_delta_ - psi_delta_) / hg;
  kv_[i] = (z_v_ - psi_v_) / hg;
  return true;
}

bool Sdirk3::solve_stages(SecondOrderSystem& system, const State& start, double h) {
  for (int i = 0; i < 3; ++i) {
    if (!solve_stage(system, start, h, i)) return false;
  }
  return true;
}

double Sdirk3::step(SecondOrderSystem& system, State& state, double h) {
  if (!(h > 0.0)) {
    throw InvalidArgument(fmt::format("sdirk3: the step must be positive, got {}", h));
  }
  system.begin_step(state.t, state.t + h);
  // A Jacobian under which Newton's method contracted slowly last step is renewed first.
  if (slowest_contraction_ > kRenewContraction && !jacobian_fresh_) update_jacobian(system, state);
  slowest_contraction_ = 0.0;
  if (factored_h_ != h) factor(h);
  // The first iteration of a step trusts the last contraction rate, never more than √ that.
  eta_ = math::portable_pow(std::max(eta_, std::numeric_limits<double>::epsilon()), 0.8);
  non_finite_at_ = std::numeric_limits<double>::quiet_NaN();
  if (!solve_stages(system, state, h)) {
    // A stale Jacobian, or a step too large: retry once with a fresh one.
    ++statistics_.rejected_steps;
    const bool was_fresh = jacobian_fresh_;
    if (!was_fresh) {
      update_jacobian(system, state);
      factor(h);
      eta_ = 1.0;
    }
    non_finite_at_ = std::numeric_limits<double>::quiet_NaN();
    if (was_fresh || !solve_stages(system, state, h)) {
      if (!std::isnan(non_finite_at_)) {
        throw NumericalError(fmt::format(
            "sdirk3: the acceleration became non-finite at t = {:.9g} s, in the step from t = "
            "{:.9g} s of {:.3g} s: the model may be singular there, or the step too large",
            non_finite_at_, state.t, h));
      }
      throw NumericalError(OptionMessage{fmt::format(
          "sdirk3: Newton's method did not converge in the step from t = {:.9g} s of {:.3g} s{}: "
          "the step is too large for the model's nonlinearity there — take a smaller ‹step›, or "
          "‹integrator=bdf›",
          state.t, h, was_fresh ? "" : ", even with a fresh Jacobian")});
    }
  }
  // Stiffly accurate: the last stage is the solution.
  system.integrate(state.q, z_delta_, q_);
  state.q.swap(q_);
  state.v = z_v_;
  state.t += h;
  jacobian_fresh_ = false;
  ++statistics_.steps;
  return h;
}

}  // namespace momenta::integrate
