#pragma once
// Jacobians of the exponential map of SO(3), used to integrate rotations on the group.
//
// For R(t) = R0 Exp(δ(t)) the body-frame angular velocity is ω_B = J_r(δ) δ̇, where J_r is the
// right Jacobian of SO(3) (Chirikjian 2011, vol. 2, §10.6; Solà et al. 2018, eq. 143). Runge–Kutta
// methods in local coordinates (Munthe-Kaas 1998) integrate δ̇ = J_r(δ)⁻¹ ω.

#include "momenta/math/types.hpp"

namespace momenta {

/// The right Jacobian J_r(δ) = I − (1 − cos θ)/θ² [δ]× + (θ − sin θ)/θ³ [δ]×², θ = |δ|.
/// Accurate for every θ < 2π (series near 0).
Mat3 so3_right_jacobian(const Vec3& delta);

/// Its rate d/dt J_r(δ(t)) along a path with δ̇ = `delta_rate`: for R(t) = Exp(δ(t)) the body
/// angular acceleration is ω̇_B = J_r(δ) δ̈ + J̇_r δ̇ (prescribed rotations, model/prescribed_motion).
/// Accurate for every θ < 2π (series below θ = 0.1).
Mat3 so3_right_jacobian_rate(const Vec3& delta, const Vec3& delta_rate);

/// Its inverse J_r(δ)⁻¹ = I + ½ [δ]× + (1/θ² − (1 + cos θ)/(2 θ sin θ)) [δ]×², θ = |δ| < 2π.
/// Singular at θ = 2π; integrators keep |δ| far below that (one step's rotation).
Mat3 so3_right_jacobian_inverse(const Vec3& delta);

}  // namespace momenta
