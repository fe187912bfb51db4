// Points fixed in a body: a spinning disk (centripetal and tangential terms) and the tip of a
// double pendulum (Coriolis term in J̇ v).
#include "momenta/dynamics/point_kinematics.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics {
namespace {

TEST(PointKinematics, SpinningDisk) {
  model::ModelBuilder b;
  b.add_body("disk", inertia::MassProperties(1.0, Vec3::Zero(), 0.1 * Mat3::Identity()));
  b.add_joint(test::make_joint("axle", model::JointType::revolute, "world", "disk", Vec3::UnitZ()));
  const Model model = b.build();
  Data data(model);
  const double theta = 0.5, w = 3.0, alpha = -2.0;
  const Vec3 p_B(0.3, 0.0, 0.1);
  const PointKinematics k =
      point_kinematics(model, data, VecX::Constant(1, theta), VecX::Constant(1, w),
                       VecX::Constant(1, alpha), 1, p_B);
  const Vec3 r(0.3 * std::cos(theta), 0.3 * std::sin(theta), 0.1);
  EXPECT_MATRIX_NEAR(k.p_WoP_W, r, 1e-15);
  EXPECT_MATRIX_NEAR(k.v_WP_W, w * Vec3(-r.y(), r.x(), 0), 1e-15);
  EXPECT_MATRIX_NEAR(k.centripetal, -w * w * Vec3(r.x(), r.y(), 0), 1e-14);
  EXPECT_MATRIX_NEAR(k.tangential, alpha * Vec3(-r.y(), r.x(), 0), 1e-15);
  EXPECT_MATRIX_NEAR(k.a_WBo_W, Vec3::Zero(), 1e-15);
  EXPECT_MATRIX_NEAR(k.velocity_product, k.centripetal, 1e-15);
  EXPECT_MATRIX_NEAR(k.from_vdot, k.tangential, 1e-15);
}

// Tip p = l1 u(θ1) + l2 u(φ), φ = θ1 + θ2, u(φ) = (−sin φ, 0, −cos φ), u' = (−cos φ, 0, sin φ),
// u'' = −u:  a = l1 (u'(θ1) θ̈1 − u(θ1) θ̇1²) + l2 (u'(φ) φ̈ − u(φ) φ̇²). The velocity-product part
// −l1 u θ̇1² − l2 u (θ̇1 + θ̇2)² holds the Coriolis term −2 l2 u θ̇1 θ̇2.
TEST(PointKinematics, DoublePendulumTipWithCoriolis) {
  const double l1 = 0.6, l2 = 0.45;
  const Model model = test::double_pendulum(1.0, 1.0, l1, l2);
  Data data(model);
  const VecX q = (VecX(2) << 0.4, -0.9).finished();
  const VecX v = (VecX(2) << 1.3, 2.1).finished();
  const VecX a = (VecX(2) << -0.7, 0.5).finished();
  const auto u = [](double f) { return Vec3(-std::sin(f), 0, -std::cos(f)); };
  const auto du = [](double f) { return Vec3(-std::cos(f), 0, std::sin(f)); };
  const double phi = q[0] + q[1], phid = v[0] + v[1], phidd = a[0] + a[1];
  const PointKinematics k = point_kinematics(model, data, q, v, a, 2, Vec3(0, 0, -l2));
  EXPECT_MATRIX_NEAR(k.p_WoP_W, l1 * u(q[0]) + l2 * u(phi), 1e-15);
  EXPECT_MATRIX_NEAR(k.v_WP_W, l1 * du(q[0]) * v[0] + l2 * du(phi) * phid, 1e-15);
  EXPECT_MATRIX_NEAR(k.from_vdot, l1 * du(q[0]) * a[0] + l2 * du(phi) * phidd, 1e-14);
  EXPECT_MATRIX_NEAR(k.velocity_product, -l1 * u(q[0]) * v[0] * v[0] - l2 * u(phi) * phid * phid,
                     1e-14);
  EXPECT_MATRIX_NEAR(k.a_WP_W, k.from_vdot + k.velocity_product, 1e-15);
  MatX J(6, 2);
  frame_jacobian(model, data, 2, Vec3(0, 0, -l2), J);
  EXPECT_MATRIX_NEAR(J.bottomRows<3>().col(1), l2 * du(phi), 1e-15);
  EXPECT_THROW(point_kinematics(model, static_cast<const Data&>(data), 7, Vec3::Zero()),
               InvalidArgument);
}

}  // namespace
}  // namespace momenta::dynamics
