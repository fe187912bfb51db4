#pragma once
// High-order finite differences on a model's configuration tangent (q ⊕ s e_k, model::integrate):
// the independent reference for analytic derivatives of the dynamics.

#include <functional>

#include "momenta/model/model.hpp"

namespace momenta::test {

/// ∂f/∂δ_k at δ = 0 for f(q ⊕ δ), column by column: central differences D(h) extrapolated twice
/// (Richardson: D(h), D(h/2), D(h/4) → f' + O(h⁶)). With h = 0.04 on coordinates of order one
/// the truncation is ~h⁶ f⁽⁷⁾/5040 ≈ 1e-12 of the derivative's scale and round-off
/// ~10 ε |f| / (h/4) ≈ 6e-14, so agreement to 1e-10 relative is a demanding check.
inline MatX tangent_jacobian(const model::Model& m, const VecX& q,
                             const std::function<VecX(const VecX&)>& f, double h = 0.04) {
  const VecX f0 = f(q);
  MatX J(f0.size(), m.nv());
  VecX tangent(m.nv()), q_step(m.nq());
  const auto central = [&](int k, double step) {
    tangent.setZero();
    tangent[k] = step;
    model::integrate(m, q, tangent, 1.0, q_step);
    const VecX plus = f(q_step);
    tangent[k] = -step;
    model::integrate(m, q, tangent, 1.0, q_step);
    return VecX((plus - f(q_step)) / (2 * step));
  };
  for (int k = 0; k < m.nv(); ++k) {
    const VecX d1 = central(k, h), d2 = central(k, h / 2), d4 = central(k, h / 4);
    const VecX r1 = (4 * d2 - d1) / 3, r2 = (4 * d4 - d2) / 3;
    J.col(k) = (16 * r2 - r1) / 15;
  }
  return J;
}

/// ∂f/∂x for f quadratic in x (the dynamics in v): one central difference of step 1 is exact up
/// to round-off (the odd part of a quadratic is linear).
inline MatX quadratic_jacobian(const VecX& x, const std::function<VecX(const VecX&)>& f) {
  const VecX f0 = f(x);
  MatX J(f0.size(), x.size());
  for (int k = 0; k < x.size(); ++k) {
    VecX plus = x, minus = x;
    plus[k] += 1.0;
    minus[k] -= 1.0;
    J.col(k) = (f(plus) - f(minus)) / 2.0;
  }
  return J;
}

}  // namespace momenta::test
