// MJCF's geoms on the world's plane (io/mjcf/mjcf_contacts.cpp) run as the textbook's rigid
// contacts: a MuJoCo ball launched skidding starts rolling at the closed form's instant and speed
// (Beer & Johnston ch. 16); a MuJoCo box slides to Coulomb's stop on its four bottom corners; one
// dropped tumbling comes to rest on its face with no energy made, and so does a heavier one whose
// corner starts to slip from its cone's edge, along the direction Coulomb's law gives there.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/io/mjcf_file.hpp"
#include "momenta/system/constraint_solver.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta_test/allocation_counter.hpp"
#include "momenta_test/tolerance.hpp"
#include "unilateral_runs.hpp"

namespace momenta::simulate {
namespace mjcf_contacts {
namespace {

using namespace unilateral_test;

// A free body on a floor of friction `floor_friction`, starting at rest on it with velocity
// qvel (MuJoCo's order: linear, then angular); `geom` is the body's geom.
model::Model on_the_floor(const std::string& geom, double height, double floor_friction,
                          double vx) {
  return io::parse_mjcf(fmt::format(R"(<mujoco model="on_the_floor">
  <option gravity="0 0 -9.81"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1" friction="{}"/>
    <body name="thing" pos="0 0 {}">
      <freejoint name="free"/>
      {}
    </body>
  </worldbody>
  <keyframe><key name="initial" qpos="0 0 {} 1 0 0 0" qvel="{} 0 0 0 0 0"/></keyframe>
</mujoco>)",
                                    floor_friction, height, geom, height, vx),
                        "on_the_floor.xml")
      .model;
}

// MuJoCo takes the larger of the two geoms' friction (0.3, the ball's): sliding from v₀ with no
// spin, friction μ m g slows the centre and spins the ball up until v = r ω at
// t = 2 v₀ / (7 μ g), v = 5 v₀ / 7, then it rolls with no friction at all.
TEST(MjcfContacts, AMuJoCoBallStartsRollingAtTheClosedFormsInstant) {
  const double r = 0.1, m = 1.0, mu = 0.3, v0 = 3.0;
  const model::Model ball = on_the_floor(
      fmt::format(R"(<geom name="ball" type="sphere" size="{}" mass="{}" friction="{}"/>)", r, m,
                  mu),
      r, 0.2, v0);
  ASSERT_EQ(ball.constraints().size(), 1u);
  const UnilateralRun run = run_unilaterals(ball, "dopri5", 1e-2, 0.6);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].kind, StopEventKind::rest);
  EXPECT_EQ(events[0].friction, FrictionState::sliding);
  EXPECT_EQ(events[1].kind, StopEventKind::stick);
  EXPECT_EQ(events[1].contact, "ball_floor");
  const double t_roll = 2.0 * v0 / (7.0 * mu * kG);
  // The slip falls linearly and dopri5 is exact on it: the locator's 1e-12 relative in time.
  EXPECT_NEAR(events[1].time, t_roll, 1e-12 * t_roll);
  const auto& last = run.table.rows.back();
  const double vx = last[static_cast<std::size_t>(run.table.column("free.vx"))];
  const double wy = last[static_cast<std::size_t>(run.table.column("free.wy"))];
  EXPECT_NEAR(vx, 5.0 * v0 / 7.0, 1e-12 * v0);
  EXPECT_NEAR(wy * r, vx, 1e-12 * v0);  // rolling: no slip at the floor
  EXPECT_NEAR(last[static_cast<std::size_t>(run.table.column("free.z"))], r, 1e-14);
}

