// dynamics::impulsive_motion against the impulse–momentum principle's closed forms (Beer &
// Johnston ch. 17): a rod struck about its pin — its rate P d / I_O, the pin's impulse, zero at
// the centre of percussion d = 2L/3 — with a rotor's armature and on a carriage whose drive holds
// its speed; a sphere striking the pinned rod with restitution e (eccentric impact); a free body's
// momentum jumps by P and its angular momentum about G by r × P; on the constrained classics, the
// speeds after equal those of an independent null-space form and keep the loops closed; Kelvin's
// theorem (ΔT = Σ ½ P·(v⁻ + v⁺)) on random trees of every joint type.

#include "momenta/dynamics/impulse.hpp"

#include <random>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <Eigen/LU>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/constraints.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/momentum.hpp"
#include "momenta/dynamics/point_kinematics.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/multibody_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics::impulse_test {
namespace {

using model::Joint;
using model::JointType;

// A uniform rod of mass m and length L hanging from a pin about y at the world origin (or at a
// carriage on a rail along x, prescribed to move at constant speed); its centre L/2 below.
struct Rod {
  double m = 2.0, L = 1.2, armature = 0.0;
  bool on_carriage = false;
  double I_O() const { return m * L * L / 3.0 + armature; }
  Model build() const {
    model::ModelBuilder b;
    std::string parent = "world";
    if (on_carriage) {
      b.add_signal(model::Signal("rail", model::RampSignal{.slope = 0.5, .offset = 0.0}));
      b.add_body("carriage", inertia::MassProperties(5.0, Vec3::Zero(), 0.1 * Mat3::Identity()));
      Joint rail =
          test::make_joint("rail", JointType::prismatic, "world", "carriage", Vec3::UnitX());
      rail.prescribed_signals = {"rail"};
      b.add_joint(rail);
      parent = "carriage";
    }
    const Mat3 I_G = Vec3(m * L * L / 12.0, m * L * L / 12.0, 1e-6).asDiagonal();
    b.add_body("rod", inertia::MassProperties(m, Vec3(0, 0, -L / 2), I_G));
    Joint pin = test::make_joint("pin", JointType::revolute, parent, "rod", Vec3::UnitY());
    pin.armature = armature;
    b.add_joint(pin);
    return b.build();
  }
};

// Struck at rest at depth d by P along x: the point moves at (−θ̇ d, 0, 0), so θ̇ = −P d / I_O;
// the rod's momentum m v̄ = P + R gives the pin's impulse R = P (m d L / (2 I_O) − 1).
TEST(ImpulsiveMotion, ARodStruckAboutItsPinAsTheTextbookHasIt) {
  for (const Rod rod : {Rod{}, Rod{.armature = 0.15}, Rod{.on_carriage = true}}) {
    const Model model = rod.build();
    const int pin = model.joint_index("pin");
    const int rate = model.joint(pin).v_index;
    for (const double d : {0.3 * rod.L, 2.0 * rod.L / 3.0, rod.L}) {
      SCOPED_TRACE(testing::Message() << "armature " << rod.armature << ", carriage "
                                      << rod.on_carriage << ", d = " << d);
      const double P = 4.0;
      VecX q = VecX::Zero(model.nq()), v = VecX::Zero(model.nv());
      if (rod.on_carriage) v[0] = 0.5;  // the carriage's prescribed speed
      const PointImpulse hit{model.body_index("rod"), Vec3(0, 0, -d), Vec3(P, 0, 0)};
      const ImpulsiveMotion r = impulsive_motion(model, q, v, std::span(&hit, 1));
      // A few products of O(1) numbers: round-off ~1e-15.
      EXPECT_NEAR(r.v_after[rate], -P * d / rod.I_O(), 1e-14);
      const double R = P * (rod.m * d * rod.L / (2.0 * rod.I_O()) - 1.0);
      const JointReaction& J = r.joint_impulses[static_cast<std::size_t>(pin)];
      EXPECT_NEAR(J.force.x(), R, 1e-14);
      EXPECT_NEAR(J.force.z(), 0.0, 1e-14);
      if (rod.armature == 0.0 && d == 2.0 * rod.L / 3.0) {
        EXPECT_NEAR(R, 0.0, 1e-15);
      }
      // The pin turns freely: the only impulsive moment about its axis is the one that spins
      // the rotor up, −I_a θ̇ on the rod (none without armature).
      EXPECT_NEAR(J.moment.y(), -rod.armature * r.v_after[rate], 1e-14);
      // ΔT = ½ I_O θ̇² (+ m v_c · (−θ̇ L/2), the rod's new swing against the carriage's speed
      // v_c) = Kelvin's ½ P·(v_P⁻ + v_P⁺) (+ the drive impulse's work R v_c).
      const double v_c = rod.on_carriage ? 0.5 : 0.0;
      EXPECT_NEAR(r.kinetic_after - r.kinetic_before,
                  P * P * d * d / (2.0 * rod.I_O()) + rod.m * v_c * P * d * rod.L / (2 * rod.I_O()),
                  1e-14);
      EXPECT_NEAR(r.impulse_work, r.kinetic_after - r.kinetic_before, 1e-14);
      if (rod.on_carriage) {
        // The carriage keeps its speed; its drive gives the impulse the pin passes down to it.
        EXPECT_EQ(r.v_after[0], 0.5);
        EXPECT_NEAR(r.drive_impulses[0], R, 1e-14);
      }
    }
  }
}

// A free body (turned, its centre of mass off its origin) struck off its centre: ΔL = P and
// ΔH_G = (p_P − p_G) × P, the impulse–momentum principle for a rigid body.
TEST(ImpulsiveMotion, AFreeBodysMomentaJumpByTheImpulseAndItsMoment) {
  model::ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -9.81));
  b.add_body("box",
             inertia::MassProperties(2.0, Vec3(0.1, -0.05, 0.2), Vec3(0.1, 0.2, 0.3).asDiagonal()));
  b.add_joint(test::make_joint("float", JointType::free, "world", "box"));
  const Model model = b.build();
  std::mt19937 rng(3);
  const VecX q = test::random_configuration(model, rng);
  const VecX v = test::random_vector(model.nv(), rng);
  const PointImpulse hit{1, Vec3(0.3, 0.2, -0.1), Vec3(1.5, -0.7, 2.2)};
  const ImpulsiveMotion r = impulsive_motion(model, q, v, std::span(&hit, 1));
  Data data(model);
  const Momentum before = momentum(model, data, q, v);
  const Momentum after = momentum(model, data, q, r.v_after);
  forward_kinematics(model, data, q);
  const Vec3 p_P = data.X_WB[1].apply(hit.p_BoP_B);
  EXPECT_MATRIX_NEAR(after.linear - before.linear, hit.impulse_W, 1e-14);
  EXPECT_MATRIX_NEAR(after.angular_about_com - before.angular_about_com,
                     (p_P - before.p_WoScm_W).cross(hit.impulse_W), 1e-14);
  EXPECT_TRUE(r.joint_impulses[0].force.isZero(1e-14));  // a free joint carries nothing
  EXPECT_NEAR(r.impulse_work, r.kinetic_after - r.kinetic_before, 1e-13);
}

