#pragma once
// The joint-space mass matrix by the composite-rigid-body algorithm (Featherstone 2008, §6.2,
// Table 6.2).

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// M(q) (nv × nv, symmetric positive definite for a valid model, both triangles filled), with
/// kinetic energy ½ vᵀ M v. Writes and returns data.M; sets data.X_PB and data.S. No allocation.
const MatX& crba(const Model& model, Data& data, VecRef q);

/// Allocating convenience form of crba.
MatX mass_matrix(const Model& model, VecRef q);

/// Checks that M(q) of the coordinates that are not prescribed is positive definite, so that
/// forward dynamics has a unique answer. Throws InvalidArgument naming the first coordinate along
/// which no inertia resists the motion — a body with zero inertia about an axis its joint lets it
/// turn about (a slender rod or a point mass spinning about itself), or a massless body carrying
/// degrees of freedom — with the pivot that vanished, its joint ("joint 'pivot': ...") and a
/// hint; Error::item() names the joint. A pivot of the Cholesky factorization in coordinate order
/// counts as vanished when it is below 1e-12 of its own diagonal entry M_ii, or below 1e-14 of the
/// largest diagonal entry (round-off in a singular M is far smaller — a rod turned 90° about its
/// axis leaves 1e-33 of m L²; a physically lopsided but valid inertia ratio is far larger).
/// Allocates: a model check, not a hot path.
void check_mass_matrix(const Model& model, VecRef q);

}  // namespace momenta::dynamics
