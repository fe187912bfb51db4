// Coulomb's law for the contacts that hold while another strikes (simulate/unilaterals.hpp,
// docs/contacts.md "A sticking contact in another's impact"): a sticking contact whose cone
// cannot hold the friction impulse sticking would need slides through the impact, its friction
// impulse μk P_n against the slip; a sliding one takes μk P_n against its slip. Against closed
// forms:
// - billiards: a cue ball sliding at V strikes an object ball resting on the cloth, centre on
//   centre. The cloth's normal impulses are zero, so no friction impulse: the object ball leaves
//   at (1 + e) V / 2 without spin — not the 5/7 of that a cloth that stuck would give it — and
//   slides until it rolls at t = 2 v / (7 μk g) with 5 v / 7 (Beer & Johnston ch. 17 and 16);
// - a ball struck obliquely from above, 20° below the horizontal, through its centre: the cloth
//   pushes back with P_n = P sin β and its friction μk P_n holds the ball back and spins it:
//   P = (1 + e) m V / (1 + cos β (cos β − μk sin β)), then the ball slides until it rolls.

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/simulate/simulation.hpp"
#include "unilateral_runs.hpp"

namespace momenta::simulate {
namespace friction_in_impact {
namespace {

using namespace unilateral_test;

constexpr double kMass = 0.17, kRadius = 0.025;

const StopEvent* find_event(const std::vector<StopEvent>& events, const std::string& contact,
                            StopEventKind kind) {
  for (const StopEvent& e : events) {
    if (e.contact == contact && e.kind == kind) return &e;
  }
  return nullptr;
}

TEST(FrictionInImpact, ABilliardBallStruckCentreOnCentreSlidesOffThenRolls) {
  const double V = 2.0, e = 0.9, mu = 0.2;
  const double v_object = (1.0 + e) * V / 2.0, v_cue = (1.0 - e) * V / 2.0;
  const model::Model model = load(fmt::format(
      "gravity: [0, 0, -9.81]\n"
      "bodies:\n"
      "  - {{name: cue, shape: sphere, mass: {m}, radius: {r}}}\n"
      "  - {{name: object, shape: sphere, mass: {m}, radius: {r}}}\n"
      "joints:\n"
      "  - {{name: cue_free, type: free, parent: world, child: cue,\n"
      "     q0: {{position: [-0.05, 0, {r}]}}, v0: [0, 0, 0, {V}, 0, 0]}}\n"
      "  - {{name: object_free, type: free, parent: world, child: object,\n"
      "     q0: {{position: [0, 0, {r}]}}}}\n"
      "constraints:\n"
      "  - {{name: cue_cloth, type: contact, body: cue, radius: {r}, friction: {mu}}}\n"
      "  - {{name: object_cloth, type: contact, body: object, radius: {r}, friction: {mu}}}\n"
      "  - {{name: hit, type: contact, body: object, radius: {r}, other_body: cue,\n"
      "     other_radius: {r}, restitution: {e}}}\n",
      fmt::arg("m", kMass), fmt::arg("r", kRadius), fmt::arg("V", V), fmt::arg("mu", mu),
      fmt::arg("e", e)));
  const double t_object = 2.0 * v_object / (7.0 * mu * kG);
  const UnilateralRun run = run_unilaterals(model, "dopri5", 1e-3, t_object + 0.05);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  // The impact at the start, the cloth under the object ball slipping in it.
  const StopEvent* hit = find_event(events, "hit", StopEventKind::impact);
  ASSERT_NE(hit, nullptr);
  EXPECT_EQ(hit->time, 0.0);
  EXPECT_NEAR(hit->impulse, kMass * v_object, 1e-12 * kMass * V);
  const StopEvent* slip = find_event(events, "object_cloth", StopEventKind::slip);
  ASSERT_NE(slip, nullptr);
  EXPECT_TRUE(slip->in_impact);
  EXPECT_EQ(slip->time, 0.0);
  // Sticking would have needed 2/7 of the impulse a cloth that held gave: (2/7) m (1 + e) V /
  // (2 + 5/7·…): the rolling ball's impulse P_s = m v' with v' from (1/m + 1/(7m/5)) — its
  // friction 2/7 of its effective mass' impulse; and the cone gives μs · 0.
  const double P_stuck = (1.0 + e) * V / (1.0 / kMass + 5.0 / (7.0 * kMass));
  EXPECT_NEAR(slip->friction_needed, 2.0 / 7.0 * P_stuck, 1e-12 * kMass * V);
  EXPECT_NEAR(slip->friction_limit, 0.0, 1e-12 * kMass * V);
  // Each ball then slides until it rolls, at 2 v / (7 μk g).
  const StopEvent* cue_rolls = find_event(events, "cue_cloth", StopEventKind::stick);
  const StopEvent* object_rolls = find_event(events, "object_cloth", StopEventKind::stick);
  ASSERT_NE(cue_rolls, nullptr);
  ASSERT_NE(object_rolls, nullptr);
  const double t_cue = 2.0 * v_cue / (7.0 * mu * kG);
  EXPECT_NEAR(cue_rolls->time, t_cue, 1e-12 * t_object);
  EXPECT_NEAR(object_rolls->time, t_object, 1e-12 * t_object);
  // Just after the impact: the speeds of a frictionless cloth, no spin.
  const std::vector<double>* after = nullptr;
  for (const std::vector<double>& row : run.table.rows) {
    if (row[0] > 0.0) break;
    after = &row;
  }
  ASSERT_NE(after, nullptr);
  EXPECT_NEAR((*after)[run.table.column("object_free.vx")], v_object, 1e-12 * V);
  EXPECT_NEAR((*after)[run.table.column("cue_free.vx")], v_cue, 1e-12 * V);
  EXPECT_NEAR((*after)[run.table.column("object_free.wy")], 0.0, 1e-12 * V / kRadius);
  const std::vector<double>& last = run.table.rows.back();
  EXPECT_NEAR(last[run.table.column("object_free.vx")], 5.0 * v_object / 7.0, 1e-12 * V);
  EXPECT_NEAR(last[run.table.column("cue_free.vx")], 5.0 * v_cue / 7.0, 1e-12 * V);
}

TEST(FrictionInImpact, ABallStruckFromAboveIsHeldBackByTheClothsFrictionImpulse) {
  const double V = 2.0, e = 0.5, mu_s = 0.3, mu_k = 0.2, beta = 20.0 * std::numbers::pi / 180.0;
  const double c = std::cos(beta), s = std::sin(beta);
  const model::Model model = load(fmt::format(
      "gravity: [0, 0, -9.81]\n"
      "bodies:\n"
      "  - {{name: striker, shape: sphere, mass: {m}, radius: {r}}}\n"
      "  - {{name: ball, shape: sphere, mass: {m}, radius: {r}}}\n"
      "joints:\n"
      "  - {{name: striker_free, type: free, parent: world, child: striker,\n"
      "     q0: {{position: [{x:.17g}, 0, {z:.17g}]}},\n"
      "     v0: [0, 0, 0, {vx:.17g}, 0, {vz:.17g}]}}\n"
      "  - {{name: ball_free, type: free, parent: world, child: ball,\n"
      "     q0: {{position: [0, 0, {r}]}}}}\n"
      "constraints:\n"
      "  - {{name: cloth, type: contact, body: ball, radius: {r},\n"
      "     friction: {{static: {mu_s}, kinetic: {mu_k}}}}}\n"
      "  - {{name: hit, type: contact, body: ball, radius: {r}, other_body: striker,\n"
      "     other_radius: {r}, restitution: {e}}}\n",
      fmt::arg("m", kMass), fmt::arg("r", kRadius), fmt::arg("x", -2.0 * kRadius * c),
      fmt::arg("z", kRadius + 2.0 * kRadius * s), fmt::arg("vx", V * c), fmt::arg("vz", -V * s),
      fmt::arg("mu_s", mu_s), fmt::arg("mu_k", mu_k), fmt::arg("e", e)));
  // The struck ball: P u from the striker, P_n = P s up and μk P_n back (−x) from the cloth at
  // its lowest point, which spins it forward (ω_y = (5/2) μk P_n / (m r)). Newton's law along u:
  // u · (v_ball − v_striker) after = e V.
  const double P = (1.0 + e) * kMass * V / (1.0 + c * (c - mu_k * s));
  const double N = P * s;
  const double vx = (P * c - mu_k * N) / kMass, wy = 2.5 * mu_k * N / (kMass * kRadius);
  const double slip_after = vx - kRadius * wy;
  const double t_rolls = slip_after / (3.5 * mu_k * kG);
  const UnilateralRun run = run_unilaterals(model, "dopri5", 1e-3, t_rolls + 0.02);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  const StopEvent* hit = find_event(events, "hit", StopEventKind::impact);
  ASSERT_NE(hit, nullptr);
  EXPECT_NEAR(hit->time, 0.0, 1e-15);
  EXPECT_NEAR(hit->impulse, P, 1e-12 * P);
  // Sticking needs (2/7) of cos β times its own impulse; the cone gives μs times its P_n.
  const StopEvent* slip = find_event(events, "cloth", StopEventKind::slip);
  ASSERT_NE(slip, nullptr);
  EXPECT_TRUE(slip->in_impact);
  const double P_stuck = (1.0 + e) * kMass * V / (1.0 + c * c * 5.0 / 7.0);
  EXPECT_NEAR(slip->friction_needed, 2.0 / 7.0 * c * P_stuck, 1e-12 * P);
  EXPECT_NEAR(slip->friction_limit, mu_s * P_stuck * s, 1e-12 * P);
  const std::vector<double>* after = nullptr;
  for (const std::vector<double>& row : run.table.rows) {
    if (row[0] > hit->time) break;
    after = &row;
  }
  ASSERT_NE(after, nullptr);
  const auto at = [&](const char* column) { return (*after)[run.table.column(column)]; };
  EXPECT_NEAR(at("ball_free.vx"), vx, 1e-12 * V);
  EXPECT_NEAR(at("ball_free.vz"), 0.0, 1e-12 * V);
  EXPECT_NEAR(at("ball_free.wy"), wy, 1e-12 * V / kRadius);
  EXPECT_NEAR(at("striker_free.vx"), (V - P / kMass) * c, 1e-12 * V);
  EXPECT_NEAR(at("striker_free.vz"), -(V - P / kMass) * s, 1e-12 * V);
  // The cloth's friction took energy: the kinetic energy after is what the closed form leaves.
  const double kinetic_after = 0.5 * kMass * (vx * vx + (V - P / kMass) * (V - P / kMass)) +
                               0.5 * 0.4 * kMass * kRadius * kRadius * wy * wy;
  EXPECT_NEAR(at("energy_kinetic"), kinetic_after, 1e-12 * kMass * V * V);
  // It then slides until its lowest point stops slipping.
  const StopEvent* rolls = find_event(events, "cloth", StopEventKind::stick);
  ASSERT_NE(rolls, nullptr);
  EXPECT_NEAR(rolls->time, hit->time + t_rolls, 1e-12 * t_rolls);
}

}  // namespace
}  // namespace friction_in_impact
}  // namespace momenta::simulate