// A MuJoCo box (half sizes 0.2, 0.1, 0.05 m, 2 kg) sliding on the floor (μ = 0.4, the floor's
// and the box's) at v₀: its eight corners
// are contacts, the bottom four carry it (redundant: the least-norm split, docs/contacts.md), the
// top four stay open. Coulomb's μ g stops it at t = v₀ / (μ g), x = v₀² / (2 μ g), level.
TEST(MjcfContacts, AMuJoCoCrateSlidesToAStopOnItsBottomCorners) {
  const double mu = 0.4, v0 = 2.0, c = 0.05, m = 2.0;
  const model::Model crate = on_the_floor(
      fmt::format(R"(<geom name="crate" type="box" size="0.2 0.1 {}" mass="{}" friction="{}"/>)", c,
                  m, mu),
      c, mu, v0);
  ASSERT_EQ(crate.constraints().size(), 8u);
  const double t_stop = v0 / (mu * kG), x_stop = v0 * v0 / (2.0 * mu * kG);
  const UnilateralRun run = run_unilaterals(crate, "dopri5", 1e-2, 1.5 * t_stop, true);
  const int z = run.table.column("free.z"), x = run.table.column("free.x");
  for (const auto& row : run.table.rows) {
    EXPECT_NEAR(row[std::size_t(z)], c, 1e-14) << row[0];
    double weight = 0.0;
    for (int k = 1; k <= 8; ++k) {
      const double N =
          row[std::size_t(run.table.column(fmt::format("crate_corner{}_floor.normal", k)))];
      if (k > 4) {
        EXPECT_EQ(N, 0.0) << "top corner " << k << " at t = " << row[0];
      }
      weight += N;
    }
    EXPECT_NEAR(weight, m * kG, 1e-12 * m * kG) << row[0];
  }
  const auto& last = run.table.rows.back();
  EXPECT_NEAR(last[std::size_t(x)], x_stop, 1e-12 * x_stop);
}

// No energy made: the total never rises by more than dopri5's drift in flight between rows (1e-12
// of it per step, a run's few thousand steps under 1e-9 J).
void expect_no_energy_made(const UnilateralRun& run) {
  const int energy = run.table.column("energy_total");
  for (std::size_t k = 1; k < run.table.rows.size(); ++k) {
    EXPECT_LE(run.table.rows[k][std::size_t(energy)],
              run.table.rows[k - 1][std::size_t(energy)] + 1e-9)
        << run.table.rows[k][0];
  }
}

// A box of mass m on its free joint `joint`, its corners' contacts `<geom>_corner<k>_floor`, at
// rest on a face at the run's end `t_end`: level at its half height c, every speed round-off, its
// weight on the bottom corners.
void expect_at_rest_on_its_face(const UnilateralRun& run, const std::string& joint,
                                const std::string& geom, double c, double m, double t_end) {
  const auto& last = run.table.rows.back();
  const auto at = [&](const std::string& column) {
    return last[std::size_t(run.table.column(column))];
  };
  EXPECT_EQ(last[0], t_end);
  EXPECT_NEAR(at(joint + ".z"), c, 1e-12);
  for (const char* tilt : {".qx", ".qy"}) EXPECT_NEAR(at(joint + tilt), 0.0, 1e-12) << tilt;
  for (const char* speed : {".vx", ".vy", ".vz", ".wx", ".wy", ".wz"}) {
    EXPECT_NEAR(at(joint + speed), 0.0, 1e-12) << speed;
  }
  double weight = 0.0;
  for (int k = 1; k <= 8; ++k) weight += at(fmt::format("{}_corner{}_floor.normal", geom, k));
  EXPECT_NEAR(weight, m * kG, 1e-12 * m * kG);
}

// The crate dropped tumbling — tilted about all three axes, 0.4 m up, μ = 1, plastic — lands on
// one corner, slides on it, and strikes with its others while that one slides through each
// impact. It comes to rest on its bottom face with no energy made on the way: the total
// energy never rises by more than dopri5's drift in flight (1e-12 of it per step, the run's few
// thousand steps under 1e-9 J), and at rest friction carrying round-off alone neither slips nor
// sticks. Once, a sliding contact's friction held against its direction
// before the impact pushed it on after (energy made: the run stopped), and corners at rest
// slipped and stuck at every step.
TEST(MjcfContacts, ACrateDroppedTumblingComesToRestOnItsFace) {
  const double c = 0.05, m = 2.0;
  const model::Model crate = io::parse_mjcf(fmt::format(R"(<mujoco model="tumbling_crate">
  <option gravity="0 0 -9.81"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1" friction="1"/>
    <body name="crate" pos="0 0 0.4" quat="0.95 0.2 0.15 0.05">
      <freejoint name="free"/>
      <geom name="box" type="box" size="0.2 0.1 {}" mass="{}"/>
    </body>
  </worldbody>
</mujoco>)",
                                                        c, m),
                                            "tumbling_crate.xml")
                                 .model;
  const UnilateralRun run = run_unilaterals(crate, "dopri5", 1e-2, 2.0, true);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_FALSE(events.empty());
  // It lands at 0.23 s and its last corner settles by 0.30 s; after that a corner carrying
  // round-off alone may be let go (the box then rests on two corners of a diagonal, the other two
  // touching: rigid bodies leave the split open), but none slips or sticks.
  EXPECT_LT(events.size(), 100u);  // 37 (26 impacts); slipping and sticking at rest made 1 469
  EXPECT_TRUE(std::any_of(events.begin(), events.end(), [](const StopEvent& e) {
    return e.kind == StopEventKind::stick && e.in_impact;
  }));  // a corner whose slip an impact turned
  for (const StopEvent& e : events) {
    if (e.time > 0.35) {
      EXPECT_EQ(e.kind, StopEventKind::release) << e.contact << " at t = " << e.time;
    }
  }
  expect_no_energy_made(run);
  expect_at_rest_on_its_face(run, "free", "box", c, m, 2.0);
}

