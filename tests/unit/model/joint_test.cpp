// Joints: names, and the motion subspace as the derivative of the joint transform along the
// configuration-space motion q ⊕ v t, for every joint type.
#include "momenta/model/joint.hpp"

#include <algorithm>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta/model/model_builder.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::model {
namespace {

TEST(Joint, TypeNames) {
  EXPECT_EQ(joint_type_from_name("ball"), JointType::spherical);
  EXPECT_EQ(joint_type_from_name("revolute"), JointType::revolute);
  EXPECT_EQ(joint_type_name(JointType::free), "free");
  try {
    joint_type_from_name("revolut");
    ADD_FAILURE();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'revolute'"), std::string::npos);
  }
}

// The traits table agrees with the motion it describes: a unit per coordinate, rates in rad/s
// where the coordinate is an angle (the motion subspace turns the body: S's angular rows) and
// m/s where it translates, its quaternion where integrate() keeps one, names and aliases unique
// and read back.
TEST(Joint, TraitsDescribeEachTypesMotion) {
  std::vector<std::string_view> names;
  for (const JointTraits& t : kJointTraits) {
    SCOPED_TRACE(std::string(t.name));
    EXPECT_EQ(joint_type_from_name(t.name), t.type);
    names.push_back(t.name);
    if (!t.alias.empty()) {
      EXPECT_EQ(joint_type_from_name(t.alias), t.type);
      names.push_back(t.alias);
    }
    for (int k = 0; k < 7; ++k) {
      EXPECT_EQ(t.q_units[k].empty(), k >= t.nq) << k;
      EXPECT_EQ(t.q_names[k].empty(), k >= t.nq) << k;
    }
    for (int k = 0; k < 6; ++k) {
      EXPECT_EQ(t.v_units[k].empty(), k >= t.nv) << k;
      EXPECT_EQ(t.v_names[k].empty(), k >= t.nv) << k;
    }
    Joint j;
    j.type = t.type;
    j.axis = Vec3(0.6, 0.0, 0.8);
    j.axis2 = Vec3(0.0, 1.0, 0.0);
    VecX q = VecX::Zero(t.nq);
    if (t.quaternion_at >= 0) q[t.quaternion_at] = 1.0;
    const Mat6 S = joint_motion_subspace(j, q.data());
    for (int k = 0; k < t.nv; ++k) {
      const bool turns = S.col(k).head<3>().norm() > 0.5;
      EXPECT_EQ(is_rotation_rate(t.type, k), turns) << k;
      EXPECT_EQ(turns ? S.col(k).tail<3>().norm() : S.col(k).head<3>().norm(), 0.0) << k;
    }
    // A quaternion exactly where the configuration has more entries than the velocity.
    EXPECT_EQ(t.quaternion_at >= 0, t.nq > t.nv);
    for (int k = 0; k < t.nq; ++k) {
      const bool in_quaternion =
          t.quaternion_at >= 0 && k >= t.quaternion_at && k < t.quaternion_at + 4;
      EXPECT_EQ(t.q_units[k] == "1", in_quaternion) << k;
    }
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
}

// S v = the spatial velocity of J' relative to J, in J' about J'o: [(Rᵀ Ṙ)∨; Rᵀ ṗ], here by
// central differences of X_JJ'(q ⊕ ±h v) (truncation h²/6 ≈ 2e-13, round-off eps/h ≈ 2e-10).
TEST(Joint, MotionSubspaceIsTheDerivativeOfTheTransform) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const JointTraits& traits : kJointTraits) {  // every type that moves
    if (traits.nv == 0) continue;
    const JointType type = traits.type;
    ModelBuilder b;
    b.add_body("body", inertia::MassProperties(1.0, Vec3(0.1, 0.2, 0.3),
                                               Vec3(0.1, 0.2, 0.25).asDiagonal().toDenseMatrix()));
    Joint j;
    j.name = "j";
    j.type = type;
    j.parent = "world";
    j.child = "body";
    j.axis = Vec3(1, 2, 2) / 3.0;
    j.axis2 = Vec3(2, -1, 0) / std::sqrt(5.0);
    b.add_joint(j);
    const Model m = b.build();
    VecX q = neutral(m);
    for (int trial = 0; trial < 3; ++trial) {
      VecX v(m.nv());
      for (int i = 0; i < m.nv(); ++i) v[i] = u(rng);
      q = integrate(m, q, v, 1.0);  // somewhere away from neutral
      const double h = 1e-6;
      const Transform Xp = joint_transform(m.joint(0), integrate(m, q, v, h).data());
      const Transform Xm = joint_transform(m.joint(0), integrate(m, q, v, -h).data());
      const Transform X = joint_transform(m.joint(0), q.data());
      const Mat3 W = X.R.transpose() * (Xp.R - Xm.R) / (2 * h);
      const Vec3 p_dot = X.R.transpose() * (Xp.p - Xm.p) / (2 * h);
      const Mat6 S = joint_motion_subspace(m.joint(0), q.data());
      const Vec6 expected = S.leftCols(m.nv()) * v;
      EXPECT_MATRIX_NEAR(Vec3(W(2, 1), W(0, 2), W(1, 0)), expected.head<3>(), 1e-8)
          << joint_type_name(type);
      EXPECT_MATRIX_NEAR(p_dot, expected.tail<3>(), 1e-8) << joint_type_name(type);
    }
  }
}

// integrate uses the exponential map: a constant body rate ω for time t turns a spherical joint
// by exactly |ω| t about ω; configuration_rate is the derivative of integrate at dt = 0.
TEST(Joint, ExponentialMapIntegration) {
  ModelBuilder b;
  b.add_body("ball", inertia::MassProperties(1.0, Vec3::Zero(), Mat3::Identity()));
  Joint j;
  j.name = "j";
  j.type = JointType::spherical;
  j.parent = "world";
  j.child = "ball";
  b.add_joint(j);
  const Model m = b.build();
  const Vec3 w(0.3, -1.2, 2.0);
  const VecX q = integrate(m, neutral(m), VecX(w), 2.5);
  const Mat3 R = Quat(q[0], q[1], q[2], q[3]).toRotationMatrix();
  EXPECT_MATRIX_NEAR(R, rotation_from_axis_angle(w, w.norm() * 2.5), 1e-14);
  EXPECT_NEAR(q.norm(), 1.0, 1e-15);
  VecX qdot;
  configuration_rate(m, q, VecX(w), qdot);
  const double h = 1e-6;
  const VecX fd = (integrate(m, q, VecX(w), h) - integrate(m, q, VecX(w), -h)) / (2 * h);
  EXPECT_MATRIX_NEAR(qdot, fd, 1e-9);
  // difference is the logarithm.
  EXPECT_MATRIX_NEAR(difference(m, neutral(m), integrate(m, neutral(m), VecX(w), 1.0)), w, 1e-14);
  VecX bad = q;
  bad.setZero();
  EXPECT_THROW(normalize(m, bad), NumericalError);
}

}  // namespace
}  // namespace momenta::model
