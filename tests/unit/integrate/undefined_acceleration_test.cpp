// An acceleration with no value at some states (integrate::UndefinedAcceleration: a sliding
// contact past Painlevé's point, say). The adaptive integrators retry smaller steps where only a
// trial point of a step meets it, and throw it on, naming how far they shrank, where the motion
// itself reaches it; a fixed-step one throws it at once.

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "momenta/integrate/bdf.hpp"
#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/integrate/second_order_system.hpp"

namespace momenta::integrate {
namespace {

// The oscillator q̈ = −4 q from q = 1 at rest (q = cos 2t), whose acceleration exists only within
// `tube` of that motion and before `end` (s): a trial point of a long step strays out of the
// tube; the motion itself reaches `end`.
class OscillatorInATube final : public SecondOrderSystem {
 public:
  OscillatorInATube(double tube, double end) : tube_(tube), end_(end) {}
  int nq() const override { return 1; }
  int nv() const override { return 1; }
  void acceleration(double t, const VecX& q, const VecX&, VecX& vdot) override {
    if (t > end_ || std::abs(q[0] - std::cos(2.0 * t)) > tube_) {
      ++undefined;
      throw UndefinedAcceleration("no acceleration here (the test's tube)");
    }
    vdot[0] = -4.0 * q[0];
  }
  void integrate(const VecX& q, const VecX& dq, VecX& q_out) const override { q_out = q + dq; }
  long undefined = 0;

 private:
  double tube_, end_;
};

// Runs to T; the largest distance from cos 2t at the steps' ends.
double run_in_the_tube(Integrator& integrator, OscillatorInATube& system, double T) {
  State state{0.0, VecX::Constant(1, 1.0), VecX::Zero(1)};
  integrator.initialize(system, state);
  double farthest = 0.0;
  while (state.t < T) {
    integrator.step(system, state, T - state.t);
    farthest = std::max(farthest, std::abs(state.q[0] - std::cos(2.0 * state.t)));
  }
  EXPECT_EQ(state.t, T);
  return farthest;
}

// At rtol 1e-3 dopri5's steps are long and their trial stages stray 1e-5 from the motion: those
// steps are retried smaller, and every step taken stays in the tube.
TEST(UndefinedAcceleration, Dopri5RetriesAStepWhoseTrialStageHasNone) {
  OscillatorInATube system(1e-5, INFINITY);
  DormandPrince5 dopri(Tolerances{1e-3, 1e-3});
  EXPECT_LE(run_in_the_tube(dopri, system, 10.0), 1e-5);
  EXPECT_GT(system.undefined, 0);  // it met the tube's wall, and went on
  EXPECT_GT(dopri.statistics().rejected_steps, 0);
}

// (bdf is not tested in a tube: one tight enough for its trial points to meet is also left by its
// accepted steps' global error. tests/validation/simulate/painleve_jam_test.cpp has a rod whose
// slip stops short of the point, under bdf too.)

// Where the motion reaches the point, the error stands: dopri5 shrinks its step to time's
// resolution at t = 1 s and throws the system's error on, saying so.
TEST(UndefinedAcceleration, Dopri5ThrowsItOnWhereTheMotionReachesIt) {
  OscillatorInATube system(1.0, 1.0);
  DormandPrince5 dopri(Tolerances{1e-8, 1e-8});
  State state{0.0, VecX::Constant(1, 1.0), VecX::Zero(1)};
  dopri.initialize(system, state);
  try {
    while (state.t < 2.0) dopri.step(system, state, 2.0 - state.t);
    ADD_FAILURE() << "no error";
  } catch (const UndefinedAcceleration& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no acceleration here"), std::string::npos) << what;
    EXPECT_NE(what.find("the motion reaches it: dopri5 shrank its step"), std::string::npos)
        << what;
  }
  EXPECT_LE(state.t, 1.0);
  EXPECT_GT(state.t, 1.0 - 1e-12);
}

// bdf: CVODE's steps that meet it fail as recoverable ones and shrink; where it gives up, step()
// hands back the last internal step reached (the caller may find an event before it) and starts
// afresh from there; a step from which none gets on throws the system's error, saying so.
TEST(UndefinedAcceleration, BdfHandsBackWhatItReachedThenThrowsItOn) {
  OscillatorInATube system(1.0, 1.0);
  Bdf bdf(Tolerances{1e-8, 1e-8});
  State state{0.0, VecX::Constant(1, 1.0), VecX::Zero(1)};
  bdf.initialize(system, state);
  int short_steps = 0;
  try {
    for (int k = 0; k < 1000; ++k) {
      const double from = state.t;
      bdf.step(system, state, 2.0 - from);
      EXPECT_GT(state.t, from);
      EXPECT_LT(state.t, 1.0 + 1e-15);
      EXPECT_NEAR(state.q[0], std::cos(2.0 * state.t), 1e-6);  // the state of the time reached
      ++short_steps;
    }
    ADD_FAILURE() << "no error";
  } catch (const UndefinedAcceleration& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no acceleration here"), std::string::npos) << what;
    EXPECT_NE(what.find("bdf's steps from t ="), std::string::npos) << what;
  }
  EXPECT_GE(short_steps, 1);
  EXPECT_GT(state.t, 1.0 - 1e-6);
}

TEST(UndefinedAcceleration, Rk4ThrowsItAtOnce) {
  OscillatorInATube system(1.0, 0.5);
  RungeKutta4 rk4;
  State state{0.0, VecX::Constant(1, 1.0), VecX::Zero(1)};
  rk4.initialize(system, state);
  EXPECT_THROW(
      {
        for (int k = 0; k < 100; ++k) rk4.step(system, state, 0.01);
      },
      UndefinedAcceleration);
  EXPECT_NEAR(state.t, 0.49, 1e-12);  // the step from 0.49 s has a stage at 0.5 s … past it
}

}  // namespace
}  // namespace momenta::integrate
