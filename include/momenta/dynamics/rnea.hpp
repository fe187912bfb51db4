#pragma once
// Inverse dynamics by the recursive Newton–Euler algorithm (Featherstone 2008, §5.3, Table 5.1),
// and the bias forces it gives with v̇ = 0.
//
// External forces f_ext: a span of num_bodies() wrenches, f_ext[b] acting on body b, expressed
// in B about Bo ([moment; force], N·m and N; see body_wrench_from_world_force in kinematics.hpp);
// f_ext[0] (the world) is ignored; an empty span means none.

#include <span>

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// τ = M(q) v̇ + C(q, v) v + g(q) − Σ J_bᵀ f_ext[b]: the generalized forces (size nv) that
/// produce accelerations v̇ at (q, v) under gravity. Writes data.tau (and data.F_B, the wrench
/// each joint transmits) and returns data.tau. Sizes q nq, v and vdot nv, f_ext empty or one
/// per body, data built for the model: checked, InvalidArgument naming the argument otherwise
/// (as in every dynamics algorithm). No allocation.
const VecX& rnea(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot,
                 std::span<const Vec6> f_ext = {});

/// Allocating convenience form of rnea.
VecX inverse_dynamics(const Model& model, VecRef q, VecRef v, VecRef vdot,
                      std::span<const Vec6> f_ext = {});

/// Bias forces C(q, v) v + g(q) (size nv): rnea with v̇ = 0 and no external force. Writes and
/// returns data.nle.
const VecX& nonlinear_effects(const Model& model, Data& data, VecRef q, VecRef v);

/// Generalized gravity g(q) = ∂V/∂q (in velocity coordinates; size nv): rnea with v = v̇ = 0.
/// Writes and returns data.g.
const VecX& generalized_gravity(const Model& model, Data& data, VecRef q);

}  // namespace momenta::dynamics
