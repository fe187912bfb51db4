#pragma once
// The stages of a joint's motion (private to src/dynamics), for the analytic derivatives
// (rnea_derivatives.hpp): a multi-dof joint is a sequence of stages whose motion-subspace columns
// are fixed in the frame the stage moves, each stage moving the next. Perturbing a coordinate
// moves its own stage's columns, the later stages' and everything below the joint rigidly; the
// earlier stages' columns stay. Also what that does to the bodies it moves (body_motion_rate),
// shared by the derivatives of the force elements and of the constraint rows.

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
    case model::JointType::fixed:
    case model::JointType::revolute:
    case model::JointType::prismatic:
    case model::JointType::cylindrical:
    case model::JointType::spherical:
      return 0;  // one stage
  }
  return 0;  // not reached: every type is named above
}

/// How many stages a joint of this type has.
inline int joint_stage_count(model::JointType type) {
  switch (type) {
    case model::JointType::universal:
    case model::JointType::planar:
    case model::JointType::free:
      return 2;
    case model::JointType::fixed:
    case model::JointType::revolute:
    case model::JointType::prismatic:
    case model::JointType::cylindrical:
    case model::JointType::spherical:
      return 1;
  }
  return 1;  // not reached: every type is named above
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

/// Which derivative: along the configuration's tangent δq_k or along the velocity v_k.
enum class Along { configuration, velocity };

/// How body b's motion changes along coordinate k, from the terms rnea_derivatives leaves in
/// Data (W, about Wo): the twist its pose moves by, and the rates of its spatial velocity and of
/// its acceleration (dA_W's, shifted by −g; the shift's rate is zero). Coordinate k moves the
/// bodies below its stage rigidly along S_k:
///   along δq_k   twist S_k,  ∂V = S_k × V + ΔV_k,  ∂A = S_k × A + ΔV_k × V + x_k;
///   along v_k    no twist,   ∂V = S_k,             ∂A = S_k × V + W_k.
/// All zero where k does not support b.
struct BodyMotionRate {
  Vec6 twist = Vec6::Zero();
  Vec6 V = Vec6::Zero();
  Vec6 A = Vec6::Zero();
};

inline BodyMotionRate body_motion_rate(const Data& data, int b, int k, Along along) {
  BodyMotionRate rate;
  if (!supports(data, b, k)) return rate;
  const Vec6 S = data.dS_W.col(k);
  if (along == Along::configuration) {
    const Vec6 delta_V = data.dDeltaV_W.col(k);
    rate.twist = S;
    rate.V = cross_motion(S, data.dV_W[b]) + delta_V;
    rate.A = cross_motion(S, data.dA_W[b]) + cross_motion(delta_V, data.dV_W[b]) + data.dX_W.col(k);
  } else {
    rate.V = S;
    rate.A = cross_motion(S, data.dV_W[b]) + data.dW_W.col(k);
  }
  return rate;
}

/// Whether coordinate k moves the motion-subspace column of coordinate j, both supporting one
/// body: k in an ancestor joint, or in j's joint at j's stage or an earlier one.
inline bool moves_column(const Model& model, int k, int j) {
  const model::JointConstants& c = model.joint_constants()[model.joint_of_v(j)];
  return k < c.v_index + c.nv && support_stage(c, k) <= joint_stage(c.type, j - c.v_index);
}

}  // namespace momenta::dynamics::detail
