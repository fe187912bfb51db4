// Joint stops in a run (simulate/joint_stops.hpp) against closed forms:
// - a ball dropped from h on a floor (examples/bouncing_ball.yaml) with restitution e (a prismatic
// joint's lower stop): the
//   bounce times t₁ (1 + 2e + … + 2e^{k−1}), t₁ = √(2h/g), each rebound's speed e^k √(2gh) and so
//   its height h e^{2k}, the measured e, and rest at t₁ (1 + e)/(1 − e) — the Zeno limit — after
//   which the ball lies still with the floor's force m g;
// - a pendulum swinging into a stop: its rate there from energy, the rebound −e times it, the
//   angle never past the stop;
// - elastic stops (e = 1): the energy audit holds across every impact;
// - a slider rattling between elastic stops: 1 µm apart, followed impact by impact; 1 nm apart
//   (10 000 impacts within 10 µs), stopped with an error naming the stop;
// - a pendulum held on a stop by gravity and pulled off by a torque ramp: released when the torque
//   equals the weight's moment, the stop's force until then m g (l/2) sin θ − c t;
// - a robot's limits (URDF's <limit>, MJCF's range): a rod falling into one is held there; a
//   falling humanoid's joints resting on theirs are left alone;
// - stops on constrained models: a four-bar whose crank falls onto its stop — the loop's rows and
//   the hold together — loses (1 − e²) of what gravity gave it at each impact and comes to rest
//   on the stop, which then pushes with the torque virtual work gives, dV/dθ₂ along the loop; a
//   robot whose mimic joint (URDF) or joint equality (MJCF) couples a second rod to the limited
//   one: the stop holds both, its force the moments of both weights;
// - the model file's errors for stops where there are none to give.

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/io/mjcf_file.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/io/urdf_file.hpp"
#include "momenta/simulate/simulation.hpp"
#include "momenta_test/tolerance.hpp"
#include "unilateral_runs.hpp"

