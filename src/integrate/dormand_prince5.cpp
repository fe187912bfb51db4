#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/math/portable_pow.hpp"

namespace momenta::integrate {

namespace {
// Dormand & Prince (1980), as tabulated in Hairer, Nørsett & Wanner, Table II.5.2.
constexpr double kDopriC[7] = {0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1};
constexpr double kDopriA[7][6] = {
    {0, 0, 0, 0, 0, 0},
    {1.0 / 5, 0, 0, 0, 0, 0},
    {3.0 / 40, 9.0 / 40, 0, 0, 0, 0},
    {44.0 / 45, -56.0 / 15, 32.0 / 9, 0, 0, 0},
    {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729, 0, 0},
    {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656, 0},
    {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}};
// The fifth-order solution's weights are the last row of a (first same as last).
constexpr const double* kDopriB = kDopriA[6];
// Fifth- minus embedded fourth-order weights: the local error estimate.
constexpr double kDopriE[7] = {71.0 / 57600,      0,          -71.0 / 16695, 71.0 / 1920,
                               -17253.0 / 339200, 22.0 / 525, -1.0 / 40};
// Dense output of order four (Hairer's dopri5 code, CONTD5).
constexpr double kD[7] = {-12715105075.0 / 11282082432.0,  0,
                          87487479700.0 / 32700410799.0,   -10690763975.0 / 1880347072.0,
                          701980252875.0 / 199316789632.0, -1453857185.0 / 822651844.0,
                          69997945.0 / 29380423.0};

// Step-size controller (Hairer's defaults): safety factor, bounds on the change per step, and the
// PI controller's β (Gustafsson 1991).
constexpr double kSafety = 0.9;
constexpr double kMinFactor = 0.2;
constexpr double kMaxFactor = 10.0;
constexpr double kBeta = 0.04;
constexpr double kExponent = 0.2 - 0.75 * kBeta;
}  // namespace

DormandPrince5::DormandPrince5(const Tolerances& tolerances) : tolerances_(tolerances) {
  check_tolerances(name(), tolerances);
}

void DormandPrince5::initialize(SecondOrderSystem& system, const State& state) {
  const int nq = system.nq();
  const int nv = system.nv();
  controlled_ = std::clamp(system.error_controlled(), 0, nv);
  stages_.resize(nq, nv, 7);
  for (VecX* x :
       {&delta1_, &v1_, &error_delta_, &error_v_, &scale_q0_, &scale_q1_, &delta6_, &v6_}) {
    *x = VecX::Zero(nv);
  }
  for (VecX& d : dense_) d = VecX::Zero(2 * nv);
  q_prev_ = state.q;
  v_prev_ = state.v;
  t_prev_ = state.t;
  h_prev_ = 0.0;
  statistics_ = {};
  previous_error_ = 1e-4;
  last_rejected_ = false;
  stiff_streak_ = 0;
  // The first stage's acceleration, reused by the first step (inputs from the right).
  system.begin_step(state.t, std::numeric_limits<double>::infinity());
  system.acceleration(state.t, state.q, state.v, stages_.kv[0]);
  ++statistics_.evaluations;
  have_last_acceleration_ = true;
  h_ = initial_step(system, state);
}

// Hairer, Nørsett & Wanner §II.4, "Starting step size": a step whose explicit Euler error is
// about the tolerance, limited by a first-order look at the second derivative.
double DormandPrince5::initial_step(SecondOrderSystem& system, const State& state) {
  const int nv = system.nv();
  const int n = controlled_;
  system.configuration_scale(state.q, scale_q0_);
  const auto rms = [&](const VecX& dq, const VecX& dv) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const double sq = tolerances_.absolute + tolerances_.relative * scale_q0_[i];
      const double sv = tolerances_.absolute + tolerances_.relative * std::abs(state.v[i]);
      sum += (dq[i] / sq) * (dq[i] / sq) + (dv[i] / sv) * (dv[i] / sv);
    }
    return n == 0 ? 0.0 : std::sqrt(sum / (2 * n));
  };
  const VecX& a0 = stages_.kv[0];
  const double d0 = rms(VecX::Zero(nv), state.v) + rms(scale_q0_, VecX::Zero(nv));
  const double d1 = rms(state.v, a0);
  double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
  // One explicit Euler step to estimate the second derivative.
  VecX dq = h0 * state.v;
  VecX v_euler = state.v + h0 * a0;
  VecX q_euler(system.nq()), a1(nv);
  system.integrate(state.q, dq, q_euler);
  system.acceleration(state.t + h0, q_euler, v_euler, a1);
  ++statistics_.evaluations;
  const double d2 = rms(v_euler - state.v, a1 - a0) / h0;
  const double dmax = std::max(d1, d2);
  const double h1 =
      dmax <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : math::portable_pow(0.01 / dmax, 1.0 / 5.0);
  const double h = std::min(100.0 * h0, h1);
  // Scales that overflow (a state of 1e200) leave no estimate: start small and let the error
  // control grow the step.
  return std::isfinite(h) && h > 0.0 ? h : 1e-6;
}

