// Coulomb friction at contacts with the ground (model::Contact with μs, μk; simulate/
// unilaterals.hpp) against the textbook's closed forms:
// - a ball set down skidding with v₀ and no spin (examples/skidding_ball.yaml): it rolls from
//   t = 2 v₀ / (7 μk g) at 5 v₀ / 7, friction −μk m g until then and none after, the energy
//   friction took m v₀² / 7;
// - a crate thrown up a rough ramp (examples/block_on_incline.yaml): it decelerates at
//   g (sin θ + μk cos θ), stops at v₀ / that, and with tan θ < μs sticks there, held by m g sin θ;
//   with tan θ > μs it slides back at g (sin θ − μk cos θ);
// - a block on a level floor pushed by a force growing from zero (μs = μk): it sticks until the
//   push reaches μ m g and then slides with s = c (t − t₀)³ / (6 m) along the push;
// - a crate set down at rest on a ramp with tan θ < μs moves less than 1e-12 m in 100 s (no
//   creep), and with tan θ > μs slides at g (sin θ − μk cos θ) from the start;
// - a block on a moving belt held by a spring (examples/belt_stick_slip.yaml: a contact with
//   another body's plane): the stick–slip cycle's instants, positions and friction from the
//   piecewise closed form;
// - a ball dropped sliding onto a rough floor: it leaves the first impact rolling (Coulomb's law
//   at impact, sticking), and rests rolling;
// - a rod dropped tilted on a rough floor (examples/falling_rod.yaml): it strikes by one end,
//   which sticks or slides from rest as Routh's process says;
// - a ball rolling off a fixed dome (friction between two spheres): rolling until its cone
//   gives out where (2/7) sin θ = μs (17 cos θ − 10 cos θ₀) / 7;
// - the model file's errors for friction.

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/io/model_file.hpp"
#include "momenta/simulate/simulation.hpp"
#include "momenta/system/multibody_system.hpp"
#include "unilateral_runs.hpp"

namespace momenta::simulate {
namespace friction {
namespace {

using namespace unilateral_test;

constexpr double kTheta = std::numbers::pi / 6.0;  // the ramp: 30°

TEST(Friction, SkiddingBallRollsFromTheClosedFormsInstant) {
  const double m = 7.0, r = 0.11, v0 = 6.0, mu_k = 0.1;
  const double t_roll = 2.0 * v0 / (7.0 * mu_k * kG), v_roll = 5.0 * v0 / 7.0;
  const model::Model model = io::read_model_file("examples/skidding_ball.yaml").model;
  for (const std::string integrator : {"rk4", "dopri5"}) {
    SCOPED_TRACE(integrator);
    const UnilateralRun run = run_unilaterals(model, integrator, 1e-3, 3.0, /*reactions=*/true);
    const std::vector<StopEvent>& events = run.summary.stop_events;
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].kind, StopEventKind::rest);
    EXPECT_EQ(events[0].friction, FrictionState::sliding);
    EXPECT_EQ(events[0].time, 0.0);
    EXPECT_EQ(events[1].kind, StopEventKind::stick);
    EXPECT_EQ(events[1].friction, FrictionState::sticking);
    EXPECT_EQ(events[1].contact, "lane");
    // The slip is linear in time and the integrators exact on it: the instant to the locator's
    // 1e-14 and the round-off the speeds gather over 1 750 steps (~1e-12 m/s at a slip
    // deceleration of 3.4 m/s²).
    EXPECT_NEAR(events[1].time, t_roll, 1e-12 * t_roll);
    EXPECT_LT(events[1].rate_before, 1e-13);
    EXPECT_NEAR(events[1].friction_limit, 0.12 * m * kG, 1e-12);
    EXPECT_LT(events[1].friction_needed, 1e-12);  // rolling on the level: no friction at all

