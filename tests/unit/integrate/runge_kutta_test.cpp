#include "momenta/integrate/runge_kutta.hpp"

#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta_test/tolerance.hpp"
#include "test_systems.hpp"

namespace momenta::integrate {
namespace {

using test::FreeRigidBody;
using test::HarmonicOscillator;

// Global error at T of a fixed-step integrator on the oscillator q(0) = 1, v(0) = 0, ω = 2.
double oscillator_error(Integrator& integrator, double h, double T) {
  HarmonicOscillator system(2.0);
  State state{0.0, VecX::Constant(1, 1.0), VecX::Zero(1)};
  integrator.initialize(system, state);
  const int n = static_cast<int>(std::lround(T / h));
  for (int i = 0; i < n; ++i) integrator.step(system, state, h);
  return std::hypot(state.q[0] - std::cos(2.0 * T), state.v[0] + 2.0 * std::sin(2.0 * T));
}

TEST(RungeKutta4, ConvergesAtFourthOrderOnAnOscillator) {
  RungeKutta4 rk4;
  const double e1 = oscillator_error(rk4, 0.02, 5.0);
  const double e2 = oscillator_error(rk4, 0.01, 5.0);
  // Halving h divides a fourth-order global error by 2⁴ = 16, up to the next term O(h⁵).
  EXPECT_NEAR(std::log2(e1 / e2), 4.0, 0.05);
  EXPECT_EQ(rk4.statistics().evaluations, 4 * 500);
}

// Attitude error at T of a fixed-step integrator on an axisymmetric free body, against the
// closed form (test_systems.hpp).
double rigid_body_error(Integrator& integrator, double h, double T, double* norm_error = nullptr) {
  const double I1 = 1.0, I3 = 2.5;
  FreeRigidBody system(Vec3(I1, I1, I3));
  const Mat3 R0 = rotation_from_euler("ZYX", Vec3(0.3, -0.2, 0.9));
  const Vec3 w0(0.7, -0.4, 3.0);
  const Quat q0(R0);
  State state{0.0, VecX(4), VecX(w0)};
  state.q << q0.w(), q0.x(), q0.y(), q0.z();
  integrator.initialize(system, state);
  const int n = static_cast<int>(std::lround(T / h));
  double worst_norm = 0.0;
  for (int i = 0; i < n; ++i) {
    integrator.step(system, state, h);
    worst_norm = std::max(worst_norm, std::abs(state.q.norm() - 1.0));
  }
  if (norm_error) *norm_error = worst_norm;
  Vec3 w_exact;
  const Mat3 R_exact = test::axisymmetric_attitude(I1, I3, R0, w0, T, &w_exact);
  const Mat3 R = FreeRigidBody::quaternion(state.q).toRotationMatrix();
  return std::max((R - R_exact).norm(), (state.v.head<3>() - w_exact).norm());
}

TEST(RungeKutta4, KeepsFourthOrderOnTheRotationGroup) {
  RungeKutta4 rk4;
  double norm_error = 0.0;
  const double e1 = rigid_body_error(rk4, 0.01, 4.0, &norm_error);
  const double e2 = rigid_body_error(rk4, 0.005, 4.0);
  // Munthe-Kaas stages with the exact dexp⁻¹ keep the classical order (adding to the quaternion
  // and renormalizing would too, but the exponential update keeps |q| = 1 to round-off).
  EXPECT_NEAR(std::log2(e1 / e2), 4.0, 0.1);
  EXPECT_LT(e2, 1e-7);
  // 400 unit-quaternion products: round-off grows like √n ε, far below 1e-13.
  EXPECT_LT(norm_error, 1e-13);
}

TEST(DormandPrince5, GlobalErrorFollowsTheTolerance) {
  HarmonicOscillator system(2.0);
  double previous = 0.0;
  for (const double rtol : {1e-5, 1e-8, 1e-11}) {
    DormandPrince5 dopri(Tolerances{rtol, rtol});
    State state{0.0, VecX::Constant(1, 1.0), VecX::Zero(1)};
    dopri.initialize(system, state);
    const double T = 10.0;
    while (state.t < T) dopri.step(system, state, T - state.t);
    EXPECT_DOUBLE_EQ(state.t, T);
    const double error =
        std::hypot(state.q[0] - std::cos(2.0 * T), state.v[0] + 2.0 * std::sin(2.0 * T));
    // Over ~3 periods the accumulated error stays within two orders of the per-step tolerance
    // (Hairer, Nørsett & Wanner §II.4: global ≈ Σ local errors, each ≤ tol).
    EXPECT_LT(error, 100.0 * rtol) << "rtol " << rtol;
    // Tolerance proportionality: 1000× tighter gives at least 100× smaller error.
    if (previous > 0.0) {
      EXPECT_LT(error, previous / 100.0) << "rtol " << rtol;
    }
    previous = error;
    EXPECT_GT(dopri.statistics().steps, 0);
  }
}

// An oscillator carrying a fast, large companion it does not control (as the sensitivities ride
// along a run, SecondOrderSystem::error_controlled): the steps are the oscillator's alone, the
// same as without the companion, bit for bit.
class OscillatorWithPassenger final : public SecondOrderSystem {
 public:
  int nq() const override { return 2; }
  int nv() const override { return 2; }
  int error_controlled() const override { return 1; }
  void acceleration(double, const VecX& q, const VecX&, VecX& vdot) override {
    vdot[0] = -4.0 * q[0];
    vdot[1] = -400.0 * q[1];  // ten times faster and a thousand times larger
  }
  void integrate(const VecX& q, const VecX& dq, VecX& q_out) const override { q_out = q + dq; }
};

TEST(DormandPrince5, WeighsOnlyTheCoordinatesTheSystemControls) {
  const auto steps_of = [](SecondOrderSystem& system, State state) {
    DormandPrince5 dopri(Tolerances{1e-8, 1e-10});
    dopri.initialize(system, state);
    std::vector<double> times;
    while (state.t < 5.0) {
      dopri.step(system, state, 5.0 - state.t);
      times.push_back(state.t);
    }
    return std::pair{times, state.q[0]};
  };
  HarmonicOscillator alone(2.0);
  OscillatorWithPassenger carrying;
  const auto [times_alone, q_alone] =
      steps_of(alone, State{0.0, VecX::Constant(1, 1.0), VecX::Zero(1)});
  VecX q0(2);
  q0 << 1.0, 1000.0;
  const auto [times_carrying, q_carrying] = steps_of(carrying, State{0.0, q0, VecX::Zero(2)});
  EXPECT_EQ(times_carrying, times_alone);
  EXPECT_EQ(q_carrying, q_alone);
}

TEST(DormandPrince5, DenseOutputIsFourthOrderInsideAStep) {
  HarmonicOscillator system(2.0);
  DormandPrince5 dopri(Tolerances{1e-6, 1e-6});
  State state{0.0, VecX::Constant(1, 1.0), VecX::Zero(1)};
  dopri.initialize(system, state);
  dopri.step(system, state, 1.0);
  const double t0 = 0.0, t1 = state.t;
  State out{0.0, VecX(1), VecX(1)};
  for (double s : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const double t = t0 + s * (t1 - t0);
    dopri.interpolate(system, t, out);
    // The continuous extension is O(h⁵) locally, like the step's own error (≤ tol here).
    EXPECT_NEAR(out.q[0], std::cos(2.0 * t), 1e-5) << "s = " << s;
    EXPECT_NEAR(out.v[0], -2.0 * std::sin(2.0 * t), 1e-5) << "s = " << s;
  }
  // The end points are the step's own states exactly.
  dopri.interpolate(system, t1, out);
  EXPECT_EQ(out.q[0], state.q[0]);
  EXPECT_THROW(dopri.interpolate(system, t1 + 0.1, out), InvalidArgument);
}

TEST(DormandPrince5, FollowsTheRotationGroup) {
  const double I1 = 1.0, I3 = 2.5;
  FreeRigidBody system(Vec3(I1, I1, I3));
  const Mat3 R0 = rotation_from_euler("ZYX", Vec3(0.3, -0.2, 0.9));
  const Vec3 w0(0.7, -0.4, 3.0);
  const Quat q0(R0);
  State state{0.0, VecX(4), VecX(w0)};
  state.q << q0.w(), q0.x(), q0.y(), q0.z();
  DormandPrince5 dopri(Tolerances{1e-10, 1e-10});
  dopri.initialize(system, state);
  const double T = 20.0;
  while (state.t < T) {
    dopri.step(system, state, T - state.t);
    ASSERT_NEAR(state.q.norm(), 1.0, 1e-13);
  }
  Vec3 w_exact;
  const Mat3 R_exact = test::axisymmetric_attitude(I1, I3, R0, w0, T, &w_exact);
  const Mat3 R = FreeRigidBody::quaternion(state.q).toRotationMatrix();
  // About 20 rad of rotation at rtol 1e-10: the phase error accumulates to ~1e-8.
  EXPECT_LT((R - R_exact).norm(), 1e-7);
  EXPECT_LT((state.v.head<3>() - w_exact).norm(), 1e-7);
}

TEST(DormandPrince5, RejectsBadTolerancesAndStepLimits) {
  EXPECT_THROW(DormandPrince5(Tolerances{0.0, 1e-8}), InvalidArgument);
  EXPECT_THROW(DormandPrince5(Tolerances{1e-8, -1.0}), InvalidArgument);
  HarmonicOscillator system(1.0);
  DormandPrince5 dopri;
  State state{0.0, VecX::Constant(1, 1.0), VecX::Zero(1)};
  dopri.initialize(system, state);
  EXPECT_THROW(dopri.step(system, state, 0.0), InvalidArgument);
}

}  // namespace
}  // namespace momenta::integrate