// The constrained classics at their consistent initial state, struck at a body's point: the
// speeds after satisfy G v⁺ = 0 and equal the null-space form v⁺ = N (Nᵀ M N)⁻¹ Nᵀ (M v⁻ + J_Pᵀ P),
// N spanning G's null space (the four-bar's driven crank held) — a second algorithm, in
// independent coordinates. Redundant rows are counted as the constraint solver counts them;
// Kelvin's theorem holds.
TEST(ImpulsiveMotion, ConstrainedMechanismsAgreeWithTheNullSpaceForm) {
  for (const char* name : {"slider_crank", "four_bar", "parallelogram_swing", "geared_pair"}) {
    SCOPED_TRACE(name);
    const io::ModelFile file =
        io::read_model_file(test::source_dir() + "/examples/constraints/" + name + ".yaml");
    const Model& model = file.model;
    system::MultibodySystem system(model);
    VecX q = model.initial_q(), v = model.initial_v();
    system.make_consistent(0.0, q, v);
    const int body = model.num_bodies() - 1;
    const PointImpulse hit{body, Vec3(0.05, 0.02, -0.1), Vec3(0.8, 0.3, -1.1)};
    const ImpulsiveMotion r = impulsive_motion(model, q, v, std::span(&hit, 1));

    Data data(model);
    const MatX M = crba(model, data, q);
    ConstraintRows rows(model);
    constraint_equations(model, data, q, rows);
    forward_kinematics(model, data, q);
    MatX J = MatX::Zero(6, model.nv());
    frame_jacobian(model, data, body, hit.p_BoP_B, J);
    // A v = b: the rows, and the prescribed coordinates held at their speeds; v = v0 + N y with
    // A v0 = b and N spanning A's null space, y minimizing ½ (v − v⁻)ᵀ M (v − v⁻) − Pᵀ J_P v.
    std::vector<int> held;
    for (const model::Joint& joint : model.joints()) {
      for (int k = 0; joint.is_prescribed() && k < joint.nv(); ++k)
        held.push_back(joint.v_index + k);
    }
    MatX A = MatX::Zero(rows.count + static_cast<int>(held.size()), model.nv());
    VecX b = VecX::Zero(A.rows());
    A.topRows(rows.count) = rows.G;
    for (std::size_t k = 0; k < held.size(); ++k) {
      A(rows.count + static_cast<int>(k), held[k]) = 1.0;
      b[rows.count + static_cast<int>(k)] = v[held[k]];
    }
    const VecX v0 = A.completeOrthogonalDecomposition().solve(b);
    const MatX N = Eigen::FullPivLU<MatX>(A).kernel();
    const VecX rhs = N.transpose() * (M * (v - v0) + J.bottomRows<3>().transpose() * hit.impulse_W);
    const VecX v_after = v0 + N * (N.transpose() * M * N).ldlt().solve(rhs);
    const double scale = std::max(1.0, v_after.cwiseAbs().maxCoeff());
    EXPECT_MATRIX_NEAR(r.v_after, v_after, 1e-12 * scale);
    EXPECT_MATRIX_NEAR(rows.G * r.v_after, VecX::Zero(rows.count), 1e-12 * scale);
    // The planar loops' out-of-plane rows are redundant: as many as the constraint solver finds.
    EXPECT_EQ(r.redundant_rows, static_cast<int>(system.constraints()->redundant_rows().size()));
    EXPECT_NEAR(r.impulse_work, r.kinetic_after - r.kinetic_before,
                1e-12 * std::max(1.0, r.kinetic_after));
  }
}