    const int vx = run.table.column("free.vx"), wy = run.table.column("free.wy");
    const int normal = run.table.column("lane.normal");
    const int f1 = run.table.column("lane.tangent_1"), f2 = run.table.column("lane.tangent_2");
    const int kinetic = run.table.column("energy_kinetic");
    const double kinetic_0 = 0.5 * m * v0 * v0;
    // Speeds to the round-off of a thousand steps' sums (1e-12 of v₀); forces to 1e-12 of the
    // weight (the sliding normal force comes from three solves, see MultibodySystem).
    for (const std::vector<double>& row : run.table.rows) {
      const double t = row[0];
      EXPECT_NEAR(row[normal], m * kG, 1e-12 * m * kG) << t;
      EXPECT_EQ(row[f2], 0.0) << t;
      if (t < events[1].time) {
        EXPECT_NEAR(row[vx], v0 - mu_k * kG * t, 1e-12 * v0) << t;
        EXPECT_NEAR(row[wy], 5.0 * mu_k * kG * t / (2.0 * r), 1e-12 * v0 / r) << t;
        EXPECT_NEAR(row[f1], -mu_k * m * kG, 1e-12 * m * kG) << t;
      } else if (t > events[1].time) {
        EXPECT_NEAR(row[vx], v_roll, 1e-12 * v0) << t;
        EXPECT_NEAR(row[wy], v_roll / r, 1e-12 * v0 / r) << t;
        EXPECT_NEAR(row[f1], 0.0, 1e-12 * m * kG) << t;
        EXPECT_NEAR(kinetic_0 - row[kinetic], m * v0 * v0 / 7.0, 1e-10) << t;
      }
    }
  }
}

// The 2 kg crate of examples/block_on_incline.yaml on its 30° ramp (it translates: a joint up the
// ramp, one along its normal), with μs, μk and its speed up the ramp v0.
std::string crate(double mu_s, double mu_k, double v0) {
  return fmt::format(
      "gravity: [0, 0, -9.81]\n"
      "bodies: [{{name: carriage, mass: 0}}, {{name: crate, shape: box, mass: 2.0, size: [0.4, "
      "0.3, 0.2]}}]\n"
      "joints:\n"
      "  - {{name: up, type: prismatic, parent: world, child: carriage, axis: [1, 0, 0], v0: {},\n"
      "     in_parent: {{quaternion: [{:.17g}, 0, {:.17g}, 0]}}}}\n"
      "  - {{name: lift, type: prismatic, parent: carriage, child: crate, axis: [0, 0, 1], q0: "
      "0.1}}\n"
      "constraints: [{{name: ramp, type: contact, body: crate, point: [0, 0, -0.1], normal: "
      "[{:.17g}, 0, {:.17g}], friction: {{static: {}, kinetic: {}}}}}]\n",
      v0, std::cos(kTheta / 2), -std::sin(kTheta / 2), -std::sin(kTheta), std::cos(kTheta), mu_s,
      mu_k);
}

// The crate's distance up the ramp, or its speed up it, in a row.
double up_the_ramp(const UnilateralRun& run, const std::vector<double>& row, bool rate) {
  return row[run.table.column(rate ? "up.position_rate" : "up.position")];
}

TEST(Friction, CrateThrownUpTheRampStopsAndSticks) {
  const double m = 2.0, v0 = 3.0, mu_k = 0.5, mu_s = 0.7;
  const double a = kG * (std::sin(kTheta) + mu_k * std::cos(kTheta));
  const double t_stop = v0 / a, d = v0 * v0 / (2.0 * a);
  const model::Model model = io::read_model_file("examples/block_on_incline.yaml").model;
  const UnilateralRun run = run_unilaterals(model, "rk4", 1e-3, 2.0, /*reactions=*/true);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].friction, FrictionState::sliding);
  EXPECT_EQ(events[1].kind, StopEventKind::stick);
  EXPECT_NEAR(events[1].time, t_stop, 1e-14 * 8);
  EXPECT_NEAR(events[1].friction_needed, m * kG * std::sin(kTheta), 1e-12);
  EXPECT_NEAR(events[1].friction_limit, mu_s * m * kG * std::cos(kTheta), 1e-12);
  // The rows at the stick's instant itself (before and after it) are left out.
  const int normal = run.table.column("ramp.normal"), f1 = run.table.column("ramp.tangent_1");
  for (const std::vector<double>& row : run.table.rows) {
    const double t = row[0];
    EXPECT_NEAR(row[normal], m * kG * std::cos(kTheta), 1e-12) << t;
    if (t < events[1].time) {
      EXPECT_NEAR(up_the_ramp(run, row, true), v0 - a * t, 1e-12) << t;
      EXPECT_NEAR(up_the_ramp(run, row, false), v0 * t - 0.5 * a * t * t, 1e-12) << t;
      // t₁ is the world's x on the plane: up the ramp. Friction points down it.
      EXPECT_NEAR(row[f1], -mu_k * m * kG * std::cos(kTheta), 1e-12) << t;
    } else if (t > events[1].time) {
      EXPECT_NEAR(up_the_ramp(run, row, false), d, 1e-12) << t;
      EXPECT_NEAR(up_the_ramp(run, row, true), 0.0, 1e-14) << t;  // the projection's round-off
      EXPECT_NEAR(row[f1], m * kG * std::sin(kTheta), 1e-12) << t;
    }
  }
}

