#pragma once
// Internal to momenta::dynamics: rnea_derivatives' passes for aba_derivatives, which has just run
// aba at the same q, so Data's joint transforms X_PB and motion subspaces S are current and are
// not computed again. No argument checks (aba made them).

#include <span>

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics::detail {

/// The factors of ∂τ/∂q and ∂τ/∂v per velocity coordinate, at (q, v, vdot): dtau_lower_W,
/// dtau_upper_q_W, dtau_upper_v_W, with the columns dS_W, dDeltaV_W, dX_W, dW_W (data.hpp says
/// which entry is which product). Neither ∂τ, M nor τ is written.
void rnea_derivative_factors_at_current_positions(const Model& model, Data& data, VecRef q,
                                                  VecRef v, VecRef vdot,
                                                  std::span<const Vec6> f_ext);

}  // namespace momenta::dynamics::detail