namespace momenta::simulate {
namespace {

using namespace unilateral_test;

TEST(JointStops, BouncingBallMatchesTheClosedForm) {
  const double h = 1.0, e = 0.8;
  const double t1 = std::sqrt(2.0 * h / kG);
  const double v1 = std::sqrt(2.0 * kG * h);
  for (const std::string integrator : {"rk4", "dopri5"}) {
    SCOPED_TRACE(integrator);
    // examples/bouncing_ball.yaml: h = 1 m, e = 0.8 (tests run from the source tree).
    const UnilateralRun run =
        run_unilaterals(io::read_model_file("examples/bouncing_ball.yaml").model, integrator, 1e-3,
                        5.0, /*reactions=*/true);
    const std::vector<StopEvent>& events = run.summary.stop_events;
    ASSERT_GT(events.size(), 50u);
    double t_expected = t1;
    for (std::size_t k = 0; k < events.size(); ++k) {
      const StopEvent& s = events[k];
      EXPECT_EQ(s.joint, "drop");
      EXPECT_FALSE(s.upper);
      if (k + 1 < events.size()) {
        ASSERT_EQ(s.kind, StopEventKind::impact) << k;
      }
      // Its time, the speed it arrives with, e^k √(2gh), and the measured e. rk4 integrates the
      // parabola exactly and the Hermite interpolant reproduces it; dopri5's error is its
      // tolerance's. The errors of the event location (1e-14 relative in time) add up over k.
      const double v_in = v1 * std::pow(e, static_cast<double>(k));
      if (k < 20) {
        EXPECT_NEAR(s.time, t_expected, 1e-12 * t_expected) << k;
        EXPECT_NEAR(s.rate_before, -v_in, 1e-11 * v1) << k;
      }
      if (s.kind == StopEventKind::impact) {
        EXPECT_NEAR(-s.rate_after / s.rate_before, e, 1e-12) << k;
        // The impulse turns m v⁻ into m v⁺, and takes ½ m (v⁻² − v⁺²).
        EXPECT_NEAR(s.impulse, 0.1 * (s.rate_after - s.rate_before), 1e-14) << k;
        EXPECT_NEAR(s.energy_lost, 0.05 * s.rate_before * s.rate_before * (1 - e * e), 1e-13) << k;
      }
      t_expected += 2.0 * v_in * e / kG;
    }
    // The last event holds the ball: its bounces end at t₁ (1 + e)/(1 − e).
    const StopEvent& rest = events.back();
    ASSERT_EQ(rest.kind, StopEventKind::rest);
    EXPECT_NEAR(rest.rest_time, t1 * (1 + e) / (1 - e), 1e-10);
    EXPECT_LT(rest.rest_time - rest.time, 1e-8);

    // The heights between bounces: never above h e^{2k}; never below the floor; at rest on it
    // with the floor's force m g.
    const int z = run.table.column("drop.position");
    const int w = run.table.column("drop.position_rate");
    const int force = run.table.column("drop.stop_force");
    std::size_t k = 0;
    for (const std::vector<double>& row : run.table.rows) {
      while (k + 1 < events.size() && row[0] > events[k].time) ++k;
      EXPECT_GE(row[z], 0.0) << row[0];
      EXPECT_LE(row[z], h * std::pow(e, 2.0 * k) * (1 + 1e-12) + 1e-15) << row[0];
      if (row[0] > rest.time) {
        EXPECT_EQ(row[z], 0.0);
        EXPECT_EQ(row[w], 0.0);
        EXPECT_NEAR(row[force], 0.1 * kG, 1e-13);
      } else if (row[0] < events.front().time) {
        EXPECT_EQ(row[force], 0.0);
      }
    }
  }
}

TEST(JointStops, PendulumReboundsOffAStopAndNeverPassesIt) {
  const double e = 0.5, lower = -0.2, theta0 = 1.0;
  const UnilateralRun run = run_unilaterals(
      load(hanging_rod("q0: 1.0, limits: {lower: -0.2, upper: 2.0, restitution: 0.5}")), "dopri5",
      1e-2, 3.0);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_GE(events.size(), 2u);
  // Energy from θ0 to the stop: ½ I_O θ̇² = m g (l/2)(cos θ_s − cos θ0), I_O = 1/3.
  const double rate = -std::sqrt(3.0 * kG * (std::cos(lower) - std::cos(theta0)));
  EXPECT_NEAR(events[0].rate_before, rate, 1e-9);
  for (const StopEvent& s : events) {
    if (s.kind != StopEventKind::impact) continue;
    EXPECT_FALSE(s.upper);
    EXPECT_NEAR(s.rate_after, -e * s.rate_before, 1e-15);
  }
  const int angle = run.table.column("pin.angle");
  for (const std::vector<double>& row : run.table.rows) EXPECT_GE(row[angle], lower);
}

TEST(JointStops, ElasticStopsKeepTheEnergy) {
  const UnilateralRun run = run_unilaterals(
      load(hanging_rod("v0: 3.0, limits: {lower: -0.3, upper: 0.3, restitution: 1}")), "dopri5",
      1e-2, 10.0);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_GT(events.size(), 20u);
  bool upper = false, lower = false;
  for (const StopEvent& s : events) {
    ASSERT_EQ(s.kind, StopEventKind::impact);
    EXPECT_EQ(s.rate_after, -s.rate_before);
    EXPECT_NEAR(s.energy_lost, 0.0, 1e-13);
    (s.upper ? upper : lower) = true;
  }
  EXPECT_TRUE(upper && lower);
  ASSERT_TRUE(run.summary.energy_audited);
  ASSERT_FALSE(run.summary.audit.empty());
  EXPECT_EQ(run.summary.audit[0].name, "energy");
  EXPECT_LT(run.summary.audit[0].max_drift, 1e-10);
}

// A slider rattling between elastic stops `clearance` m apart at 1 m/s, no gravity: it strikes
// every `clearance` seconds, one stop then the other.
std::string rattling_slider(double clearance) {
  return fmt::format(
      "bodies: [{{name: b, shape: sphere, mass: 1, radius: 0.01}}]\n"
      "joints:\n"
      "  - {{name: slider, type: prismatic, parent: world, child: b, axis: [1, 0, 0], v0: 1,\n"
      "     limits: {{lower: 0, upper: {}, restitution: 1}}}}\n",
      clearance);
}

// A rattle the run follows: stops 1 µm apart, 2 000 impacts in 2 ms (a hundred within any
// 0.1 ms), each elastic and 1 µs after the last.
TEST(JointStops, ARattleBetweenNearStopsIsFollowedImpactByImpact) {
  const double clearance = 1e-6;
  const UnilateralRun run =
      run_unilaterals(load(rattling_slider(clearance)), "dopri5", 1e-2, 2e-3 + 0.5e-6);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_EQ(events.size(), 2000u);
  for (std::size_t k = 0; k < events.size(); ++k) {
    const StopEvent& s = events[k];
    ASSERT_EQ(s.kind, StopEventKind::impact) << k;
    EXPECT_EQ(s.upper, k % 2 == 0) << k;
    // Each at (k + 1) µs, the crossings' times adding up: each located to 1e-14 relative in
    // time (2e-17 s at 2 ms), 2 000 of them at most 4e-14 s.
    EXPECT_NEAR(s.time, static_cast<double>(k + 1) * clearance, 4e-14) << k;
    EXPECT_EQ(s.rate_after, -s.rate_before) << k;
    EXPECT_NEAR(std::abs(s.rate_before), 1.0, 1e-12) << k;
  }
}

// What stops a run of the rattling slider (dopri5 at `step`), or "the run went on".
std::string rattle_error(double clearance, double step, double duration) {
  try {
    run_unilaterals(load(rattling_slider(clearance)), "dopri5", step, duration);
  } catch (const NumericalError& e) {
    return e.what();
  }
  return "the run went on";
}

// Stops 1 nm apart: 10 000 impacts within 10 µs is a sequence no run can follow to its end (a
// rattle at 1 GHz). After 10 000 acts within 0.1 ms the run stops, naming the stop and the span,
// instead of crawling on an impact at a time.
TEST(JointStops, ARattleTooFineToFollowStopsTheRunWithAnError) {
  const std::string message = rattle_error(1e-9, 1e-2, 1.0);
  EXPECT_NE(message.find("acted 10000 times since t = 1e-09 s"), std::string::npos) << message;
  EXPECT_NE(message.find("joint 'slider''s"), std::string::npos) << message;
  EXPECT_NE(message.find("at t = 1.0001e-05 s"), std::string::npos) << message;
}

// Stops 0.5 µm apart, rattled through at 1 m/s, act twice a microsecond: a run of 1 ms steps
// meets two thousand in every step and would crawl on (a second of it is two million impacts).
// After 10 000 acts within ten steps it stops, at the 10 001st, t = 5.0005e-3 s. (Stops 1 µm
// apart fill the ten steps' 10 ms with exactly 10 000, and are followed.)
TEST(JointStops, ThousandsOfActsInEveryStepStopTheRunWithAnError) {
  const std::string message = rattle_error(5e-7, 1e-3, 0.05);
  EXPECT_NE(message.find("acted 10000 times since t = 5e-07 s"), std::string::npos) << message;
  EXPECT_NE(message.find("at t = 0.0050005 s"), std::string::npos) << message;
}

TEST(JointStops, HeldOnAStopUntilATorqueRampPullsItOff) {
  // θ_s = 0.3 rad: gravity's moment −m g (l/2) sin θ_s pushes the rod into its lower stop; the
  // torque c t about +y, c = 1 N·m/s, equals it at t_r = m g (l/2) sin θ_s / c.
  const std::string forces =
      "inputs: [{name: pull, type: ramp, slope: 1.0}]\n"
      "forces: [{name: hand, type: torque, body: rod, vector: [0, 1, 0], signal: pull}]\n";
  const model::Model model = load(hanging_rod("q0: 0.3, limits: {lower: 0.3}", forces));
  const double weight_moment = kG * 0.5 * std::sin(0.3);
  for (const std::string integrator : {"rk4", "dopri5", "bdf"}) {
    SCOPED_TRACE(integrator);
    const UnilateralRun run = run_unilaterals(model, integrator, 1e-2, 2.0, /*reactions=*/true);
    const std::vector<StopEvent>& events = run.summary.stop_events;
    expect_held_then_let_go(events, weight_moment);
    if (HasFatalFailure()) return;
    const int angle = run.table.column("pin.angle");
    const int force = run.table.column("pin.stop_force");
    for (const std::vector<double>& row : run.table.rows) {
      if (row[0] < events[1].time) {
        EXPECT_EQ(row[angle], 0.3) << row[0];
        EXPECT_NEAR(row[force], weight_moment - row[0], 1e-12) << row[0];
      } else if (row[0] > events[1].time) {
        EXPECT_GT(row[angle], 0.3) << row[0];
        EXPECT_EQ(row[force], 0.0);
      }
    }
  }
}

// A robot's limits are stops: a rod (m = 1 kg, its centre 0.5 m from the pin, I_O = I_yy +
// m 0.5²) released level, as URDF draws it (q = 0) and as MJCF does, falls into its upper limit
// at 1 rad. It arrives with the rate energy gives, ½ I_O θ̇² = m g 0.5 sin θ_s; the stop is plastic
// (neither format has a restitution), so it holds the rod there, pushing back the weight's moment
// m g 0.5 cos θ_s.
TEST(JointStops, ARobotsLimitsAreStops) {
  const double iyy = 0.08333333333333333, I_O = iyy + 0.25, stop = 1.0;
  const std::string urdf = R"(<robot name="rod">
  <link name="world"/>
  <link name="rod"><inertial><origin xyz="0.5 0 0"/><mass value="1"/>
    <inertia ixx="1e-6" iyy="0.08333333333333333" izz="0.08333333333333333"/></inertial></link>
  <joint name="pin" type="revolute"><parent link="world"/><child link="rod"/><axis xyz="0 1 0"/>
    <limit lower="-3" upper="1" effort="0" velocity="0"/></joint>
</robot>)";
  const std::string mjcf = R"(<mujoco><compiler angle="radian"/><worldbody>
  <body name="rod"><joint name="pin" axis="0 1 0" range="-3 1"/>
    <inertial pos="0.5 0 0" mass="1" diaginertia="1e-6 0.08333333333333333 0.08333333333333333"/>
  </body></worldbody></mujoco>)";
  for (const io::ModelFile& file :
       {io::parse_urdf(urdf, "rod.urdf"), io::parse_mjcf(mjcf, "rod.xml")}) {
    SCOPED_TRACE(file.file);
    const UnilateralRun run = run_unilaterals(file.model, "dopri5", 1e-2, 2.0, /*reactions=*/true);
    const std::vector<StopEvent>& events = run.summary.stop_events;
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].kind, StopEventKind::rest);
    EXPECT_TRUE(events[0].upper);
    const double rate = std::sqrt(2.0 * kG * 0.5 * std::sin(stop) / I_O);
    EXPECT_NEAR(events[0].rate_before, rate, 1e-9);
    EXPECT_EQ(events[0].rate_after, 0.0);
    EXPECT_NEAR(events[0].energy_lost, kG * 0.5 * std::sin(stop), 1e-8);
    const int angle = run.table.column("pin.angle");
    const int force = run.table.column("pin.stop_force");
    for (const std::vector<double>& row : run.table.rows) {
      EXPECT_LE(row[angle], stop) << row[0];
      if (row[0] > events[0].time) {
        EXPECT_EQ(row[angle], stop) << row[0];
        EXPECT_NEAR(row[force], -kG * 0.5 * std::cos(stop), 1e-12) << row[0];
      }
    }
  }
}

