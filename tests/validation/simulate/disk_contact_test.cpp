// Contacts of a disk's rim with a plane (model::Contact, shape disk; a `rolling` contact with
// friction) against closed forms:
// - a wheel set down skidding with v₀ and no spin (examples/skidding_wheel.yaml): it rolls from
//   t = v₀ / (3 μk g) at 2 v₀ / 3 (I = m r² / 2), friction −μk m g until then and none after;
// - the rolling coin of examples/constraints/rolling_coin.yaml held by friction instead of the
//   rolling constraint: its steady precession, lean and spin, and the contact force (m g up,
//   m ρ Ω² towards the circle's centre) from the steady motion's closed form;
// - a thin disk dropped tilted by φ onto its rim (frictionless, e): the impulse
//   P = (1 + e) m v / (1 + 4 sin² φ) (the rim's lever arm r sin φ about a diameter, I = m r² / 4),
//   the motion after it and the energy lost m v² (1 − e²) / 4 at φ = 30°;
// - a disk landing flat (a face contact, not modelled) stops the run with the time named;
// - the model file's errors for disk contacts.

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/model/constraint.hpp"
#include "momenta/simulate/simulation.hpp"
#include "unilateral_runs.hpp"

namespace momenta::simulate {
namespace disk_contact {
namespace {

using namespace unilateral_test;

TEST(DiskContact, SkiddingWheelRollsFromTheClosedFormsInstant) {
  const double m = 2.0, r = 0.3, v0 = 3.0, mu_k = 0.3;
  const double t_roll = v0 / (3.0 * mu_k * kG), v_roll = 2.0 * v0 / 3.0;
  const model::Model model = io::read_model_file("examples/skidding_wheel.yaml").model;
  // `rolling` with friction is a contact of the disk's rim.
  const auto* ground = std::get_if<model::Contact>(&model.constraints()[0]);
  ASSERT_NE(ground, nullptr);
  EXPECT_EQ(ground->shape, model::ContactShape::disk);
  for (const std::string integrator : {"rk4", "dopri5"}) {
    SCOPED_TRACE(integrator);
    const UnilateralRun run = run_unilaterals(model, integrator, 1e-3, 1.0, /*reactions=*/true);
    const std::vector<StopEvent>& events = run.summary.stop_events;
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].kind, StopEventKind::rest);
    EXPECT_EQ(events[0].friction, FrictionState::sliding);
    EXPECT_EQ(events[1].kind, StopEventKind::stick);
    EXPECT_EQ(events[1].contact, "ground");
    // The slip is linear in time and the integrators exact on it: the instant to the locator's
    // 1e-14 and the round-off of a few hundred steps.
    EXPECT_NEAR(events[1].time, t_roll, 1e-12 * t_roll);
    EXPECT_NEAR(events[1].friction_limit, 0.4 * m * kG, 1e-12);
    EXPECT_LT(events[1].friction_needed, 1e-12);  // rolling on the level: no friction

