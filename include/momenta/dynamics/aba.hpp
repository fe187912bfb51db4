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

/// Allocating convenience form of aba.
VecX forward_dynamics(const Model& model, VecRef q, VecRef v, VecRef tau,
                      std::span<const Vec6> f_ext = {});

}  // namespace momenta::dynamics
