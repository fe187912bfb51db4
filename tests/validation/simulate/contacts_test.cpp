// Contacts with the ground in a run (model::Contact, simulate/unilaterals.hpp) against closed
// forms and a second algorithm:
// - a free sphere dropped from h on a frictionless floor with restitution e
//   (examples/bouncing_sphere.yaml): the bounce times t₁ (1 + 2e + … + 2e^{k−1}), t₁ = √(2h/g),
//   the speeds it arrives with e^k √(2gh), the measured e, rest at the Zeno limit
//   t₁ (1 + e)/(1 − e), then the ball still on the floor with its force m g; its sideways speed
//   and spin untouched;
// - elastic contact (e = 1): the energy audit holds across every impact;
// - a pendulum whose tip strikes a plane tangent to its path: the same impacts as a stop on its
//   joint at that angle (simulate's stops, a second algorithm), its rate there from energy;
// - a ball resting on the floor lifted by a force ramp c t: let go at t = m g / c, the floor's
//   force m g − c t until then;
// - Newton's cradle (examples/newtons_cradle.yaml): balls touching balls, the impacts at one
//   instant struck one after another: the swing's quarter period from the elliptic integral, the
//   momentum passed along whole, the middle ball still, the energy kept;
// - the model file's errors for a contact.

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/simulate/simulation.hpp"
#include "unilateral_runs.hpp"

