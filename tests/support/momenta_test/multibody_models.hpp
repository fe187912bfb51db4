#pragma once
// Multibody models for the dynamics tests and benchmarks: serial chains, and random trees with
// every joint type, random frames, axes and mass properties, from a fixed seed.

#include <cmath>
#include <random>
#include <string>

#include <fmt/format.h>

#include "momenta/math/rotation.hpp"
#include "momenta/math/spatial.hpp"
#include "momenta/model/model_builder.hpp"

namespace momenta::test {

using model::Joint;
using model::JointType;
using model::Model;
using model::ModelBuilder;

/// A uniform random unit quaternion (Shoemake).
template <class Rng>
Quat random_quaternion(Rng& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double u1 = u(rng), u2 = 2 * M_PI * u(rng), u3 = 2 * M_PI * u(rng);
  return Quat(std::sqrt(u1) * std::cos(u3), std::sqrt(1 - u1) * std::sin(u2),
              std::sqrt(1 - u1) * std::cos(u2), std::sqrt(u1) * std::sin(u3));
}

template <class Rng>
Vec3 random_unit(Rng& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Vec3 a(n(rng), n(rng), n(rng));
  return a / a.norm();
}

/// Random physical mass properties: mass in [0.5, 2] kg, centre of mass within 0.2 m, principal
/// moments in [0.01, 0.1] kg·m² kept well inside the triangle inequality, random principal axes.
template <class Rng>
inertia::MassProperties random_mass_properties(Rng& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double m = 0.5 + 1.5 * u(rng);
  const Vec3 c(0.4 * u(rng) - 0.2, 0.4 * u(rng) - 0.2, 0.4 * u(rng) - 0.2);
  const Vec3 moments(0.05 + 0.05 * u(rng), 0.05 + 0.05 * u(rng), 0.05 + 0.05 * u(rng));
  const Mat3 R = random_quaternion(rng).toRotationMatrix();
  return {m, c, R * moments.asDiagonal() * R.transpose()};
}

template <class Rng>
Transform random_transform(Rng& rng, double reach) {
  std::uniform_real_distribution<double> u(-reach, reach);
  return {random_quaternion(rng).toRotationMatrix(), Vec3(u(rng), u(rng), u(rng))};
}

/// Every joint type, in random_tree's default order.
inline std::vector<JointType> all_joint_types() {
  return {JointType::revolute,    JointType::free,      JointType::prismatic, JointType::spherical,
          JointType::cylindrical, JointType::universal, JointType::fixed,     JointType::planar};
}

/// A random tree of n bodies; joint k has type types[k % types.size()] (all eight by default),
/// a random parent among the bodies before it (the world for the first), random X_PJ and X_CJ,
/// random unit axes; armature (Joint::armature, kg·m² or kg) `armature` · (1 + k mod 3) on joint
/// k when given (drawing no random numbers, so the tree is otherwise the same). Fixed seed → the
/// same tree every run.
inline Model random_tree(int n, unsigned seed, std::vector<JointType> types = all_joint_types(),
                         const Vec3& gravity = Vec3(0, 0, -9.81), double armature = 0.0) {
  std::mt19937 rng(seed);
  ModelBuilder builder;
  builder.set_gravity(gravity);
  for (int k = 0; k < n; ++k) {
    // fmt::format rather than "b" + std::to_string(k): GCC 12 raises a false -Wrestrict on the
    // inlined operator+ (GCC bug 105329).
    const std::string name = fmt::format("b{}", k);
    builder.add_body(name, random_mass_properties(rng));
    Joint j;
    j.name = fmt::format("j{}", k);
    j.type = types[k % types.size()];
    j.parent = k == 0 ? "world"
                      : fmt::format("b{}", std::uniform_int_distribution<int>(std::max(0, k - 3),
                                                                              k - 1)(rng));
    j.child = name;
    j.X_PJ = random_transform(rng, 0.3);
    j.X_CJ = random_transform(rng, 0.2);
    j.axis = random_unit(rng);
    Vec3 a2 = random_unit(rng);
    j.axis2 = (a2 - a2.dot(j.axis) * j.axis).normalized();  // well away from parallel
    j.armature = armature * (1 + k % 3);
    builder.add_joint(j);
  }
  return builder.build();
}

/// A random configuration: uniform angles and displacements in [−1, 1], random unit quaternions.
template <class Rng>
VecX random_configuration(const Model& m, Rng& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  VecX q(m.nq());
  for (int i = 0; i < m.nq(); ++i) q[i] = u(rng);
  for (const Joint& j : m.joints()) {
    const int k = j.type == JointType::spherical ? 0 : (j.type == JointType::free ? 3 : -1);
    if (k < 0) continue;
    const Quat r = random_quaternion(rng);
    q.segment<4>(j.q_index + k) << r.w(), r.x(), r.y(), r.z();
  }
  return q;
}

template <class Rng>
VecX random_vector(int n, Rng& rng, double scale = 1.0) {
  std::uniform_real_distribution<double> u(-scale, scale);
  VecX x(n);
  for (int i = 0; i < n; ++i) x[i] = u(rng);
  return x;
}

/// The benchmark chain: n revolute links, each a 1 kg solid cylinder of length 0.1 m and radius
/// 0.01 m along its x axis (centre of mass at x = 0.05 m), joint k + 1 at the end of link k,
/// axes alternating z and y; gravity −9.81 ẑ.
inline Model revolute_chain(int n) {
  ModelBuilder builder;
  const double m = 1.0, L = 0.1, r = 0.01;
  const double Ixx = 0.5 * m * r * r;
  const double Iyy = m * (3 * r * r + L * L) / 12.0;
  for (int k = 0; k < n; ++k) {
    const std::string name = "link" + std::to_string(k);
    builder.add_body(name,
                     inertia::MassProperties(m, Vec3(L / 2, 0, 0),
                                             Vec3(Ixx, Iyy, Iyy).asDiagonal().toDenseMatrix()));
    Joint j;
    j.name = "joint" + std::to_string(k);
    j.type = JointType::revolute;
    j.parent = k == 0 ? "world" : "link" + std::to_string(k - 1);
    j.child = name;
    j.X_PJ = Transform::translation(k == 0 ? Vec3::Zero() : Vec3(L, 0, 0));
    j.axis = k % 2 == 0 ? Vec3::UnitZ() : Vec3::UnitY();
    builder.add_joint(j);
  }
  return builder.build();
}

/// The peer figures' tumbling body (/work/shared/references.md): I = diag(1, 2, 3) kg·m² on a free
/// joint to the world, ω0 = (0.01, 2, 0.01) rad/s near the intermediate axis (it flips), no
/// gravity. B is principal and every placement the identity, so w_WB_B is v[0..2] and R_WB the
/// joint's quaternion q[3..6].
inline Model tumbling_free_body() {
  Joint joint;
  joint.name = "free";
  joint.type = JointType::free;
  joint.parent = "world";
  joint.child = "racket";
  joint.v0 = VecX::Zero(6);
  joint.v0.head<3>() = Vec3(0.01, 2.0, 0.01);
  return ModelBuilder()
      .set_gravity(Vec3::Zero())
      .add_body("racket", inertia::MassProperties(1.0, Vec3::Zero(), Vec3(1, 2, 3).asDiagonal()))
      .add_joint(joint)
      .build();
}

}  // namespace momenta::test
