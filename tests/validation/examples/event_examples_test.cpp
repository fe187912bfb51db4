// Events on the bundled examples against closed forms: the pendulum of examples/pendulum.yaml
// reaching the vertical at the quarter period the complete elliptic integral gives, and Beer &
// Johnston 18.3's rod hanging from a braked shaft (examples/constraints/
// rod_on_shaft_spinning_down.yaml) whose wire goes slack at the speed the statics give.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <boost/math/special_functions/ellint_1.hpp>

#include "example_simulation.hpp"
#include "momenta/simulate/simulation.hpp"

namespace momenta {
namespace {

struct EventRun {
  simulate::SimulationSummary summary;
  simulate::TableSink table;
};

EventRun run_example(const std::string& name, const std::string& integrator, double step,
                     std::vector<model::EventSpec> extra = {}) {
  const io::ModelFile file = test::load_example(name);
  simulate::SimulationOptions options;
  options.duration = file.simulation.duration.value_or(10.0);
  options.step = step;
  options.integrator = integrator;
  options.tolerances = {1e-12, 1e-14};
  options.events = file.simulation.events;
  for (model::EventSpec& e : extra) options.events.push_back(std::move(e));
  simulate::Simulation simulation(file.model, file.outputs, options);
  EventRun run;
  run.summary = simulation.run(run.table);
  return run;
}

// Released from rest at θ0 = 120°, a point pendulum (L = 1 m) first hangs straight down at a
// quarter period, t = √(L/g) K(sin(θ0/2)) = 0.688522457222 s. The event 'pivot.angle < 0' stops
// the run there. Measured relative errors: rk4 3.6e-13 at h = 1 ms, dopri5 1.5e-16 at rtol 1e-12
// (the bound 2e-12 is rk4's global error at that step, (ω h)⁴ ≈ 1e-11 of the phase, measured
// smaller); the location itself is good to 1e-14 (free fall in event_test.cpp).
TEST(EventExamples, PendulumReachesTheVerticalAtTheEllipticIntegralTime) {
  const double theta0 = 120.0 * M_PI / 180.0;
  const double exact = std::sqrt(1.0 / 9.81) * boost::math::ellint_1(std::sin(theta0 / 2));
  for (const auto& [integrator, step] :
       std::vector<std::pair<std::string, double>>{{"rk4", 1e-3}, {"dopri5", 1e-2}}) {
    SCOPED_TRACE(integrator);
    const EventRun run =
        run_example("pendulum", integrator, step,
                    {model::parse_event_condition("pivot.angle < 0", model::EventAction::stop)});
    ASSERT_EQ(run.summary.events.size(), 1u);
    EXPECT_NEAR(run.summary.events[0].time, exact, 2e-12 * exact);
    EXPECT_EQ(run.summary.t_end, run.summary.events[0].time);
    // At the bottom the speed is √(2 g L (1 − cos θ0)) = √(3 g), the angle 0.
    const std::vector<double>& last = run.table.rows.back();
    EXPECT_NEAR(last[run.table.column("pivot.angle")], 0.0, 1e-12);
    EXPECT_NEAR(last[run.table.column("pivot.angle_rate")], -std::sqrt(3 * 9.81), 1e-10);
  }
}

// The rod hangs at β = 30° from a shaft braked by 20 N·m from 15 rad/s. The wire's tension is
// T(ω) = m ω² L sin β / 3 − m g tan β / 2 (the file's comment derives it), zero at
// ω_s² = 3 g / (2 L cos β); shaft and rod turn as one body of I_z = ½ m_s r² + m L² sin² β / 3,
// so ω falls linearly and the wire goes slack at t_s = (15 − ω_s) I_z / 20 = 4.0297796 s. Every
// method here integrates a linear ω exactly: what is left is the round-off of the constrained
// solve (1e-13 of T ≈ 1.5e-10 N, against dT/dt ≈ −116 N/s: 1e-12 s). Measured: rk4 1.3e-13
// relative.
TEST(EventExamples, RodOnABrakedShaftLosesItsWireAtTheSpeedTheStaticsGive) {
  const double g = 9.81, L = 2.0, m = 20.0, beta = M_PI / 6;
  const double omega_s = std::sqrt(3 * g / (2 * L * std::cos(beta)));
  const double I_z = 0.5 * 5.0 * 0.03 * 0.03 + m * L * L * std::sin(beta) * std::sin(beta) / 3;
  const double t_s = (15.0 - omega_s) * I_z / 20.0;
  for (const auto& [integrator, step] : std::vector<std::pair<std::string, double>>{
           {"rk4", 1e-3}, {"dopri5", 0.05}, {"bdf", 0.05}}) {
    SCOPED_TRACE(integrator);
    const EventRun run = run_example("constraints/rod_on_shaft_spinning_down", integrator, step);
    ASSERT_EQ(run.summary.events.size(), 1u);
    const simulate::EventOccurrence& slack = run.summary.events[0];
    EXPECT_EQ(slack.name, "slack");
    EXPECT_EQ(slack.condition, "tension < 0");
    EXPECT_EQ(slack.action, model::EventAction::stop);
    EXPECT_NEAR(slack.time, t_s, 1e-10 * t_s);
    EXPECT_EQ(run.summary.t_end, slack.time);
    const std::vector<double>& last = run.table.rows.back();
    EXPECT_EQ(last[run.table.column("time")], slack.time);
    EXPECT_NEAR(last[run.table.column("shaft_speed")], omega_s, 1e-10 * omega_s);
    EXPECT_LE(last[run.table.column("tension")], 1e-9);
    EXPECT_NEAR(last[run.table.column("tension")], 0.0, 1e-8);  // of T(15) = 1443 N
    EXPECT_NEAR(last[run.table.column("beta")], beta, 1e-12);   // the wire held the rod
    // Before it, the tension follows T(ω) row by row.
    const auto& first = run.table.rows.front();
    EXPECT_NEAR(first[run.table.column("tension")],
                m * 225.0 * L * std::sin(beta) / 3 - m * g * std::tan(beta) / 2, 1e-9 * 1443.0);
  }
}

}  // namespace
}  // namespace momenta
