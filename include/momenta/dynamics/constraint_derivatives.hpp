#pragma once
// Analytic derivatives of the constraint rows (constraints.hpp) with respect to the state, for
// every kind of constraint: what the linearization of constrained dynamics needs
// (analysis::linearize, docs/constraints.md). ∂/∂q is taken on the configuration's tangent,
// q ⊕ δ, one column per velocity coordinate, as in rnea_derivatives.hpp.
//
//   velocity_dq   ∂(G v)/∂q at fixed v                       rows × nv
//   residual_dq   ∂(G v̇ + k)/∂q at fixed v and v̇             rows × nv
//   residual_dv   ∂(G v̇ + k)/∂v at fixed v̇, that is ∂k/∂v    rows × nv
//   force_dq      ∂(Gᵀ λ)/∂q at fixed λ                      nv × nv
//
// Method. A wrench row's values are formulas of the poses, velocities and accelerations of the
// two frames it joins (constraints.hpp). Perturbing coordinate k moves every body below its
// joint stage rigidly along its column S_k (in W), and changes a moved body's velocity and
// acceleration by
//
//     ∂V/∂q_k = S_k × V + ΔV_k,    ∂A/∂q_k = S_k × A + ΔV_k × V + x_k,
//     ∂V/∂v_k = S_k,               ∂A/∂v_k = S_k × V + W_k,
//
// with ΔV_k, x_k and W_k the terms of rnea_derivatives (Data::dDeltaV_W, dX_W, dW_W; A shifted
// by −g, which the differences cancel). The row formulas evaluated on dual numbers whose
// derivative parts are these give each row's derivatives exactly — no differences, no truncation.
// ∂(Gᵀ λ)/∂q adds to the turn of the wrenches themselves the turn of the joint columns that
// carry them to the coordinates, S_k × S_j for a column S_j that coordinate k moves. A coupler's
// row is constant in q and v: its derivatives are zero.

#include <vector>

#include "momenta/dynamics/constraints.hpp"
#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// The constraint rows' derivatives at one state, sized once for the model.
struct ConstraintDerivatives {
  explicit ConstraintDerivatives(const Model& model);

  MatX velocity_dq;  ///< rows × nv: ∂(G v)/∂q at fixed v
  MatX residual_dq;  ///< rows × nv: ∂(G v̇ + k)/∂q at fixed v, v̇
  MatX residual_dv;  ///< rows × nv: ∂k/∂v
  MatX force_dq;     ///< nv × nv: ∂(Gᵀ λ)/∂q at fixed λ
  /// The rows at q: φ, G and the wrenches (RowTerms::jacobian; bias is not set).
  ConstraintRows rows;
  std::vector<Mat6X> wrench_dq;  ///< per row: ∂w_i/∂q (6 × nv; zero for a coupler)
};

/// The derivatives of the constraint rows at (q, v, v̇), with multipliers λ (size
/// num_constraint_rows) for force_dq. Runs rnea_derivatives (data's dtau_dq, dtau_dv, M and tau
/// are left as it writes them). Arguments checked as rnea's, λ's size too; throws NumericalError
/// where a constraint has no direction (constraints.hpp).
void constraint_derivatives(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot,
                            VecRef lambda, ConstraintDerivatives& out);

}  // namespace momenta::dynamics
