// The balancing examples (examples/parts/overhung_fan.yaml, two_disk_shaft.yaml) against the
// multibody dynamics: each rotor on a revolute joint about its axis, turning at ω with angular
// acceleration α, has a joint reaction (Newton–Euler on the subtree, dynamics/reactions.hpp) equal
// to the two bearing forces the balancing arithmetic gives, their moments about the axis point
// and the drive torque; after the computed correction, added as point masses, the dynamics
// reaction vanishes to round-off. The two-disk shaft's correction gives back the unbalance
// masses the file puts in it, opposite.

#include <array>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "momenta/dynamics/data.hpp"
#include "momenta/dynamics/reactions.hpp"
#include "momenta/inertia/balancing.hpp"
#include "momenta/io/part_file.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta {
namespace {

using inertia::BearingReactions;
using inertia::MassProperties;
using inertia::Unbalance;

// The joint reaction (force and moment about the axis point, in the rotor frame) of `rotor`
// turning about B's z axis through Bo at angle θ, speed ω, acceleration α, without gravity.
dynamics::JointReaction dynamics_reaction(const MassProperties& rotor, double theta, double omega,
                                          double alpha) {
  model::ModelBuilder b;
  b.set_gravity(Vec3::Zero());
  b.add_body("rotor", rotor);
  b.add_joint(
      test::make_joint("shaft", model::JointType::revolute, "world", "rotor", Vec3::UnitZ()));
  const model::Model model = b.build();
  dynamics::Data data(model);
  const VecX q = VecX::Constant(1, theta), v = VecX::Constant(1, omega),
             vdot = VecX::Constant(1, alpha);
  dynamics::joint_reactions(model, data, q, v, vdot);
  return dynamics::joint_reaction(model, data, 0, model::ReactionFrame::child);
}

// The same wrench from the two bearing forces and the drive torque.
dynamics::JointReaction from_bearings(const BearingReactions& r, double zA, double zB) {
  const Vec3 A(r.A.x(), r.A.y(), 0.0), B(r.B.x(), r.B.y(), 0.0);
  return {A + B, Vec3(0, 0, zA).cross(A) + Vec3(0, 0, zB).cross(B) + Vec3(0, 0, r.drive_torque)};
}

MassProperties with_point_masses(MassProperties rotor,
                                 std::span<const inertia::CorrectionMass> corrections,
                                 double radius) {
  for (const auto& c : corrections) {
    const Vec2 at = radius * c.mass_radius.normalized();
    rotor += MassProperties(c.mass_at(radius), Vec3(at.x(), at.y(), c.z), Mat3::Zero());
  }
  return rotor;
}

struct Case {
  const char* file;
  double zA, zB, z1, z2;
};

class BalancingExamples : public ::testing::TestWithParam<Case> {};

TEST_P(BalancingExamples, BearingForcesAreTheJointReactionAndVanishAfterCorrection) {
  const Case c = GetParam();
  const io::CompositePart part = io::read_part_file(std::string("examples/parts/") + c.file);
  const Unbalance u = inertia::unbalance(part.total, {});
  // The axis is B's z through Bo: R is B.
  ASSERT_MATRIX_NEAR(u.R_BR, Mat3::Identity(), 0.0);
  for (const auto& [omega, alpha] : {std::pair{314.1592653589793, 0.0}, std::pair{120.0, 35.0}}) {
    const BearingReactions r = inertia::bearing_reactions(u, c.zA, c.zB, omega, alpha);
    const dynamics::JointReaction expected = from_bearings(r, c.zA, c.zB);
    const dynamics::JointReaction computed = dynamics_reaction(part.total, 0.7, omega, alpha);
    // Loads of O(1e3) N: 1e-12 relative is round-off of two different summations.
    const double scale = std::max(1.0, expected.force.norm() + expected.moment.norm());
    EXPECT_MATRIX_NEAR(computed.force, expected.force, 1e-12 * scale) << c.file << " ω " << omega;
    EXPECT_MATRIX_NEAR(computed.moment, expected.moment, 1e-12 * scale) << c.file << " ω " << omega;
    // After the two-plane correction (point masses at 0.2 m) only the drive torque is left.
    const auto correction = inertia::two_plane_correction(u, c.z1, c.z2);
    const MassProperties balanced = with_point_masses(part.total, correction, 0.2);
    const dynamics::JointReaction after = dynamics_reaction(balanced, 0.7, omega, alpha);
    EXPECT_LT(after.force.norm(), 1e-12 * scale) << c.file;
    EXPECT_LT(after.moment.head<2>().norm(), 1e-12 * scale) << c.file;
    EXPECT_REL_NEAR(after.moment.z(), alpha * inertia::unbalance(balanced, {}).polar_moment, 1e-13);
  }
}

INSTANTIATE_TEST_SUITE_P(Rotors, BalancingExamples,
                         ::testing::Values(Case{"overhung_fan.yaml", 0.05, 0.25, 0.3, 0.4},
                                           Case{"two_disk_shaft.yaml", 0.0, 1.0, 0.25, 0.75}));

// The file puts 12 g at 150 mm, 0°, on disk 1 and 8 g at 150 mm, 120°, on disk 2 of an otherwise
// perfect rotor: the correction in the disks' planes takes them back, opposite.
TEST(BalancingExamples, TwoDiskShaftCorrectionGivesBackItsUnbalanceMasses) {
  const io::CompositePart part = io::read_part_file("examples/parts/two_disk_shaft.yaml");
  const Unbalance u = inertia::unbalance(part.total, {});
  const auto correction = inertia::two_plane_correction(u, 0.25, 0.75);
  const double r = 0.15, deg = std::numbers::pi / 180;
  EXPECT_REL_NEAR(correction[0].mass_at(r), 0.012, 1e-12);
  EXPECT_REL_NEAR(correction[1].mass_at(r), 0.008, 1e-12);
  // Angles compared modulo 2π (180° may come out as −180°).
  const auto turn = [](double a, double b) {
    return std::abs(std::remainder(a - b, 2 * std::numbers::pi));
  };
  EXPECT_LT(turn(inertia::angle_of(correction[0].mass_radius), 180 * deg), 1e-12);
  EXPECT_LT(turn(inertia::angle_of(correction[1].mass_radius), -60 * deg), 1e-12);
}

}  // namespace
}  // namespace momenta
