#pragma once
// The model's force elements evaluated at one instant: springs, dampers, joint friction and applied
// loads (model/force_element.hpp), plus each joint's own viscous `damping`, as generalized forces
// on the joints and wrenches on the bodies — the inputs τ and f_ext of aba, rnea and
// hybrid_dynamics. Also the potential energy the springs store and the power the elements deliver.
//
// Conventions. τ has size nv; f_ext has num_bodies() wrenches, f_ext[b] on body b expressed in B
// about Bo ([moment; force]), the convention of rnea.hpp. The signals that scale applied loads are
// passed in already evaluated — `signal_values[i]` is the value of model.signals()[i] — so a
// caller can evaluate them once per instant, or perturb them (linearization).

#include <span>

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// Writes the generalized forces of every force element at (q, v) with the given signal values:
///  - on the joints, into tau (size nv): joint damping −c v, joint friction −c v, torsional
///    springs on 1-dof joints −k (q − rest) − c q̇, fixed tendons −cᵢ T on each of their joints;
///  - on the bodies, into f_ext (num_bodies() entries): linear spring-dampers between two points,
///    two-body torsional springs, applied forces and torques (scaled by their signal's value).
/// Both outputs are overwritten (zeroed first); tau is resized to nv if it is not (allocating
/// only then). Preconditions: forward_kinematics(model, data, q, v) has run (the elements on
/// bodies read its poses and velocities; the joint elements read only q and v). Throws
/// InvalidArgument when f_ext does not have num_bodies() entries or signal_values fewer than
/// the model's signals. No allocation.
///
/// A linear spring whose two points coincide has no direction: its k ℓ u = k d part is exact (zero
/// there), and the parts that need u — the push k ℓ0 u of a compressed spring, the damper c ℓ̇ u —
/// are left out at that instant rather than made NaN.
void force_element_forces(const Model& model, const Data& data,
                          std::span<const double> signal_values, VecRef q, VecRef v, VecX& tau,
                          std::span<Vec6> f_ext);

/// The generalized forces and body wrenches of model.force_elements()[element] alone (the joints'
/// own damping left out), in the outputs and conventions of force_element_forces: what a
/// free-body diagram draws element by element. Throws InvalidArgument for an index out of range.
/// No allocation.
void force_element_forces_of(const Model& model, const Data& data, int element,
                             std::span<const double> signal_values, VecRef q, VecRef v, VecX& tau,
                             std::span<Vec6> f_ext);

/// A fixed tendon's length L = offset + Σ cᵢ qᵢ and its rate L̇ = Σ cᵢ q̇ᵢ.
double tendon_length(const Model& model, const model::FixedTendon& tendon, VecRef q);
double tendon_rate(const Model& model, const model::FixedTendon& tendon, VecRef v);

/// Potential energy stored in the springs (linear, torsional and tendons') at configuration q
/// (J).
/// Preconditions: forward_kinematics(model, data, q) has run.
double spring_potential_energy(const Model& model, const Data& data, VecRef q);

/// Power the force elements deliver to the system at (q, v) (W): τ·v plus, for every body
/// load, the wrench's power on its body's velocity. Negative for dampers and friction; equals
/// −d(spring energy)/dt for the conservative springs. Preconditions: forward_kinematics(model,
/// data, q, v) has run; tau and f_ext as force_element_forces wrote them.
double force_element_power(const Model& model, const Data& data, VecRef v, VecRef tau,
                           std::span<const Vec6> f_ext);

/// True when no force element dissipates or injects energy: every damping and friction
/// coefficient is zero and there are no applied forces or torques. Together with no prescribed
/// joints this makes the model conservative (kinetic + gravity + spring energy is constant).
bool force_elements_conservative(const Model& model);

}  // namespace momenta::dynamics
