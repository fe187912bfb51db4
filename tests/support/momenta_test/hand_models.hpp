#pragma once
// Small models with closed-form dynamics for the unit tests, and the builders of their joints and
// force elements. Rotations about y carry a body frame whose −z axis hangs down at θ = 0:
// R_y(θ) (0, 0, −l) = (−l sin θ, 0, −l cos θ).

#include <string>
#include <vector>

#include "momenta/model/model_builder.hpp"

namespace momenta::test {

using model::Joint;
using model::JointType;
using model::Model;
using model::ModelBuilder;

/// A joint of `type` from `parent` to `child` about (or along) `axis`, its frame at X_PJ in the
/// parent; every other field at its default.
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

/// A torsional spring–damper (stiffness k, damping c) on the 1-dof joint `joint`, at rest at
/// `rest`.
inline model::TorsionalSpringDamper joint_spring(std::string name, std::string joint, double k,
                                                 double c, double rest) {
  model::TorsionalSpringDamper t;
  t.name = std::move(name);
  t.joint = std::move(joint);
  t.stiffness = k;
  t.damping = c;
  t.rest_angle = rest;
  return t;
}

/// A fixed tendon L = offset + Σ cᵢ qᵢ over (joint, cᵢ) terms, with a spring–damper (k, c) relaxed
/// at `rest`.
inline model::FixedTendon fixed_tendon(std::string name, std::vector<model::TendonTerm> terms,
                                       double offset, double k, double c, double rest) {
  model::FixedTendon t;
  t.name = std::move(name);
  t.terms = std::move(terms);
  t.offset = offset;
  t.stiffness = k;
  t.damping = c;
  t.rest_length = rest;
  return t;
}

/// A torsional spring–damper (stiffness k, damping c) between bodies a and b.
inline model::TorsionalSpringDamper body_spring(std::string name, std::string a, std::string b,
                                                double k, double c) {
  model::TorsionalSpringDamper t;
  t.name = std::move(name);
  t.body_a = std::move(a);
  t.body_b = std::move(b);
  t.stiffness = k;
  t.damping = c;
  return t;
}

/// An applied force `vector` (in `frame`) at p_BoP_B on `body`, scaled by `signal` ("" for none).
/// (Designated initializers of AppliedForce trip GCC 12's maybe-uninitialized.)
inline model::AppliedForce applied_force(std::string name, std::string body, const Vec3& p_BoP_B,
                                         model::LoadFrame frame, const Vec3& vector,
                                         std::string signal) {
  model::AppliedForce f;
  f.name = std::move(name);
  f.at.body = std::move(body);
  f.at.p_BoP_B = p_BoP_B;
  f.frame = frame;
  f.vector = vector;
  f.signal = std::move(signal);
  return f;
}

/// The builder of a pendulum: body "bob", mass m with its centre l below the pivot and inertia
/// I_c about that centre (isotropic), on the revolute joint "pivot" from the world about `axis`,
/// gravity g along −z. Tests add their inputs and elements before building it.
inline ModelBuilder pendulum_builder(double m, double l, double I_c, double g = 9.81,
                                     const Vec3& axis = Vec3::UnitY()) {
  ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -g));
  b.add_body("bob", inertia::MassProperties(m, Vec3(0, 0, -l), I_c * Mat3::Identity()));
  b.add_joint(make_joint("pivot", JointType::revolute, "world", "bob", axis));
  return b;
}

/// A pendulum about y: mass m with its centre l below the pivot and inertia I_c about y at the
/// centre (isotropic), gravity g along −z.
inline Model pendulum(double m, double l, double I_c, double g = 9.81) {
  return pendulum_builder(m, l, I_c, g).build();
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
