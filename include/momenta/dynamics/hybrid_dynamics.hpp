#pragma once
// Hybrid dynamics: some joints have prescribed motion (given q, v, v̇), the others given forces
// (Featherstone 2008, §9.2: the articulated-body algorithm with known accelerations at the
// prescribed joints).

#include <span>
#include <vector>

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// Solves for the accelerations of the free joints and the generalized forces needed at the
/// prescribed ones. `prescribed` has num_joints() entries (nonzero = prescribed). Inputs (size
/// nv): vdot_in, read at the prescribed joints' coordinates, and tau_in, read at the free ones.
/// Outputs: data.vdot (all coordinates; prescribed ones copied from vdot_in) and data.tau (all
/// coordinates; free ones copied from tau_in, prescribed ones the force the prescription needs).
/// Returns data.vdot. No allocation. Consistency: rnea(q, v, data.vdot) == data.tau.
const VecX& hybrid_dynamics(const Model& model, Data& data, const std::vector<char>& prescribed,
                            VecRef q, VecRef v, VecRef vdot_in, VecRef tau_in,
                            std::span<const Vec6> f_ext = {});

/// As above with the model's own prescribed joints (Joint::is_prescribed()).
const VecX& hybrid_dynamics(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot_in,
                            VecRef tau_in, std::span<const Vec6> f_ext = {});

/// The model's prescribed-joint mask (num_joints() entries) for the first overload.
std::vector<char> prescribed_joint_mask(const Model& model);

}  // namespace momenta::dynamics
