#pragma once
// Analytic derivatives of forward dynamics, v̇ = ABA(q, v, τ), from those of inverse dynamics
// (Carpentier & Mansard, RSS 2018, §IV): differentiating RNEA(q, v, ABA(q, v, τ)) = τ gives
//
//     ∂v̇/∂q = −M⁻¹ ∂τ/∂q,   ∂v̇/∂v = −M⁻¹ ∂τ/∂v,   ∂v̇/∂τ = M⁻¹,
//
// with ∂τ/∂(q, v) taken at v̇ = ABA(q, v, τ). Tangent space and f_ext as in rnea_derivatives.hpp.
// M⁻¹ comes from the articulated-body factors of that ABA pass by Carpentier's recursion
// ("Analytical inverse of the joint space inertia matrix", 2018): O(n d) for a tree of depth d,
// neither M nor a factorization of it formed. The products −M⁻¹ ∂τ take O(n²), ∂τ never formed:
// its entries are products of per-coordinate factors, and M⁻¹ is applied to the factors through
// running sums over subtrees and paths (aba_derivatives.cpp; docs/dynamics.md).

#include <span>

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// ∂v̇/∂q (tangent space), ∂v̇/∂v and M⁻¹ (each nv × nv) of v̇ = aba(q, v, tau, f_ext). Writes
/// data.dvdot_dq, data.dvdot_dv, data.Minv and data.vdot (v̇ itself), and the workspace fields d*_W
/// and minv_*; not dtau_dq, dtau_dv, M or tau (rnea_derivatives' results). Arguments checked as
/// aba's; throws NumericalError when M is not positive definite (a joint's D = Sᵀ IA S singular:
/// no mass or inertia along one of its axes). Does not allocate.
void aba_derivatives(const Model& model, Data& data, VecRef q, VecRef v, VecRef tau,
                     std::span<const Vec6> f_ext = {});

}  // namespace momenta::dynamics
