#pragma once
// Internal to momenta::dynamics: rnea_derivatives for aba_derivatives, which has just run aba at
// the same q, so Data's joint transforms X_PB and motion subspaces S are current and are not
// computed again. No argument checks (aba made them).

#include <span>

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics::detail {

void rnea_derivatives_at_current_positions(const Model& model, Data& data, VecRef q, VecRef v,
                                           VecRef vdot, std::span<const Vec6> f_ext);

}  // namespace momenta::dynamics::detail
