#include "momenta/model/signal.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"

namespace momenta::model {
namespace {

// Central differences of the value (and of the rate) against the analytic derivatives. With step
// h = 1e-5 the truncation error is O(h²·u''') ≈ 1e-9 for these O(1)–O(100) signals, and round-off
// O(eps/h) ≈ 1e-11; 1e-6 relative covers both with margin while catching any wrong factor.
void expect_derivatives_consistent(const Signal& s, double t) {
  const double h = 1e-5;
  const SignalSample at = s.sample(t);
  const double rate_fd = (s.value(t + h) - s.value(t - h)) / (2 * h);
  const double acc_fd = (s.sample(t + h).rate - s.sample(t - h).rate) / (2 * h);
  EXPECT_NEAR(at.rate, rate_fd, 1e-6 * std::max(1.0, std::abs(rate_fd))) << s.name() << " t=" << t;
  EXPECT_NEAR(at.acceleration, acc_fd, 1e-6 * std::max(1.0, std::abs(acc_fd)))
      << s.name() << " t=" << t;
}

TEST(Signal, StepJumpsAndSmoothStepIsC2) {
  const Signal hard("u", StepSignal{.start = 1.0, .initial = 0.0, .final = 2.0});
  EXPECT_EQ(hard.value(0.999), 0.0);
  EXPECT_EQ(hard.value(1.0), 2.0);
  const Signal smooth("r",
                      StepSignal{.start = 1.0, .initial = 0.0, .final = 2.0, .rise_time = 0.5});
  EXPECT_NEAR(smooth.value(1.25), 1.0, 1e-15);  // midpoint of a symmetric blend
  EXPECT_EQ(smooth.value(1.5), 2.0);
  for (double t : {1.05, 1.2, 1.3, 1.45}) expect_derivatives_consistent(smooth, t);
}

TEST(Signal, RampPulseSineChirpTable) {
  const Signal ramp("ramp", RampSignal{.start = 1.0, .slope = 3.0, .offset = 1.0, .stop = 2.0});
  EXPECT_NEAR(ramp.value(1.5), 2.5, 1e-15);
  EXPECT_NEAR(ramp.value(5.0), 4.0, 1e-15);
  const Signal pulse("p", PulseSignal{.start = 1, .width = 0.5, .amplitude = 10, .period = 2});
  EXPECT_EQ(pulse.value(1.2), 10.0);
  EXPECT_EQ(pulse.value(1.6), 0.0);
  EXPECT_EQ(pulse.value(3.2), 10.0);
  EXPECT_EQ(pulse.value(0.9), 0.0);
  const Signal sine("s", SineSignal{.amplitude = 2, .frequency = 0.5, .phase = 0.3, .offset = 1});
  EXPECT_NEAR(sine.value(0.7), 1 + 2 * std::sin(std::numbers::pi * 0.7 + 0.3), 1e-15);
  expect_derivatives_consistent(sine, 0.7);
  const Signal chirp("c", ChirpSignal{.amplitude = 1, .f0 = 1, .f1 = 5, .start = 0, .duration = 4});
  for (double t : {0.3, 1.7, 3.9}) expect_derivatives_consistent(chirp, t);
  // Instantaneous frequency at the end is f1: zero crossings 1/(2 f1) apart there.
  const Signal table("tab", TableSignal{{0, 1, 3}, {0, 2, -2}});
  EXPECT_NEAR(table.value(0.5), 1.0, 1e-15);
  EXPECT_NEAR(table.value(2.0), 0.0, 1e-15);
  EXPECT_NEAR(table.sample(2.0).rate, -2.0, 1e-15);
  EXPECT_EQ(table.value(-1), 0.0);
  EXPECT_EQ(table.value(9), -2.0);
}

TEST(Signal, LimitsFromBothSidesAtBreakpoints) {
  // At a breakpoint the right limit is the piece starting there, the left limit the piece ending
  // there; away from breakpoints they agree.
  const Signal pulse("p", PulseSignal{.start = 1, .width = 0.5, .amplitude = 10, .period = 2});
  EXPECT_EQ(pulse.sample(1.0).value, 10.0);
  EXPECT_EQ(pulse.sample(1.0, Limit::left).value, 0.0);
  EXPECT_EQ(pulse.sample(1.5).value, 0.0);
  EXPECT_EQ(pulse.sample(1.5, Limit::left).value, 10.0);
  EXPECT_EQ(pulse.sample(3.0, Limit::left).value, 0.0);  // the end of the first period
  EXPECT_EQ(pulse.sample(3.0).value, 10.0);
  EXPECT_EQ(pulse.sample(1.2, Limit::left).value, 10.0);
  const Signal ramp("r", RampSignal{.start = 1.0, .slope = 3.0, .offset = 1.0, .stop = 2.0});
  EXPECT_EQ(ramp.sample(1.0).rate, 3.0);
  EXPECT_EQ(ramp.sample(1.0, Limit::left).rate, 0.0);
  EXPECT_EQ(ramp.sample(2.0).rate, 0.0);
  EXPECT_EQ(ramp.sample(2.0, Limit::left).rate, 3.0);
  EXPECT_EQ(ramp.sample(2.0, Limit::left).value, ramp.sample(2.0).value);  // continuous value
  const Signal step("s", StepSignal{.start = 1.0, .initial = 0.0, .final = 2.0, .rise_time = 0.5});
  // The quintic blend's acceleration jumps at both ends: 0 outside, ±60/T²·... inside → 0 at the
  // ends, so both limits of the C² blend agree in value, rate and acceleration there.
  EXPECT_EQ(step.sample(1.0, Limit::left).value, step.sample(1.0).value);
  const Signal hard("h", StepSignal{.start = 1.0, .initial = 0.0, .final = 2.0});
  EXPECT_EQ(hard.sample(1.0, Limit::left).value, 0.0);
  EXPECT_EQ(hard.sample(1.0).value, 2.0);
  const Signal table("tab", TableSignal{{0, 1, 3}, {0, 2, -2}});
  EXPECT_EQ(table.sample(1.0).rate, -2.0);
  EXPECT_EQ(table.sample(1.0, Limit::left).rate, 2.0);
  EXPECT_EQ(table.sample(0.0, Limit::left).rate, 0.0);
  EXPECT_EQ(table.sample(0.0).rate, 2.0);
  EXPECT_EQ(table.sample(3.0, Limit::left).rate, -2.0);
  EXPECT_EQ(table.sample(3.0).rate, 0.0);
  const Signal chirp("c", ChirpSignal{.amplitude = 1, .f0 = 1, .f1 = 5, .start = 0, .duration = 4});
  EXPECT_EQ(chirp.sample(0.0, Limit::left).rate, 0.0);
  EXPECT_GT(chirp.sample(0.0).rate, 0.0);
  EXPECT_NE(chirp.sample(4.0, Limit::left).rate, 0.0);
  EXPECT_EQ(chirp.sample(4.0).rate, 0.0);
}

TEST(Signal, NextBreakpointIsTheFirstJumpAfterT) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  EXPECT_EQ(Signal("k", ConstantSignal{3.0}).next_breakpoint(0.0), kNone);
  const Signal step("s", StepSignal{.start = 1.0, .initial = 0.0, .final = 2.0, .rise_time = 0.5});
  EXPECT_EQ(step.next_breakpoint(0.0), 1.0);
  EXPECT_EQ(step.next_breakpoint(1.0), 1.5);  // strictly after t
  EXPECT_EQ(step.next_breakpoint(1.5), kNone);
  const Signal pulse("p", PulseSignal{.start = 1, .width = 0.5, .amplitude = 10, .period = 2});
  EXPECT_EQ(pulse.next_breakpoint(0.0), 1.0);
  EXPECT_EQ(pulse.next_breakpoint(1.0), 1.5);
  EXPECT_EQ(pulse.next_breakpoint(1.7), 3.0);
  EXPECT_EQ(pulse.next_breakpoint(3.0), 3.5);
  EXPECT_EQ(pulse.next_breakpoint(100.2), 101.0);
  const Signal once("o", PulseSignal{.start = 1, .width = 0.5});
  EXPECT_EQ(once.next_breakpoint(1.2), 1.5);
  EXPECT_EQ(once.next_breakpoint(1.5), kNone);
  const Signal ramp("r", RampSignal{.start = 1.0, .slope = 3.0});
  EXPECT_EQ(ramp.next_breakpoint(0.0), 1.0);
  EXPECT_EQ(ramp.next_breakpoint(1.0), kNone);  // no stop
  const Signal table("tab", TableSignal{{0, 1, 3}, {0, 2, -2}});
  EXPECT_EQ(table.next_breakpoint(-5.0), 0.0);
  EXPECT_EQ(table.next_breakpoint(0.0), 1.0);
  EXPECT_EQ(table.next_breakpoint(2.0), 3.0);
  EXPECT_EQ(table.next_breakpoint(3.0), kNone);
  const Signal sine("sin", SineSignal{.start = 2.0});
  EXPECT_EQ(sine.next_breakpoint(0.0), 2.0);
  EXPECT_EQ(sine.next_breakpoint(2.0), kNone);
}

TEST(Signal, RejectsBadParameters) {
  EXPECT_THROW(Signal("p", PulseSignal{.width = 0}), InvalidArgument);
  EXPECT_THROW(Signal("p", PulseSignal{.width = 2, .period = 1}), InvalidArgument);
  EXPECT_THROW(Signal("c", ChirpSignal{.duration = -1}), InvalidArgument);
  EXPECT_THROW(Signal("t", TableSignal{{0, 0}, {1, 2}}), InvalidArgument);
  EXPECT_THROW(Signal("t", TableSignal{{0, 1}, {1}}), InvalidArgument);
  EXPECT_THROW(Signal("s", StepSignal{.rise_time = -1}), InvalidArgument);
  try {
    Signal("road", TableSignal{{0, 2, 1}, {0, 0, 0}});
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("road"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("row 3"), std::string::npos);
  }
}

}  // namespace
}  // namespace momenta::model