// examples/constraints/four_bar_on_a_stop.yaml: the four-bar of four_bar.yaml (ground d = 0.30 m,
// crank a = 0.10 m of 1 kg, coupler b = 0.30 m of 2 kg, rocker c = 0.25 m of 1.5 kg, uniform rods,
// pins about z, gravity −y), its crank free with a lower stop at θ_s = −0.5 rad (e = 0.5),
// released at rest from θ₂ ≈ 0.
// Its potential energy along the loop, V(θ₂) = g Σ mᵢ yᵢ: the crank's end A = a (cos θ₂, sin θ₂),
// the coupler–rocker pin B where the circles of radius b about A and c about O₄ = (d, 0) meet
// (the branch above the ground line, θ₄ ≈ 97° at θ₂ = 0), the centres halfway along the rods.
double four_bar_potential(double theta2) {
  const double a = 0.10, b = 0.30, c = 0.25, d = 0.30;
  const Eigen::Vector2d A(a * std::cos(theta2), a * std::sin(theta2)), O4(d, 0.0);
  const Eigen::Vector2d AO4 = O4 - A;
  const double L = AO4.norm();
  const double along = (b * b - c * c + L * L) / (2.0 * L),
               across = std::sqrt(b * b - along * along);
  const Eigen::Vector2d u = AO4 / L, n(-u.y(), u.x());
  Eigen::Vector2d B = A + along * u + across * n;
  if (B.y() < 0.0) B = A + along * u - across * n;
  return kG * (1.0 * A.y() / 2.0 + 2.0 * (A.y() + B.y()) / 2.0 + 1.5 * B.y() / 2.0);
}

