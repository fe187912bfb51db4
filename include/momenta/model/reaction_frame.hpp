#pragma once
// The frame a joint reaction is expressed in: part of what a user asks to record (an output's
// `frame:`), and of what dynamics::joint_reaction computes.

namespace momenta::model {

/// Frame in which a reaction is expressed.
enum class ReactionFrame {
  joint,   ///< The child-side joint frame J'.
  child,   ///< The child body frame C.
  parent,  ///< The parent body frame P.
  world,   ///< The world frame W.
};

}  // namespace momenta::model