std::string DormandPrince5::largest_error_coordinate(const SecondOrderSystem& system,
                                                     const State& state) const {
  if (error_v_.size() == 0) return "no coordinate";
  int worst = 0;
  double largest = -1.0;
  for (int i = 0; i < static_cast<int>(error_v_.size()); ++i) {
    const double e = std::max(std::abs(error_delta_[i]), std::abs(error_v_[i]));
    if (!(e <= largest)) {  // a NaN error counts as the largest
      largest = std::isnan(e) ? std::numeric_limits<double>::infinity() : e;
      worst = i;
    }
  }
  return fmt::format("{} = {:.9g}", system.coordinate_name(worst, true), state.v[worst]);
}

double DormandPrince5::error_norm(const State& start, const VecX& v1) const {
  const int n = controlled_;
  if (n == 0) return 0.0;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double sq =
        tolerances_.absolute + tolerances_.relative * std::max(scale_q0_[i], scale_q1_[i]);
    const double sv = tolerances_.absolute +
                      tolerances_.relative * std::max(std::abs(start.v[i]), std::abs(v1[i]));
    sum +=
        (error_delta_[i] / sq) * (error_delta_[i] / sq) + (error_v_[i] / sv) * (error_v_[i] / sv);
  }
  return std::sqrt(sum / (2 * n));
}

bool DormandPrince5::evaluate_stages(SecondOrderSystem& system, const State& state, double h) {
  for (int i = 1; i < 7; ++i) {
    try {
      stages_.evaluate(system, state, h, i, kDopriA[i], kDopriC[i], statistics_.evaluations);
    } catch (const UndefinedAcceleration& e) {
      undefined_ = e;
      return false;
    }
    if (i == 5) {
      delta6_ = stages_.delta;
      v6_ = stages_.v;
    }
  }
  return true;
}

double DormandPrince5::step(SecondOrderSystem& system, State& state, double h_max) {
  if (!(h_max > 0.0)) {
    throw InvalidArgument(fmt::format("dopri5: the step limit must be positive, got {}", h_max));
  }
  if (!have_last_acceleration_) {
    // The step's start, from the right: no step end is announced yet.
    system.begin_step(state.t, std::numeric_limits<double>::infinity());
    system.acceleration(state.t, state.q, state.v, stages_.kv[0]);
    ++statistics_.evaluations;
    have_last_acceleration_ = true;
  }
  system.configuration_scale(state.q, scale_q0_);
  const double t_break = system.next_discontinuity(state.t);
  for (;;) {
    const double h = std::min(h_, h_max);
    // (Written so that a NaN step fails it too.)
    if (!(h >= 16.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(state.t)))) {
      if (undefined_) {  // every smaller step still met it: the motion reaches it
        throw UndefinedAcceleration(fmt::format(
            "{} (the motion reaches it: dopri5 shrank its step to {:.3g} s at t = {:.9g} s and "
            "still met it)",
            std::exchange(undefined_, std::nullopt)->what(), h, state.t));
      }
      throw NumericalError(fmt::format(
          "dopri5: the step size fell to {:.3g} s at t = {:.9g} s, below the resolution of time; "
          "the largest error is in the rate {}. The system may be stiff or singular there, or "
          "the tolerances (rtol = {}, atol = {}) too tight",
          h, state.t, largest_error_coordinate(system, state), tolerances_.relative,
          tolerances_.absolute));
    }
    // Stages 1..6; stage 0 is the last step's final acceleration.
    system.begin_step(state.t, state.t + h);
    stages_.kq[0] = state.v;
    // A rejected step: the next try's length, and no growth after it.
    const auto reject = [&](double h_next) {
      h_ = h_next;
      ++statistics_.rejected_steps;
      last_rejected_ = true;
    };
    if (!evaluate_stages(system, state, h)) {
      // A stage past a point where the acceleration has no value: retry much smaller.
      reject(h * kMinFactor);
      continue;
    }
    undefined_.reset();
    // The fifth-order solution is the last stage's point; the error estimate is Σ e_i k_i.
    delta1_ = stages_.delta;
    v1_ = stages_.v;
    error_delta_.setZero();
    error_v_.setZero();
    for (int j = 0; j < 7; ++j) {
      if (kDopriE[j] == 0.0) continue;
      error_delta_.noalias() += (h * kDopriE[j]) * stages_.kq[j];
      error_v_.noalias() += (h * kDopriE[j]) * stages_.kv[j];
    }
    system.configuration_scale(stages_.q, scale_q1_);
    const double error = error_norm(state, v1_);
    const double factor11 = math::portable_pow(error, kExponent);
    if (!std::isfinite(error)) {
      // A non-finite stage: retry much smaller; the caller sees the failure if it persists.
      reject(h * kMinFactor);
      continue;
    }
    if (error > 1.0) {
      // Reject: shrink, at most by kMinFactor.
      reject(h / std::min(1.0 / kMinFactor, factor11 / kSafety));
      continue;
    }
    // Accept: keep the dense-output coefficients over (δ, v) in the start's local coordinates.
    const int nv = system.nv();
    dense_[0].head(nv).setZero();
    dense_[0].tail(nv) = state.v;
    dense_[1].head(nv) = delta1_;
    dense_[1].tail(nv) = v1_ - state.v;
    dense_[2].head(nv) = h * stages_.kq[0] - dense_[1].head(nv);
    dense_[2].tail(nv) = h * stages_.kv[0] - dense_[1].tail(nv);
    dense_[3].head(nv) = dense_[1].head(nv) - h * stages_.kq[6] - dense_[2].head(nv);
    dense_[3].tail(nv) = dense_[1].tail(nv) - h * stages_.kv[6] - dense_[2].tail(nv);
    dense_[4].setZero();
    for (int j = 0; j < 7; ++j) {
      if (kD[j] == 0.0) continue;
      dense_[4].head(nv).noalias() += (h * kD[j]) * stages_.kq[j];
      dense_[4].tail(nv).noalias() += (h * kD[j]) * stages_.kv[j];
    }
    estimate_stiffness(h, state.t);
    q_prev_ = state.q;
    v_prev_ = state.v;
    t_prev_ = state.t;
    h_prev_ = h;
    // The new state is the last stage's point, whose acceleration starts the next step.
    state.q = stages_.q;
    state.v = v1_;
    state.t += h;
    stages_.kv[0].swap(stages_.kv[6]);
    // A step that ended on a discontinuity saw the inputs' left limits there: the next step must
    // start from their right limits, so first-same-as-last does not apply.
    if (t_break <= state.t + 1e-12 * std::max(1.0, std::abs(state.t))) {
      have_last_acceleration_ = false;
    }
    // PI control of the next step; no growth right after a rejection.
    double factor = factor11 / math::portable_pow(previous_error_, kBeta);
    factor = std::clamp(factor / kSafety, 1.0 / kMaxFactor, 1.0 / kMinFactor);
    double h_next = h / factor;
    if (last_rejected_) h_next = std::min(h_next, h);
    // A step clipped to land on an output time says nothing about the natural step size.
    h_ = (h < h_ && h == h_max) ? std::max(h_next, h_) : h_next;
    previous_error_ = std::max(error, 1e-4);
    last_rejected_ = false;
    ++statistics_.steps;
    return h;
  }
}

