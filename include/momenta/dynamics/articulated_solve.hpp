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

#include "momenta/dynamics/constraints.hpp"
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

/// The constraint rows' side of a constrained aba, by the innovations factorization
/// M⁻¹ = Lᵀ D⁻¹ L that the articulated-body algorithm is (Rodriguez, Jain & Kreutz-Delgado 1991;
/// L x is what pass 2 makes of generalized forces x, Lᵀ D⁻¹ what pass 3 does). For the rows of
/// constraint_equations and the factors aba_articulate left in `data` (the same configuration,
/// no prescribed joints):
///   LGt ← L Gᵀ (nv × m): pass 2 run on each row's force alone — its wrench w on body b and −w
///     on body a (a coupler's row: its generalized force) — giving the joints' u = x − Sᵀ p;
///   Dinv_LGt ← D⁻¹ L Gᵀ, joint by joint, so that G M⁻¹ Gᵀ = (L Gᵀ)ᵀ (D⁻¹ L Gᵀ);
///   acceleration ← per row w·(A_b − A_a), the bodies' relative acceleration along the row at the
///     v̇₀ aba_accelerate() would give (velocity products and gravity included; a coupler's row
///     G v̇₀), without running pass 3: Σ_j u_jᵀ D_j⁻¹ (u⁰_j − U_jᵀ a⁰_i) − Σ_i p_iᵀ a⁰_i, with u⁰
///     aba's own, p_i the row's force on body i (its own and its children's) and a⁰_i what pass 3
///     adds at body i before its joint's v̇ (c_i, and ⁱX_0 (−g) at a root joint), plus w·g for
///     the −g the passes carry — the adjoint of pass 3. G v̇₀ + k is this plus ẇ·(V_b − V_a).
/// Then v̇ = v̇₀ + M⁻¹ Gᵀ λ is aba_accelerate(model, data, (L Gᵀ) λ): one pass 3 for both. A row
/// with a zero row of G (it exerts no force here) has acceleration 0, and its columns of LGt and
/// Dinv_LGt are not written (they are zero); the others are listed in `active` (size m), in
/// order, and their number returned. O(n m) with
/// 6-vectors, as articulated_solve's first pass; uses data.X_WB (set by constraint_equations),
/// data.solve_f and data.solve_U_parent. No allocation.
int articulated_row_factors(const Model& model, Data& data, const ConstraintRows& rows,
                            Eigen::Ref<MatX> LGt, Eigen::Ref<MatX> Dinv_LGt,
                            Eigen::Ref<VecX> acceleration, std::span<int> active);

}  // namespace momenta::dynamics
