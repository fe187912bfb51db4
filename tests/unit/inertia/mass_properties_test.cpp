#include "momenta/inertia/mass_properties.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::inertia {
namespace {

// Round-off of a handful of 3×3 products on O(1) numbers.
constexpr double kTol = 1e-13;

MassProperties sample_body() {
  Mat3 I;
  I << 2.0, -0.3, 0.1, -0.3, 3.0, 0.2, 0.1, 0.2, 4.0;
  return MassProperties(5.0, Vec3(0.1, -0.2, 0.3), I, 0.002);
}

TEST(MassProperties, ParallelAxisOfPointMassAndRoundTrip) {
  const MassProperties body = sample_body();
  const Vec3 q(1.0, 2.0, -0.5);
  // Shift by hand: d = com − q.
  const Vec3 d = body.center_of_mass() - q;
  Mat3 expected = body.inertia_about_com();
  expected(0, 0) += 5.0 * (d.y() * d.y() + d.z() * d.z());
  expected(1, 1) += 5.0 * (d.x() * d.x() + d.z() * d.z());
  expected(2, 2) += 5.0 * (d.x() * d.x() + d.y() * d.y());
  expected(0, 1) -= 5.0 * d.x() * d.y();
  expected(1, 0) -= 5.0 * d.x() * d.y();
  expected(0, 2) -= 5.0 * d.x() * d.z();
  expected(2, 0) -= 5.0 * d.x() * d.z();
  expected(1, 2) -= 5.0 * d.y() * d.z();
  expected(2, 1) -= 5.0 * d.y() * d.z();
  EXPECT_MATRIX_NEAR(body.inertia_about(q), expected, kTol);
  // And back.
  const MassProperties back =
      MassProperties::from_inertia_about(5.0, body.center_of_mass(), expected, q);
  EXPECT_MATRIX_NEAR(back.inertia_about_com(), body.inertia_about_com(), kTol);
}

TEST(MassProperties, RigidMotionKeepsPrincipalMoments) {
  const MassProperties body = sample_body();
  const Mat3 R = rotation_from_euler("ZYX", Vec3(0.7, -0.2, 1.9));
  const MassProperties moved = body.transformed(R, Vec3(3, -1, 2));
  EXPECT_MATRIX_NEAR(moved.principal_axes().moments, body.principal_axes().moments, kTol);
  EXPECT_MATRIX_NEAR(moved.center_of_mass(), Vec3(3, -1, 2) + R * body.center_of_mass(), kTol);
}

TEST(MassProperties, PrincipalAxesDiagonalizeAndAreRightHanded) {
  const MassProperties body = sample_body();
  const PrincipalAxes p = body.principal_axes();
  EXPECT_TRUE(p.moments[0] <= p.moments[1] && p.moments[1] <= p.moments[2]);
  EXPECT_NEAR(p.R_BP.determinant(), 1.0, kTol);
  EXPECT_MATRIX_NEAR(p.R_BP.transpose() * body.inertia_about_com() * p.R_BP,
                     Mat3(p.moments.asDiagonal()), kTol);
}

TEST(MassProperties, RepeatedMomentsGiveCanonicalAxes) {
  // Sphere: all moments equal, axes are B's.
  const MassProperties sphere(1.0, Vec3::Zero(), 0.4 * Mat3::Identity());
  EXPECT_MATRIX_NEAR(sphere.principal_axes().R_BP, Mat3::Identity(), 0.0);
  // Cylinder along z: x and y share a moment; the axes stay x, y, z.
  const MassProperties cylinder(1.0, Vec3::Zero(), Vec3(2.0, 2.0, 1.0).asDiagonal());
  const PrincipalAxes p = cylinder.principal_axes();
  EXPECT_MATRIX_NEAR(p.moments, Vec3(1, 2, 2), kTol);
  EXPECT_MATRIX_NEAR(p.R_BP.col(0).cwiseAbs(), Vec3::UnitZ(), kTol);
  EXPECT_NEAR(p.R_BP.determinant(), 1.0, kTol);
}

TEST(MassProperties, RepeatedMomentsOfATurnedBodyGiveTheAxesClosestToB) {
  // A cylinder (moments 2, 2 about its cross-section, 1 about its axis n) turned so that n is
  // no coordinate axis: the solver's basis of the repeated plane is arbitrary; momenta's is
  // u = (e_k − n n_k)/|…| for the B axis e_k farthest from n, then n × u.
  const Vec3 n = Vec3(1.0, 2.0, 2.0) / 3.0;
  const Mat3 I = 2.0 * Mat3::Identity() - n * n.transpose();
  const PrincipalAxes p = MassProperties(1.0, Vec3::Zero(), I).principal_axes();
  EXPECT_MATRIX_NEAR(p.moments, Vec3(1, 2, 2), kTol);
  EXPECT_NEAR(std::abs(p.R_BP.col(0).dot(n)), 1.0, kTol);
  // n_x = 1/3 is the smallest component: e_x is farthest from n.
  const Vec3 u = (Vec3::UnitX() - n * n.x()).normalized();
  EXPECT_MATRIX_NEAR(p.R_BP.col(1), u, kTol);
  EXPECT_MATRIX_NEAR(p.R_BP.col(2), p.R_BP.col(0).cross(u), kTol);
  EXPECT_NEAR(p.R_BP.determinant(), 1.0, kTol);
  EXPECT_MATRIX_NEAR(p.R_BP.transpose() * I * p.R_BP, Mat3(p.moments.asDiagonal()), kTol);
  // A sphere's tensor turned by a rotation (equal moments up to round-off): B's own axes.
  const Mat3 R = rotation_from_euler("ZYX", Vec3(0.7, -0.2, 1.9));
  const Mat3 sphere = R * (0.4 * Mat3::Identity()) * R.transpose();
  EXPECT_MATRIX_NEAR(MassProperties(1.0, Vec3::Zero(), sphere).principal_axes().R_BP,
                     Mat3::Identity(), 0.0);
}

TEST(MassProperties, NearlyEqualMomentsAreDiagonalizedToHalfTheirGap) {
  // Moments within 1e-10 of the largest count as repeated, and their plane gets B's axes: the
  // tensor in those axes is then diagonal only to half the gap, here 5e-12 (documented limit).
  // diag(1, 1 + 1e-11, 2) turned 45° about z: the canonical axes x, y leave ±5e-12 off the
  // diagonal.
  const double gap = 1e-11;
  const Mat3 R = rotation_from_axis_angle(Vec3::UnitZ(), std::numbers::pi / 4);
  const Mat3 I = R * Vec3(1.0, 1.0 + gap, 2.0).asDiagonal() * R.transpose();
  const PrincipalAxes p = MassProperties(1.0, Vec3::Zero(), I).principal_axes();
  EXPECT_MATRIX_NEAR(p.moments, Vec3(1.0, 1.0 + gap, 2.0), kTol);
  EXPECT_MATRIX_NEAR(p.R_BP, Mat3::Identity(), kTol);
  const Mat3 D = p.R_BP.transpose() * I * p.R_BP;
  EXPECT_NEAR(std::abs(D(0, 1)), gap / 2, 1e-15);
  // Ten times farther apart (1e-10 < gap), the moments are distinct: the solver's axes, and a
  // diagonal to round-off.
  const Mat3 I_apart = R * Vec3(1.0, 1.0 + 1e-9, 2.0).asDiagonal() * R.transpose();
  const PrincipalAxes q = MassProperties(1.0, Vec3::Zero(), I_apart).principal_axes();
  EXPECT_MATRIX_NEAR(q.R_BP.transpose() * I_apart * q.R_BP, Mat3(q.moments.asDiagonal()), kTol);
}

TEST(MassProperties, CompositeThenShiftEqualsShiftThenComposite) {
  const MassProperties a = sample_body();
  const MassProperties b(2.0, Vec3(-1, 0.5, 0), Vec3(0.1, 0.2, 0.25).asDiagonal(), 0.001);
  const Mat3 R = rotation_from_euler("XYZ", Vec3(0.2, 0.4, -0.9));
  const Vec3 p(0.5, 0.5, -2);
  const MassProperties first = (a + b).transformed(R, p);
  const MassProperties second = a.transformed(R, p) + b.transformed(R, p);
  EXPECT_NEAR(first.mass(), 7.0, kTol);
  EXPECT_NEAR(first.volume(), 0.003, kTol);
  EXPECT_MATRIX_NEAR(first.center_of_mass(), second.center_of_mass(), kTol);
  EXPECT_MATRIX_NEAR(first.inertia_about_com(), second.inertia_about_com(), kTol);
}

TEST(MassProperties, SubtractingAPartUndoesAddingIt) {
  const MassProperties a = sample_body();
  const MassProperties b(2.0, Vec3(-1, 0.5, 0), Vec3(0.1, 0.2, 0.25).asDiagonal(), 0.001);
  const MassProperties back = (a + b) - b;
  EXPECT_NEAR(back.mass(), a.mass(), kTol);
  EXPECT_MATRIX_NEAR(back.center_of_mass(), a.center_of_mass(), kTol);
  EXPECT_MATRIX_NEAR(back.inertia_about_com(), a.inertia_about_com(), kTol);
  EXPECT_THROW(b - a, InvalidInertia);
}

TEST(MassProperties, PhysicalValidity) {
  EXPECT_NO_THROW(sample_body().check_physical("body"));
  // Point mass and slender rod are idealizations with zero moments: valid.
  EXPECT_NO_THROW(MassProperties(1.0, Vec3::Zero(), Mat3::Zero()).check_physical("point"));
  EXPECT_NO_THROW(
      MassProperties(1.0, Vec3::Zero(), Vec3(0, 1, 1).asDiagonal()).check_physical("rod"));
  EXPECT_THROW(MassProperties(0.0, Vec3::Zero(), Mat3::Identity()).check_physical("b"),
               InvalidInertia);
  EXPECT_THROW(MassProperties(-1.0, Vec3::Zero(), Mat3::Identity()).check_physical("b"),
               InvalidInertia);
  // Triangle inequality: 1 + 1 < 3.
  try {
    MassProperties(1.0, Vec3::Zero(), Vec3(1, 1, 3).asDiagonal()).check_physical("disk");
    FAIL() << "expected InvalidInertia";
  } catch (const InvalidInertia& e) {
    EXPECT_NE(std::string(e.what()).find("triangle inequality"), std::string::npos) << e.what();
  }
  // Not positive semi-definite: products of inertia with the wrong magnitude.
  Mat3 bad;
  bad << 1, 2, 0, 2, 1, 0, 0, 0, 1.5;
  EXPECT_THROW(MassProperties(1.0, Vec3::Zero(), bad).check_physical("b"), InvalidInertia);
  // Asymmetric.
  Mat3 asym = Mat3::Identity();
  asym(0, 1) = 0.1;
  EXPECT_THROW(MassProperties(1.0, Vec3::Zero(), asym).check_physical("b"), InvalidInertia);
}

}  // namespace
}  // namespace momenta::inertia