TEST(Friction, CrateThrownUpASteepRampSlidesBack) {
  // tan 30° = 0.577 > μs = 0.55: stopped, it cannot stick.
  const double v0 = 3.0, mu_k = 0.5;
  const double up = kG * (std::sin(kTheta) + mu_k * std::cos(kTheta));
  const double down = kG * (std::sin(kTheta) - mu_k * std::cos(kTheta));
  const double t_stop = v0 / up, d = v0 * v0 / (2.0 * up);
  const UnilateralRun run = run_unilaterals(load(crate(0.55, mu_k, v0)), "dopri5", 1e-2, 2.0);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[1].kind, StopEventKind::slip);
  EXPECT_EQ(events[1].friction, FrictionState::sliding);
  EXPECT_NEAR(events[1].time, t_stop, 1e-14 * 8);
  EXPECT_NEAR(events[1].friction_needed, 2.0 * kG * std::sin(kTheta), 1e-12);
  for (const std::vector<double>& row : run.table.rows) {
    const double t = row[0];
    if (t <= events[1].time) continue;
    const double after = t - t_stop;
    EXPECT_NEAR(up_the_ramp(run, row, true), -down * after, 1e-12) << t;
    EXPECT_NEAR(up_the_ramp(run, row, false), d - 0.5 * down * after * after, 1e-12) << t;
  }
}

TEST(Friction, CrateAtRestOnTheRampNeverCreeps) {
  // tan 30° < μs = 0.7: held from the start for 100 s, it moves by round-off alone.
  const double m = 2.0;
  const UnilateralRun run =
      run_unilaterals(load(crate(0.7, 0.5, 0.0)), "dopri5", 1e-1, 100.0, /*reactions=*/true);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, StopEventKind::rest);
  EXPECT_EQ(events[0].friction, FrictionState::sticking);
  const std::vector<double>& last = run.table.rows.back();
  EXPECT_EQ(last[0], 100.0);
  EXPECT_LT(std::abs(up_the_ramp(run, last, false)), 1e-12);
  // On the ramp to the projection's 1e-14 (the plane's normal and the joints' frame are rounded).
  EXPECT_NEAR(last[run.table.column("lift.position")], 0.1, 1e-14);
  EXPECT_NEAR(last[run.table.column("ramp.tangent_1")], m * kG * std::sin(kTheta), 1e-12);
  EXPECT_NEAR(last[run.table.column("ramp.normal")], m * kG * std::cos(kTheta), 1e-12);
}

TEST(Friction, CrateAtRestOnASteepRampSlidesFromTheStart) {
  const double mu_k = 0.4, a = kG * (std::sin(kTheta) - mu_k * std::cos(kTheta));
  const UnilateralRun run = run_unilaterals(load(crate(0.5, mu_k, 0.0)), "rk4", 1e-3, 2.0);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].friction, FrictionState::sliding);
  for (const std::vector<double>& row : run.table.rows) {
    const double t = row[0];
    EXPECT_NEAR(up_the_ramp(run, row, true), -a * t, 1e-12) << t;
    EXPECT_NEAR(up_the_ramp(run, row, false), -0.5 * a * t * t, 1e-12) << t;
  }
}