// The crank strikes its stop through the loop: one coordinate of motion, so each impact leaves
// e² of the kinetic energy, all of it V(0) − V(θ_s) at the first (energy conserved between
// impacts to the integrator's tolerance: 1e-8 J allows for it with rtol 1e-12); the stop's rate
// rule is exact on the coordinate. The bounces end in rest on the stop, where the stop's torque
// balances gravity's through the loop: dV/dθ₂ at θ_s (central difference, δ = 1e-5: truncation
// ~1e-10, round-off ~1e-10 N·m).
TEST(JointStops, AFourBarFallsOntoItsCranksStopAndRestsWhereVirtualWorkSays) {
  const double e = 0.5, stop = -0.5, delta = 1e-5;
  const model::Model model =
      io::read_model_file("examples/constraints/four_bar_on_a_stop.yaml").model;
  ASSERT_EQ(model.joint(model.joint_index("crank_pin")).limits->restitution, e);
  const UnilateralRun run = run_unilaterals(model, "dopri5", 1e-2, 3.0, /*reactions=*/true);
  const int angle = run.table.column("crank_pin.angle");
  // Every angle is given roughly, so the assembly moves the crank too (1.3 mrad): V from there.
  const double start = run.table.rows.front()[angle];
  EXPECT_NEAR(start, 0.0, 2e-3);
  const double fallen = four_bar_potential(start) - four_bar_potential(stop);
  const double holding =
      (four_bar_potential(stop + delta) - four_bar_potential(stop - delta)) / (2.0 * delta);
  ASSERT_GT(fallen, 1.0);   // J: gravity turns the crank into its stop ...
  ASSERT_GT(holding, 2.0);  // N·m: ... and holds it there
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_GE(events.size(), 3u);
  EXPECT_EQ(events[0].kind, StopEventKind::impact);
  EXPECT_NEAR(events[0].energy_lost, (1.0 - e * e) * fallen, 1e-8);
  for (std::size_t k = 0; k + 1 < events.size(); ++k) {
    EXPECT_EQ(events[k].joint, "crank_pin");
    EXPECT_FALSE(events[k].upper);
    EXPECT_EQ(events[k].rate_after, -e * events[k].rate_before);
  }
  EXPECT_EQ(events.back().kind, StopEventKind::rest);
  const double rest = events.back().time;
  EXPECT_LT(rest, 2.0);
  const int force = run.table.column("crank_pin.stop_force");
  const int rocker_rate = run.table.column("rocker_pin.angle_rate");
  for (const std::vector<double>& row : run.table.rows) {
    EXPECT_GE(row[angle], stop) << row[0];
    if (row[0] <= rest) continue;
    EXPECT_EQ(row[angle], stop) << row[0];
    EXPECT_NEAR(row[force], holding, 1e-8) << row[0];
    EXPECT_NEAR(row[rocker_rate], 0.0, 1e-12) << row[0];
  }
}

