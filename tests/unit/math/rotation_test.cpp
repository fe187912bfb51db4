#include "momenta/math/rotation.hpp"

#include <cctype>
#include <cmath>
#include <numbers>
#include <random>

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

namespace momenta {
namespace {

const char* const kEulerSequences[] = {"XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX", "XYX", "XZX",
                                       "YXY", "YZY", "ZXZ", "ZYZ", "xyz", "xzy", "yxz", "yzx",
                                       "zxy", "zyx", "xyx", "xzx", "yxy", "yzy", "zxz", "zyz"};

TEST(EulerAngles, RoundTripEverySequenceWithinItsRanges) {
  // Angles inside the ranges euler_from_rotation returns give themselves back, and any rotation
  // gives angles that rebuild it, to round-off.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(-3.0, 3.0), middle(0.05, 3.09), tilt(-1.5, 1.5);
  for (const char* sequence : kEulerSequences) {
    const bool proper = sequence[0] == sequence[2];
    for (int trial = 0; trial < 50; ++trial) {
      const Vec3 a(angle(random), proper ? middle(random) : tilt(random), angle(random));
      const Mat3 R = rotation_from_euler(sequence, a);
      const Vec3 back = euler_from_rotation(sequence, R);
      EXPECT_LT((back - a).cwiseAbs().maxCoeff(), 1e-12) << sequence << " " << a.transpose();
      EXPECT_LT((rotation_from_euler(sequence, back) - R).cwiseAbs().maxCoeff(), 1e-14) << sequence;
    }
  }
}

TEST(EulerAngles, GimbalLockStillRebuildsTheRotation) {
  // Middle angle 0 (proper) or π/2 (Tait–Bryan): only a0 ± a2 is defined; the intrinsic third
  // angle (an extrinsic sequence's first) is set to 0.
  for (const char* sequence : kEulerSequences) {
    const bool proper = sequence[0] == sequence[2];
    const Vec3 a(0.7, proper ? 0.0 : std::numbers::pi / 2, 0.4);
    const Mat3 R = rotation_from_euler(sequence, a);
    const Vec3 back = euler_from_rotation(sequence, R);
    const bool intrinsic = std::isupper(static_cast<unsigned char>(sequence[0])) != 0;
    EXPECT_EQ(back[intrinsic ? 2 : 0], 0.0) << sequence;
    EXPECT_LT((rotation_from_euler(sequence, back) - R).cwiseAbs().maxCoeff(), 1e-12) << sequence;
  }
  EXPECT_THROW(euler_from_rotation("ZZX", Mat3::Identity()), InvalidArgument);
}

TEST(EulerAngles, RateMatrixGivesTheAngularVelocity) {
  // ω from the rotation's derivative, [ω]× = Ṙ Rᵀ by central differences (error O(h²) ≈ 1e-10),
  // against E(a) ȧ, and its determinant against sin (proper) or cos (Tait–Bryan) of the middle
  // angle.
  const Vec3 a(0.3, 1.1, -2.0), rate(0.5, -0.8, 1.7);
  const double h = 1e-5;
  for (const char* sequence : kEulerSequences) {
    const Mat3 R = rotation_from_euler(sequence, a);
    const Mat3 R_dot = (rotation_from_euler(sequence, a + h * rate) -
                        rotation_from_euler(sequence, a - h * rate)) /
                       (2 * h);
    const Mat3 w_skew = R_dot * R.transpose();
    const Vec3 w(w_skew(2, 1), w_skew(0, 2), w_skew(1, 0));
    const Mat3 E = euler_rate_matrix(sequence, a);
    EXPECT_LT((E * rate - w).cwiseAbs().maxCoeff(), 1e-9) << sequence;
    const bool proper = sequence[0] == sequence[2];
    EXPECT_NEAR(std::abs(E.determinant()), proper ? std::sin(a[1]) : std::cos(a[1]), 1e-14)
        << sequence;
  }
}

}  // namespace
}  // namespace momenta