// A 2 kg block on a level floor, free to slide in x and y (two prismatic joints, a third lifts
// it), pushed along (0.6, 0.8) by a force growing from zero, F = c t, with μs = μk = μ = 0.5 (as
// MuJoCo's one friction gives). It sticks until c t₀ = μ m g, t₀ = 0.981 s, and then slides along
// the push with m s̈ = c (t − t₀): s = c (t − t₀)³ / (6 m). Its slip starts from its cone's edge
// with no acceleration at all (μk = μs) — the case where the arm of mjcf_contacts_test once took
// the slip's round-off as its stop (here the steps after the slip are long enough that it never
// did: this is the closed form, the arm the regression).
TEST(Friction, BlockPushedByAGrowingForceSlipsAtMuMgAndRunsOnTheCubic) {
  const double m = 2.0, mu = 0.5, c = 10.0, ux = 0.6, uy = 0.8;
  const model::Model block = load(fmt::format(
      "gravity: [0, 0, -9.81]\n"
      "bodies: [{{name: x_carriage, mass: 0}}, {{name: y_carriage, mass: 0}},\n"
      "         {{name: block, shape: box, mass: {}, size: [0.4, 0.3, 0.2]}}]\n"
      "joints:\n"
      "  - {{name: x, type: prismatic, parent: world, child: x_carriage, axis: [1, 0, 0]}}\n"
      "  - {{name: y, type: prismatic, parent: x_carriage, child: y_carriage, axis: [0, 1, 0]}}\n"
      "  - {{name: lift, type: prismatic, parent: y_carriage, child: block, axis: [0, 0, 1], "
      "q0: 0.1}}\n"
      "inputs: [{{name: push, type: ramp, slope: {}}}]\n"
      "forces: [{{name: push, type: force, body: block, point: [0, 0, 0], vector: [{}, {}, 0], "
      "signal: push}}]\n"
      "constraints: [{{name: floor, type: contact, body: block, point: [0, 0, -0.1], normal: "
      "[0, 0, 1], friction: {{static: {}, kinetic: {}}}}}]\n",
      m, c, ux, uy, mu, mu));
  const UnilateralRun run = run_unilaterals(block, "dopri5", 1e-3, 2.0);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  const double t0 = mu * m * kG / c;
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].friction, FrictionState::sticking);
  EXPECT_EQ(events[1].kind, StopEventKind::slip);
  // The margin μ m g − c t is linear in t: the locator's 1e-12 relative.
  EXPECT_NEAR(events[1].time, t0, 1e-12 * t0);
  const int x = run.table.column("x.position"), y = run.table.column("y.position");
  for (const std::vector<double>& row : run.table.rows) {
    const double t = row[0];
    // dopri5 is exact on a cubic; the slip's start to 1e-12 s moves s by far less.
    const double s = t > t0 ? c * std::pow(t - t0, 3) / (6.0 * m) : 0.0;
    EXPECT_NEAR(row[std::size_t(x)], ux * s, 1e-12) << t;
    EXPECT_NEAR(row[std::size_t(y)], uy * s, 1e-12) << t;
  }
  EXPECT_EQ(run.table.rows.back()[0], 2.0);
}