// One Simulation run twice runs twice alike: the second starts from the model's initial state
// with every stop and contact open, whatever the first left held (the four-bar ends held on its
// stop; the bouncing sphere resting on its floor, the contact's row on).
TEST(JointStops, ASecondRunStartsWithNothingHeld) {
  for (const char* path :
       {"examples/constraints/four_bar_on_a_stop.yaml", "examples/bouncing_sphere.yaml"}) {
    SCOPED_TRACE(path);
    const io::ModelFile file = io::read_model_file(path);
    SimulationOptions options;
    options.duration = file.simulation.duration.value();
    options.step = 1e-3;
    options.integrator = "rk4";
    Simulation simulation(file.model, {}, options);
    TableSink first, second;
    const SimulationSummary a = simulation.run(first);
    const SimulationSummary b = simulation.run(second);
    ASSERT_GT(a.stop_events.size(), 2u);
    EXPECT_EQ(a.stop_events.back().kind, StopEventKind::rest);
    ASSERT_EQ(b.stop_events.size(), a.stop_events.size());
    for (std::size_t k = 0; k < a.stop_events.size(); ++k) {
      EXPECT_EQ(b.stop_events[k].time, a.stop_events[k].time) << k;
      EXPECT_EQ(b.stop_events[k].impulse, a.stop_events[k].impulse) << k;
    }
    EXPECT_EQ(second.rows, first.rows);
  }
}

