// Events: conditions read from text, and a run that watches them — located on the dense output
// to round-off where that output is exact (a body in free fall: a quadratic that rk4, sdirk3 and
// dopri5 integrate exactly and that the cubic Hermite and dopri5's quartic interpolants
// reproduce), rows at the events' times, stop ending the run, rising, falling and either-way
// crossings, a quantity that starts on its value, and the errors for a condition that cannot be
// watched.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/model/event_spec.hpp"
#include "momenta/model/model_builder.hpp"
#include "momenta/simulate/event_monitor.hpp"
#include "momenta/simulate/simulation.hpp"

namespace momenta::simulate {
namespace {

using model::EventAction;
using model::EventDirection;
using model::EventSpec;
using model::parse_event_condition;

// A 1 kg body on a vertical slider, g = 9.81 m/s², from z0 with speed w0 (up positive).
model::Model slider(double z0, double w0) {
  model::ModelBuilder b;
  b.add_body("ball", inertia::MassProperties(1.0, Vec3::Zero(), Mat3::Identity() * 1e-3));
  model::Joint j;
  j.name = "lift";
  j.type = model::JointType::prismatic;
  j.parent = "world";
  j.child = "ball";
  j.axis = Vec3::UnitZ();
  j.q0 = VecX::Constant(1, z0);
  j.v0 = VecX::Constant(1, w0);
  b.add_joint(j);
  return b.build();
}

EventSpec stop_when(const std::string& condition) {
  return parse_event_condition(condition, EventAction::stop);
}

struct EventRun {
  SimulationSummary summary;
  TableSink table;
};

EventRun simulate(const model::Model& model, const std::string& integrator, double step,
                  std::vector<EventSpec> events, double duration = 2.0) {
  SimulationOptions options;
  options.duration = duration;
  options.step = step;
  options.integrator = integrator;
  options.tolerances = {1e-10, 1e-12};
  options.events = std::move(events);
  Simulation simulation(model, {}, options);
  EventRun run;
  run.summary = simulation.run(run.table);
  return run;
}

TEST(EventCondition, ReadsTheQuantityTheComparisonAndTheValue) {
  const EventSpec falling = parse_event_condition("tension < 0");
  EXPECT_EQ(falling.quantity, "tension");
  EXPECT_EQ(falling.direction, EventDirection::falling);
  EXPECT_EQ(falling.value, 0.0);
  EXPECT_EQ(falling.action, EventAction::record);
  EXPECT_EQ(falling.name, "tension < 0");
  const EventSpec rising = parse_event_condition("bob.z>-0.25");
  EXPECT_EQ(rising.quantity, "bob.z");
  EXPECT_EQ(rising.direction, EventDirection::rising);
  EXPECT_EQ(rising.value, -0.25);
  const EventSpec either = parse_event_condition("  pivot.angle =  +1.5e-3 ");
  EXPECT_EQ(either.quantity, "pivot.angle");
  EXPECT_EQ(either.direction, EventDirection::either);
  EXPECT_EQ(either.value, 1.5e-3);
  EXPECT_EQ(model::event_condition_text(either), "pivot.angle = 0.0015");
}

TEST(EventCondition, RefusesWhatIsNotOneComparisonOfAQuantityWithANumber) {
  const auto message = [](const std::string& text) {
    try {
      parse_event_condition(text);
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("tension").find("no comparison"), std::string::npos);
  EXPECT_NE(message("x <= 1").find("one comparison only"), std::string::npos);
  EXPECT_NE(message("0 < x < 1").find("one comparison only"), std::string::npos);
  EXPECT_NE(message(" < 1").find("no quantity"), std::string::npos);
  EXPECT_NE(message("x < y").find("'y' is not a finite number"), std::string::npos);
  EXPECT_NE(message("x < nan").find("not a finite number"), std::string::npos);
  EXPECT_NE(message("x < 1e999").find("not a finite number"), std::string::npos);
  EXPECT_NE(message("x > 1 m").find("'1 m' is not a finite number"), std::string::npos);
}

// z = 1 − g t²/2 reaches 0 at t = √(2/g): every method here integrates the quadratic exactly and
// its dense output reproduces it, so the located time is the exact one to round-off — whatever
// the step (0.1 s: the event lies deep inside one).
TEST(Events, FreeFallReachesTheFloorAtTheExactTimeOnEveryDenseOutput) {
  const double exact = std::sqrt(2.0 / 9.81);
  const model::Model model = slider(1.0, 0.0);
  for (const char* integrator : {"rk4", "sdirk3", "dopri5"}) {
    SCOPED_TRACE(integrator);
    const EventRun run = simulate(model, integrator, 0.1, {stop_when("lift.position < 0")});
    ASSERT_EQ(run.summary.events.size(), 1u);
    const EventOccurrence& e = run.summary.events.front();
    EXPECT_NEAR(e.time, exact, 1e-14 * exact);
    EXPECT_EQ(e.action, EventAction::stop);
    EXPECT_NEAR(e.value, 0.0, 1e-13);  // |ż| = 4.4 m/s times the time's round-off
    // The run ends on the event's row: its time, z there, the speed −g t.
    EXPECT_EQ(run.summary.t_end, e.time);
    const std::vector<double>& last = run.table.rows.back();
    EXPECT_EQ(last[run.table.column("time")], e.time);
    EXPECT_NEAR(last[run.table.column("lift.position")], 0.0, 1e-13);
    EXPECT_NEAR(last[run.table.column("lift.position_rate")], -9.81 * exact, 1e-12);
    // Fixed steps: rows at 0, 0.1, ..., 0.4 and the event at 0.4515 (dopri5 starts smaller).
    if (std::string(integrator) != "dopri5") {
      EXPECT_EQ(run.table.rows.size(), 6u);
    }
  }
}

// Thrown up at 5 m/s from z = 0: above 1 m from t1 to t2 (roots of 5 t − g t²/2 = 1), the apex at
// 5/g. A record event adds a row and the run goes on; '=' sees both crossings; one run can watch
// several conditions, each reported in time order.
TEST(Events, RecordEventsAddRowsInTimeOrderAndSeeEachCrossing) {
  const double g = 9.81;
  const double disc = std::sqrt(25.0 - 2.0 * g);
  const double t1 = (5.0 - disc) / g, t2 = (5.0 + disc) / g, apex = 5.0 / g;
  const model::Model model = slider(0.0, 5.0);
  const EventRun plain = simulate(model, "rk4", 0.01, {}, 1.0);
  const EventRun run = simulate(
      model, "rk4", 0.01,
      {parse_event_condition("lift.position = 1"), parse_event_condition("lift.position_rate < 0"),
       parse_event_condition("lift.position > 1")},
      1.0);
  ASSERT_EQ(run.summary.events.size(), 4u);
  const auto& ev = run.summary.events;
  EXPECT_EQ(ev[0].name, "lift.position = 1");  // rising through 1 m: '=' and '>' at t1
  EXPECT_NEAR(ev[0].time, t1, 1e-14);
  EXPECT_EQ(ev[1].name, "lift.position > 1");
  EXPECT_NEAR(ev[1].time, t1, 1e-14);
  EXPECT_EQ(ev[2].name, "lift.position_rate < 0");
  EXPECT_NEAR(ev[2].time, apex, 1e-14);
  EXPECT_EQ(ev[3].name, "lift.position = 1");  // falling back through 1 m: '=' only
  EXPECT_NEAR(ev[3].time, t2, 1e-14);
  for (const EventOccurrence& e : ev) EXPECT_EQ(e.action, EventAction::record);
  // The whole run, and one more row per event, times increasing.
  EXPECT_EQ(run.summary.t_end, 1.0);
  EXPECT_EQ(run.table.rows.size(), plain.table.rows.size() + 4);
  const int time = run.table.column("time");
  for (std::size_t i = 1; i < run.table.rows.size(); ++i)
    EXPECT_GE(run.table.rows[i][time], run.table.rows[i - 1][time]);
}

// Starting on the value, an event waits until the quantity has left it: the slider at rest at
// z = 0 thrown up is not "z = 0" at t = 0⁺, only when it comes back down.
TEST(Events, AQuantityStartingOnItsValueCountsOnlyOnceItHasLeftIt) {
  const EventRun run =
      simulate(slider(0.0, 5.0), "rk4", 0.01, {parse_event_condition("lift.position = 0")}, 1.2);
  ASSERT_EQ(run.summary.events.size(), 1u);
  EXPECT_NEAR(run.summary.events[0].time, 10.0 / 9.81, 1e-14);
}

TEST(Events, AConditionOnAQuantityTheRunDoesNotHaveIsRefusedWithTheNamesThereAre) {
  const model::Model model = slider(1.0, 0.0);
  try {
    simulate(model, "rk4", 0.01, {parse_event_condition("lift.postion < 0")});
    FAIL() << "accepted";
  } catch (const InvalidArgument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("event 'lift.postion < 0': no quantity 'lift.postion'"), std::string::npos)
        << what;
    EXPECT_NE(what.find("did you mean 'lift.position'"), std::string::npos) << what;
    EXPECT_NE(what.find("energy_total"), std::string::npos) << what;
  }
}

TEST(Events, TheSummaryListsThemAndSaysWhichStoppedTheRun) {
  const EventRun run =
      simulate(slider(0.0, 5.0), "rk4", 0.01,
               {parse_event_condition("lift.position_rate < 0"), stop_when("lift.position < 0.5")});
  const std::string text = format_summary(run.summary);
  EXPECT_NE(text.find("events       lift.position_rate < 0 at t = 0.509683995923 s\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("             lift.position < 0.5 at t = "), std::string::npos) << text;
  EXPECT_NE(text.find(": the run stops there"), std::string::npos) << text;
}

}  // namespace
}  // namespace momenta::simulate