// Stages 6 and 7 both lie at t + h: the ratio of their slopes' difference to their points'
// difference estimates the dominant eigenvalue |λ| of the Jacobian (Hairer's dopri5 code,
// after Shampine 1977). h|λ| past 3.25 — the edge of dopri5's stability region on the negative
// real axis — means stability, not the error estimate, holds the step.
void DormandPrince5::estimate_stiffness(double h, double t) {
  constexpr double kStabilityEdge = 3.25;
  constexpr int kStreak = 15;
  const double slopes =
      (stages_.kq[6] - stages_.kq[5]).squaredNorm() + (stages_.kv[6] - stages_.kv[5]).squaredNorm();
  const double points = (delta1_ - delta6_).squaredNorm() + (v1_ - v6_).squaredNorm();
  if (!(points > 0.0) || !std::isfinite(slopes)) return;
  const double h_lambda = h * std::sqrt(slopes / points);
  if (h_lambda < kStabilityEdge) {
    stiff_streak_ = 0;
    return;
  }
  ++statistics_.stability_limited_steps;
  statistics_.stiff_eigenvalue = std::max(statistics_.stiff_eigenvalue, h_lambda / h);
  if (++stiff_streak_ == kStreak && std::isnan(statistics_.stiff_from)) statistics_.stiff_from = t;
}

void DormandPrince5::interpolate(const SecondOrderSystem& system, double t, State& out) const {
  const double t_end = t_prev_ + h_prev_;
  const double slack = 1e-12 * std::max(1.0, std::abs(t_end));
  if (h_prev_ <= 0.0 || t < t_prev_ - slack || t > t_end + slack) {
    throw InvalidArgument(fmt::format(
        "dopri5: dense output asked at t = {} outside the last step [{}, {}]", t, t_prev_, t_end));
  }
  const double s = (t - t_prev_) / h_prev_;
  const double s1 = 1.0 - s;
  const int nv = static_cast<int>(v_prev_.size());
  // y(s) = d0 + s (d1 + (1 − s) (d2 + s (d3 + (1 − s) d4))), over (δ, v).
  const auto y = [&](int offset) {
    return dense_[0].segment(offset, nv) +
           s * (dense_[1].segment(offset, nv) +
                s1 * (dense_[2].segment(offset, nv) +
                      s * (dense_[3].segment(offset, nv) + s1 * dense_[4].segment(offset, nv))));
  };
  const VecX delta = y(0);
  out.v = y(nv);
  system.integrate(q_prev_, delta, out.q);
  out.t = t;
}

}  // namespace momenta::integrate