// The block on the belt of examples/belt_stick_slip.yaml (m = 1 kg, k = 100 N/m, V = 0.1 m/s,
// μs = 0.6, μk = 0.4), started where a slip ends, riding the belt: it sticks for 2 d / V, slips
// for (π + 2 atan2(V/ω, d)) / ω, and again, d = (μs − μk) m g / k, ω = √(k/m). While it sticks
// x = x_k − d + V τ and the belt holds it with the spring's k x; while it slips x = x_k +
// A cos(θ₀ + ω τ), A = √(d² + (V/ω)²), θ₀ = −atan2(V/ω, d), friction μk m g along the belt.
TEST(Friction, BlockOnABeltSticksAndSlipsOnTheClosedFormCycle) {
  const double m = 1.0, k = 100.0, V = 0.1, mu_s = 0.6, mu_k = 0.4;
  const double w = std::sqrt(k / m), x_s = mu_s * m * kG / k, x_k = mu_k * m * kG / k;
  const double d = x_s - x_k, A = std::hypot(d, V / w), theta0 = -std::atan2(V / w, d);
  const double stick = 2.0 * d / V, slip = (std::numbers::pi - 2.0 * theta0) / w;
  const double period = stick + slip;
  const model::Model model = io::read_model_file("examples/belt_stick_slip.yaml").model;
  const UnilateralRun run = run_unilaterals(model, "rk4", 1e-3, 4.0, /*reactions=*/true);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_EQ(events.size(), 1u + 2u * 4u + 1u);  // rest, then four cycles and a fifth slip
  EXPECT_EQ(events[0].friction, FrictionState::sticking);
  for (std::size_t i = 1; i < events.size(); ++i) {
    const int cycle = static_cast<int>((i - 1) / 2);
    const bool slips = i % 2 == 1;
    const StopEvent& e = events[i];
    SCOPED_TRACE(fmt::format("event {}", i));
    EXPECT_EQ(e.contact, "belt_contact");
    EXPECT_EQ(e.kind, slips ? StopEventKind::slip : StopEventKind::stick);
    // rk4's error over each slip's swing (h = 1 ms at ω = 10 rad/s) shifts each cycle by ~3e-11 s
    // (measured): the instants to 5e-11 s a cycle.
    EXPECT_NEAR(e.time, cycle * period + (slips ? stick : period), 5e-11 * (cycle + 1));
    if (slips) {  // where the spring's pull reaches the cone
      EXPECT_NEAR(e.friction_needed, mu_s * m * kG, 1e-9);
      EXPECT_NEAR(e.friction_limit, mu_s * m * kG, 1e-12);
    }
  }
  const int x = run.table.column("slide.position");
  const int friction = run.table.column("belt_contact.tangent_1");
  const int normal = run.table.column("belt_contact.normal");
  for (const std::vector<double>& row : run.table.rows) {
    const double t = row[0];
    const double tau = std::fmod(t, period);
    if (std::abs(tau - stick) < 1e-9 || std::min(tau, period - tau) < 1e-9) continue;  // events
    EXPECT_NEAR(row[normal], m * kG, 1e-12) << t;
    if (tau < stick) {
      EXPECT_NEAR(row[x], x_k - d + V * tau, 1e-10) << t;
      EXPECT_NEAR(row[friction], k * row[x], 1e-9) << t;
    } else {
      EXPECT_NEAR(row[x], x_k + A * std::cos(theta0 + w * (tau - stick)), 1e-10) << t;
      EXPECT_NEAR(row[friction], mu_k * m * kG, 1e-12) << t;
    }
  }
}

// A ball (m = 0.1 kg, r = 0.05 m) dropped from 1 m moving sideways at 1 m/s without spin on a
// rough floor (e = 0.8, μ = 0.3): at the first impact its contact point slips at u = 1 m/s and
// sticking needs P_t = 2 m u / 7 = 0.0286 N·s, within μ P_n = 0.3 · 1.8 m √(2gh) = 0.239 N·s: it
// leaves rolling, v_x = 5/7 m/s and ω_y = 5 / (7 r) rad/s, having lost ½ m (1 − e²) v_n² and
// m u² / 7 more; every later impact has no slip to stop, and it comes to rest rolling at 5/7 m/s.
TEST(Friction, BallDroppedSlidingOntoARoughFloorLeavesRolling) {
  const double m = 0.1, r = 0.05, e = 0.8, h = 1.0;
  const double t1 = std::sqrt(2.0 * h / kG), V = std::sqrt(2.0 * kG * h);
  const std::string model =
      "gravity: [0, 0, -9.81]\n"
      "bodies: [{name: ball, shape: sphere, mass: 0.1, radius: 0.05}]\n"
      "joints: [{name: free, type: free, parent: world, child: ball, q0: [0, 0, 1.05, 1, 0, 0, "
      "0], v0: [0, 0, 0, 1, 0, 0]}]\n"
      "constraints: [{name: floor, type: contact, body: ball, radius: 0.05, restitution: 0.8, "
      "friction: 0.3}]\n";
  const UnilateralRun run = run_unilaterals(load(model), "dopri5", 1e-2, 5.0);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_GT(events.size(), 20u);
  const StopEvent& first = events[0];
  EXPECT_EQ(first.kind, StopEventKind::impact);
  EXPECT_NEAR(first.time, t1, 1e-12 * t1);
  EXPECT_NEAR(first.impulse, (1 + e) * m * V, 1e-12);
  EXPECT_NEAR(first.energy_lost, 0.5 * m * (1 - e * e) * V * V + m / 7.0, 1e-12);
  EXPECT_EQ(events.back().kind, StopEventKind::rest);
  EXPECT_EQ(events.back().friction, FrictionState::sticking);
  const int vx = run.table.column("free.vx"), wy = run.table.column("free.wy");
  for (const std::vector<double>& row : run.table.rows) {
    if (row[0] < first.time) {
      EXPECT_EQ(row[vx], 1.0) << row[0];
    } else if (row[0] > first.time) {
      EXPECT_NEAR(row[vx], 5.0 / 7.0, 1e-12) << row[0];
      EXPECT_NEAR(row[wy], 5.0 / (7.0 * r), 1e-11) << row[0];
    }
  }
}

