#pragma once
// Small models with closed-form dynamics for the unit tests. Rotations about y carry a body
// frame whose −z axis hangs down at θ = 0: R_y(θ) (0, 0, −l) = (−l sin θ, 0, −l cos θ).

#include <string>

#include "momenta/model/model_builder.hpp"

namespace momenta::test {

using model::Joint;
using model::JointType;
using model::Model;
using model::ModelBuilder;

inline Joint make_joint(std::string name, JointType type, std::string parent, std::string child,
                        const Vec3& axis = Vec3::UnitY(), const Transform& X_PJ = Transform()) {
  Joint j;
  j.name = std::move(name);
  j.type = type;
  j.parent = std::move(parent);
  j.child = std::move(child);
  j.axis = axis;
  j.X_PJ = X_PJ;
  return j;
}

/// A pendulum about y: mass m with its centre l below the pivot and inertia I_c about y at the
/// centre (isotropic), gravity g along −z.
inline Model pendulum(double m, double l, double I_c, double g = 9.81) {
  ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -g));
  b.add_body("bob", inertia::MassProperties(m, Vec3(0, 0, -l), I_c * Mat3::Identity()));
  b.add_joint(make_joint("pivot", JointType::revolute, "world", "bob"));
  return b.build();
}

/// A planar double pendulum of point masses m1, m2 on massless rods l1, l2, both joints about y.
inline Model double_pendulum(double m1, double m2, double l1, double l2, double g = 9.81) {
  ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -g));
  b.add_body("upper", inertia::MassProperties(m1, Vec3(0, 0, -l1), Mat3::Zero()));
  b.add_body("lower", inertia::MassProperties(m2, Vec3(0, 0, -l2), Mat3::Zero()));
  b.add_joint(make_joint("shoulder", JointType::revolute, "world", "upper"));
  b.add_joint(make_joint("elbow", JointType::revolute, "upper", "lower", Vec3::UnitY(),
                         Transform::translation(Vec3(0, 0, -l1))));
  return b.build();
}

}  // namespace momenta::test
