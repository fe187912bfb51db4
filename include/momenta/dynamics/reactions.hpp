#pragma once
// Joint reactions: the force and moment each joint transmits from its parent to its child
// (bearing loads of shafts, pin forces), by Newton–Euler on each subtree (the backward pass of
// Featherstone 2008, Table 5.1).

#include <span>

#include "momenta/dynamics/data.hpp"
#include "momenta/model/reaction_frame.hpp"

namespace momenta::dynamics {

using model::ReactionFrame;  // model/reaction_frame.hpp

/// The wrench a joint transmits onto its child: force (N) and moment (N·m) about the origin of
/// the child-side joint frame J' (the joint centre of revolute, universal and spherical joints).
/// It is the whole transmitted wrench: its components along the motion subspace are the joint's
/// generalized force τ (actuation), the rest is the constraint reaction.
struct JointReaction {
  Vec3 force;
  Vec3 moment;
};

/// Computes every joint's transmitted wrench for the motion (q, v, vdot) under gravity and
/// external wrenches f_ext (convention in rnea.hpp); vdot typically comes from aba or
/// hybrid_dynamics. Sets data.F_B, data.X_WB and what rnea sets. No allocation.
void joint_reactions(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot,
                     std::span<const Vec6> f_ext = {});

/// Joint j's reaction from data filled by joint_reactions, expressed in `frame`.
JointReaction joint_reaction(const Model& model, const Data& data, int j, ReactionFrame frame);

}  // namespace momenta::dynamics
