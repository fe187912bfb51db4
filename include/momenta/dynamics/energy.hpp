#pragma once
// Mechanical energies of the bodies (springs' potential energy belongs to the force elements).

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// Kinetic energy T = Σ ½ V_bᵀ I_b V_b + Σ ½ armature_i v_i² = ½ vᵀ M(q) v (J): the bodies' and
/// the rotors' reflected inertia (model::Joint::armature). Runs forward_kinematics(q, v).
double kinetic_energy(const Model& model, Data& data, VecRef q, VecRef v);

/// Gravitational potential energy V = −Σ m_b g · p_WoBcm_W (J), zero with every centre of mass
/// at the world origin. Runs forward_kinematics(q).
double potential_energy(const Model& model, Data& data, VecRef q);

/// From data already filled by forward_kinematics (with that v for the kinetic energy).
double kinetic_energy(const Model& model, const Data& data, VecRef v);
double potential_energy(const Model& model, const Data& data);

}  // namespace momenta::dynamics
