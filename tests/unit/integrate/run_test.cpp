#include "momenta/integrate/run.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/integrate/symplectic_euler.hpp"
#include "test_systems.hpp"

namespace momenta::integrate {
namespace {

TEST(Run, FixedStepsLandOnMultiplesOfTheStep) {
  test::HarmonicOscillator system(1.0);
  RungeKutta4 rk4;
  State state{0.0, VecX::Constant(1, 1.0), VecX::Zero(1)};
  std::vector<double> times;
  const RunSummary summary =
      run(system, rk4, state, {1.0, 0.1, 3}, [&](const State& s) { times.push_back(s.t); });
  // Start, steps 3, 6, 9, and the last (10): times are k h exactly, not sums of h.
  ASSERT_EQ(times.size(), 5u);
  EXPECT_EQ(times[0], 0.0);
  EXPECT_EQ(times[1], 3 * 0.1);
  EXPECT_EQ(times[3], 9 * 0.1);
  EXPECT_EQ(times[4], 1.0);
  EXPECT_EQ(summary.statistics.steps, 10);
}

TEST(Run, AdaptiveStepsEndExactlyAtTheFinalTime) {
  test::HarmonicOscillator system(1.0);
  DormandPrince5 dopri(Tolerances{1e-9, 1e-9});
  State state{0.0, VecX::Constant(1, 1.0), VecX::Zero(1)};
  double last = -1.0;
  run(system, dopri, state, {7.3, 0.5, 1}, [&](const State& s) { last = s.t; });
  EXPECT_EQ(last, 7.3);
  EXPECT_NEAR(state.q[0], std::cos(7.3), 1e-7);
}

// q̈ = u(t), u a pulse of height a on [t_on, t_off): q is piecewise quadratic, so a method of
// order ≥ 2 whose steps never straddle an edge integrates it exactly. Breakpoints and one-sided
// inputs are announced through next_discontinuity / begin_step, as a model's signals are.
class PulseDriven final : public SecondOrderSystem {
 public:
  static constexpr double kOn = 0.1234, kOff = 0.6789, kHeight = 3.0;
  int nq() const override { return 1; }
  int nv() const override { return 1; }
  void begin_step(double, double t1) override { step_end_ = t1; }
  double next_discontinuity(double t) const override {
    if (t < kOn) return kOn;
    if (t < kOff) return kOff;
    return std::numeric_limits<double>::infinity();
  }
  void acceleration(double t, const VecX&, const VecX&, VecX& vdot) override {
    // The left limit at the end of the step, the right limit elsewhere.
    const bool at_end = t >= step_end_;
    const bool on = at_end ? (t > kOn && t <= kOff) : (t >= kOn && t < kOff);
    vdot[0] = on ? kHeight : 0.0;
  }
  void integrate(const VecX& q, const VecX& dq, VecX& q_out) const override { q_out = q + dq; }
  // Exact q(t) from rest at 0.
  static double exact_q(double t) {
    const auto ramp2 = [](double s) { return s > 0 ? 0.5 * s * s : 0.0; };
    return kHeight * (ramp2(t - kOn) - ramp2(t - kOff));
  }

