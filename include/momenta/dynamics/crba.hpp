#pragma once
// The joint-space mass matrix by the composite-rigid-body algorithm (Featherstone 2008, §6.2,
// Table 6.2).

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// M(q) (nv × nv, symmetric positive definite for a valid model, both triangles filled), with
/// kinetic energy ½ vᵀ M v. Writes and returns data.M; sets data.X_PB and data.S. No allocation.
const MatX& crba(const Model& model, Data& data, const VecX& q);

/// Allocating convenience form of crba.
MatX mass_matrix(const Model& model, const VecX& q);

}  // namespace momenta::dynamics