// Kelvin's theorem on random trees of every joint type, with armature, at random states, two
// impulses at once: ΔT = Σ ½ P·(v_P⁻ + v_P⁺), a scalar identity the solve does not impose.
TEST(ImpulsiveMotion, KelvinsTheoremOnRandomTrees) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE(seed);
    const Model model =
        test::random_tree(8, seed, test::all_joint_types(), Vec3(0, 0, -9.81), 0.05);
    std::mt19937 rng(seed);
    const VecX q = test::random_configuration(model, rng);
    const VecX v = test::random_vector(model.nv(), rng);
    const PointImpulse hits[2] = {{3, Vec3(0.1, -0.2, 0.05), Vec3(2.0, -1.0, 0.5)},
                                  {7, Vec3(-0.1, 0.0, 0.2), Vec3(0.3, 0.9, -1.4)}};
    const ImpulsiveMotion r = impulsive_motion(model, q, v, hits);
    EXPECT_NEAR(r.impulse_work, r.kinetic_after - r.kinetic_before,
                1e-12 * std::max({1.0, r.kinetic_before, r.kinetic_after}));
    EXPECT_GT(std::abs(r.kinetic_after - r.kinetic_before), 1e-3);  // the impulses do work
  }
}

// A stop striking one coordinate of a random tree (every joint type present): the rate after is
// −e times the rate before exactly; the impulse is the closed form −(1 + e) v_i⁻ / (M⁻¹)_ii with
// M⁻¹ from CRBA's dense matrix by LU (not the LDLᵀ of the free block the solve uses); the speeds
// balance M Δv = e_i P; the energy lost is ½ (1 − e²) v_i⁻² / (M⁻¹)_ii; Kelvin's work matches.
TEST(ImpulsiveMotion, AStopStrikesOneCoordinateThroughTheWholeTree) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE(seed);
    const Model model =
        test::random_tree(8, seed, test::all_joint_types(), Vec3(0, 0, -9.81), 0.05);
    std::mt19937 rng(seed);
    const VecX q = test::random_configuration(model, rng);
    const VecX v = test::random_vector(model.nv(), rng);
    Data data(model);
    const MatX M = crba(model, data, q);
    const MatX M_inv = M.fullPivLu().inverse();
    int struck = 0;
    for (const model::Joint& j : model.joints()) {
      if (j.nv() != 1) continue;
      const int i = j.v_index;
      for (const double e : {0.0, 0.6, 1.0}) {
        const StopImpact s = stop_impact(model, q, v, i, e);
        EXPECT_EQ(s.rate_before, v[i]);
        EXPECT_EQ(s.motion.v_after[i], -e * v[i]);
        const double P = -(1.0 + e) * v[i] / M_inv(i, i);
        EXPECT_NEAR(s.impulse, P, 1e-12 * std::max(1.0, std::abs(P)));
        VecX generalized = VecX::Zero(model.nv());
        generalized[i] = s.impulse;
        EXPECT_LT((M * (s.motion.v_after - v) - generalized).norm(),
                  1e-11 * std::max(1.0, std::abs(P)));
        const double lost = 0.5 * (1.0 - e * e) * v[i] * v[i] / M_inv(i, i);
        const double T = std::max(1.0, s.motion.kinetic_before);
        EXPECT_NEAR(s.motion.kinetic_before - s.motion.kinetic_after, lost, 1e-12 * T);
        EXPECT_NEAR(s.motion.impulse_work, s.motion.kinetic_after - s.motion.kinetic_before,
                    1e-12 * T);
      }
      ++struck;
    }
    EXPECT_GT(struck, 0);
  }
  const Model model = test::random_tree(3, 1, test::all_joint_types(), Vec3(0, 0, -9.81), 0.05);
  const VecX q = model.initial_q(), v = VecX::Zero(model.nv());
  EXPECT_THROW(stop_impact(model, q, v, model.nv(), 0.5), InvalidArgument);
  EXPECT_THROW(stop_impact(model, q, v, 0, 1.5), InvalidArgument);
}

