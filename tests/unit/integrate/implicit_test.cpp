// The implicit integrators, bdf (SUNDIALS CVODE) and sdirk3, on systems with exact solutions: a
// stiff overdamped spring-damper (the A05 governor's 8e5 N/m, 4e4 N·s/m on 1 kg), a stiff spring
// with an input step, and a torque-free body whose attitude lives on SO(3).

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/integrate/bdf.hpp"
#include "momenta/integrate/run.hpp"
#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/integrate/sdirk3.hpp"
#include "momenta/integrate/second_order_system.hpp"
#include "test_systems.hpp"

namespace momenta::integrate {
namespace {

constexpr double kX0 = 0.01;  // m: released 10 mm out

// The largest |x − x_exact| over the rows of a run to 1 s with rows every `h`.
double largest_error(test::SpringDamper& system, Integrator& integrator, double h) {
  State state{0.0, VecX::Constant(1, kX0), VecX::Zero(1)};
  double worst = 0.0;
  run(system, integrator, state, {1.0, h, 1},
      [&](const State& s) { worst = std::max(worst, std::abs(s.q[0] - system.exact(s.t, kX0))); });
  return worst;
}

TEST(Bdf, StiffSpringDamperInAtMost200StepsWithinItsTolerance) {
  // λ = −20.01 and −39 980 1/s. dopri5 needs 12 158 steps for this second (stability-limited,
  // h |λ| ≈ 3.3); BDF's steps follow the slow creep: measured 200 steps, 267 evaluations,
  // largest error 6.5e-8 m (6.5e-6 of x0) at rtol 1e-6, atol 1e-8.
  test::SpringDamper system(1.0, 8e5, 4e4);
  Bdf bdf(Tolerances{1e-6, 1e-8});
  const double error = largest_error(system, bdf, 0.01);
  EXPECT_LE(bdf.statistics().steps, 200);
  EXPECT_LT(error, 2e-7);
  EXPECT_EQ(bdf.statistics().evaluations, system.evaluations);
  EXPECT_EQ(bdf.restarts(), 0);
  // Tightening the tolerance tightens the answer (measured 8.1e-10 m at 1e-8, 1e-10).
  test::SpringDamper tight_system(1.0, 8e5, 4e4);
  Bdf tight(Tolerances{1e-8, 1e-10});
  EXPECT_LT(largest_error(tight_system, tight, 0.01), 3e-9);
}

TEST(Bdf, ExplicitMethodTakesSixtyTimesTheSteps) {
  // The figure the stiff benchmark rests on, as a check that cannot drift unnoticed.
  test::SpringDamper system(1.0, 8e5, 4e4);
  DormandPrince5 dopri(Tolerances{1e-6, 1e-8});
  largest_error(system, dopri, 0.01);
  EXPECT_GT(dopri.statistics().steps, 12000);
}

TEST(Sdirk3, StiffSpringDamperAtTheMotionsStepIsAccurateAndThirdOrder) {
  // h |λ2| = 400 at h = 10 ms: far outside any explicit method's stability region; L-stability
  // damps the fast mode in one step. Measured largest errors 6.85e-7 m (h = 10 ms) and 9.0e-8 m
  // (5 ms): ratio 7.6, order 3 (2³ = 8).
  test::SpringDamper coarse_system(1.0, 8e5, 4e4), fine_system(1.0, 8e5, 4e4);
  Sdirk3 coarse, fine;
  const double coarse_error = largest_error(coarse_system, coarse, 0.01);
  const double fine_error = largest_error(fine_system, fine, 0.005);
  EXPECT_LT(coarse_error, 1e-6);
  EXPECT_GT(coarse_error / fine_error, 6.0);
  EXPECT_LT(coarse_error / fine_error, 10.0);
  EXPECT_EQ(coarse.statistics().steps, 100);
  EXPECT_EQ(coarse.statistics().evaluations, coarse_system.evaluations);
}

TEST(ImplicitIntegrators, LandOnAnInputStepAndKeepTheirAccuracy) {
  // k = 1e6 N/m, c = 2e3 N·s/m (critically damped at 2√(mk) = 2e3 with m = 1 kg), pushed by a
  // 1000 N step at t = 0.3 s: x settles to u/k = 1 mm. From x(0) = 0 the motion is zero until the
  // step, then the critically damped response x = (u/k)(1 − (1 + ω τ) e^{−ω τ}), τ = t − 0.3,
  // ω = 1000 rad/s. A step straddling t = 0.3 s would smear the jump.
  const double u = 1000.0, k = 1e6, omega = 1000.0, t_step = 0.3;
  const auto exact = [&](double t) {
    const double tau = t - t_step;
    return tau <= 0 ? 0.0 : (u / k) * (1.0 - (1.0 + omega * tau) * std::exp(-omega * tau));
  };
  const auto largest_error = [&](Integrator& integrator, double h) {
    test::SpringDamper system(1.0, k, 2e3, t_step, u);
    State state{0.0, VecX::Zero(1), VecX::Zero(1)};
    double worst = 0.0;
    run(system, integrator, state, {0.5, h, 1},
        [&](const State& s) { worst = std::max(worst, std::abs(s.q[0] - exact(s.t))); });
    return worst;
  };
  // bdf restarts once, after the step; measured 6.9e-14 m of a 1 mm motion.
  Bdf bdf(Tolerances{1e-9, 1e-12});
  EXPECT_LT(largest_error(bdf, 0.01), 1e-12);
  EXPECT_EQ(bdf.restarts(), 1);
  // sdirk3 keeps its third order across the jump: measured 1.91e-8 m at h = 0.1 ms (ωh = 0.1)
  // and 2.48e-9 m at 0.05 ms, ratio 7.7.
  Sdirk3 coarse, fine;
  const double coarse_error = largest_error(coarse, 1e-4);
  const double fine_error = largest_error(fine, 5e-5);
  EXPECT_LT(coarse_error, 3e-8);
  EXPECT_GT(coarse_error / fine_error, 6.0);
}

// A jump in the acceleration that the system does not declare (SecondOrderSystem::
// next_discontinuity): a sliding contact's friction taking its reference direction where its slip
// turns slower than 1e-10 m/s, say. CVODE's error test shrinks the steps that straddle it until
// the jump's share of the local error, ~h·|Δa|, is within atol, creeping up to it with steps that
// end short of it; where even a step at time's resolution (16 ε t) cannot meet atol, the run stops
// naming the time. (bdf allows 20 failed tests of one step, not CVODE's 7: with 7 the MuJoCo arm
// under bdf at 6 ms stopped at 2.2017 s — MjcfContacts.TheArmUnderBdfsLongStepsCrossesItsRocking.)
class JumpingAcceleration final : public SecondOrderSystem {
 public:
  JumpingAcceleration(double t_jump, double jump) : t_jump_(t_jump), jump_(jump) {}
  int nq() const override { return 1; }
  int nv() const override { return 1; }
  void acceleration(double t, const VecX&, const VecX&, VecX& vdot) override {
    vdot[0] = t < t_jump_ ? 0.0 : jump_;
  }
  void integrate(const VecX& q, const VecX& dq, VecX& q_out) const override { q_out = q + dq; }
  double exact_q(double t) const {
    return t < t_jump_ ? 0.0 : 0.5 * jump_ * (t - t_jump_) * (t - t_jump_);
  }

