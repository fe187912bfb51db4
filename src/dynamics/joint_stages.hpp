#pragma once
// The stages of a joint's motion (private to src/dynamics), for the analytic derivatives
// (rnea_derivatives.hpp): a multi-dof joint is a sequence of stages whose motion-subspace columns
// are fixed in the frame the stage moves, each stage moving the next. Perturbing a coordinate
// moves its own stage's columns, the later stages' and everything below the joint rigidly; the
// earlier stages' columns stay.

#include "momenta/dynamics/data.hpp"
#include "momenta/model/joint.hpp"
#include "momenta/model/model.hpp"

namespace momenta::dynamics::detail {

/// The stage of velocity coordinate k of a joint of this type.
inline int joint_stage(model::JointType type, int k) {
  switch (type) {
    case model::JointType::universal:
      return k;  // the first axis, then the second, turned by the first
    case model::JointType::planar:
      return k == 2 ? 1 : 0;  // x and y in the parent, then the turn
    case model::JointType::free:
      return k < 3 ? 1 : 0;  // the translation in the parent, then the rotation in the child
    default:
      return 0;  // revolute, prismatic, cylindrical, spherical: one stage
  }
}

/// How many stages a joint of this type has.
inline int joint_stage_count(model::JointType type) {
  switch (type) {
    case model::JointType::universal:
    case model::JointType::planar:
    case model::JointType::free:
      return 2;
    default:
      return 1;
  }
}

/// The stage of velocity coordinate k (an index into v) seen from joint c, k being c's own or one
/// of an ancestor's: its stage in c, or −1 for an ancestor's (every stage of which moves c).
/// Coordinate k moves c's coordinate m exactly when support_stage(c, k) ≤ c's stage of m.
inline int support_stage(const model::JointConstants& c, int k) {
  return k >= c.v_index ? joint_stage(c.type, k - c.v_index) : -1;
}

/// True when velocity coordinate k moves body b (k's joint is on b's path to the world; never
/// for the world itself).
inline bool supports(const Data& data, int b, int k) {
  if (b == 0) return false;
  for (const auto& [start, length] : data.support_ranges[b - 1]) {
    if (k >= start && k < start + length) return true;
  }
  return false;
}

}  // namespace momenta::dynamics::detail