// A heavier crate dropped the same way. Its first corner lands and sticks at 0.2004 s; at
// 0.2402 s its friction reaches the cone's edge and the corner starts to slip from rest. The
// crate pivots on that corner, so the slip's acceleration is not along the friction it feels
// (docs/contacts.md, "Coulomb friction"): started against the friction sticking needed, the
// slip turned at 1e11 rad/s at 1e-11 m/s, and dopri5 crawled at 6e-12 s steps until the run
// stopped with an error (integrate::kCrawlingSteps) — where it once wrote 1.5 GB of rows a
// minute. Started along its stable direction, where its acceleration is along it, the slip
// grows, and the crate comes to rest on a face with no energy made.
model::Model heavier_crate(double mu) {
  return io::parse_mjcf(fmt::format(R"(<mujoco model="crate">
  <worldbody>
    <geom name="floor" type="plane" size="0 0 1" friction="{}"/>
    <body name="crate" pos="0 0 0.4" quat="0.95 0.2 0.15 0.05">
      <freejoint/>
      <geom name="crate" type="box" size="0.2 0.15 0.1" mass="3" friction="{}"/>
    </body>
  </worldbody>
</mujoco>)",
                                    mu, mu),
                        "crate.xml")
      .model;
}

TEST(MjcfContacts, ASlipFromTheConesEdgeRunsOnAndTheCrateComesToRest) {
  const double c = 0.1, m = 3.0;
  const UnilateralRun run = run_unilaterals(heavier_crate(1.0), "dopri5", 1e-2, 1.0, true);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  // Its corner sticks on landing, slips from its cone's edge, and the crate settles by 0.35 s
  // (19 events, 13 of them impacts).
  ASSERT_GE(events.size(), 2u);
  EXPECT_EQ(events[1].contact, "crate_corner2_floor");
  EXPECT_EQ(events[1].kind, StopEventKind::slip);
  EXPECT_NEAR(events[1].time, 0.2402252588, 1e-9);
  EXPECT_LT(events.size(), 100u);
  for (const StopEvent& e : events) {
    EXPECT_LT(e.time, 0.35) << e.contact;
  }
  expect_no_energy_made(run);
  expect_at_rest_on_its_face(run, "joint0", "crate", c, m, 1.0);
}