 private:
  double t_jump_, jump_;
};

TEST(Bdf, CrossesAJumpInTheAccelerationThatIsNoEvent) {
  constexpr double kJumpTime = 0.3141592653589793;
  const auto run_to = [&](JumpingAcceleration& system, double T) {
    Bdf bdf(Tolerances{1e-8, 1e-10});
    State state{0.0, VecX::Zero(1), VecX::Zero(1)};
    run(system, bdf, state, {T, 0.006, 1}, [](const State&) {});
    return state;
  };
  // Measured 7e-11 to 2.7e-10 m (1e3 m/s²) at 0.5 s: within 10 atol.
  for (const double jump : {1e-6, 1e-3, 1.0, 1e3}) {
    SCOPED_TRACE(jump);
    JumpingAcceleration system(kJumpTime, jump);
    const State end = run_to(system, 0.5);
    EXPECT_EQ(end.t, 0.5);
    EXPECT_NEAR(end.q[0], system.exact_q(0.5), 1e-9);
  }
  // 1e6 m/s² over a step of 16 ε t = 3.6e-15 s is 3.6e-9 m/s, above atol.
  JumpingAcceleration too_big(kJumpTime, 1e6);
  try {
    run_to(too_big, 0.5);
    ADD_FAILURE() << "no error";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("t = 0.314159265 s"), std::string::npos) << e.what();
  }
}

TEST(Bdf, FollowsATorqueFreeBodyOnSO3AcrossChartChanges) {
  // An axisymmetric body (I = 1, 1, 2) spinning at 5 rad/s about a tilted axis: the attitude has
  // a closed form. The chart's base moves each time a local coordinate passes 2.5 rad; the
  // quaternion stays unit because it advances by the exponential map.
  test::FreeRigidBody system(Vec3(1.0, 1.0, 2.0));
  const Vec3 w0(0.3, 0.0, 5.0);
  Bdf bdf(Tolerances{1e-11, 1e-13});
  State state{0.0, VecX(4), VecX(w0)};
  state.q << 1.0, 0.0, 0.0, 0.0;
  double worst_attitude = 0.0, worst_norm = 0.0;
  run(system, bdf, state, {10.0, 0.05, 1}, [&](const State& s) {
    const Mat3 R = test::FreeRigidBody::quaternion(s.q).normalized().toRotationMatrix();
    const Mat3 exact = test::axisymmetric_attitude(1.0, 2.0, Mat3::Identity(), w0, s.t);
    worst_attitude = std::max(worst_attitude, (R - exact).cwiseAbs().maxCoeff());
    worst_norm = std::max(worst_norm, std::abs(s.q.norm() - 1.0));
  });
  // About 5 rad/s × 10 s / 2.5 rad = 20 chart changes (measured 19).
  EXPECT_GE(bdf.restarts(), 15);
  EXPECT_LE(bdf.restarts(), 25);
  EXPECT_LT(worst_attitude, 1e-8);
  EXPECT_LT(worst_norm, 1e-14);
}

TEST(Bdf, AProjectionWithinTheToleranceKeepsTheHistoryABiggerOneRestarts) {
  test::SpringDamper system(1.0, 8e5, 4e4);
  Bdf bdf(Tolerances{1e-8, 1e-10});
  State state{0.0, VecX::Constant(1, kX0), VecX::Zero(1)};
  bdf.initialize(system, state);
  bdf.step(system, state, 0.01);
  state.q[0] += 1e-12;  // a hundredth of atol + rtol |x| ≈ 1.3e-10
  bdf.step(system, state, 0.01);
  EXPECT_EQ(bdf.restarts(), 0);
  state.q[0] += 1e-6;
  bdf.step(system, state, 0.01);
  EXPECT_EQ(bdf.restarts(), 1);
  EXPECT_NEAR(state.q[0], system.exact(0.03, kX0), 2e-6);  // continued from the moved state
}

// a = NaN from t = 0.25 s on: the integrators stop with the time, not with garbage.
class FailsLater final : public SecondOrderSystem {
 public:
  int nq() const override { return 1; }
  int nv() const override { return 1; }
  void acceleration(double t, const VecX& q, const VecX&, VecX& vdot) override {
    vdot[0] = t < 0.25 ? -q[0] : std::nan("");
  }
  void integrate(const VecX& q, const VecX& dq, VecX& q_out) const override { q_out = q + dq; }
};

TEST(ImplicitIntegrators, ANonFiniteAccelerationStopsTheRunNamingTheTime) {
  for (const std::string name : {"bdf", "sdirk3"}) {
    FailsLater system;
    auto integrator = make_integrator(name);
    State state{0.0, VecX::Constant(1, 1.0), VecX::Zero(1)};
    try {
      run(system, *integrator, state, {1.0, 0.01, 1}, [](const State&) {});
      FAIL() << name << ": no throw";
    } catch (const NumericalError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("t = 0.2"), std::string::npos) << message;
      EXPECT_NE(message.find(name), std::string::npos) << message;
    }
  }
}

TEST(ImplicitIntegrators, RefuseToleranceTheyCannotMeet) {
  EXPECT_THROW(Bdf(Tolerances{0.0, 1e-10}), InvalidArgument);
  EXPECT_THROW(Bdf(Tolerances{1e-20, 1e-10}), InvalidArgument);
  EXPECT_THROW(Sdirk3(Tolerances{1e-8, -1.0}), InvalidArgument);
  EXPECT_THROW(make_integrator("bdff"), InvalidArgument);
}

}  // namespace
}  // namespace momenta::integrate
