// A disk against a sphere (model::Contact, shape disk, other_body's sphere): the disk's point
// nearest the sphere's centre — on its face or its rim — struck by Newton's law along the line
// from the sphere's centre to it, against closed forms:
// - a ball bouncing on a fixed disk's face, off its centre: the bouncing ball's times
//   t₁ (1 + 2e + … + 2e^{k−1}), t₁ = √(2h/g), and speeds e^k √(2gh); it never leaves its line;
// - a ball dropped onto a fixed upright disk's rim, beside its plane: struck where
//   |s − p| = r_s along n = (p − s) / r_s, its velocity after v⁻ − (1 + e) (v⁻ · n) n, no spin;
// - a coin falling flat onto a fixed ball, ρ off its centre: P = (1 + e) m v / (1 + 4 ρ² / R²)
//   (the lever ρ about a diameter, I = m R² / 4), the coin's fall and turn after it and the
//   energy lost;
// - a ball rolling on a turntable spinning at Ω (examples/ball_on_turntable.yaml): its centre
//   goes round a circle at 2 Ω / 7, centre −(5/2) r₀, radius (7/2) r₀, the friction holding it
//   m (2/7) Ω |v| towards that centre;
// - the model file's errors.

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/simulate/simulation.hpp"
#include "unilateral_runs.hpp"