// Two rods (m = 1 kg, centre 0.5 m from the pin, I_O = 1/3 kg·m²) on pins about y at the world,
// the second coupled to the first (q_b = q_a: URDF's mimic joint, MJCF's joint equality), the first
// with an upper limit at 1 rad, released level. They fall as one, ½ (2 I_O) θ̇² = 2 m g 0.5 sin θ_s,
// into the stop, which (plastic) holds both: its force the moments of both weights,
// −2 m g 0.5 cos θ_s — the coupler carries the second rod's to it.
TEST(JointStops, ALimitHoldsTheJointsCoupledToIt) {
  const double I_O = 0.08333333333333333 + 0.25, stop = 1.0;
  const std::string urdf = R"(<robot name="rods">
  <link name="world"/>
  <link name="a"><inertial><origin xyz="0.5 0 0"/><mass value="1"/>
    <inertia ixx="1e-6" iyy="0.08333333333333333" izz="0.08333333333333333"/></inertial></link>
  <link name="b"><inertial><origin xyz="0.5 0 0"/><mass value="1"/>
    <inertia ixx="1e-6" iyy="0.08333333333333333" izz="0.08333333333333333"/></inertial></link>
  <joint name="pin" type="revolute"><parent link="world"/><child link="a"/><axis xyz="0 1 0"/>
    <limit lower="-3" upper="1" effort="0" velocity="0"/></joint>
  <joint name="follower" type="continuous"><parent link="world"/><child link="b"/>
    <origin xyz="0 1 0"/><axis xyz="0 1 0"/><mimic joint="pin"/></joint>
</robot>)";
  const std::string mjcf = R"(<mujoco><compiler angle="radian"/><worldbody>
  <body name="a"><joint name="pin" axis="0 1 0" range="-3 1"/>
    <inertial pos="0.5 0 0" mass="1" diaginertia="1e-6 0.08333333333333333 0.08333333333333333"/>
  </body>
  <body name="b" pos="0 1 0"><joint name="follower" axis="0 1 0"/>
    <inertial pos="0.5 0 0" mass="1" diaginertia="1e-6 0.08333333333333333 0.08333333333333333"/>
  </body></worldbody>
  <equality><joint joint1="follower" joint2="pin" polycoef="0 1 0 0 0"/></equality></mujoco>)";
  for (const io::ModelFile& file :
       {io::parse_urdf(urdf, "rods.urdf"), io::parse_mjcf(mjcf, "rods.xml")}) {
    SCOPED_TRACE(file.file);
    ASSERT_TRUE(file.model.has_constraints());
    const UnilateralRun run = run_unilaterals(file.model, "dopri5", 1e-2, 2.0, /*reactions=*/true);
    const std::vector<StopEvent>& events = run.summary.stop_events;
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].kind, StopEventKind::rest);
    EXPECT_TRUE(events[0].upper);
    EXPECT_NEAR(events[0].rate_before, std::sqrt(2.0 * kG * 0.5 * std::sin(stop) / I_O), 1e-9);
    EXPECT_EQ(events[0].rate_after, 0.0);
    EXPECT_NEAR(events[0].energy_lost, 2.0 * kG * 0.5 * std::sin(stop), 1e-8);
    const int angle = run.table.column("pin.angle");
    const int follower = run.table.column("follower.angle");
    const int force = run.table.column("pin.stop_force");
    for (const std::vector<double>& row : run.table.rows) {
      EXPECT_LE(row[angle], stop) << row[0];
      if (row[0] <= events[0].time) continue;
      EXPECT_EQ(row[angle], stop) << row[0];
      EXPECT_NEAR(row[follower], stop, 1e-14) << row[0];
      EXPECT_NEAR(row[force], -2.0 * kG * 0.5 * std::cos(stop), 1e-12) << row[0];
    }
  }
}