// Eccentric impact (Beer & Johnston ch. 17): a sphere of mass m_s sliding at v₀ strikes a rod
// hanging at rest from a pin (I_O = m L²/3) at depth d. Angular momentum about the pin and
// Newton's restitution give the rod's ω = m_s v₀ d (1 + e) / (I_O + m_s d²) and the sphere's
// v_s = v₀ (m_s d² − e I_O) / (I_O + m_s d²); the pin's impulse R = m ω L/2 − P vanishes at the
// centre of percussion whatever e; energy is kept at e = 1.
TEST(ImpulsiveMotion, ASphereStrikingAPinnedRodAsTheTextbookHasIt) {
  const double m = 4.0, L = 1.2, I_O = m * L * L / 3.0, m_s = 0.5, v0 = 3.0;
  for (const double d : {0.5, 2.0 * L / 3.0, 1.1}) {
    model::ModelBuilder b;
    b.add_body("rod",
               inertia::MassProperties(m, Vec3(0, 0, -L / 2),
                                       Vec3(m * L * L / 12, m * L * L / 12, 1e-6).asDiagonal()));
    b.add_body("sphere", inertia::MassProperties(m_s, Vec3::Zero(), 1e-4 * Mat3::Identity()));
    b.add_joint(test::make_joint("pin", JointType::revolute, "world", "rod", Vec3::UnitY()));
    b.add_joint(test::make_joint("slide", JointType::prismatic, "world", "sphere", Vec3::UnitX(),
                                 Transform::translation(Vec3(0, 0, -d))));
    const Model model = b.build();
    const VecX q = VecX::Zero(2), v = (VecX(2) << 0.0, v0).finished();
    const PointContact contact{model.body_index("sphere"), Vec3::Zero(), model.body_index("rod"),
                               Vec3(0, 0, -d), Vec3::UnitX()};
    for (const double e : {0.0, 0.6, 1.0}) {
      SCOPED_TRACE(testing::Message() << "d = " << d << ", e = " << e);
      const Impact impact = restitution_impact(model, q, v, contact, e);
      const double omega = m_s * v0 * d * (1 + e) / (I_O + m_s * d * d);
      const double v_s = v0 * (m_s * d * d - e * I_O) / (I_O + m_s * d * d);
      // A few products of O(1) numbers: round-off ~1e-15.
      EXPECT_NEAR(impact.motion.v_after[0], -omega, 1e-14);  // +x at depth d is −θ̇ d
      EXPECT_NEAR(impact.motion.v_after[1], v_s, 1e-14);
      EXPECT_NEAR(impact.approach_speed, -v0, 1e-15);
      EXPECT_NEAR(impact.separation_speed, e * v0, 1e-14);
      const double P = m_s * (v0 - v_s);
      EXPECT_NEAR(impact.normal_impulse, P, 1e-14);
      const double R = m * omega * L / 2 - P;
      EXPECT_NEAR(impact.motion.joint_impulses[0].force.x(), R, 1e-14);
      if (d == 2.0 * L / 3.0) {
        EXPECT_NEAR(R, 0.0, 1e-14);
      }
      const double lost = impact.motion.kinetic_before - impact.motion.kinetic_after;
      EXPECT_NEAR(lost, 0.5 * m_s * v0 * v0 - 0.5 * m_s * v_s * v_s - 0.5 * I_O * omega * omega,
                  1e-14);
      if (e == 1.0) {
        EXPECT_NEAR(lost, 0.0, 1e-14);
      }
    }
    // Moving apart, or a coefficient outside [0, 1]: no impact.
    const auto message = [&](const VecX& speeds, double e) {
      try {
        restitution_impact(model, q, speeds, contact, e);
      } catch (const InvalidArgument& error) {
        return std::string(error.what());
      }
      return std::string("no error");
    };
    EXPECT_NE(message((VecX(2) << 0.0, -1.0).finished(), 0.5).find("do not approach"),
              std::string::npos);
    EXPECT_NE(message(v, 1.5).find("outside [0, 1]"), std::string::npos);
  }
}