    // The body's z is world y: its spin about its axis is free.wz.
    const int vx = run.table.column("free.vx"), spin = run.table.column("free.wz");
    const int normal = run.table.column("ground.normal");
    const int f1 = run.table.column("ground.tangent_1"), f2 = run.table.column("ground.tangent_2");
    const int kinetic = run.table.column("energy_kinetic");
    const double kinetic_0 = 0.5 * m * v0 * v0;
    for (const std::vector<double>& row : run.table.rows) {
      const double t = row[0];
      EXPECT_NEAR(row[normal], m * kG, 1e-12 * m * kG) << t;
      EXPECT_NEAR(row[f2], 0.0, 1e-12 * m * kG) << t;
      if (t < events[1].time) {
        EXPECT_NEAR(row[vx], v0 - mu_k * kG * t, 1e-12 * v0) << t;
        EXPECT_NEAR(row[spin], 2.0 * mu_k * kG * t / r, 1e-12 * v0 / r) << t;
        EXPECT_NEAR(row[f1], -mu_k * m * kG, 1e-12 * m * kG) << t;
      } else if (t > events[1].time) {
        EXPECT_NEAR(row[vx], v_roll, 1e-12 * v0) << t;
        EXPECT_NEAR(row[spin], v_roll / r, 1e-12 * v0 / r) << t;
        EXPECT_NEAR(row[f1], 0.0, 1e-12 * m * kG) << t;
        EXPECT_NEAR(kinetic_0 - row[kinetic], m * v0 * v0 / 6.0, 1e-11) << t;
      }
    }
  }
}

TEST(DiskContact, CoinHeldByFrictionRollsInTheSteadyCircle) {
  // examples/constraints/rolling_coin.yaml, its rolling constraint swapped for a disk contact
  // whose friction holds it: the same closed form (classic_constraints_test's).
  const double m = 1.0, R = 0.1, rho = 0.5, phi = -20.0 * std::numbers::pi / 180.0;
  const double W =
      std::sqrt(-kG * std::sin(phi) / (std::cos(phi) * (1.5 * rho - 0.25 * R * std::sin(phi))));
  const double s = rho * W / R - W * std::sin(phi);
  const model::Model model = io::parse_model_file(
                                 R"(name: coin on a rough floor
gravity: [0, 0, -9.81]
bodies:
  - {name: coin, shape: thin_disk, mass: 1.0, radius: 0.1}
joints:
  - name: free
    type: free
    parent: world
    child: coin
    q0:
      position: [0.5, 0, 0.09396926207859085]
      rotation: [[0, 0.3420201433256687, -0.9396926207859084],
                 [1, 0, 0],
                 [0, -0.9396926207859084, -0.3420201433256687]]
    v0: [0.0, -2.038736056205166, 10.847887974793696, 0, 1.0847887974793695, 0]
constraints:   # it needs friction ρ Ω² / g = 0.24 of its weight
  - {name: floor, type: contact, shape: disk, body: coin, radius: 0.1, friction: 0.5}
)",
                                 "coin.yaml", ".")
                                 .model;
  const UnilateralRun run = run_unilaterals(model, "rk4", 1e-3, 10.0, /*reactions=*/true);
  // It rests, sticking, from the start: its rim point's normal speed, 3e-16 m/s of round-off in
  // the file's state, is no bounce.
  ASSERT_EQ(run.summary.stop_events.size(), 1u);
  EXPECT_EQ(run.summary.stop_events[0].friction, FrictionState::sticking);
  EXPECT_EQ(run.summary.stop_events[0].rest_time, 0.0);
  const auto relative = [](double x, double ref) { return std::abs(x - ref) / std::abs(ref); };
  const int wx = run.table.column("free.wx"), wy = run.table.column("free.wy");
  const int z = run.table.column("free.z"), normal = run.table.column("floor.normal");
  const int f1 = run.table.column("floor.tangent_1"), f2 = run.table.column("floor.tangent_2");
  double worst = 0.0, worst_force = 0.0;
  for (std::size_t i = 0; i < run.table.rows.size(); i += 10) {
    const std::vector<double>& row = run.table.rows[i];
    // ω in the body: s along the axis (body z), Ω z across it — |(ωx, ωy)| = Ω cos φ.
    worst = std::max({worst, relative(row[run.table.column("free.wz")], s + W * std::sin(phi)),
                      relative(std::hypot(row[wx], row[wy]), W * std::cos(phi)),
                      relative(row[z], R * std::cos(phi))});
    worst_force = std::max({worst_force, relative(row[normal], m * kG),
                            relative(std::hypot(row[f1], row[f2]), m * rho * W * W)});
  }
  // The rolling constraint's own bound on the same run (RK4, 10⁴ steps; its test: 1e-8).
  EXPECT_LT(worst, 1e-8);
  EXPECT_LT(worst_force, 1e-8);
}

// A thin disk, m = 1 kg, r = 0.1 m, its axis (body z) tilted φ above the horizontal in the x–z
// plane, its lowest rim point h above the floor, let fall; restitution e, frictionless.
std::string tilted_disk(double phi, double h, double e) {
  const double beta = std::numbers::pi / 2 - phi;  // body z turned about y onto the axis
  const double r = 0.1;
  return fmt::format(
      "gravity: [0, 0, -9.81]\n"
      "bodies: [{{name: coin, shape: thin_disk, mass: 1.0, radius: {r}}}]\n"
      "joints:\n"
      "  - name: free\n"
      "    type: free\n"
      "    parent: world\n"
      "    child: coin\n"
      "    q0:\n"
      "      position: [0, 0, {z:.17g}]\n"
      "      rotation: [[{c:.17g}, 0, {s:.17g}], [0, 1, 0], [{ms:.17g}, 0, {c:.17g}]]\n"
      "constraints:\n"
      "  - {{name: floor, type: contact, shape: disk, body: coin, radius: {r}, restitution: "
      "{e}}}\n",
      fmt::arg("r", r), fmt::arg("z", r * std::cos(phi) + h), fmt::arg("c", std::cos(beta)),
      fmt::arg("s", std::sin(beta)), fmt::arg("ms", -std::sin(beta)), fmt::arg("e", e));
}