// Joints resting on their stops with nothing pushing them either way but round-off: the MJCF
// humanoid falling freely, its elbows on their upper stops and its knees on their lower ones (a
// run that struck them over and over at t = 0 until the gap's round-off was given slack). The run
// ends; no coordinate passes its stop by more than that slack; no stop strikes with more than a
// round-off's impulse.
TEST(JointStops, JointsRestingOnStopsWithNothingPushingAreLeftAlone) {
  const model::Model model =
      io::read_mjcf_file(test::source_dir() + "/tests/data/models/mjcf/humanoid.xml").model;
  const UnilateralRun run = run_unilaterals(model, "rk4", 1e-3, 0.2);
  EXPECT_LE(run.summary.stop_events.size(), 6u);
  for (const StopEvent& e : run.summary.stop_events) EXPECT_LT(std::abs(e.impulse), 1e-12);
  for (const model::Joint& j : model.joints()) {
    if (!j.limits) continue;
    const int q = run.table.column(model.q_name(j.q_index));
    for (const std::vector<double>& row : run.table.rows) {
      EXPECT_GE(row[q], j.limits->lower - 1e-15) << j.name << " at " << row[0];
      EXPECT_LE(row[q], j.limits->upper + 1e-15) << j.name << " at " << row[0];
    }
  }
  EXPECT_EQ(run.table.rows.back()[0], 0.2);
}

TEST(JointStops, ModelFileRefusesStopsWhereThereAreNone) {
  const auto message = load_error;
  const std::string head =
      "bodies: [{name: b, shape: sphere, mass: 1, radius: 0.1}]\njoints:\n  - {name: j, parent: "
      "world, child: b, ";
  EXPECT_NE(message(head + "type: spherical, limits: {lower: 0}}\n").find("revolute or prismatic"),
            std::string::npos);
  EXPECT_NE(
      message(head + "type: prismatic, limits: {lower: 0, restitution: 1.5}}\n").find("above 1"),
      std::string::npos);
  EXPECT_NE(message(head + "type: prismatic, q0: -1, limits: {lower: 0}}\n").find("outside"),
            std::string::npos);
  EXPECT_NE(message(head + "type: prismatic, limits: {lower: 1, upper: 0}}\n").find("not below"),
            std::string::npos);
  EXPECT_NE(message(head + "type: prismatic, limits: {restitution: 0.5}}\n").find("give 'lower'"),
            std::string::npos);
  EXPECT_NE(message(head + "type: prismatic, limits: {lower_deg: 0}}\n").find("lower_deg"),
            std::string::npos);
  EXPECT_NE(message(head + "type: revolute, limits: {lower_deg: 10, upper: 1}}\n").find("outside"),
            std::string::npos);
}

}  // namespace
}  // namespace momenta::simulate
