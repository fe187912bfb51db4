#pragma once
// A tree of five joint types with one constraint of every kind, and random (inconsistent)
// states of it: the fixture of the constraint rows' tests (dynamics/constraints.hpp and
// constraint_derivatives.hpp).

#include <random>

#include <Eigen/Geometry>

#include "momenta/inertia/primitives.hpp"
#include "momenta/model/model_builder.hpp"

namespace momenta::test {

using model::JointType;

// A joint of `type` from parent to child at `at` (in the parent) about or along `axis` (a
// universal joint's second axis: y).
inline void add_joint(model::ModelBuilder& b, const char* name, JointType type, const char* parent,
                      const char* child, const Vec3& at, const Vec3& axis) {
  model::Joint j;
  j.name = name;
  j.type = type;
  j.parent = parent;
  j.child = child;
  j.X_PJ = Transform::translation(at);
  j.axis = axis;
  b.add_joint(j);
}

// Five boxes on revolute, spherical, free, prismatic and planar joints.
inline void add_tree_of_joint_types(model::ModelBuilder& b) {
  const auto box = inertia::box(inertia::Amount::mass(1.0), Vec3(0.1, 0.2, 0.3));
  for (const char* name : {"b1", "b2", "b3", "b4", "b5"}) b.add_body(name, box);
  add_joint(b, "j1", JointType::revolute, "world", "b1", Vec3::Zero(), Vec3::UnitZ());
  add_joint(b, "j2", JointType::spherical, "b1", "b2", Vec3(0.3, 0, 0), Vec3::UnitZ());
  add_joint(b, "j3", JointType::free, "world", "b3", Vec3::Zero(), Vec3::UnitZ());
  add_joint(b, "j4", JointType::prismatic, "world", "b4", Vec3(0, 1, 0), Vec3(0.6, 0.8, 0));
  add_joint(b, "j5", JointType::planar, "world", "b5", Vec3::Zero(), Vec3::UnitZ());
}

inline model::BodyFrame frame(const char* body, const Transform& X_BF) {
  return model::BodyFrame{body, X_BF, -1};
}

inline model::Model every_constraint_model() {
  model::ModelBuilder b;
  add_tree_of_joint_types(b);
  const Transform X(Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()).toRotationMatrix(),
                    Vec3(0.1, -0.2, 0.05));
  b.add_constraint(
      model::LoopClosure{"weld", model::LoopType::weld, frame("b2", X), frame("b3", {})});
  b.add_constraint(
      model::LoopClosure{"ball", model::LoopType::point, frame("b1", X), frame("b3", X)});
  b.add_constraint(model::LoopClosure{"pin", model::LoopType::hinge, frame("world", X),
                                      frame("b3", X.inverse())});
  b.add_constraint(
      model::LoopClosure{"slide", model::LoopType::slider, frame("b2", {}), frame("b4", X)});
  b.add_constraint(model::DistanceLink{"wire", frame("b1", X), frame("b3", {}), 0.5});
  b.add_constraint(model::RollingContact{"wheel", frame("b3", X), model::RollingShape::disk, 0.2,
                                         Vec3(0, 0.6, 0.8), Vec3(0, 0, -0.1)});
  b.add_constraint(model::RollingContact{"ball_roll", frame("b2", X), model::RollingShape::sphere,
                                         0.1, Vec3::UnitZ(), Vec3::Zero()});
  b.add_constraint(model::KnifeEdge{"blade", frame("b5", X), Vec3::UnitZ()});
  b.add_constraint(model::JointCoupler{"gear", "j1", "j4", -1.7, 0.2});
  return b.build();
}

struct RandomState {
  VecX q, v, vdot;
};

inline RandomState random_state(const model::Model& model, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  RandomState s;
  s.q = VecX::NullaryExpr(model.nq(), [&] { return u(rng); });
  model::normalize(model, s.q);
  s.v = VecX::NullaryExpr(model.nv(), [&] { return 2 * u(rng); });
  s.vdot = VecX::NullaryExpr(model.nv(), [&] { return 3 * u(rng); });
  return s;
}

}  // namespace momenta::test