// A free solid sphere (m = 0.5 kg, r = 0.1 m, I = 2/5 m r²) striking the ground at its lowest
// point with v = (v_x, 0, −V) and spin ω_y: its contact point slips at u = v_x − r ω_y, and for a
// sphere the normal and the slip do not couple (W = diag(1/m, 7/(2m), …) at the contact). Sticking
// (Beer & Johnston's ball that rolls off the impact): P_t = −2 m u / 7, so v_x⁺ = v_x − 2u/7 and
// ω_y⁺ = ω_y + 5u/(7r), no slip after. Sliding (μ below 2u / (7 (1 + e) V)): P_t = −μk (1 + e) m V
// along the slip, v_x⁺ = v_x − μk (1 + e) V, ω_y⁺ = ω_y + 5 μk (1 + e) V / (2r). Either way
// v_z⁺ = e V, and the energy lost is Kelvin's.
TEST(ImpulsiveMotion, ASpinningSphereStrikesTheGroundWithFriction) {
  const double m = 0.5, r = 0.1, V = 3.0, e = 0.6, v_x = 1.0, w_y = -4.0;
  const double u = v_x - r * w_y;  // 1.4 m/s forward
  model::ModelBuilder b;
  b.add_body("ball", inertia::MassProperties(m, Vec3::Zero(), 0.4 * m * r * r * Mat3::Identity()));
  b.add_joint(test::make_joint("free", JointType::free, "world", "ball", Vec3::UnitZ()));
  const Model model = b.build();
  VecX q = model.initial_q();
  q[2] = r;
  VecX v = VecX::Zero(6);
  v << 0, w_y, 0, v_x, 0, -V;  // ω in the body (here W), then the centre's velocity
  const PointContact floor{0, Vec3(0, 0, 0), 1, Vec3(0, 0, -r), Vec3::UnitZ()};

  const FrictionalImpact stick = frictional_impact(model, q, v, floor, e, 0.5, 0.4);
  EXPECT_TRUE(stick.sticking);
  EXPECT_NEAR(stick.normal_impulse, (1 + e) * m * V, 1e-14);
  EXPECT_NEAR(stick.impulse_W.x(), -2.0 * m * u / 7.0, 1e-14);
  const VecX& after = stick.motion.v_after;
  EXPECT_NEAR(after[3], v_x - 2.0 * u / 7.0, 1e-14);
  EXPECT_NEAR(after[1], w_y + 5.0 * u / (7.0 * r), 1e-13);
  EXPECT_NEAR(after[5], e * V, 1e-14);
  EXPECT_LT(stick.slip_after_W.norm(), 1e-14);
  EXPECT_NEAR(stick.slip_before_W.x(), u, 1e-15);
  EXPECT_NEAR(stick.motion.kinetic_after - stick.motion.kinetic_before, stick.motion.impulse_work,
              1e-13);

  const double mu = 0.05;  // below 2u / (7 (1 + e) V) = 0.0833: it slides through the impact
  const FrictionalImpact slide = frictional_impact(model, q, v, floor, e, mu, mu);
  EXPECT_FALSE(slide.sticking);
  EXPECT_NEAR(slide.impulse_W.x(), -mu * (1 + e) * m * V, 1e-14);
  EXPECT_NEAR(slide.motion.v_after[3], v_x - mu * (1 + e) * V, 1e-14);
  EXPECT_NEAR(slide.motion.v_after[1], w_y + 5.0 * mu * (1 + e) * V / (2.0 * r), 1e-13);
  EXPECT_NEAR(slide.motion.v_after[5], e * V, 1e-14);
  EXPECT_NEAR(slide.slip_after_W.x(), u - 3.5 * mu * (1 + e) * V, 1e-13);
  EXPECT_LE(slide.motion.kinetic_after, slide.motion.kinetic_before);

  // Without slip before it sticks with no friction at all; friction coefficients out of order
  // are refused.
  VecX rolling = v;
  rolling[3] = r * w_y;
  const FrictionalImpact none = frictional_impact(model, q, rolling, floor, e, 0.5, 0.4);
  EXPECT_TRUE(none.sticking);
  EXPECT_LT(none.impulse_W.head<2>().norm(), 1e-15);
  EXPECT_THROW(frictional_impact(model, q, v, floor, e, 0.3, 0.4), InvalidArgument);
}

