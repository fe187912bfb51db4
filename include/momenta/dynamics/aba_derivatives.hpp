#pragma once
// Analytic derivatives of forward dynamics, v̇ = ABA(q, v, τ), from those of inverse dynamics
// (Carpentier & Mansard, RSS 2018, §IV): differentiating RNEA(q, v, ABA(q, v, τ)) = τ gives
//
//     ∂v̇/∂q = −M⁻¹ ∂τ/∂q,   ∂v̇/∂v = −M⁻¹ ∂τ/∂v,   ∂v̇/∂τ = M⁻¹,
//
// with ∂τ/∂(q, v) taken at v̇ = ABA(q, v, τ). Tangent space and f_ext as in rnea_derivatives.hpp.

#include <span>

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// ∂v̇/∂q (tangent space), ∂v̇/∂v and M⁻¹ (each nv × nv) of v̇ = aba(q, v, tau, f_ext). Writes
/// data.dvdot_dq, data.dvdot_dv, data.Minv and data.vdot (v̇ itself), and what rnea_derivatives
/// writes. Arguments checked as aba's; throws NumericalError when M is not positive definite
/// (a massless chain end). The recursions do not allocate; the two dense products M⁻¹ ∂τ are
/// Eigen's, which may take blocking workspace from the heap at large nv (none at the 16-body tree
/// of the allocation test).
void aba_derivatives(const Model& model, Data& data, VecRef q, VecRef v, VecRef tau,
                     std::span<const Vec6> f_ext = {});

}  // namespace momenta::dynamics