// The law the slip above starts by, checked at one instant by whole evaluations: the crate as it
// was when its corner's friction reached the cone's edge (t = 0.2402 s above), on a floor of
// μ = 0.9, so that sticking there needs 1.1 times what the cone holds. The direction the slip
// takes is one where its acceleration, found with the friction against it, is along it and away
// from rest (λ > 0), and a slip turned 1 mrad from it turns back.
TEST(MjcfContacts, ASlipStartsWhereItsAccelerationIsAlongIt) {
  const model::Model crate = heavier_crate(0.9);
  system::MultibodySystem system(crate);
  int k = -1;
  Vec3 corner = Vec3::Zero();  // in the crate
  for (std::size_t i = 0; i < crate.constraints().size(); ++i) {
    const auto* c = std::get_if<model::Contact>(&crate.constraints()[i]);
    if (c != nullptr && c->name == "crate_corner2_floor") {
      k = static_cast<int>(i);
      corner = c->frame.X_BF.p;
    }
  }
  ASSERT_GE(k, 0);
  const double t = 0.24022525879447776;
  VecX q(7), v(6), vdot(6);
  q << -0.029717163794790946, 0.013594090022746969, 0.16922619066754566, 0.9820966743303651,
      0.15693788529957006, 0.08083070537779373, 0.06574967296545756;
  v << -2.9730415568391604, -3.693541398759955, 1.1001925590506056, -0.743332002650041,
      0.3428092570541837, -1.0123756970176645;
  // What sticking needs there: the tangent rows' forces along the floor's x and y.
  system.hold_contact(k, q, system::ContactHold::sticking);
  system.acceleration(t, q, v, vdot);
  const int first = system.constraints()->rows().first_row[static_cast<std::size_t>(k)];
  const VecX& lambda = system.constraints()->multipliers();
  const Vec2 needed(lambda[first + 1], lambda[first + 2]);
  ASSERT_GT(needed.norm(), 1.05 * 0.9 * lambda[first]);
  // The slip's acceleration with the friction against unit direction d alone (end_slip_start:
  // against its reference, the slip being round-off), from the crate's: the corner's
  // a = a_O + R (ω̇ × r + ω × (ω × r)), ω and ω̇ in the crate, a_O in the world.
  const Mat3 R = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized().toRotationMatrix();
  const Vec3 w = v.head<3>();
  const auto slip_acceleration = [&](const Vec2& d) {
    system.hold_contact(k, q, system::ContactHold::sliding, Vec3(d.x(), d.y(), 0.0));
    system.end_slip_start(k);
    system.acceleration(t, q, v, vdot);
    const Vec3 a =
        vdot.tail<3>() + R * (Vec3(vdot.head<3>()).cross(corner) + w.cross(w.cross(corner)));
    EXPECT_NEAR(a.z(), 0.0, 1e-12) << "the corner leaves the floor";
    return Vec2(a.head<2>());
  };
  const auto across = [](const Vec2& d, const Vec2& a) { return d.x() * a.y() - d.y() * a.x(); };
  const auto turned = [](const Vec2& d, double angle) {
    return Vec2(std::cos(angle) * d.x() - std::sin(angle) * d.y(),
                std::sin(angle) * d.x() + std::cos(angle) * d.y());
  };
  // The way it slides, started against the friction sticking needed.
  system.hold_contact(k, q, system::ContactHold::sliding, Vec3(-needed.x(), -needed.y(), 0.0));
  system.acceleration(t, q, v, vdot);
  const Vec2 taken = -system.contact_friction(k).head<2>().normalized();
  // Its workspace made by that first evaluation, the starting slip's evaluation (two solves per
  // tangent and the search of the plane's directions) allocates nothing, and takes the same way;
  // nor does a sliding evaluation once the slip has started (one solve per sliding contact). Both
  // once allocated a byte: the normal forces solved in place over those without friction.
  long before = test::allocation_count();
  system.acceleration(t, q, v, vdot);
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_EQ(-system.contact_friction(k).head<2>().normalized(), taken);
  system.end_slip_start(k);
  before = test::allocation_count();
  system.acceleration(t, q, v, vdot);
  EXPECT_EQ(test::allocation_count() - before, 0);
  // Along it, to the round-off of accelerations of up to 10 m/s² summed (1e-15 of them a hundred
  // times over; measured 1e-15), and away from rest (measured λ = 0.0899 m/s²).
  const Vec2 a = slip_acceleration(taken);
  EXPECT_NEAR(across(taken, a), 0.0, 1e-12);
  EXPECT_GT(a.dot(taken), 0.05);
  // Stable: turned 1 mrad either way, the slip's acceleration turns it back (measured ±4.4e-3).
  EXPECT_LT(across(turned(taken, 1e-3), slip_acceleration(turned(taken, 1e-3))), -1e-3);
  EXPECT_GT(across(turned(taken, -1e-3), slip_acceleration(turned(taken, -1e-3))), 1e-3);
  // Not the way the friction sticking needed pointed (0.33° from it): a slip started there
  // accelerates across itself at 27 % of its rate along (0.025 m/s² of 0.093), turning without
  // bound as it leaves rest.
  const Vec2 naive = -needed.normalized();
  const Vec2 a_naive = slip_acceleration(naive);
  EXPECT_GT(std::abs(across(naive, a_naive)), 0.2 * a_naive.dot(naive));
}