// A slender rod (m = 1 kg, L = 1 m) tilted θ = 30° from the vertical, dropped from its lower end
// h = 0.2 m above a rough floor (examples/falling_rod.yaml, e = 0.5): it strikes by that end at
// t₁ = √(2h/g) at V = √(2gh), and the normal impulse alone would make the end slip. With W at the
// end (a = 1 + 3 cos² θ, b = −3 sin θ cos θ, c = 1 + 3 sin² θ, over m, in (x, z)) the friction
// that keeps it stuck is f* = −b/a per unit normal impulse: within μs = 0.5 it sticks, the normal
// speed grows at 4 / (m a), and P_n = (1 + e) m V a / 4, P_t = f* P_n; with μs = μk = 0.2 < |f*| it
// slides from rest the other way, P_t = μk P_n and P_n = (1 + e) m V / (c − 3 μk sin θ cos θ).
// After the impact the rod flies: v_x, ω_y constant and v_z = v_z⁺ − g (t − t₁) until its next;
// it bounces on both ends, the energy never rising, to rest.
TEST(Friction, RodDroppedOnARoughFloorStrikesByItsEndAsRouthSays) {
  const double m = 1.0, L = 1.0, h = 0.2, e = 0.5, theta = std::numbers::pi / 6;
  const double s = std::sin(theta), c = std::cos(theta), I = m * L * L / 12;
  const double t1 = std::sqrt(2 * h / kG), V = std::sqrt(2 * kG * h);
  const Vec3 r(-L / 2 * s, 0, -L / 2 * c);  // centre to the lower end
  std::ifstream file("examples/falling_rod.yaml");
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  ASSERT_NE(text.find("friction: {static: 0.5, kinetic: 0.4}"), std::string::npos);
  std::string sliding_text = text;  // both ends' friction μs = μk = 0.2
  const std::string rough = "friction: {static: 0.5, kinetic: 0.4}";
  for (auto at = sliding_text.find(rough); at != std::string::npos; at = sliding_text.find(rough))
    sliding_text.replace(at, rough.size(), "friction: 0.2");
  struct Case {
    std::string text;
    double P_n, P_t;
    FrictionState friction;
  };
  const double mu = 0.2;
  const double sticking_P_n = (1 + e) * m * V * (1 + 3 * c * c) / 4;
  const double sliding_P_n = (1 + e) * m * V / (1 + 3 * s * s - 3 * mu * s * c);
  for (const Case& k :
       {Case{text, sticking_P_n, 3 * s * c / (1 + 3 * c * c) * sticking_P_n,
             FrictionState::sticking},
        Case{sliding_text, sliding_P_n, mu * sliding_P_n, FrictionState::sliding}}) {
    SCOPED_TRACE(k.text == text ? "sticking" : "sliding");
    const model::Model model = load(k.text);
    const UnilateralRun run = run_unilaterals(model, "dopri5", 1e-3, 2.0);
    const std::vector<StopEvent>& events = run.summary.stop_events;
    ASSERT_GE(events.size(), 1u);
    const StopEvent& first = events[0];
    EXPECT_EQ(first.kind, StopEventKind::impact);
    EXPECT_NEAR(first.time, t1, 1e-12 * t1);
    EXPECT_NEAR(first.impulse, k.P_n, 1e-12 * m * V);
    const double next = events.size() > 1 ? events[1].time : 2.0;
    const Vec3 P(k.P_t, 0, k.P_n);
    const double omega = r.cross(P).y() / I, vx = P.x() / m, vz = -V + P.z() / m;
    // The end leaves the floor at e V where it sticks (u_n linear in p: Newton's e).
    if (k.friction == FrictionState::sticking) {
      EXPECT_NEAR(vz - omega * r.x(), e * V, 1e-12 * V);
    }
    const int wy = run.table.column("free.wy"), vx_col = run.table.column("free.vx"),
              vz_col = run.table.column("free.vz");
    int rows = 0;
    for (const std::vector<double>& row : run.table.rows) {
      if (!(row[0] > first.time && row[0] < next)) continue;
      ++rows;
      EXPECT_NEAR(row[wy], omega, 1e-12 * V / L) << row[0];
      EXPECT_NEAR(row[vx_col], vx, 1e-12 * V) << row[0];
      EXPECT_NEAR(row[vz_col], vz - kG * (row[0] - t1), 1e-11 * V) << row[0];
    }
    EXPECT_GT(rows, 10);
    // Through every later impact on either end, coupled like the first: the energy never rises
    // (dopri5 at 1e-12 holds it between them to 1e-10 of the initial).
    system::MultibodySystem system(model);
    double energy = INFINITY;
    const double initial = system.energy(model.initial_q(), model.initial_v()).total();
    for (const std::vector<double>& row : run.table.rows) {
      const VecX q = Eigen::Map<const VecX>(row.data() + 1, model.nq());
      const VecX v = Eigen::Map<const VecX>(row.data() + 1 + model.nq(), model.nv());
      const double now = system.energy(q, v).total();
      EXPECT_LE(now, energy + 1e-10 * std::abs(initial)) << row[0];
      energy = std::min(energy, now);
    }
    EXPECT_GT(events.size(), 20u);
    EXPECT_EQ(events.back().kind, StopEventKind::rest);
  }
}

