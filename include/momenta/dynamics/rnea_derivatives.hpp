#pragma once
// Analytic derivatives of inverse dynamics, τ = RNEA(q, v, v̇), with respect to the state
// (Carpentier & Mansard, "Analytical derivatives of rigid body dynamics algorithms", RSS 2018),
// for every joint type momenta has.
//
// Tangent space. ∂/∂q is taken along the configuration's tangent, q ⊕ δ (model::integrate): one
// column per velocity coordinate (nv columns, not nq). A ball joint's quaternion is differentiated
// along its rotation vector in the child frame, a free joint's along [rotation in the child frame;
// translation in the parent frame] — the coordinates linearize() uses.
//
// External forces f_ext (the convention of rnea.hpp: wrenches in each body's frame about its
// origin) are held fixed in their bodies: a follower load, which turns with its body. A load
// fixed in the world, or one that depends on the state (a spring between bodies), adds its own
// derivative; analysis::linearize adds the force elements'.
//
// Method. The recursion runs in the world frame. A multi-dof joint is a sequence of stages whose
// motion-subspace columns are fixed in the stage's moving frame (universal: its two axes one
// after the other; planar and free: the translations, then the rotation; spherical, cylindrical
// and 1-dof joints: one stage). Perturbing coordinate k moves everything after its stage rigidly
// by its column S_k, so each body's force changes by S_k ×* f plus a part linear in
// ΔV_k = V_p × S_k and A_p × S_k (V_p, A_p: the frame before the stage) through the subtree's
// composite inertia and its Coriolis inertia B = Σ (−I (V×) + (I V)×̄* + V ×* I), whose right-hand
// blocks vanish (data.hpp, CoriolisInertia). Cost O(n d) beyond the O(n) pass, d the depth of the
// tree.

#include <span>

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// ∂τ/∂q (tangent space) and ∂τ/∂v of τ = rnea(q, v, vdot, f_ext), and M(q) = ∂τ/∂v̇, each
/// nv × nv. Writes data.dtau_dq, data.dtau_dv, data.M and data.tau (τ itself); f_ext is held in
/// its bodies (the header comment). Arguments checked as rnea's. No allocation.
void rnea_derivatives(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot,
                      std::span<const Vec6> f_ext = {});

}  // namespace momenta::dynamics
