#pragma once
// The motion of a prescribed joint from its signals: q, v and v̇ of its coordinates.
//
// A prescribed joint names one signal per velocity coordinate (Joint::prescribed_signals, in the
// order of v):
//  - revolute, prismatic, cylindrical, universal, planar (nq == nv): each signal is its
//    coordinate, q = u, v = u̇, v̇ = ü;
//  - spherical: three signals φ = (φx, φy, φz) are the rotation vector of J' in J (exponential
//    coordinates: q_JJ' = Exp(φ), a turn of |φ| about φ/|φ|); v = w_JJ'_J' = J_r(φ) φ̇ and
//    v̇ = J_r(φ) φ̈ + J̇_r φ̇ (math/lie_group.hpp). A spin at rate Ω about a fixed unit axis n is
//    φ = n Ω t; any other smooth rotation is some φ(t) with |φ| < 2π;
//  - free: six signals, the rotation vector φ then the position p_JoJ'o_J (rotation first, as in
//    v): q = [p; Exp(φ)], v = [J_r(φ) φ̇; ṗ].

#include <span>

#include "momenta/model/joint.hpp"
#include "momenta/model/signal.hpp"

namespace momenta::model {

/// Writes the joint's nq coordinates at `q`, nv speeds at `v` and, when `vdot` is not null, nv
/// accelerations at `vdot` from the samples of every signal of the model (indexed as
/// Model::signals(); the joint reads those of its prescribed_signal_indices). Preconditions: the
/// joint is prescribed and built. Does not allocate.
void prescribed_joint_motion(const Joint& joint, std::span<const SignalSample> signal_samples,
                             double* q, double* v, double* vdot);

}  // namespace momenta::model
