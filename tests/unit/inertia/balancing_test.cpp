// Rotor balancing (inertia/balancing.hpp) against independent references: a cloud of particles
// whose centrifugal and tangential inertial forces are summed one by one (d'Alembert), the
// closed form of a skewed disk's products of inertia, corrections applied as real point masses
// composed into the rotor, and the ISO 21940-11 relation e_per ω = G.

#include "momenta/inertia/balancing.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/inertia/amount.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::inertia {
namespace {

struct Particle {
  double mass;
  Vec3 p_B;  // position in the part frame B
};

// A lumpy rotor: random particles in a 0.4 m × 0.4 m × 1 m box.
std::vector<Particle> particle_cloud(unsigned seed, int count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> mass(0.1, 2.0), xy(-0.2, 0.2), z(-0.1, 0.9);
  std::vector<Particle> cloud;
  for (int k = 0; k < count; ++k) cloud.push_back({mass(rng), Vec3(xy(rng), xy(rng), z(rng))});
  return cloud;
}

MassProperties composed(const std::vector<Particle>& cloud) {
  MassProperties total;
  for (const Particle& p : cloud) total += MassProperties(p.mass, p.p_B, Mat3::Zero());
  return total;
}

// The same rotor's particles in the axis frame R (origin on the axis).
std::vector<Particle> in_axis_frame(const std::vector<Particle>& cloud, const Unbalance& u,
                                    const Vec3& p_BoAo_B) {
  std::vector<Particle> out;
  for (const Particle& p : cloud) out.push_back({p.mass, u.R_BR.transpose() * (p.p_B - p_BoAo_B)});
  return out;
}

const RotorAxis kTiltedAxis{Vec3(0.01, -0.02, 0.05), Vec3(0.1, -0.2, 1.0)};

TEST(Balancing, UnbalanceIsTheParticleSums) {
  const auto cloud = particle_cloud(7, 40);
  const Unbalance u = unbalance(composed(cloud), kTiltedAxis);
  // The axis frame: a proper rotation with z along the axis and x from B's x.
  EXPECT_MATRIX_NEAR(u.R_BR.transpose() * u.R_BR, Mat3::Identity(), 1e-15);
  EXPECT_NEAR(u.R_BR.determinant(), 1.0, 1e-15);
  EXPECT_MATRIX_NEAR(u.R_BR.col(2), kTiltedAxis.direction_B.normalized(), 1e-15);
  const Vec3 a = kTiltedAxis.direction_B.normalized();
  const Vec3 x_projected = Vec3::UnitX() - a.x() * a;
  EXPECT_MATRIX_NEAR(u.R_BR.col(0), x_projected.normalized(), 1e-15);
  double m = 0, z_sum = 0, Izz = 0;
  Vec2 U = Vec2::Zero(), P = Vec2::Zero();
  for (const Particle& p : in_axis_frame(cloud, u, kTiltedAxis.p_BoAo_B)) {
    const Vec3& r = p.p_B;
    m += p.mass;
    z_sum += p.mass * r.z();
    U += p.mass * r.head<2>();
    P += p.mass * r.z() * r.head<2>();
    Izz += p.mass * r.head<2>().squaredNorm();
  }
  // Sums of 40 terms of O(1): round-off of the composition's parallel-axis shifts, ~1e-15.
  EXPECT_REL_NEAR(u.mass, m, 1e-14);
  EXPECT_NEAR(u.axial_com, z_sum / m, 1e-14);
  EXPECT_MATRIX_NEAR(u.static_unbalance, U, 1e-14);
  EXPECT_MATRIX_NEAR(u.products, P, 1e-14);
  EXPECT_MATRIX_NEAR(u.couple_unbalance, P - (z_sum / m) * U, 1e-14);
  EXPECT_NEAR(u.eccentricity, U.norm() / m, 1e-15);
  EXPECT_REL_NEAR(u.polar_moment, Izz, 1e-13);
}

// The bearings' forces on the rotor balance the particles' inertial forces: each particle at r
// in R needs m (−ω² r_xy + α ẑ × r) (d'Alembert), and the moments of those about Ao.
TEST(Balancing, BearingReactionsBalanceEveryParticlesInertialForce) {
  const auto cloud = particle_cloud(11, 30);
  const Unbalance u = unbalance(composed(cloud), kTiltedAxis);
  const double zA = -0.05, zB = 0.8;
  for (const auto& [omega, alpha] :
       {std::pair{314.159, 0.0}, std::pair{50.0, 120.0}, std::pair{0.0, -30.0}}) {
    Vec3 F = Vec3::Zero(), M = Vec3::Zero();
    for (const Particle& p : in_axis_frame(cloud, u, kTiltedAxis.p_BoAo_B)) {
      const Vec3& r = p.p_B;
      const Vec3 a(-omega * omega * r.x() - alpha * r.y(), -omega * omega * r.y() + alpha * r.x(),
                   0.0);
      F += p.mass * a;
      M += r.cross(p.mass * a);
    }
    const BearingReactions R = bearing_reactions(u, zA, zB, omega, alpha);
    const Vec3 A(R.A.x(), R.A.y(), 0.0), B(R.B.x(), R.B.y(), 0.0);
    const Vec3 moment =
        Vec3(0, 0, zA).cross(A) + Vec3(0, 0, zB).cross(B) + Vec3(0, 0, R.drive_torque);
    // Forces up to ~1e5 N at 3000 rpm: 1e-13 relative is round-off of the sums.
    const double scale = std::max(1.0, F.norm());
    EXPECT_MATRIX_NEAR(A + B, F, 1e-13 * scale) << "ω = " << omega << ", α = " << alpha;
    EXPECT_MATRIX_NEAR(moment, M, 1e-13 * scale) << "ω = " << omega << ", α = " << alpha;
  }
}

// A thin disk (mass m, radius a) skewed by β about x at the middle of a span L: no static
// unbalance, products P_yz = (C − A) sin β cos β with C = m a²/2, A = m a²/4 (Beer & Johnston
// §18.5), so the bearings carry equal and opposite forces ω² P_yz / L along y.
TEST(Balancing, SkewedDiskGivesTheClosedFormCouple) {
  const double m = 3.0, a = 0.25, beta = 0.02, L = 0.6, omega = 200.0;
  const Mat3 R = Eigen::AngleAxisd(beta, Vec3::UnitX()).toRotationMatrix();
  const MassProperties disk = thin_disk(Amount::mass(m), a).transformed(R, Vec3(0, 0, 0.3));
  const Unbalance u = unbalance(disk, {});
  const double P_yz = (m * a * a / 4) * std::sin(beta) * std::cos(beta);
  EXPECT_MATRIX_NEAR(u.static_unbalance, Vec2::Zero(), 1e-16);
  EXPECT_MATRIX_NEAR(u.couple_unbalance, Vec2(0.0, P_yz), 1e-17);
  EXPECT_NEAR(u.principal_axis_tilt, beta, 1e-12);
  const BearingReactions r = bearing_reactions(u, 0.0, L, omega);
  EXPECT_MATRIX_NEAR(r.A, Vec2(0.0, omega * omega * P_yz / L), 1e-11);
  EXPECT_MATRIX_NEAR(r.B, Vec2(0.0, -omega * omega * P_yz / L), 1e-11);
}

TEST(Balancing, TwoPlaneCorrectionAsRealPointMassesLeavesNoUnbalance) {
  const auto cloud = particle_cloud(3, 25);
  const MassProperties rotor = composed(cloud);
  const Unbalance u = unbalance(rotor, kTiltedAxis);
  const double radius = 0.15;
  const auto corrections = two_plane_correction(u, 0.1, 0.7);
  // Each correction as a point mass m = |m·r| / r at radius r, at its angle, in its plane.
  MassProperties corrected = rotor;
  for (const CorrectionMass& c : corrections) {
    const Vec2 at = radius * c.mass_radius.normalized();
    const Vec3 p_B = kTiltedAxis.p_BoAo_B + u.R_BR * Vec3(at.x(), at.y(), c.z);
    corrected += MassProperties(c.mass_at(radius), p_B, Mat3::Zero());
  }
  const Unbalance after = unbalance(corrected, kTiltedAxis);
  // U_s ~ 0.5 kg·m and P ~ 0.3 kg·m² cancel to round-off.
  EXPECT_MATRIX_NEAR(after.static_unbalance, Vec2::Zero(), 1e-14);
  EXPECT_MATRIX_NEAR(after.products, Vec2::Zero(), 1e-14);
  // The same from the balancing arithmetic alone, and no reaction at any speed.
  const Unbalance shortcut = with_corrections(u, corrections);
  EXPECT_MATRIX_NEAR(shortcut.static_unbalance, Vec2::Zero(), 1e-15);
  EXPECT_MATRIX_NEAR(shortcut.products, Vec2::Zero(), 1e-15);
  const BearingReactions r = bearing_reactions(after, -0.05, 0.8, 400.0, 50.0);
  EXPECT_LT(r.A.norm() + r.B.norm(), 1e-8);  // vs ~1e5 N before
}

TEST(Balancing, SinglePlaneCorrectionLeavesExactlyTheCouple) {
  const Unbalance u = unbalance(composed(particle_cloud(5, 20)), kTiltedAxis);
  const double z = 0.35;
  const CorrectionMass c = single_plane_correction(u, z);
  const std::array<CorrectionMass, 1> one{c};
  const Unbalance after = with_corrections(u, one);
  EXPECT_MATRIX_NEAR(after.static_unbalance, Vec2::Zero(), 1e-15);
  EXPECT_MATRIX_NEAR(after.products, u.products - z * u.static_unbalance, 1e-15);
  // In the centre of mass's plane it leaves the couple unbalance itself.
  const std::array<CorrectionMass, 1> at_com{single_plane_correction(u, u.axial_com)};
  EXPECT_MATRIX_NEAR(with_corrections(u, at_com).products, u.couple_unbalance, 1e-15);
}

// ISO 21940-11: e_per ω = G. A 3600 kg rotor at 3000 rev/min in grade G 2.5 may keep
// e_per = 2.5 mm/s / 314.16 rad/s = 7.96 µm (the standard's chart reads 8 g·mm/kg), so
// U_per = 28.65 kg·mm.
TEST(Balancing, GradeIsEperTimesOmega) {
  MassProperties heavy(3600.0, Vec3(0, 0, 1.0), Vec3(500, 500, 200).asDiagonal());
  const Unbalance u = unbalance(heavy, {});
  const double omega = 3000 * 2 * std::numbers::pi / 60;
  const GradeCheck g = check_grade(u, 2.5, omega, 0.0, 2.5);
  EXPECT_REL_NEAR(g.permissible, 3600 * 2.5e-3 / omega, 1e-15);
  EXPECT_NEAR(g.permissible * 1e6, 28647.9, 0.05);  // g·mm
  // Centre of mass at 0.4 of the span: A gets 0.6 of U_per, B 0.4.
  EXPECT_REL_NEAR(g.permissible_A, 0.6 * g.permissible, 1e-15);
  EXPECT_REL_NEAR(g.permissible_B, 0.4 * g.permissible, 1e-15);
  EXPECT_TRUE(g.pass);  // perfectly balanced
  // Near bearing A (0.1 of the span): the shares are held to 70 % / 30 %.
  const GradeCheck near_A = check_grade(u, 2.5, omega, 0.85, 10.85);
  EXPECT_REL_NEAR(near_A.permissible_A, 0.7 * g.permissible, 1e-15);
  EXPECT_FALSE(near_A.overhung);
  // Overhung: the centre of mass outside the bearings.
  const GradeCheck overhung = check_grade(u, 2.5, omega, 0.0, 0.5);
  EXPECT_TRUE(overhung.overhung);
  EXPECT_REL_NEAR(overhung.permissible_A, 0.5 * g.permissible, 1e-15);
}

TEST(Balancing, GradeVerdictFollowsThePlaneUnbalances) {
  // A balanced 100 kg rotor with 10 g at 50 mm in bearing plane A: U_A = 5e-4 kg·m, U_B = 0.
  MassProperties rotor(100.0, Vec3(0, 0, 0.5), Vec3(5, 5, 2).asDiagonal());
  rotor += MassProperties(0.01, Vec3(0.05, 0, 0.0), Mat3::Zero());
  const Unbalance u = unbalance(rotor, {});
  const double omega = 100.0;
  const GradeCheck g = check_grade(u, 6.3, omega, 0.0, 1.0);
  EXPECT_MATRIX_NEAR(g.plane_A, Vec2(0.01 * 0.05, 0.0), 1e-17);
  EXPECT_MATRIX_NEAR(g.plane_B, Vec2::Zero(), 1e-17);
  // U_per = 100.01 kg · 6.3e-3 / 100 = 6.3e-3 kg·m; A may keep ~half of it: 5e-4 passes.
  EXPECT_TRUE(g.pass);
  EXPECT_FALSE(check_grade(u, 0.4, omega, 0.0, 1.0).pass);  // U_per,A ≈ 2e-4 < 5e-4
  // The bearing reactions are ω² times the plane unbalances, opposite.
  const BearingReactions r = bearing_reactions(u, 0.0, 1.0, omega);
  EXPECT_MATRIX_NEAR(r.A, -omega * omega * g.plane_A, 1e-14);
  EXPECT_MATRIX_NEAR(r.B, -omega * omega * g.plane_B, 1e-14);
}

TEST(Balancing, BadInputIsNamed) {
  const MassProperties rotor(2.0, Vec3(0.001, 0, 0.1), Mat3::Identity() * 0.01);
  const Unbalance u = unbalance(rotor, {});
  EXPECT_THROW(unbalance(rotor, {Vec3::Zero(), Vec3::Zero()}), InvalidArgument);
  EXPECT_THROW(unbalance(MassProperties(), {}), InvalidInertia);
  try {
    two_plane_correction(u, 0.2, 0.2);
    FAIL() << "coinciding planes accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("coincide"), std::string::npos) << e.what();
  }
  EXPECT_THROW(bearing_reactions(u, 0.3, 0.3, 10.0), InvalidArgument);
  EXPECT_THROW(bearing_reactions(u, 0.0, 1.0, std::nan("")), InvalidArgument);
  EXPECT_THROW(check_grade(u, 0.0, 10.0, 0.0, 1.0), InvalidArgument);
  EXPECT_THROW(check_grade(u, 2.5, -1.0, 0.0, 1.0), InvalidArgument);
  EXPECT_THROW(single_plane_correction(u, INFINITY), InvalidArgument);
}

}  // namespace
}  // namespace momenta::inertia