 private:
  double step_end_ = std::numeric_limits<double>::infinity();
};

TEST(Run, StepsLandOnInputDiscontinuitiesAndKeepTheirOrder) {
  // With steps ending on both edges and the left limit at each step's end, RK4 and Dormand–
  // Prince are exact for this piecewise-quadratic motion (round-off only, 1e-14); straddling an
  // edge would cost an O(h·a) = 3e-2 error in v. The grid steps (h = 0.1) are still reported at
  // k h: the short steps to the edges are not.
  for (const bool adaptive : {false, true}) {
    PulseDriven system;
    RungeKutta4 rk4;
    DormandPrince5 dopri(Tolerances{1e-10, 1e-12});
    Integrator& integrator = adaptive ? static_cast<Integrator&>(dopri) : rk4;
    State state{0.0, VecX::Zero(1), VecX::Zero(1)};
    std::vector<double> times;
    run(system, integrator, state, {1.0, 0.1, 1}, [&](const State& s) {
      times.push_back(s.t);
      EXPECT_NEAR(s.q[0], PulseDriven::exact_q(s.t), 1e-14) << integrator.name() << " t=" << s.t;
    });
    EXPECT_NEAR(state.v[0], PulseDriven::kHeight * (PulseDriven::kOff - PulseDriven::kOn), 1e-14)
        << integrator.name();
    if (!adaptive) {
      ASSERT_EQ(times.size(), 11u);
      for (int k = 0; k <= 10; ++k) EXPECT_EQ(times[k], k * 0.1);
      EXPECT_EQ(integrator.statistics().steps, 12);  // ten grid steps and two to the edges
    }
  }
}

// q̈ = 2 q³ blows up in finite time: q = 1/(1 − t) for q(0) = v(0) = 1.
class Blowup final : public SecondOrderSystem {
 public:
  int nq() const override { return 1; }
  int nv() const override { return 1; }
  void acceleration(double, const VecX& q, const VecX&, VecX& vdot) override {
    vdot[0] = 2.0 * q[0] * q[0] * q[0];
  }
  void integrate(const VecX& q, const VecX& dq, VecX& q_out) const override { q_out = q + dq; }
  std::string coordinate_name(int, bool velocity) const override {
    return velocity ? "slider.v0" : "slider.q0";
  }
};

TEST(Run, NonFiniteStateStopsWithTheTimeAndTheCoordinate) {
  // q = 1/(1 − t) solves q̈ = 2q³ with q(0) = 1, v(0) = 1: infinite at t = 1.
  Blowup system;
  SymplecticEuler euler;
  State state{0.0, VecX::Constant(1, 1.0), VecX::Constant(1, 1.0)};
  try {
    run(system, euler, state, {2.0, 0.05, 1}, [](const State&) {});
    FAIL() << "no throw";
  } catch (const NumericalError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("non-finite at t = "), std::string::npos) << message;
    EXPECT_NE(message.find("slider."), std::string::npos) << message;
    // What to try, as options (the front ends spell them: --dt, dt=).
    EXPECT_NE(message.find("try a smaller step, or integrator dopri5"), std::string::npos)
        << message;
    EXPECT_EQ(error.options(), (std::vector<std::string>{"step", "integrator", "integrator"}));
  }
}

// q̈ = −sign(q̇): Coulomb friction with nothing to hold the mass still. From q̇ = 1 it stops at
// t = 1; after that no step is accurate (the right side turns round within any step) and
// dopri5's steps shrink to round-off, advancing nothing.
class CoulombSlider final : public SecondOrderSystem {
 public:
  int nq() const override { return 1; }
  int nv() const override { return 1; }
  void acceleration(double, const VecX&, const VecX& v, VecX& vdot) override {
    vdot[0] = v[0] > 0.0 ? -1.0 : 1.0;
  }
  void integrate(const VecX& q, const VecX& dq, VecX& q_out) const override { q_out = q + dq; }
};

TEST(Run, ACrawlingAdaptiveRunStopsWithTheTimeAndTheStep) {
  CoulombSlider system;
  DormandPrince5 dopri(Tolerances{1e-12, 1e-14});
  State state{0.0, VecX::Zero(1), VecX::Constant(1, 1.0)};
  long reported = 0;
  try {
    run(system, dopri, state, {2.0, 0.1, 1}, [&](const State&) { ++reported; });
    FAIL() << "the run ended";
  } catch (const NumericalError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("the run crawls at t = 1"), std::string::npos) << message;
    EXPECT_NE(message.find("dopri5's last 10000 steps each advanced it by less than 1e-10 of its "
                           "span"),
              std::string::npos)
        << message;
    EXPECT_EQ(error.options(), (std::vector<std::string>{"integrator"}));
  }
  // Stopped where it stalled, at the stop, after the 10 000 steps that crawled.
  EXPECT_NEAR(state.t, 1.0, 1e-6);
  EXPECT_GE(reported, kCrawlingSteps);
  EXPECT_LT(reported, kCrawlingSteps + 1000);
}

TEST(Run, RejectsBadOptions) {
  test::HarmonicOscillator system(1.0);
  RungeKutta4 rk4;
  State state{0.0, VecX::Constant(1, 1.0), VecX::Zero(1)};
  const auto nothing = [](const State&) {};
  EXPECT_THROW(run(system, rk4, state, {0.0, 0.1, 1}, nothing), InvalidArgument);
  EXPECT_THROW(run(system, rk4, state, {1.0, -0.1, 1}, nothing), InvalidArgument);
  EXPECT_THROW(run(system, rk4, state, {1.0, 0.1, 0}, nothing), InvalidArgument);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(run(system, rk4, state, {1.0, nan, 1}, nothing), InvalidArgument);
}

}  // namespace
}  // namespace momenta::integrate