namespace momenta::simulate {
namespace contacts {
namespace {

using namespace unilateral_test;

// The free ball of examples/bouncing_sphere.yaml (m = 0.1 kg, r = 0.05 m, h = 1 m), with
// restitution e.
std::string sphere(double e, const std::string& v0 = "[0, 0, 3, 1, 0, 0]") {
  return fmt::format(
      "gravity: [0, 0, -9.81]\n"
      "bodies: [{{name: ball, shape: sphere, mass: 0.1, radius: 0.05}}]\n"
      "joints: [{{name: free, type: free, parent: world, child: ball, q0: [0, 0, 1.05, 1, 0, 0, "
      "0], v0: {}}}]\n"
      "constraints: [{{name: floor, type: contact, body: ball, radius: 0.05, restitution: {}}}]\n",
      v0, e);
}

TEST(Contacts, BouncingSphereMatchesTheClosedForm) {
  const double h = 1.0, e = 0.8, m = 0.1;
  const double t1 = std::sqrt(2.0 * h / kG), v1 = std::sqrt(2.0 * kG * h);
  const model::Model model = io::read_model_file("examples/bouncing_sphere.yaml").model;
  for (const std::string integrator : {"rk4", "dopri5"}) {
    SCOPED_TRACE(integrator);
    const UnilateralRun run = run_unilaterals(model, integrator, 1e-3, 5.0, /*reactions=*/true);
    const std::vector<StopEvent>& events = run.summary.stop_events;
    ASSERT_GT(events.size(), 21u);
    double t_k = t1;
    for (int k = 0; k < 20; ++k) {
      const StopEvent& s = events[static_cast<std::size_t>(k)];
      ASSERT_EQ(s.kind, StopEventKind::impact) << k;
      EXPECT_EQ(s.contact, "floor");
      EXPECT_TRUE(s.joint.empty());
      EXPECT_NEAR(s.time, t_k, 1e-12 * t_k) << k;
      EXPECT_NEAR(s.rate_before, -std::pow(e, k) * v1, 1e-11 * v1) << k;
      EXPECT_NEAR(-s.rate_after / s.rate_before, e, 1e-12) << k;
      EXPECT_NEAR(s.impulse, m * (s.rate_after - s.rate_before), 1e-14) << k;
      EXPECT_NEAR(s.energy_lost, 0.5 * m * s.rate_before * s.rate_before * (1 - e * e), 1e-14);
      t_k += 2.0 * std::pow(e, k + 1) * t1;
    }
    // The Zeno limit. Near it the ball's centre sits at 0.05 m, where a coordinate's round-off
    // (0.05 · 2⁻⁵² ≈ 1e-17 m) at the last bounces' speeds (~1e-8 m/s) is ~1e-9 s of their times:
    // the limit is met to that, where a stop's coordinate near 0 meets it to 1e-10 s.
    const StopEvent& rest = events.back();
    ASSERT_EQ(rest.kind, StopEventKind::rest);
    EXPECT_NEAR(rest.rest_time, t1 * (1 + e) / (1 - e), 5e-9);
    const int z = run.table.column("free.z"), vz = run.table.column("free.vz");
    const int vx = run.table.column("free.vx"), wz = run.table.column("free.wz");
    const int normal = run.table.column("floor.normal");
    for (const std::vector<double>& row : run.table.rows) {
      EXPECT_GT(row[z], 0.05 - 1e-12) << row[0];   // never below the floor
      EXPECT_NEAR(row[vx], 1.0, 1e-13) << row[0];  // frictionless: sideways and spin untouched
      EXPECT_NEAR(row[wz], 3.0, 1e-11) << row[0];
      if (row[0] > rest.time) {
        EXPECT_NEAR(row[z], 0.05, 1e-15) << row[0];
        // Held by the floor's row: its speed along the normal projected away to round-off.
        EXPECT_NEAR(row[vz], 0.0, 1e-24) << row[0];
        EXPECT_NEAR(row[normal], m * kG, 1e-13) << row[0];
      } else if (row[0] < t1) {
        EXPECT_EQ(row[normal], 0.0) << row[0];
      }
    }
  }
}

TEST(Contacts, ElasticContactKeepsTheEnergy) {
  const UnilateralRun run = run_unilaterals(load(sphere(1.0)), "dopri5", 1e-2, 10.0);
  int impacts = 0;
  for (const StopEvent& s : run.summary.stop_events) {
    ASSERT_EQ(s.kind, StopEventKind::impact);
    EXPECT_NEAR(s.rate_after, -s.rate_before, 1e-12 * std::abs(s.rate_before));
    EXPECT_NEAR(s.energy_lost, 0.0, 1e-13);
    ++impacts;
  }
  EXPECT_EQ(impacts, 11);  // t₁ (1 + 2k) < 10 s: k ≤ 10
  ASSERT_FALSE(run.summary.audit.empty());
  EXPECT_EQ(run.summary.audit[0].name, "energy");
  EXPECT_LT(run.summary.audit[0].max_drift, 1e-10);
}

// A uniform rod (m = 1 kg, l = 1 m) on a pin about y; its tip (0, 0, −1) in the rod's frame is at
// (−sin θ, 0, −cos θ). The plane through the tip's place at θ_s with its normal along the tip's
// path there, (−cos θ_s, 0, sin θ_s), has the gap sin(θ − θ_s) m: it stops the rod at θ_s as a
// lower stop on the pin does.
TEST(Contacts, PendulumTipStrikesAPlaneAsAStopWould) {
  const double theta_s = -0.2, theta_0 = 1.0, e = 0.5;
  const std::string plane = fmt::format(
      "constraints: [{{name: wall, type: contact, body: rod, point: [0, 0, -1], normal: [{:.17g}, "
      "0, {:.17g}], plane_point: [{:.17g}, 0, {:.17g}], restitution: {}}}]\n",
      -std::cos(theta_s), std::sin(theta_s), -std::sin(theta_s), -std::cos(theta_s), e);
  const UnilateralRun contact =
      run_unilaterals(load(hanging_rod("q0: 1.0", plane)), "dopri5", 1e-2, 8.0);
  const UnilateralRun stop = run_unilaterals(
      load(hanging_rod(fmt::format("q0: 1.0, limits: {{lower: {}, restitution: {}}}", theta_s, e))),
      "dopri5", 1e-2, 8.0);
  const std::vector<StopEvent>& a = contact.summary.stop_events;
  const std::vector<StopEvent>& b = stop.summary.stop_events;
  ASSERT_GE(a.size(), 6u);
  ASSERT_GE(b.size(), 6u);
  // The rate it arrives with, from energy: ½ I_O θ̇² = m g (l/2) (cos θ_s − cos θ₀), I_O = m l²/3.
  EXPECT_NEAR(b[0].rate_before, -std::sqrt(3.0 * kG * (std::cos(theta_s) - std::cos(theta_0))),
              1e-9);
  for (std::size_t k = 0; k < 6; ++k) {
    SCOPED_TRACE(k);
    ASSERT_EQ(a[k].kind, StopEventKind::impact);
    ASSERT_EQ(b[k].kind, StopEventKind::impact);
    EXPECT_NEAR(a[k].time, b[k].time, 1e-12 * b[k].time);
    // The tip's normal speed is l θ̇ (l = 1 m); the impulses are the tip's (N·s) and the pin's
    // generalized one (N·m·s), l times it.
    EXPECT_NEAR(a[k].rate_before, b[k].rate_before, 1e-10 * std::abs(b[k].rate_before));
    EXPECT_NEAR(a[k].rate_after, -e * a[k].rate_before, 1e-12 * std::abs(a[k].rate_before));
    EXPECT_NEAR(a[k].impulse, b[k].impulse, 1e-10 * b[k].impulse);
    EXPECT_NEAR(a[k].energy_lost, b[k].energy_lost, 1e-10 * b[k].energy_lost);
  }
  const int angle = contact.table.column("pin.angle");
  for (const std::vector<double>& row : contact.table.rows) {
    EXPECT_GT(row[angle], theta_s - 1e-12) << row[0];
  }
}

TEST(Contacts, RestingBallLetGoWhenAForceLiftsIt) {
  // On the floor at rest from t = 0; the force c t upwards (c = 1 N/s) equals its weight m g at
  // t = m g / c = 0.981 s.
  const std::string text =
      sphere(0.5, "[0, 0, 0, 0, 0, 0]") +
      "inputs: [{name: lift, type: ramp, slope: 1.0}]\n"
      "forces: [{name: hand, type: force, body: ball, vector: [0, 0, 1], signal: lift}]\n";
  std::string resting = text;
  resting.replace(resting.find("1.05"), 4, "0.05");
  const model::Model model = load(resting);
  for (const std::string integrator : {"rk4", "dopri5", "bdf"}) {
    SCOPED_TRACE(integrator);
    const UnilateralRun run = run_unilaterals(model, integrator, 1e-2, 2.0, /*reactions=*/true);
    const std::vector<StopEvent>& events = run.summary.stop_events;
    expect_held_then_let_go(events, 0.1 * kG);
    if (HasFatalFailure()) return;
    const int z = run.table.column("free.z"), normal = run.table.column("floor.normal");
    for (const std::vector<double>& row : run.table.rows) {
      if (row[0] < events[1].time) {
        EXPECT_NEAR(row[z], 0.05, 1e-15) << row[0];
        EXPECT_NEAR(row[normal], 0.1 * kG - row[0], 1e-12) << row[0];
      } else if (row[0] > events[1].time) {
        EXPECT_GT(row[z], 0.05) << row[0];
        EXPECT_EQ(row[normal], 0.0) << row[0];
      }
    }
  }
}

// examples/newtons_cradle.yaml: three 0.1 kg balls on L = 0.5 m strings, touching; the first let
// go from θ₀ = 0.5 rad arrives after a quarter period t₁ = √(L/g) K(sin(θ₀/2)) at v₀ =
// √(2 g L (1 − cos θ₀)). The impacts at one instant strike one after another: 1 on 2, then 2 on
// 3, each elastic between equal masses, so that ball 3 leaves with v₀ and balls 1 and 2 stop; it
// is back at 3 t₁, and so on: the impacts at (2k + 1) t₁, in pairs.
TEST(Contacts, NewtonsCradlePassesTheMomentumAlongTheRow) {
  const double L = 0.5, theta_0 = 0.5, m = 0.1;
  const double t1 = std::sqrt(L / kG) * std::comp_ellint_1(std::sin(theta_0 / 2));
  const double v0 = std::sqrt(2 * kG * L * (1 - std::cos(theta_0)));
  const model::Model model = io::read_model_file("examples/newtons_cradle.yaml").model;
  const UnilateralRun run = run_unilaterals(model, "dopri5", 1e-3, 3.0);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_EQ(events.size(), 8u);  // (2k + 1) t₁ < 3 s: k ≤ 3, two impacts each
  for (std::size_t k = 0; k < events.size(); ++k) {
    SCOPED_TRACE(k);
    const StopEvent& s = events[k];
    ASSERT_EQ(s.kind, StopEventKind::impact);
    const bool outward = (k / 2) % 2 == 0;  // 1 → 3 at t₁, 5 t₁; 3 → 1 at 3 t₁, 7 t₁
    EXPECT_EQ(s.contact, (k % 2 == 0) == outward ? "touch12" : "touch23");
    EXPECT_NEAR(s.time, (2.0 * static_cast<double>(k / 2) + 1.0) * t1, 1e-11 * t1);
    if (k % 2 == 1) {
      // The same instant, to the time a ball's round-off in place (1e-16 m) takes at v₀.
      EXPECT_NEAR(s.time, events[k - 1].time, 1e-14);
    }
    EXPECT_NEAR(s.rate_before, -v0, 1e-10 * v0);
    EXPECT_NEAR(s.rate_after, -s.rate_before, 1e-14 * v0);
    EXPECT_NEAR(s.impulse, m * v0, 1e-10 * m * v0);
    EXPECT_NEAR(s.energy_lost, 0.0, 1e-15);
  }
  // The middle ball never moves; the first is still from t₁ to 3 t₁ while the third swings.
  const int middle = run.table.column("string2.angle"), first = run.table.column("string1.angle");
  const int third = run.table.column("string3.angle");
  for (const std::vector<double>& row : run.table.rows) {
    EXPECT_NEAR(row[middle], 0.0, 1e-14) << row[0];
    if (row[0] > t1 && row[0] < 3 * t1 - 1e-9) {
      EXPECT_NEAR(row[first], 0.0, 1e-14) << row[0];
      EXPECT_LT(row[third], 0.0) << row[0];
    }
  }
  ASSERT_FALSE(run.summary.audit.empty());
  EXPECT_EQ(run.summary.audit[0].name, "energy");
  EXPECT_LT(run.summary.audit[0].max_drift, 1e-12);
}

TEST(Contacts, TheModelFileSaysWhatIsWrongWithAContact) {
  const auto message = load_error;
  std::string text = sphere(1.5);
  EXPECT_NE(message(text).find("restitution"), std::string::npos) << message(text);
  EXPECT_NE(message(text).find("above 1"), std::string::npos) << message(text);
  EXPECT_NE(message(sphere(0.5) + "").find("no error"), std::string::npos);
  text = sphere(0.5);
  text.replace(text.find("radius: 0.05, rest"), 12, "radius: -0.1");
  EXPECT_NE(message(text).find("radius"), std::string::npos) << message(text);
  text = sphere(0.5);
  text.replace(text.find("body: ball, radius"), 10, "body: world");
  EXPECT_NE(message(text).find("world"), std::string::npos) << message(text);
  text = sphere(0.5);
  text.replace(text.find("restitution"), 11, "restitutoin");
  EXPECT_NE(message(text).find("restitution"), std::string::npos) << message(text);
  text = sphere(0.5);
  text.replace(text.find("radius: 0.05, rest"), 12, "normal: [0, 0, 2]");
  EXPECT_NE(message(text).find("unit vector"), std::string::npos) << message(text);
  text = sphere(0.5);
  text.replace(text.find("radius: 0.05, rest"), 12, "other_radius: 1");
  EXPECT_NE(message(text).find("give other_body"), std::string::npos) << message(text);
  text = sphere(0.5);
  text.replace(text.find("radius: 0.05, rest"), 12, "other_body: ball");
  EXPECT_NE(message(text).find("both spheres are on body 'ball'"), std::string::npos)
      << message(text);
}

}  // namespace
}  // namespace contacts
}  // namespace momenta::simulate