namespace momenta::simulate {
namespace disk_sphere_contact {
namespace {

using namespace unilateral_test;

// A fixed disk (the table's, radius R, its axis `axis` in W, centre at the origin) and a free
// ball (m = 0.2 kg, radius r) with its centre at `ball`; restitution e, frictionless.
std::string ball_over_fixed_disk(double R, const std::string& axis, double r, const Vec3& ball,
                                 double e) {
  return fmt::format(
      "gravity: [0, 0, -9.81]\n"
      "bodies:\n"
      "  - {{name: table, shape: thin_disk, mass: 1.0, radius: {R}}}\n"
      "  - {{name: ball, shape: sphere, mass: 0.2, radius: {r}}}\n"
      "joints:\n"
      "  - {{name: mount, type: fixed, parent: world, child: table}}\n"
      "  - {{name: free, type: free, parent: world, child: ball,\n"
      "     q0: {{position: [{x:.17g}, {y:.17g}, {z:.17g}]}}}}\n"
      "constraints:\n"
      "  - {{name: hit, type: contact, body: table, shape: disk, radius: {R}, axis: {axis},\n"
      "     other_body: ball, other_radius: {r}, restitution: {e}}}\n",
      fmt::arg("R", R), fmt::arg("r", r), fmt::arg("x", ball.x()), fmt::arg("y", ball.y()),
      fmt::arg("z", ball.z()), fmt::arg("axis", axis), fmt::arg("e", e));
}

TEST(DiskSphereContact, ABallBouncesOnADisksFaceAsOnTheFloor) {
  const double m = 0.2, r = 0.05, h = 0.2, e = 0.8;
  const double t1 = std::sqrt(2.0 * h / kG), v = std::sqrt(2.0 * kG * h);
  const Vec3 start(0.2, -0.1, r + h);  // over the face (R = 0.5), h above it
  const model::Model model = load(ball_over_fixed_disk(0.5, "[0, 0, 1]", r, start, e));
  const int bounces = 8;
  double t_last = t1;
  for (int k = 1; k < bounces; ++k) t_last += 2.0 * t1 * std::pow(e, k);
  const UnilateralRun run = run_unilaterals(model, "dopri5", 1e-3, t_last + 0.01);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_EQ(events.size(), std::size_t(bounces));
  double t_k = t1;
  for (int k = 0; k < bounces; ++k) {
    SCOPED_TRACE(k);
    const StopEvent& hit = events[std::size_t(k)];
    EXPECT_EQ(hit.kind, StopEventKind::impact);
    EXPECT_EQ(hit.contact, "hit");
    // Flights are parabolas, dopri5 exact on them: the locator's 1e-14 and the round-off of
    // the steps, measured 4e-15 relative at the eighth bounce.
    EXPECT_NEAR(hit.time, t_k, 1e-12 * t_k);
    const double arriving = std::pow(e, k) * v;
    EXPECT_NEAR(hit.rate_before, -arriving, 1e-12 * v);
    EXPECT_NEAR(hit.rate_after, e * arriving, 1e-12 * v);
    EXPECT_NEAR(hit.impulse, (1.0 + e) * m * arriving, 1e-12 * m * v);
    EXPECT_NEAR(hit.energy_lost, 0.5 * m * arriving * arriving * (1.0 - e * e), 1e-12 * m * v * v);
    t_k += 2.0 * t1 * std::pow(e, k + 1);
  }
  // Straight up and down over the same point of the face, never into it, never spinning.
  const int x = run.table.column("free.x"), y = run.table.column("free.y");
  const int z = run.table.column("free.z");
  for (const std::vector<double>& row : run.table.rows) {
    EXPECT_EQ(row[x], start.x()) << row[0];
    EXPECT_EQ(row[y], start.y()) << row[0];
    EXPECT_GE(row[z], r - 1e-15) << row[0];
    for (const char* spin : {"free.wx", "free.wy", "free.wz"}) {
      EXPECT_EQ(row[run.table.column(spin)], 0.0) << row[0];
    }
  }
}

TEST(DiskSphereContact, ABallStrikesAnUprightDisksRimBesideItsPlane) {
  // The disk (R = 0.2 m) stands in the x–z plane, its axis along y; the ball (r = 0.05 m) falls
  // δ = 0.03 m beside the plane onto the rim's top point p = (0, 0, R). It touches where
  // δ² + (z − R)² = r², at z = R + 0.04, with n = (p − s) / r = (0, −0.6, −0.8).
  const double m = 0.2, R = 0.2, r = 0.05, delta = 0.03, h = 0.1, e = 0.6;
  const double z_touch = R + std::sqrt(r * r - delta * delta);
  const double t_hit = std::sqrt(2.0 * h / kG), v = std::sqrt(2.0 * kG * h);
  const Vec3 n(0.0, -delta / r, (R - z_touch) / r);
  const model::Model model =
      load(ball_over_fixed_disk(R, "[0, 1, 0]", r, Vec3(0.0, delta, z_touch + h), e));
  const double after = t_hit + 0.01;
  const UnilateralRun run = run_unilaterals(model, "dopri5", 1e-3, after);
  ASSERT_EQ(run.summary.stop_events.size(), 1u);
  const StopEvent& hit = run.summary.stop_events[0];
  EXPECT_EQ(hit.kind, StopEventKind::impact);
  EXPECT_NEAR(hit.time, t_hit, 1e-12 * t_hit);
  // The normal speed of the table's point away from the ball's: n · (0 − v⁻).
  const Vec3 v_before(0.0, 0.0, -v);
  const double approach = n.dot(-v_before);
  EXPECT_NEAR(hit.rate_before, approach, 1e-12 * v);
  EXPECT_NEAR(hit.rate_after, -e * approach, 1e-12 * v);
  EXPECT_NEAR(hit.impulse, -(1.0 + e) * m * approach, 1e-12 * m * v);
  // The ball is pushed along −n, through its centre: its velocity jumps, its spin stays zero.
  const Vec3 v_after = v_before + (1.0 + e) * approach * n;
  const std::vector<double>& last = run.table.rows.back();
  ASSERT_NEAR(last[0], after, 1e-12);
  EXPECT_NEAR(last[run.table.column("free.vx")], 0.0, 1e-12 * v);
  EXPECT_NEAR(last[run.table.column("free.vy")], v_after.y(), 1e-12 * v);
  EXPECT_NEAR(last[run.table.column("free.vz")], v_after.z() - kG * (after - t_hit), 1e-12 * v);
  // The impulse acts at s + r n, on the line through the centre: its moment is round-off.
  for (const char* spin : {"free.wx", "free.wy", "free.wz"}) {
    EXPECT_NEAR(last[run.table.column(spin)], 0.0, 1e-12 * v / r);
  }
}

TEST(DiskSphereContact, ACoinFallingFlatOnABallTurnsAboutItsDiameter) {
  // A thin coin (m = 1 kg, R = 0.1 m, I = m R² / 4 about a diameter) falls flat, its face h above
  // a fixed ball's top (r = 0.05 m), its centre ρ = 0.05 m off the ball's vertical in x. Struck
  // at the ball's top, ρ behind its centre: P = (1 + e) m v / (1 + 4 ρ² / R²), the centre's
  // speed −v + P / m after, the turn ω_y = ρ P / I, the energy lost ½ (1 − e²) m v² / (1 +
  // 4 ρ² / R²).
  const double m = 1.0, R = 0.1, r = 0.05, rho = 0.05, h = 0.2, e = 0.5;
  const double t_hit = std::sqrt(2.0 * h / kG), v = std::sqrt(2.0 * kG * h);
  const double lever = 1.0 + 4.0 * rho * rho / (R * R);
  const double P = (1.0 + e) * m * v / lever;
  const model::Model model =
      load(fmt::format("gravity: [0, 0, -9.81]\n"
                       "bodies:\n"
                       "  - {{name: coin, shape: thin_disk, mass: {m}, radius: {R}}}\n"
                       "  - {{name: post, shape: sphere, mass: 1.0, radius: {r}}}\n"
                       "joints:\n"
                       "  - {{name: free, type: free, parent: world, child: coin,\n"
                       "     q0: {{position: [{rho}, 0, {z:.17g}]}}}}\n"
                       "  - {{name: mount, type: fixed, parent: world, child: post}}\n"
                       "constraints:\n"
                       "  - {{name: hit, type: contact, body: coin, shape: disk, radius: {R},\n"
                       "     other_body: post, other_radius: {r}, restitution: {e}}}\n",
                       fmt::arg("m", m), fmt::arg("R", R), fmt::arg("r", r), fmt::arg("rho", rho),
                       fmt::arg("z", r + h), fmt::arg("e", e)));
  const double after = t_hit + 0.005;
  const UnilateralRun run = run_unilaterals(model, "dopri5", 1e-3, after);
  ASSERT_EQ(run.summary.stop_events.size(), 1u);
  const StopEvent& hit = run.summary.stop_events[0];
  EXPECT_NEAR(hit.time, t_hit, 1e-12 * t_hit);
  EXPECT_NEAR(hit.rate_before, -v, 1e-12 * v);
  EXPECT_NEAR(hit.rate_after, e * v, 1e-12 * v);  // Newton's law at the struck point
  EXPECT_NEAR(hit.impulse, P, 1e-12 * P);
  EXPECT_NEAR(hit.energy_lost, 0.5 * (1.0 - e * e) * m * v * v / lever, 1e-12 * m * v * v);
  const std::vector<double>& last = run.table.rows.back();
  ASSERT_NEAR(last[0], after, 1e-12);
  EXPECT_NEAR(last[run.table.column("free.vz")], -v + P / m - kG * (after - t_hit), 1e-12 * v);
  // r × P = (−ρ, 0, 0) × (0, 0, P): about +y, the coin's y and the world's.
  EXPECT_NEAR(last[run.table.column("free.wy")], rho * P / (0.25 * m * R * R), 1e-12 * v / R);
  EXPECT_NEAR(last[run.table.column("free.vx")], 0.0, 1e-12 * v);
  EXPECT_NEAR(last[run.table.column("free.wx")], 0.0, 1e-12 * v / R);
  EXPECT_NEAR(last[run.table.column("free.wz")], 0.0, 1e-12 * v / R);
}

TEST(DiskSphereContact, ABallOnATurntableRollsRoundACircleAtTwoSeventhsOfItsRate) {
  // Rolling without slip on a surface turning at Ω about z: m v̇ = F, I ω̇ = (−r ẑ) × F and the
  // no-slip condition's rate give v̇ = (2/7) Ω ẑ × v (I = 2 m r² / 5). Set down at r₀ moving with
  // the surface (v₀ = Ω ẑ × r₀, no spin), the centre circles −(5/2) r₀ at Ω' = 2 Ω / 7, radius
  // (7/2) r₀.
  const double m = 0.1, r = 0.03, Omega = 2.0, r0 = 0.04, turn = 2.0 * Omega / 7.0;
  const double centre = -2.5 * r0, radius = 3.5 * r0, speed = Omega * r0;
  const model::Model model = io::read_model_file("examples/ball_on_turntable.yaml").model;
  for (const std::string integrator : {"rk4", "dopri5"}) {
    SCOPED_TRACE(integrator);
    const UnilateralRun run = run_unilaterals(model, integrator, 1e-3, 11.0, /*reactions=*/true);
    // Resting on the face, sticking, from the start, and never letting go or slipping.
    ASSERT_EQ(run.summary.stop_events.size(), 1u);
    EXPECT_EQ(run.summary.stop_events[0].kind, StopEventKind::rest);
    EXPECT_EQ(run.summary.stop_events[0].friction, FrictionState::sticking);
    const int x = run.table.column("free.x"), y = run.table.column("free.y");
    const int z = run.table.column("free.z"), normal = run.table.column("face.normal");
    const int f1 = run.table.column("face.tangent_1"), f2 = run.table.column("face.tangent_2");
    double worst = 0.0, worst_force = 0.0;
    for (const std::vector<double>& row : run.table.rows) {
      const double t = row[0], angle = turn * t;
      const Vec2 expected(centre + radius * std::cos(angle), radius * std::sin(angle));
      worst = std::max(worst, (Vec2(row[x], row[y]) - expected).norm());
      EXPECT_NEAR(row[z], r, 1e-14) << t;
      // The columns are the forces on the table (body b), along n = −ẑ (from the ball towards
      // it) and its tangents t₁ = x̂, t₂ = n × t₁ = −ŷ; the ball takes the opposite.
      EXPECT_NEAR(row[normal], m * kG, 1e-12 * m * kG) << t;
      const Vec2 friction_on_ball(-row[f1], row[f2]);
      const Vec2 towards_centre = Vec2(centre, 0.0) - Vec2(row[x], row[y]);
      const Vec2 needed = m * turn * speed * towards_centre.normalized();
      worst_force = std::max(worst_force, (friction_on_ball - needed).norm());
    }
    std::printf("%s: ball on a turntable, 11 s: position %.2e m, friction %.2e N\n",
                integrator.c_str(), worst, worst_force);
    // rk4's error at h = 1 ms over 11 s (measured 3.3e-11 m, the friction 1.2e-10 of itself);
    // dopri5 at rtol 1e-12 (measured 3.8e-15 m, 1.2e-13 of the friction).
    const bool rk4 = integrator == "rk4";
    EXPECT_LT(worst, rk4 ? 1e-10 : 1e-13);
    EXPECT_LT(worst_force, (rk4 ? 1e-9 : 1e-12) * m * turn * speed);
  }
}

TEST(DiskSphereContact, TheModelFileAndTheRunSayWhatIsWrong) {
  const std::string bodies =
      "bodies: [{name: coin, shape: thin_disk, mass: 1.0, radius: 0.1},\n"
      "         {name: ball, shape: sphere, mass: 1.0, radius: 0.05}]\n"
      "joints: [{name: f, type: free, parent: world, child: coin},\n"
      "         {name: g, type: free, parent: world, child: ball}]\n";
  EXPECT_NE(
      load_error(bodies + "constraints: [{name: c, type: contact, body: coin, shape: disk, radius: "
                          "0.1, other_body: coin, other_radius: 0.05}]\n")
          .find("both the disk and the sphere are on body 'coin'"),
      std::string::npos);
  // The ball's centre in the coin's face (both start at the origin): no side to push it to,
  // said at the start of a run with the contact's name.
  const model::Model model =
      load(bodies +
           "constraints: [{name: c, type: contact, body: coin, shape: disk, radius: 0.1, "
           "other_body: ball, other_radius: 0.05}]\n");
  try {
    run_unilaterals(model, "dopri5", 1e-3, 0.1);
    FAIL() << "a ball inside a coin ran on";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("'c'"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("in the disk's face"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace disk_sphere_contact
}  // namespace momenta::simulate