TEST(DiskContact, TiltedDiskStrikesOnItsRimAsTheImpulseEquationsSay) {
  const double m = 1.0, r = 0.1, phi = std::numbers::pi / 6, h = 0.2, e = 0.5;
  const double v = std::sqrt(2.0 * kG * h), t_hit = std::sqrt(2.0 * h / kG);
  const double P = (1.0 + e) * m * v / (1.0 + 4.0 * std::sin(phi) * std::sin(phi));
  const double after = t_hit + 0.01;  // a moment of flight after the impact
  const UnilateralRun run = run_unilaterals(load(tilted_disk(phi, h, e)), "dopri5", 1e-3, after);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_EQ(events.size(), 1u);
  const StopEvent& hit = events[0];
  EXPECT_EQ(hit.kind, StopEventKind::impact);
  EXPECT_EQ(hit.contact, "floor");
  // Free fall is a quadratic: the instant to the locator's 1e-12 relative.
  EXPECT_NEAR(hit.time, t_hit, 1e-12 * t_hit);
  EXPECT_NEAR(hit.rate_before, -v, 1e-12 * v);
  EXPECT_NEAR(hit.rate_after, e * v, 1e-12 * v);  // Newton's law at the rim point
  EXPECT_NEAR(hit.impulse, P, 1e-12 * P);
  EXPECT_NEAR(hit.energy_lost, m * v * v * (1.0 - e * e) / 4.0, 1e-12 * m * v * v);
  // After it: the centre rises at −v + P/m, less g's pull since; the disk turns about the
  // diameter along y at −r sin φ P / (m r² / 4) (body y is world y), and nothing else moves.
  const std::vector<double>& last = run.table.rows.back();
  ASSERT_NEAR(last[0], after, 1e-12);
  EXPECT_NEAR(last[run.table.column("free.vz")], -v + P / m - kG * (after - t_hit), 1e-12 * v);
  EXPECT_NEAR(last[run.table.column("free.wy")], -4.0 * std::sin(phi) * P / (m * r), 1e-12 * v / r);
  EXPECT_NEAR(last[run.table.column("free.vx")], 0.0, 1e-12 * v);
  EXPECT_NEAR(last[run.table.column("free.wx")], 0.0, 1e-12 * v / r);
  EXPECT_NEAR(last[run.table.column("free.wz")], 0.0, 1e-12 * v / r);
}

TEST(DiskContact, ADiskLandingFlatStopsTheRunWithTheTime) {
  const double h = 0.2, t_hit = std::sqrt(2.0 * h / kG);
  // φ = 90°: the axis along the normal, the face parallel to the floor.
  const model::Model model = load(tilted_disk(std::numbers::pi / 2, h, 0.0));
  try {
    run_unilaterals(model, "dopri5", 1e-3, 1.0);
    FAIL() << "a disk landing flat ran on";
  } catch (const NumericalError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("contact 'floor' at t = " + fmt::format("{:.9g}", t_hit)),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("lies flat on the plane"), std::string::npos) << what;
  }
}

TEST(DiskContact, TheModelFileSaysWhatIsWrong) {
  const std::string head =
      "bodies: [{name: coin, shape: thin_disk, mass: 1.0, radius: 0.1},\n"
      "         {name: ball, shape: sphere, mass: 1.0, radius: 0.1}]\n"
      "joints: [{name: f, type: free, parent: world, child: coin},\n"
      "         {name: g, type: free, parent: world, child: ball}]\n"
      "constraints:\n";
  const auto error = [&](const std::string& constraint) {
    return load_error(head + "  - " + constraint + "\n");
  };
  EXPECT_NE(error("{name: c, type: contact, body: coin, shape: disc, radius: 0.1}")
                .find("unknown shape 'disc' (did you mean 'disk'?)"),
            std::string::npos)
      << error("{name: c, type: contact, body: coin, shape: disc, radius: 0.1}");
  EXPECT_NE(error("{name: c, type: contact, body: coin, shape: disk}").find("radius"),
            std::string::npos);
  // A disk against another body's sphere is a contact (disk_sphere_contact_test).
  EXPECT_EQ(error("{name: c, type: contact, body: coin, shape: disk, radius: 0.1, other_body: "
                  "ball, other_radius: 0.1}"),
            "no error");
  EXPECT_NE(error("{name: c, type: contact, body: coin, radius: 0.1, axis: [1, 0, 0]}")
                .find("has no axis; give shape: disk"),
            std::string::npos);
  EXPECT_NE(error("{name: c, type: rolling, body: coin, radius: 0.1, friction: 0}")
                .find("a rolling contact's friction must be above 0"),
            std::string::npos);
  // Each names the file and line.
  EXPECT_NE(error("{name: c, type: contact, body: coin, shape: disc, radius: 0.1}")
                .find("unilaterals.yaml:6"),
            std::string::npos);
}

}  // namespace
}  // namespace disk_contact
}  // namespace momenta::simulate
