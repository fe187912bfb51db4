#pragma once
// M⁻¹ applied to generalized forces by the articulated-body factors the last aba or
// hybrid_dynamics left in Data: passes 2 and 3 of the articulated-body algorithm again, with no
// velocity, no gravity and no bias force (Featherstone 2008, §7.3, Table 7.1; the response of
// the articulated bodies to test forces, as in the constrained articulated-body algorithms of
// Sathya & Carpentier, "Constrained articulated body dynamics algorithms", 2024). Per column: one
// leaves-to-root pass
//     u_j = x_j − S_jᵀ p_i,   p_λ += ᵖX_i* (p_i + U_j D_j⁻¹ u_j)
// and one root-to-leaves pass
//     a_i = ⁱX_λ a_λ,   ẍ_j = D_j⁻¹ (u_j − U_jᵀ a_i),   a_i += S_j ẍ_j,
// O(n) with 6-vectors only: the 6 × 6 articulated inertias are not formed again. A 1-dof joint
// carries ᵖX_i* U_j D_j⁻¹ to its parent once for both passes, which it then takes as
// p_λ += ᵖX_i* p_i + (ᵖX_i* U_j D_j⁻¹) u_j and ẍ_j = D_j⁻¹ u_j − (ᵖX_i* U_j D_j⁻¹)ᵀ a_λ: the same
// sums, with each column's transform independent of its product with the factor. The constraint
// solver applies it to its rows (M⁻¹ Gᵀ) instead of forming and factorizing M.

#include <span>

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// X ← M(q)⁻¹ X, column by column (X is nv × k: generalized forces in, the accelerations they
/// alone cause out), where M is factorized by the articulated-body algorithm that the last
/// aba(q, …) or hybrid_dynamics(q, …) call ran on `data` (its U, D⁻¹ and X_PB are read). With the
/// `prescribed` mask of that hybrid_dynamics call (num_joints() entries, nonzero = prescribed;
/// empty after aba) the prescribed joints are held: X's rows of their coordinates are ignored on
/// input and 0 on output, and the others become M_ff⁻¹ X_f over the free coordinates. Uses
/// data.solve_f, data.solve_a and data.solve_U_parent. No allocation.
void articulated_solve(const Model& model, Data& data, std::span<const char> prescribed,
                       Eigen::Ref<MatX> X);

}  // namespace momenta::dynamics
