#include "momenta/math/rotation.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta {
namespace {

using std::numbers::pi;

// Round-off of a few products of rotation matrices.
constexpr double kTol = 1e-14;

TEST(Skew, IsTheCrossProductMatrix) {
  const Vec3 a(0.3, -1.2, 2.5), b(-0.7, 0.4, 1.1);
  EXPECT_MATRIX_NEAR(skew(a) * b, a.cross(b), kTol);
  EXPECT_MATRIX_NEAR(skew(a).transpose(), -skew(a), 0.0);
}

TEST(RotationFromEuler, IntrinsicIsProductOfMovingAxisRotations) {
  const Vec3 angles(0.3, -0.5, 1.1);
  const Mat3 expected = rotation_from_axis_angle(Vec3::UnitZ(), 0.3) *
                        rotation_from_axis_angle(Vec3::UnitY(), -0.5) *
                        rotation_from_axis_angle(Vec3::UnitX(), 1.1);
  EXPECT_MATRIX_NEAR(rotation_from_euler("ZYX", angles), expected, kTol);
}

TEST(RotationFromEuler, ExtrinsicEqualsReversedIntrinsic) {
  // Extrinsic x-y-z by (a, b, c) is intrinsic Z-Y-X by (c, b, a).
  const Vec3 angles(0.3, -0.5, 1.1);
  EXPECT_MATRIX_NEAR(rotation_from_euler("xyz", angles),
                     rotation_from_euler("ZYX", Vec3(1.1, -0.5, 0.3)), kTol);
}

TEST(RotationFromEuler, ProperEulerSequence) {
  // ZXZ with (90°, 90°, 0): x goes to y, then about the new x (old y) by 90°.
  const Mat3 R = rotation_from_euler("ZXZ", Vec3(pi / 2, pi / 2, 0));
  EXPECT_MATRIX_NEAR(R * Vec3::UnitX(), Vec3::UnitY(), kTol);
  EXPECT_MATRIX_NEAR(R * Vec3::UnitZ(), Vec3::UnitX(), kTol);
}

TEST(RotationFromEuler, RejectsBadSequences) {
  EXPECT_THROW(rotation_from_euler("ZZX", Vec3::Zero()), InvalidArgument);
  EXPECT_THROW(rotation_from_euler("Zyx", Vec3::Zero()), InvalidArgument);
  EXPECT_THROW(rotation_from_euler("ZYW", Vec3::Zero()), InvalidArgument);
  EXPECT_THROW(rotation_from_euler("ZY", Vec3::Zero()), InvalidArgument);
}

TEST(RotationMatrixCheck, RejectsReflectionAndShear) {
  EXPECT_TRUE(is_rotation_matrix(rotation_from_euler("XYZ", Vec3(0.1, 0.2, 0.3))));
  Mat3 reflection = Mat3::Identity();
  reflection(2, 2) = -1;
  EXPECT_FALSE(is_rotation_matrix(reflection));
  EXPECT_THROW(check_rotation_matrix(reflection, "orientation"), InvalidArgument);
  Mat3 shear = Mat3::Identity();
  shear(0, 1) = 1e-3;
  EXPECT_FALSE(is_rotation_matrix(shear));
}

TEST(Quaternion, FromWxyzNormalizesOrRejects) {
  const Quat q = quaternion_from_wxyz(Eigen::Vector4d(1, 0, 0, 1e-9), "q");
  EXPECT_NEAR(q.norm(), 1.0, kTol);
  EXPECT_THROW(quaternion_from_wxyz(Eigen::Vector4d(1, 1, 0, 0), "q"), InvalidArgument);
  EXPECT_THROW(quaternion_from_wxyz(Eigen::Vector4d::Zero(), "q"), InvalidArgument);
}

TEST(Quaternion, ExpMatchesAxisAngleAndLogInvertsIt) {
  for (const double angle : {0.0, 1e-12, 1e-6, 1e-3, 0.5, 2.0, 3.1}) {
    const Vec3 axis = Vec3(0.3, -0.4, 0.5).normalized();
    const Vec3 phi = angle * axis;
    const Quat q = quaternion_exp(phi);
    EXPECT_NEAR(q.norm(), 1.0, kTol);
    EXPECT_MATRIX_NEAR(q.toRotationMatrix(), Eigen::AngleAxisd(angle, axis).toRotationMatrix(),
                       kTol);
    EXPECT_MATRIX_NEAR(quaternion_log(q), phi, kTol);
  }
}

}  // namespace
}  // namespace momenta
