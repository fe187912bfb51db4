#pragma once
// Analytic derivatives of the generalized force the force elements apply,
//
//     Q(q, v) = τ_elements + Σ_b J_bᵀ f_ext[b]     (force_element_forces, signals held),
//
// along the configuration's tangent (as rnea_derivatives.hpp) and the velocities: joint springs,
// dampers and friction on their coordinates; linear spring-dampers between points, two-body
// torsional springs, and applied forces and torques (world loads keep their direction, follower
// loads turn with their body) through the bodies they act on.
//
// Method. Coordinate k moves every body it supports rigidly by its world column S_k (and changes
// its velocity by S_k × V + ΔV_k, rnea_derivatives.hpp); each element's world force or moment
// changes accordingly (a spring through both points' motion, a world load not at all), and
// Q_m = Σ S_mᵀ w_b changes by S_mᵀ of the part of that change a load fixed in its body would not
// have, plus, where S_m itself stays and the loaded body moves, S_mᵀ (S_k ×* w_b).

#include <span>

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// ∂Q/∂q (tangent space) and ∂Q/∂v (each nv × nv) of the force elements' generalized force at
/// the (q, v) of the last rnea_derivatives with the given signal values (force_elements.hpp), into
/// data.dQ_dq and data.dQ_dv. Preconditions: rnea_derivatives(model, data, q, v, ·) has run (its
/// world-frame poses, velocities and columns are read). Throws InvalidArgument when signal_values
/// has fewer entries than the model's signals. No allocation.
void force_element_derivatives(const Model& model, Data& data,
                               std::span<const double> signal_values);

}  // namespace momenta::dynamics
