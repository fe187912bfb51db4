// Forward dynamics against closed forms: the cart-pole, a free rigid body (Euler's equations and
// Newton's law for its centre of mass) and a heavy top on a spherical joint.
#include "momenta/dynamics/aba.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "momenta/math/rotation.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics {
namespace {

using model::JointType;

// Cart (mass M, prismatic along x) carrying a pole (mass m, centre l from the pivot, inertia
// I_c), upright at θ = 0: x_c = x + l sin θ, z_c = l cos θ. Lagrange's equations:
//   (M + m) ẍ + m l cos θ θ̈ − m l sin θ θ̇² = F
//   m l cos θ ẍ + (I_c + m l²) θ̈ − m g l sin θ = τ.
TEST(Aba, CartPoleClosedForm) {
  const double M = 1.3, m = 0.4, l = 0.55, I_c = 0.02, g = 9.81;
  model::ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -g));
  b.add_body("cart", inertia::MassProperties(M, Vec3::Zero(), 0.1 * Mat3::Identity()));
  b.add_body("pole", inertia::MassProperties(m, Vec3(0, 0, l), I_c * Mat3::Identity()));
  b.add_joint(test::make_joint("rail", JointType::prismatic, "world", "cart", Vec3::UnitX()));
  b.add_joint(test::make_joint("hinge", JointType::revolute, "cart", "pole", Vec3::UnitY()));
  const Model model = b.build();
  Data data(model);
  for (double theta : {0.0, 0.3, -2.0}) {
    const double w = 1.9, F = 2.5, tau = -0.7;
    const VecX q = (VecX(2) << 0.4, theta).finished();
    const VecX v = (VecX(2) << -0.3, w).finished();
    const VecX u = (VecX(2) << F, tau).finished();
    const double s = std::sin(theta), c = std::cos(theta);
    Eigen::Matrix2d A;
    A << M + m, m * l * c, m * l * c, I_c + m * l * l;
    const Eigen::Vector2d rhs(F + m * l * s * w * w, tau + m * g * l * s);
    const Eigen::Vector2d expected = A.lu().solve(rhs);
    EXPECT_MATRIX_NEAR(aba(model, data, q, v, u), expected, 1e-12);
    EXPECT_MATRIX_NEAR(forward_dynamics(model, q, v, u), expected, 1e-12);
  }
}

// A free body with its centre of mass at its origin: I ω̇ + ω × I ω = n (body frame) and
// m v̇ = R f_B (v is the rate of the position in the world). With an offset centre of mass the
// centre still obeys m a_cm = f.
TEST(Aba, FreeBodyEulerAndNewton) {
  const double mass = 3.0;
  const Mat3 R0 = rotation_from_axis_angle(Vec3(1, 2, 3), 0.8);
  const Mat3 I = R0 * Vec3(1.0, 2.0, 3.0).asDiagonal() * R0.transpose();
  model::ModelBuilder b;
  b.set_gravity(Vec3::Zero());
  b.add_body("body", inertia::MassProperties(mass, Vec3::Zero(), I));
  b.add_joint(test::make_joint("float", JointType::free, "world", "body"));
  const Model model = b.build();
  Data data(model);
  VecX q(7);
  const Quat r = quaternion_exp(Vec3(0.3, -0.2, 0.9));
  q << 1, 2, 3, r.w(), r.x(), r.y(), r.z();
  VecX v(6);
  v << 0.01, 2.0, 0.01, 0.5, -0.4, 0.3;  // ω (body), ṗ (world)
  const Vec3 w = v.head<3>();
  const Vec3 n(0.2, -0.1, 0.4), f(1.0, 2.0, -3.0);
  std::vector<Vec6> f_ext{Vec6::Zero(), spatial(n, f)};
  const VecX vdot = aba(model, data, q, v, VecX::Zero(6), f_ext);
  const Vec3 w_dot = I.ldlt().solve(n - w.cross(I * w));
  EXPECT_MATRIX_NEAR(vdot.head<3>(), w_dot, 1e-13);
  EXPECT_MATRIX_NEAR(vdot.tail<3>(), r.toRotationMatrix() * f / mass, 1e-13);
}

// Heavy top on a ball joint at its tip: Euler's equations about the fixed point,
// I_O ω̇ + ω × I_O ω = c × m Rᵀ g (body frame), I_O the inertia about the pivot.
TEST(Aba, HeavyTopOnSphericalJoint) {
  const double m = 1.2, g = 9.81;
  const Vec3 c(0.02, -0.01, 0.3);
  const Mat3 I_c = Vec3(0.01, 0.012, 0.004).asDiagonal();
  model::ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -g));
  const inertia::MassProperties mp(m, c, I_c);
  b.add_body("top", mp);
  b.add_joint(test::make_joint("tip", JointType::spherical, "world", "top"));
  const Model model = b.build();
  Data data(model);
  const Quat r = quaternion_exp(Vec3(0.4, 0.1, -0.2));
  const VecX q = (VecX(4) << r.w(), r.x(), r.y(), r.z()).finished();
  const VecX v = (VecX(3) << 0.3, -0.2, 40.0).finished();
  const VecX vdot = aba(model, data, q, v, VecX::Zero(3));
  const Mat3 I_O = mp.inertia_about(Vec3::Zero());
  const Vec3 w = v;
  const Vec3 torque = c.cross(m * r.toRotationMatrix().transpose() * Vec3(0, 0, -g));
  const Vec3 expected = I_O.ldlt().solve(torque - w.cross(I_O * w));
  EXPECT_MATRIX_NEAR(vdot, expected, 1e-11);  // ω = 40 rad/s: |ω × Iω| ≈ 10, round-off 1e-14·10³
}

}  // namespace
}  // namespace momenta::dynamics
