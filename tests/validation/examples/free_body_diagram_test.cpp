// Free-body and kinetic diagrams (analysis/free_body.hpp) of the bundled examples:
//  - every body of every example balances, ΣF = m a_G and ΣM_G = Ḣ_G, at the start and along a
//    run, with a_G and α from the forward dynamics and the loads taken one by one;
//  - each joint's loads on its child sum to the reaction `momenta simulate --reactions` records
//    (the same row's state), and on its parent to the opposite;
//  - closed forms: the pendulum's rod tension m g cos θ + m L θ̇², the bent rod's weld couple
//    (m L²/12) ω² sin β cos β, a spring's and a loop closure's forces equal and opposite on
//    their two bodies, a prescribed joint's drive equal to its effort, a contact's normal force
//    and its friction (sliding and sticking) at its point.

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "example_simulation.hpp"
#include "momenta/analysis/free_body.hpp"
#include "momenta/common/error.hpp"
#include "momenta/simulate/simulation.hpp"
#include "momenta/simulate/state_at.hpp"
#include "momenta/simulate/unilaterals.hpp"

namespace momenta {
namespace {

using analysis::FreeBodyDiagram;
using analysis::Load;
using analysis::LoadKind;

// The diagram's largest force and moment about G (N, N·m): what round-off is measured against.
struct Scale {
  double force = 0.0, moment = 0.0;
};

Scale scale_of(const FreeBodyDiagram& d) {
  Scale s{d.m_a_G().norm(), std::max(d.I_alpha().norm(), d.w_cross_H().norm())};
  for (const Load& load : d.loads) {
    s.force = std::max(s.force, load.force_W.norm());
    s.moment =
        std::max(s.moment, ((load.p_WoP_W - d.p_WoG_W).cross(load.force_W) + load.couple_W).norm());
  }
  return s;
}

// The loads of one joint summed: the force and the moment about the point O.
struct Wrench {
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
};

Wrench joint_loads(const FreeBodyDiagram& d, int joint, const Vec3& O) {
  Wrench w;
  for (const Load& load : d.loads) {
    if (load.joint_index != joint) continue;
    w.force += load.force_W;
    w.moment += (load.p_WoP_W - O).cross(load.force_W) + load.couple_W;
  }
  return w;
}

const Load& load_named(const FreeBodyDiagram& d, const std::string& name) {
  for (const Load& load : d.loads)
    if (load.name == name) return load;
  throw std::runtime_error("no load named " + name + " on " + d.body);
}

// A recorded run of an example with every joint's reaction, as `simulate --reactions` makes it.
simulate::TableSink recorded_run(const io::ModelFile& file, double duration, double step) {
  simulate::SimulationOptions options;
  options.duration = duration;
  options.step = step;
  options.integrator = "rk4";
  options.reactions = true;
  simulate::Simulation simulation(file.model, {}, options);
  simulate::TableSink table;
  simulation.run(table);
  return table;
}

// Row r's state: time, then q and v, the table's leading columns.
integrate::State row_state(const model::Model& m, const simulate::TableSink& table, std::size_t r) {
  const std::vector<double>& row = table.rows.at(r);
  integrate::State s{row[0], VecX(m.nq()), VecX(m.nv())};
  for (int i = 0; i < m.nq(); ++i) s.q[i] = row[static_cast<std::size_t>(1 + i)];
  for (int i = 0; i < m.nv(); ++i) s.v[i] = row[static_cast<std::size_t>(1 + m.nq() + i)];
  return s;
}

Vec3 columns(const simulate::TableSink& table, std::size_t r, const std::string& prefix) {
  const auto& row = table.rows.at(r);
  return {row[static_cast<std::size_t>(table.column(prefix + "x"))],
          row[static_cast<std::size_t>(table.column(prefix + "y"))],
          row[static_cast<std::size_t>(table.column(prefix + "z"))]};
}

// Every body's balance at the row's state, and every joint's loads against the recorded
// reaction. Round-off: each residual is a sum of a few products of the loads and kinetic terms
// (rotations, cross products, the RNEA recursion over at most a few bodies), 1e-12 of the
// largest is a hundred times the ~1e-14 the examples show and catches any missing or mis-signed
// term (those are of the order of the loads themselves).
void expect_every_body_balances(const io::ModelFile& file, const simulate::TableSink& table,
                                std::size_t r) {
  const model::Model& m = file.model;
  const integrate::State s = row_state(m, table, r);
  system::MultibodySystem system(m);
  for (int b = 1; b < m.num_bodies(); ++b) {
    const FreeBodyDiagram d = analysis::free_body_diagram(system, m.body(b).name, s.t, s.q, s.v);
    const Scale scale = scale_of(d);
    SCOPED_TRACE(file.name + ", body " + d.body + ", t = " + std::to_string(s.t));
    EXPECT_LE(d.force_residual().norm(), 1e-12 * scale.force) << d.force_residual().transpose();
    EXPECT_LE(d.moment_residual().norm(), 1e-12 * std::max(scale.moment, scale.force * 1e-3))
        << d.moment_residual().transpose();
    // The joint carrying b: its loads are the wrench it transmits (about J'o, in W).
    const int j = m.body(b).joint_index;
    const std::string& name = m.joint(j).name;
    const Vec3 F = columns(table, r, name + ".reaction.F");
    const Vec3 M = columns(table, r, name + ".reaction.M");
    const auto& c = m.joint_constants()[static_cast<std::size_t>(j)];
    const Vec3 J = (system.data().X_WB[b] * c.X_JC.inverse()).p;
    // The state is recomputed from the same double row: the same arithmetic, round-off only.
    const double tol = 1e-12 * std::max({F.norm(), M.norm(), scale.force, 1.0});
    const Wrench w = joint_loads(d, j, J);
    EXPECT_LE((w.force - F).norm(), tol) << w.force.transpose() << " vs " << F.transpose();
    EXPECT_LE((w.moment - M).norm(), tol) << w.moment.transpose() << " vs " << M.transpose();
    // The joints b carries: the opposite of what they transmit to their children.
    for (const model::Joint& child : m.joints()) {
      if (child.parent_index != b) continue;
      const auto& cc = m.joint_constants()[static_cast<std::size_t>(child.index)];
      const Vec3 Jc = (system.data().X_WB[child.child_index] * cc.X_JC.inverse()).p;
      const Wrench wc = joint_loads(d, child.index, Jc);
      EXPECT_LE((wc.force + columns(table, r, child.name + ".reaction.F")).norm(), tol);
      EXPECT_LE((wc.moment + columns(table, r, child.name + ".reaction.M")).norm(), tol);
    }
  }
}

class EveryExample : public ::testing::TestWithParam<const char*> {};

TEST_P(EveryExample, EveryBodyBalancesAndItsJointLoadsAreTheRecordedReactions) {
  const io::ModelFile file = io::read_model_file(GetParam());
  const simulate::TableSink table = recorded_run(file, 0.05, 1e-3);
  ASSERT_GE(table.rows.size(), 51U);
  for (const std::size_t r : {std::size_t{0}, std::size_t{25}, table.rows.size() - 1})
    expect_every_body_balances(file, table, r);
}

INSTANTIATE_TEST_SUITE_P(
    Diagrams, EveryExample,
    ::testing::Values(
        "examples/pendulum.yaml", "examples/compound_pendulum.yaml",
        "examples/double_pendulum.yaml", "examples/heavy_top.yaml", "examples/sleeping_top.yaml",
        "examples/gyroscope.yaml", "examples/rotating_shaft_bent_rod.yaml",
        "examples/unbalanced_rotor.yaml", "examples/rotor_on_bearings.yaml",
        "examples/quarter_car.yaml", "examples/cruise_control.yaml",
        "examples/satellite_attitude.yaml", "examples/flexible_satellite.yaml",
        "examples/free_body_tennis_racket.yaml", "examples/kinematics/turntable_bead.yaml",
        "examples/constraints/four_bar.yaml", "examples/constraints/slider_crank.yaml",
        "examples/constraints/rolling_coin.yaml", "examples/constraints/chaplygin_sleigh.yaml",
        "examples/constraints/geared_pair.yaml", "examples/constraints/parallelogram_swing.yaml",
        "examples/constraints/rod_on_rotating_shaft.yaml",
        "examples/constraints/rolling_disk_on_axle.yaml"));

TEST(FreeBodyDiagram, PendulumRodTensionIsMgCosThetaPlusMLThetaDotSquared) {
  // examples/pendulum.yaml: a 1 kg point bob on a 1 m massless rod, θ from the downward
  // vertical. The pin pulls the bob toward it with T = m g cos θ + m L θ̇²; nothing else acts
  // but the weight, and the diagram is planar in the x–z plane.
  const io::ModelFile file = test::load_example("pendulum");
  const model::Model& m = file.model;
  system::MultibodySystem system(m);
  const double g = 9.81, L = 1.0, mass = 1.0;
  for (const auto& [theta, theta_dot] : {std::pair{2.0, 0.0}, {0.7, -2.5}, {-1.2, 3.1}}) {
    VecX q(1), v(1);
    q << theta;
    v << theta_dot;
    const FreeBodyDiagram d = analysis::free_body_diagram(system, "bob", 0.0, q, v);
    ASSERT_EQ(d.loads.size(), 2U);
    ASSERT_TRUE(d.plane_normal.has_value());
    EXPECT_NEAR(std::abs(d.plane_normal->y()), 1.0, 1e-15);
    const Load& pin = load_named(d, "pivot");
    EXPECT_EQ(pin.kind, LoadKind::reaction);
    const double T = mass * g * std::cos(theta) + mass * L * theta_dot * theta_dot;
    // Toward the pivot (the origin) from the bob.
    const Vec3 expected = T * (-d.p_WoG_W / L);
    EXPECT_LE((pin.force_W - expected).norm(), 1e-13 * (g + L * theta_dot * theta_dot));
    EXPECT_LE(pin.couple_W.norm(), 1e-13);
    const Load& weight = load_named(d, "gravity");
    EXPECT_EQ(weight.kind, LoadKind::gravity);
    EXPECT_LE((weight.force_W - Vec3(0, 0, -mass * g)).norm(), 1e-15);
    EXPECT_LE((weight.p_WoP_W - d.p_WoG_W).norm(), 1e-15);
  }
}

TEST(FreeBodyDiagram, BentRodWeldCoupleIsTheProductOfInertiaTimesOmegaSquared) {
  // examples/rotating_shaft_bent_rod.yaml: the rod (m = 2 kg, L = 0.6 m) welded at β = 30° to a
  // shaft turning at ω = 20 rad/s. G is on the axis, so the weld carries the weight and a couple
  // (m L²/12) ω² sin β cos β = 10.3923 N·m that turns with the shaft — on the kinetic side
  // ω × H_G, with α = 0 and a_G = 0. The shaft feels the opposite couple.
  const io::ModelFile file = test::load_example("rotating_shaft_bent_rod");
  system::MultibodySystem system(file.model);
  const double m = 2.0, L = 0.6, w = 20.0, beta = std::numbers::pi / 6;
  const double couple = m * L * L / 12.0 * w * w * std::sin(beta) * std::cos(beta);
  for (const double t : {0.0, 0.0371, 0.25}) {
    const integrate::State s = simulate::state_at(file.model, t, {});
    const FreeBodyDiagram rod = analysis::free_body_diagram(system, "rod", s.t, s.q, s.v);
    const Load& weld = load_named(rod, "weld");
    EXPECT_NEAR(weld.couple_W.norm(), couple, 1e-12 * couple);
    EXPECT_NEAR(weld.couple_W.z(), 0.0, 1e-12 * couple);  // horizontal: it turns with the shaft
    EXPECT_LE((weld.force_W - Vec3(0, 0, m * 9.81)).norm(), 1e-12 * m * 9.81);
    EXPECT_LE(rod.m_a_G().norm(), 1e-12);
    EXPECT_LE(rod.I_alpha().norm(), 1e-12);
    EXPECT_LE((rod.w_cross_H() - weld.couple_W).norm(), 1e-12 * couple);
    ASSERT_TRUE(rod.plane_normal.has_value());  // vertical forces, a horizontal couple
    const FreeBodyDiagram shaft = analysis::free_body_diagram(system, "shaft", s.t, s.q, s.v);
    EXPECT_LE((load_named(shaft, "weld").couple_W + weld.couple_W).norm(), 1e-12 * couple);
    // The bearing carries the whole weight, 3 kg, and the couple.
    const Load& bearing = load_named(shaft, "bearing");
    EXPECT_LE((bearing.force_W - Vec3(0, 0, 3.0 * 9.81)).norm(), 1e-12 * 30.0);
    EXPECT_NEAR(bearing.couple_W.norm(), couple, 1e-12 * couple);
  }
}

TEST(FreeBodyDiagram, HeavyTopIsThreeDimensionalAndTheTipCarriesEverything) {
  // examples/heavy_top.yaml in steady precession: the tip's force is m (a_G − g), its couple
  // zero (a ball joint transmits no moment), and the diagram is not planar.
  const io::ModelFile file = test::load_example("heavy_top");
  system::MultibodySystem system(file.model);
  const integrate::State s = simulate::state_at(file.model, 0.3, {});
  const FreeBodyDiagram d = analysis::free_body_diagram(system, "top", s.t, s.q, s.v);
  EXPECT_FALSE(d.plane_normal.has_value());
  ASSERT_EQ(d.loads.size(), 2U);  // the weight and the tip's reaction: no moment along the motion
  const Load& tip = load_named(d, "tip");
  EXPECT_LE((tip.force_W - d.mass * (d.a_WG_W - file.model.gravity())).norm(), 1e-12 * 9.81);
  EXPECT_LE(tip.couple_W.norm(), 1e-13);
  EXPECT_LE(tip.p_WoP_W.norm(), 1e-15);  // at the apex
}

TEST(FreeBodyDiagram, ASpringAndALoopClosurePushTheirTwoBodiesEquallyAndOppositely) {
  // Newton's third law across two diagrams: the quarter car's suspension on the body and on the
  // wheel, and the four-bar's closing hinge on the coupler and on the rocker.
  for (const auto& [example, element, a, b] :
       {std::tuple{"quarter_car", "suspension", "body", "wheel"},
        std::tuple{"constraints/four_bar", "closure", "rocker", "coupler"}}) {
    const io::ModelFile file = test::load_example(example);
    system::MultibodySystem system(file.model);
    const integrate::State s = simulate::state_at(file.model, 0.37, {});
    const FreeBodyDiagram da = analysis::free_body_diagram(system, a, s.t, s.q, s.v);
    const FreeBodyDiagram db = analysis::free_body_diagram(system, b, s.t, s.q, s.v);
    const Load& on_a = load_named(da, element);
    const Load& on_b = load_named(db, element);
    SCOPED_TRACE(example);
    EXPECT_GT(on_a.force_W.norm(), 1e-3);
    EXPECT_LE((on_a.force_W + on_b.force_W).norm(), 1e-12 * on_a.force_W.norm());
    // Equal moments about any one point: the same line of action.
    const Vec3 O = da.p_WoG_W;
    const Vec3 m_a = (on_a.p_WoP_W - O).cross(on_a.force_W) + on_a.couple_W;
    const Vec3 m_b = (on_b.p_WoP_W - O).cross(on_b.force_W) + on_b.couple_W;
    EXPECT_LE((m_a + m_b).norm(), 1e-12 * std::max(m_a.norm(), on_a.force_W.norm()));
  }
}

TEST(FreeBodyDiagram, APrescribedJointsDriveIsItsEffort) {
  // The turntable of examples/kinematics/turntable_bead.yaml is prescribed: the couple its drive
  // puts on it is the generalized force the motion needs less the elements' (the `effort`
  // output), about the joint's axis.
  const io::ModelFile file = test::load_example("kinematics/turntable_bead");
  const model::Model& m = file.model;
  system::MultibodySystem system(m);
  const integrate::State s = simulate::state_at(m, 0.8, {});
  const FreeBodyDiagram d = analysis::free_body_diagram(system, "turntable", s.t, s.q, s.v);
  const int j = m.joint_index("spin");
  system.evaluate(s.t, s.q, s.v);
  const double effort =
      system.data().tau[m.joint(j).v_index] - system.element_forces()[m.joint(j).v_index];
  int drives = 0;
  for (const Load& load : d.loads) {
    if (load.kind != LoadKind::drive) continue;
    ++drives;
    EXPECT_EQ(load.joint_index, j);
    EXPECT_NEAR(load.couple_W.z(), effort, 1e-12 * std::abs(effort));
    EXPECT_LE(load.force_W.norm(), 1e-12 * std::abs(effort));
  }
  EXPECT_EQ(drives, 1);
  EXPECT_GT(std::abs(effort), 1e-3);
}

// A body on a contact: the contact holds as a run starting there holds it
// (simulate::hold_what_touches), and its force — normal force and friction — is one load at the
// contact point. The bowling ball set down skidding (examples/skidding_ball.yaml, m = 7 kg,
// μk = 0.1): N = m g up and μk m g against the slip, m a_G = −μk m g x̂; once it rolls (state
// set to v = r ω), N = m g and no friction. The crate thrown up the 30° ramp
// (examples/block_on_incline.yaml, m = 2 kg, μk = 0.5): N = m g cos θ along the ramp's normal
// and μk N down the ramp; set at rest there (tan θ < μs = 0.7) it sticks, the ramp holding up
// its weight: m g sin θ up the ramp, the whole force m g straight up. To 1e-12 of the weight.
TEST(FreeBodyDiagram, AContactsForceIsItsNormalForceAndItsFrictionAtItsPoint) {
  const auto diagram = [](const model::Model& m, const std::string& body, integrate::State s) {
    system::MultibodySystem system(m);
    simulate::hold_what_touches(system, s);
    return analysis::free_body_diagram(system, body, s.t, s.q, s.v);
  };
  const double g = 9.81;
  const model::Model ball = io::read_model_file("examples/skidding_ball.yaml").model;
  integrate::State s{0.0, ball.initial_q(), ball.initial_v()};
  const double m = 7.0, r = 0.11, weight = m * g;
  FreeBodyDiagram d = diagram(ball, "ball", s);
  ASSERT_EQ(d.loads.size(), 3U);  // the weight, the lane's force, the free joint's (none)
  EXPECT_EQ(load_named(d, "free").force_W, Vec3::Zero());
  const Load& lane = load_named(d, "lane");
  EXPECT_EQ(lane.kind, LoadKind::reaction);
  EXPECT_NE(lane.description.find("sliding"), std::string::npos) << lane.description;
  EXPECT_LE((lane.force_W - Vec3(-0.1 * weight, 0, weight)).norm(), 1e-12 * weight);
  EXPECT_LE(lane.p_WoP_W.norm(), 1e-15);
  EXPECT_LE(lane.couple_W.norm(), 1e-12 * weight * r);
  EXPECT_LE((d.m_a_G() - Vec3(-0.1 * weight, 0, 0)).norm(), 1e-12 * weight);
  EXPECT_LE(d.force_residual().norm(), 1e-12 * weight);
  EXPECT_LE(d.moment_residual().norm(), 1e-12 * weight * r);
  s.v[1] = 6.0 / r;  // ω_y: rolling
  d = diagram(ball, "ball", s);
  EXPECT_NE(load_named(d, "lane").description.find("sticking"), std::string::npos);
  EXPECT_LE((load_named(d, "lane").force_W - Vec3(0, 0, weight)).norm(), 1e-12 * weight);

  const model::Model crate = io::read_model_file("examples/block_on_incline.yaml").model;
  const double mc = 2.0, theta = std::numbers::pi / 6, N = mc * g * std::cos(theta);
  const Vec3 n(-std::sin(theta), 0, std::cos(theta)), up(std::cos(theta), 0, std::sin(theta));
  integrate::State c{0.0, crate.initial_q(), crate.initial_v()};
  const Load thrown = load_named(diagram(crate, "crate", c), "ramp");
  EXPECT_LE((thrown.force_W - (N * n - 0.5 * N * up)).norm(), 1e-12 * mc * g);
  c.v.setZero();
  const FreeBodyDiagram at_rest = diagram(crate, "crate", c);
  const Load& held = load_named(at_rest, "ramp");
  EXPECT_LE((held.force_W - Vec3(0, 0, mc * g)).norm(), 1e-12 * mc * g);
  EXPECT_NEAR(held.force_W.dot(up), mc * g * std::sin(theta), 1e-12 * mc * g);
  EXPECT_LE(at_rest.force_residual().norm(), 1e-12 * mc * g);
}

TEST(FreeBodyDiagram, AnUnknownBodyOrTheWorldIsRefusedWithTheReason) {
  const io::ModelFile file = test::load_example("double_pendulum");
  system::MultibodySystem system(file.model);
  const VecX q = file.model.initial_q(), v = file.model.initial_v();
  try {
    analysis::free_body_diagram(system, "mas1", 0.0, q, v);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean"), std::string::npos) << e.what();
  }
  try {
    analysis::free_body_diagram(system, "world", 0.0, q, v);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("world"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace momenta