// The seven-axis arm (tests/data/models/mjcf/arm7.xml) with its contacts on, run as
// `momenta simulate` runs it (the file's rk4 at 1 ms): it falls onto the floor from its
// keyframe-less start, its links' capsule ends and its wrist's rim striking, sliding and sticking
// with MuJoCo's μ = 1 (its joints damped, its motors idle). At 1.3321 s the fifth link's end
// reaches its cone's edge with μs = μk: its slip starts with no acceleration along it, round-off
// of either sign, and was once counted as stopped at once and stuck again, 64 times at one
// instant (the run stopped). At 2.0331 s the same end strikes while two other ends slide, and one
// of those pulls in the impact: taken with its friction against its slip, that share made
// 6.6e-8 J before it could be let go, and the run stopped there. It runs past both now, to
// 2.13 s (at 2.138 s a point rk4 tries inside a step, a wrist rim sliding on past where its slip
// stops, has no single normal force — Painlevé's paradox, docs/contacts.md — and the rk4 run stops
// there with that error; dopri5 and bdf retry shorter steps there and go on).
model::Model arm_with_contacts() {
  std::ifstream file(test::source_dir() + "/tests/data/models/mjcf/arm7.xml");
  std::stringstream text;
  text << file.rdbuf();
  std::string xml = text.str();
  const std::string off = R"(<flag contact="disable"/>)";
  EXPECT_NE(xml.find(off), std::string::npos);
  if (xml.find(off) != std::string::npos) xml.erase(xml.find(off), off.size());
  return io::parse_mjcf(xml, "arm7.xml").model;
}

TEST(MjcfContacts, TheArmRunsOnPastASlipFromItsConesEdgeAndAnImpactWhereASlidingEndPulls) {
  const model::Model arm = arm_with_contacts();
  const UnilateralRun run = run_unilaterals(arm, "rk4", 1e-3, 2.13);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  EXPECT_EQ(run.table.rows.back()[0], 2.13);
  const auto acts_at = [&](StopEventKind kind, double t) {
    return std::any_of(events.begin(), events.end(), [&](const StopEvent& e) {
      return e.contact == "link5_geom0_end2_floor" && e.kind == kind && std::abs(e.time - t) < 1e-4;
    });
  };
  EXPECT_TRUE(acts_at(StopEventKind::slip, 1.3321));
  EXPECT_TRUE(acts_at(StopEventKind::impact, 2.0331) || acts_at(StopEventKind::rest, 2.0331));
  // Each impact takes energy or none, to the guard's round-off (1e-12 J at under 1 J).
  for (const StopEvent& e : events) EXPECT_GE(e.energy_lost, -1e-12) << e.contact << " " << e.time;
  EXPECT_LT(events.size(), 2000u);
  expect_no_energy_made(run);
}

// The arm under bdf with steps of up to 6 ms (`momenta simulate … --integrator bdf --duration 6`
// takes duration/1000) at its default tolerances (rtol 1e-8, atol 1e-10). From 2.2005 s its
// fifth link's end and its wrist's rim rock on the floor: each one strikes and rests (plastic),
// and its impact lifts the other at a fraction of its speed (2e-4, 1.5e-4, 8.6e-5, 6.5e-5 m/s …),
// 40 to 220 µs apart. Among those, a step of CVODE's after an impact failed its error test 7 times
// in a row (CVODE's default limit) and the run stopped at 2.2017 s; bdf allows 20
// (implicit_test.cpp's jump in the acceleration) and runs on.
TEST(MjcfContacts, TheArmUnderBdfsLongStepsCrossesItsRocking) {
  const model::Model arm = arm_with_contacts();
  const UnilateralRun run = run_unilaterals(arm, "bdf", 0.006, 2.4, false, {1e-8, 1e-10});
  EXPECT_EQ(run.table.rows.back()[0], 2.4);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  const auto strikes = [&](const std::string& contact) {
    return std::count_if(events.begin(), events.end(), [&](const StopEvent& e) {
      return e.contact == contact && e.kind == StopEventKind::rest && e.time > 2.2005 &&
             e.time < 2.2013;
    });
  };
  EXPECT_GE(strikes("link5_geom0_end2_floor"), 2);
  EXPECT_GE(strikes("link7_geom0_rim2_floor"), 2);
  for (const StopEvent& e : events) EXPECT_GE(e.energy_lost, -1e-12) << e.contact << " " << e.time;
  expect_no_energy_made(run);
}

}  // namespace
}  // namespace mjcf_contacts
}  // namespace momenta::simulate
