#pragma once
// The planar two-link arm of the robotics texts, closed form (Spong, Hutchinson & Vidyasagar,
// Robot Modeling and Control, 2006, §7.4.1), with both angles from the downward vertical about
// y and the elbow angle relative to the upper link:
//   d11 = m1 lc1² + m2 (l1² + lc2² + 2 l1 lc2 cos θ2) + I1 + I2,
//   d12 = m2 (lc2² + l1 lc2 cos θ2) + I2,   d22 = m2 lc2² + I2,   h = m2 l1 lc2 sin θ2,
//   τ1 = d11 θ̈1 + d12 θ̈2 − h (2 θ̇1 θ̇2 + θ̇2²) + (m1 lc1 + m2 l1) g sin θ1 + m2 lc2 g sin(θ1 + θ2),
//   τ2 = d12 θ̈1 + d22 θ̈2 + h θ̇1² + m2 lc2 g sin(θ1 + θ2).
// I1, I2 about each link's centre of mass, about y; lc the centre's distance from the link's
// joint along the link.

#include <cmath>

#include "momenta/model/model_builder.hpp"
#include "momenta_test/hand_models.hpp"

namespace momenta::test {

struct TwoLinkArm {
  double m1 = 2.0, l1 = 0.8, lc1 = 0.35, I1 = 0.12;
  double m2 = 1.5, lc2 = 0.4, I2 = 0.06;
  double g = 9.81;

  /// The arm as a momenta model: bodies "upper", "lower" on revolute joints "shoulder",
  /// "elbow" about y, links hanging along −z at zero angles. Gravity −g ẑ, or along the joints'
  /// axes (−g ŷ: it then does no work on the arm) when `gravity_along_axes`.
  Model model(bool gravity_along_axes = false) const {
    ModelBuilder b;
    b.set_gravity(gravity_along_axes ? Vec3(0, -g, 0) : Vec3(0, 0, -g));
    // The moments about x and z are any a body can have with I_yy = I: they never show.
    b.add_body("upper",
               inertia::MassProperties(m1, Vec3(0, 0, -lc1), Vec3(I1, I1, 0.02).asDiagonal()));
    b.add_body("lower",
               inertia::MassProperties(m2, Vec3(0, 0, -lc2), Vec3(I2, I2, 0.01).asDiagonal()));
    b.add_joint(make_joint("shoulder", JointType::revolute, "world", "upper"));
    b.add_joint(make_joint("elbow", JointType::revolute, "upper", "lower", Vec3::UnitY(),
                           Transform::translation(Vec3(0, 0, -l1))));
    return b.build();
  }

  /// τ of the closed form at (θ, θ̇, θ̈), gravity in the plane.
  Eigen::Vector2d torque(const Eigen::Vector2d& q, const Eigen::Vector2d& v,
                         const Eigen::Vector2d& a) const {
    const double c2 = std::cos(q[1]), h = m2 * l1 * lc2 * std::sin(q[1]);
    const double d11 = m1 * lc1 * lc1 + m2 * (l1 * l1 + lc2 * lc2 + 2 * l1 * lc2 * c2) + I1 + I2;
    const double d12 = m2 * (lc2 * lc2 + l1 * lc2 * c2) + I2;
    const double d22 = m2 * lc2 * lc2 + I2;
    const double g2 = m2 * lc2 * g * std::sin(q[0] + q[1]);
    return {d11 * a[0] + d12 * a[1] - h * (2 * v[0] * v[1] + v[1] * v[1]) +
                (m1 * lc1 + m2 * l1) * g * std::sin(q[0]) + g2,
            d12 * a[0] + d22 * a[1] + h * v[0] * v[0] + g2};
  }
};

}  // namespace momenta::test