// Coulomb's law at impact where the normal and the slip decouple, at random states: a free sphere
// (m = 0.5 kg, r = 0.1 m) with random spin, speeds and coefficients — it sticks (the slip stopped
// within the impact by μk P or less, within μs P_n) or slides: the separation speed −e v_n⁻, the
// friction impulse against the slip with no slip after, or μk P_n with the slip slowed, not
// reversed; no energy created. (A coupled mechanism: impact_course_test.cpp.)
TEST(ImpulsiveMotion, CoulombsLawAtImpactWhereItFollowsTheImpact) {
  model::ModelBuilder b;
  b.add_body("ball", inertia::MassProperties(0.5, Vec3::Zero(), 0.002 * Mat3::Identity()));
  b.add_joint(test::make_joint("free", JointType::free, "world", "ball", Vec3::UnitZ()));
  const Model model = b.build();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  int sticking = 0, sliding = 0;
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE(fmt::format("trial {}", trial));
    VecX q = model.initial_q();
    q.head<3>() = Vec3(0, 0, 0.1);  // the ball on the ground at the origin
    VecX v(6);
    for (int k = 0; k < 6; ++k) v[k] = 6 * (u(rng) - 0.5);
    v[5] = -0.5 - 3 * u(rng);  // the ball falls
    const double e = u(rng), mu_s = 1.2 * u(rng), mu_k = mu_s * u(rng);
    const PointContact ball{0, Vec3::Zero(), 1, Vec3(0, 0, -0.1), Vec3::UnitZ()};
    const FrictionalImpact impact = frictional_impact(model, q, v, ball, e, mu_s, mu_k);
    const double P_n = impact.normal_impulse;
    const Vec3 P_t(impact.impulse_W.x(), impact.impulse_W.y(), 0);
    const double slip = impact.slip_before_W.norm();
    EXPECT_NEAR(impact.motion.v_after[5], -e * v[5], 1e-14);  // the centre's is the point's
    EXPECT_NEAR(P_n, -(1 + e) * 0.5 * v[5], 1e-14);
    EXPECT_LE(P_t.dot(impact.slip_before_W), 0.0);
    EXPECT_LE(impact.motion.kinetic_after, impact.motion.kinetic_before);
    EXPECT_NEAR(impact.motion.kinetic_after - impact.motion.kinetic_before,
                impact.motion.impulse_work, 1e-13);
    if (impact.sticking) {
      ++sticking;
      EXPECT_LE(P_t.norm(), mu_k * P_n * (1 + 1e-12));  // stopped while sliding, by μk
      EXPECT_LT(impact.slip_after_W.norm(), 1e-13);
    } else {
      ++sliding;
      EXPECT_NEAR(P_t.norm(), mu_k * P_n, 1e-14);
      EXPECT_GE(impact.slip_after_W.dot(impact.slip_before_W), 0.0);  // slowed, not reversed
      EXPECT_LT(impact.slip_after_W.norm(), slip);
    }
  }
  EXPECT_GT(sticking, 20);
  EXPECT_GT(sliding, 20);
}

TEST(ImpulsiveMotion, RefusesWhatIsNotAnImpulseOnTheModel) {
  const Model model = Rod{}.build();
  const VecX q = VecX::Zero(1), v = VecX::Zero(1);
  const auto message = [&](const PointImpulse& hit, const VecX& state) {
    try {
      impulsive_motion(model, state, v, std::span(&hit, 1));
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({0, Vec3::Zero(), Vec3::UnitX()}, q).find("not a moving body"),
            std::string::npos);
  EXPECT_NE(message({1, Vec3::Zero(), Vec3(NAN, 0, 0)}, q).find("not finite"), std::string::npos);
  EXPECT_NE(message({1, Vec3::Zero(), Vec3::UnitX()}, VecX::Zero(2)).find("q has 2"),
            std::string::npos);
}

}  // namespace
}  // namespace momenta::dynamics::impulse_test