// A ball (m = 1 kg, r = 0.1 m, I = 2 m r² / 5) let go from rest at θ₀ = 0.2 rad on top of a fixed
// dome (R = 1 m), with friction between the two spheres (μs = 0.5, μk = 0.4). While it rolls,
// energy and the rolling condition give, with ρ = R + r the centre's path radius,
//   ρ² θ̇² = (10/7) g ρ (cos θ₀ − cos θ),   N = m g (17 cos θ − 10 cos θ₀) / 7,   F = (2/7) m g sin
//   θ,
// so the friction it needs grows as the normal force falls: it slips where F = μs N,
// 2 sin θ = μs (17 cos θ − 10 cos θ₀) — before it would leave the dome (17 cos θ = 10 cos θ₀).
TEST(Friction, BallRollingOffADomeSlipsWhereItsConeSays) {
  const double m = 1.0, r = 0.1, R = 1.0, rho = R + r, theta0 = 0.2, mu_s = 0.5;
  const auto cone_margin = [&](double th) {
    return mu_s * (17 * std::cos(th) - 10 * std::cos(theta0)) - 2 * std::sin(th);
  };
  double lo = theta0, hi = std::acos(10 * std::cos(theta0) / 17);  // margin > 0 at lo, < 0 at hi
  for (int k = 0; k < 200; ++k) (cone_margin(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
  const double theta_slip = 0.5 * (lo + hi);
  const model::Model model = load(fmt::format(
      "gravity: [0, 0, -9.81]\n"
      "bodies: [{{name: dome, shape: sphere, mass: 10.0, radius: 1.0}},\n"
      "         {{name: ball, shape: sphere, mass: 1.0, radius: 0.1}}]\n"
      "joints:\n"
      "  - {{name: base, type: fixed, parent: world, child: dome}}\n"
      "  - {{name: free, type: free, parent: world, child: ball, q0: [{:.17g}, 0, {:.17g}, 1, 0, "
      "0, "
      "0]}}\n"
      "constraints:\n"
      "  - {{name: touch, type: contact, body: ball, radius: 0.1, other_body: dome, other_radius: "
      "1.0, friction: {{static: 0.5, kinetic: 0.4}}}}\n",
      rho * std::sin(theta0), rho * std::cos(theta0)));
  const UnilateralRun run = run_unilaterals(model, "dopri5", 1e-3, 1.5, /*reactions=*/true);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_GE(events.size(), 2u);
  EXPECT_EQ(events[0].kind, StopEventKind::rest);
  EXPECT_EQ(events[0].friction, FrictionState::sticking);
  EXPECT_EQ(events[1].kind, StopEventKind::slip);
  // At the slip the friction it needs is the cone's limit, both the closed forms' at θ_slip: the
  // angle located to the dense output's accuracy (dopri5 at rtol 1e-12).
  const double needed = 2.0 / 7.0 * m * kG * std::sin(theta_slip);
  EXPECT_NEAR(events[1].friction_needed, needed, 1e-9 * needed);
  EXPECT_NEAR(events[1].friction_limit, needed, 1e-9 * needed);
  const int x = run.table.column("free.x"), z = run.table.column("free.z");
  const int vx = run.table.column("free.vx"), vz = run.table.column("free.vz");
  const int normal = run.table.column("touch.normal");
  const int f1 = run.table.column("touch.tangent_1"), f2 = run.table.column("touch.tangent_2");
  int rolling_rows = 0;
  for (const std::vector<double>& row : run.table.rows) {
    if (!(row[0] < events[1].time)) break;
    ++rolling_rows;
    const double th = std::atan2(row[x], row[z]);
    const double scale = m * kG;
    EXPECT_NEAR(std::hypot(row[x], row[z]), rho, 1e-12) << row[0];  // on the dome
    EXPECT_NEAR(row[vx] * row[vx] + row[vz] * row[vz],
                10.0 / 7.0 * kG * rho * (std::cos(theta0) - std::cos(th)), 1e-10)
        << row[0];
    EXPECT_NEAR(row[normal], m * kG * (17 * std::cos(th) - 10 * std::cos(theta0)) / 7,
                1e-10 * scale)
        << row[0];
    EXPECT_NEAR(std::hypot(row[f1], row[f2]), 2.0 / 7.0 * m * kG * std::sin(th), 1e-10 * scale)
        << row[0];
  }
  EXPECT_GT(rolling_rows, 100);
}

TEST(Friction, ModelFileErrorsNameTheKey) {
  const std::string ball =
      "bodies: [{name: ball, shape: sphere, mass: 1, radius: 0.1}, {name: other, shape: sphere, "
      "mass: 1, radius: 0.1}]\n"
      "joints: [{name: f, type: free, parent: world, child: ball, q0: [0, 0, 1, 1, 0, 0, 0]}, "
      "{name: g, type: free, parent: world, child: other}]\n";
  const auto contact = [&](const std::string& keys) {
    return load_error(ball + "constraints: [{name: c, type: contact, body: ball, radius: 0.1, " +
                      keys + "}]\n");
  };
  EXPECT_NE(contact("friction: {static: 0.3, kinetic: 0.4}")
                .find("kinetic: 0.4 is above the static coefficient 0.3"),
            std::string::npos)
      << contact("friction: {static: 0.3, kinetic: 0.4}");
  EXPECT_NE(contact("friction: -0.1").find("friction"), std::string::npos);
  EXPECT_NE(contact("friction: {static: 0.3, kinetc: 0.2}").find("did you mean 'kinetic'"),
            std::string::npos)
      << contact("friction: {static: 0.3, kinetc: 0.2}");
  // Between two spheres too: the tangents across their line of centres.
  EXPECT_EQ(contact("other_body: other, other_radius: 0.1, friction: 0.3"), "no error");
  EXPECT_EQ(contact("friction: 0.3"), "no error");
}

}  // namespace
}  // namespace friction
}  // namespace momenta::simulate
