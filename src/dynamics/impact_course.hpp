#pragma once
// The course of an impact at one contact with Coulomb friction (Routh's process; Stronge, Impact
// Mechanics, 2000, ch. 4–5): the normal impulse p grows from zero, and the contact's relative
// velocity u follows du/dp = W (n + f), W the mechanism's inverse inertia at the contact, f the
// friction impulse per unit normal impulse — −μk ŝ against the slip while it slides, the fixed
// f* = −W_tt⁺ W_tn while it sticks (within μs). Compression ends where u_n reaches zero; the
// impact ends where the normal impulse has given back e² of the work it took in compression
// (Stronge's energetic coefficient of restitution, which cannot create energy).

#include "momenta/dynamics/impulse.hpp"
#include "momenta/math/types.hpp"

namespace momenta::dynamics::detail {

/// The impact's outcome in the contact's basis [t₁ t₂ n] (the normal last).
struct ImpactCourse {
  Vec3 impulse = Vec3::Zero();     ///< P (N·s): (P_t₁, P_t₂, P_n)
  Vec3 u_after = Vec3::Zero();     ///< u⁺ (m/s)
  double compression_impulse = 0;  ///< p_c (N·s): the normal impulse where u_n reached zero
  SlipCourse course = SlipCourse::slides;
};

/// The course from u⁻ (u_n⁻ < 0) with W (W_nn > 0; its symmetric part positive semi-definite,
/// W itself not symmetric where other contacts slide through the impact), the
/// restitution e ∈ [0, 1] and μs ≥ μk ≥ 0, μs > 0. Where W n has no tangential part and the slip
/// keeps its direction (a ball, a point mass) it is the closed form: separation speed −e u_n⁻,
/// friction μk P_n against the slip or the impulse that stops it. Throws NumericalError where the
/// impact does not end (friction jamming it: the normal impulse grows past 10⁶ times the
/// frictionless one).
ImpactCourse follow_impact(const Mat3& W, const Vec3& u_before, double restitution,
                           double static_friction, double kinetic_friction);

}  // namespace momenta::dynamics::detail
