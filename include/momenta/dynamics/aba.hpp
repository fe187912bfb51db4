#pragma once
// Forward dynamics by the articulated-body algorithm (Featherstone 2008, §7.3, Table 7.1), O(n).

#include <span>

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// v̇ = M(q)⁻¹ (τ − C(q, v) v − g(q) + Σ J_bᵀ f_ext[b]) (size nv) for generalized forces tau
/// (size nv) and external wrenches f_ext (convention in rnea.hpp). Writes and returns
/// data.vdot. Every joint is driven by its τ here, prescribed or not (hybrid_dynamics honours
/// prescription). No allocation.
const VecX& aba(const Model& model, Data& data, VecRef q, VecRef v, VecRef tau,
                std::span<const Vec6> f_ext = {});

/// aba in its two halves, for a caller that adds generalized forces known only once the
/// articulated-body factors exist (the constraint solver's multipliers:
/// system/constraint_solver.hpp, dynamics/articulated_solve.hpp's articulated_row_factors).
/// aba_articulate runs passes 1 and 2: poses, velocities and velocity products, and the factors U,
/// D⁻¹, u = τ − Sᵀ pA in data. aba_accelerate runs pass 3 with u + du: du (size nv, or empty) is L
/// x for extra generalized forces x, where M⁻¹ = Lᵀ D⁻¹ L is the factorization passes 1 and 2 leave
/// (L x is what pass 2 makes of x); writes and returns data.vdot, the accelerations of τ + x. It
/// reads data.u and does not change it: calling it again with another du starts from
/// aba_articulate's state. aba(q, v, τ, f_ext) = aba_articulate(q, v, τ, f_ext), then
/// aba_accelerate(). No allocation.
void aba_articulate(const Model& model, Data& data, VecRef q, VecRef v, VecRef tau,
                    std::span<const Vec6> f_ext = {});
const VecX& aba_accelerate(const Model& model, Data& data, VecRef du = VecX());

/// Allocating convenience form of aba.
VecX forward_dynamics(const Model& model, VecRef q, VecRef v, VecRef tau,
                      std::span<const Vec6> f_ext = {});

}  // namespace momenta::dynamics
