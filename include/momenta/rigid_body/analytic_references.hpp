#pragma once
// Closed-form references for single rigid bodies: torque-free precession (axisymmetric and
// asymmetric), and the heavy symmetric top about a fixed point (steady precession, the sleeping
// top, nutation bounds, gyroscopic precession). Used by the tests of the integrators and offered
// to users who validate their own models.
//
// Heavy top conventions (Goldstein, Classical Mechanics §5.7; Landau & Lifshitz vol. 1 §35): Euler
// angles ZXZ — precession φ about the vertical world z (up), nutation θ of the symmetry axis from
// the upward vertical, spin ψ about the symmetry axis; R_WB = Rz(φ) Rx(θ) Rz(ψ). The centre of
// mass lies on the symmetry axis at distance l from the pivot (above it when θ = 0, so the
// potential is m g l cos θ). ω3 = ψ̇ + φ̇ cos θ is the (conserved) spin: the component of ω along
// the symmetry axis.

#include "momenta/math/types.hpp"

namespace momenta::rigid_body {

// ---- torque-free ---------------------------------------------------------------------------

/// Regular precession of a torque-free axisymmetric body (Landau & Lifshitz §33).
struct AxisymmetricPrecession {
  /// Ω = (I_a − I_t) ω_a / I_t: rate at which ω and H turn about the symmetry axis as seen in
  /// the body (rad/s, positive counter-clockwise about +axis). The body cone's rate.
  double body_rate;
  /// |H| / I_t: rate at which the symmetry axis (and ω) turn about H in space (rad/s, > 0).
  double space_rate;
  /// Angle between the symmetry axis and H (rad): cos = I_a ω_a / |H|.
  double nutation_angle;
  /// Half-angle of the body cone: between ω and the symmetry axis (rad).
  double body_cone_half_angle;
  /// Half-angle of the space cone: between ω and H (rad).
  double space_cone_half_angle;
};

/// `transverse_moment` I_t and `axial_moment` I_a (kg·m², > 0), `axial_rate` ω_a (rad/s, the
/// component of ω along the symmetry axis) and `transverse_rate` |ω_⊥| (rad/s, >= 0). Throws
/// InvalidArgument for non-positive moments, a negative transverse rate or ω = 0.
AxisymmetricPrecession axisymmetric_precession(double transverse_moment, double axial_moment,
                                               double axial_rate, double transverse_rate);

/// The periodic motion of ω for three distinct principal moments.
struct AsymmetricRotation {
  double parameter;      ///< m of the Jacobi functions
  double complement;     ///< 1 − m, formed without cancellation
  double argument_rate;  ///< λ: ω(t) is a function of u = λ t + u0 (rad/s)
  /// Period of ω in the body, T = 4K(m)/λ (s); +∞ on the separatrix.
  double period;
  /// Half the period, 2K(m)/λ (s): the time between successive reversals of the intermediate
  /// component ω2 (the "tennis racket" flips) above the separatrix, or of ω3 below it.
  double flip_interval;
  /// True when ω circulates about the axis of largest moment (H² > 2 T I2).
  bool about_major_axis;
};

/// `principal_moments` ascending and distinct (I1 < I2 < I3, kg·m²), `w_P` the angular velocity
/// in the principal frame (rad/s). Follows the amplitudes of FreeRigidBodySolution
/// (docs/rotation.md §4): λ = √((I3 − I2)(H² − 2T I1)/(I1 I2 I3)) above the separatrix,
/// √((I2 − I1)(2T I3 − H²)/(I1 I2 I3)) below. Throws InvalidArgument for moments that are not
/// positive, ascending and distinct, or ω along a principal axis (no periodic motion).
AsymmetricRotation asymmetric_rotation(const Vec3& principal_moments, const Vec3& w_P);

// ---- heavy symmetric top ------------------------------------------------------------------

/// A symmetric top on a fixed pivot in uniform gravity.
struct SymmetricTop {
  double transverse_moment;  ///< I1: about any axis through the pivot normal to the symmetry axis
  double axial_moment;       ///< I3: about the symmetry axis (kg·m²)
  double mass;               ///< m (kg)
  double com_distance;       ///< l: pivot to centre of mass along the symmetry axis (m)
  double gravity = 9.80665;  ///< g (m/s²)
};

/// The two steady precession rates φ̇ (rad/s) at a fixed nutation angle.
struct SteadyPrecession {
  double slow;  ///< → m g l/(I3 ω3) for a fast top
  double fast;  ///< → I3 ω3/(I1 cos θ) for a fast top; → ±∞ as the axle turns horizontal
};

/// Roots of I1 cos θ φ̇² − I3 ω3 φ̇ + m g l = 0 (θ̈ = 0 with θ̇ = 0; Goldstein eq. 5.76), for the
/// nutation angle `theta` (rad, 0 < θ < π) and the spin `spin` ω3 (rad/s), computed without
/// cancellation. As θ → π/2 the equation turns linear: slow → m g l/(I3 ω3), fast → ±∞ (at the
/// double nearest π/2, cos θ = 6.1e-17: slow is m g l/(I3 ω3) to an ulp, fast finite but
/// ~1e16 times the slow). Throws InvalidArgument where no steady precession exists
/// (I3² ω3² < 4 I1 m g l cos θ), showing the discriminant.
SteadyPrecession steady_precession(const SymmetricTop& top, double theta, double spin);

/// The same when the spin is given relative to the precessing frame, ψ̇ (rad/s), as a motor on a
/// gimbal prescribes it: ω3 = ψ̇ + φ̇ cos θ, so (I1 − I3) cos θ φ̇² − I3 ψ̇ φ̇ + m g l = 0.
SteadyPrecession steady_precession_for_relative_spin(const SymmetricTop& top, double theta,
                                                     double relative_spin);

/// Gyroscopic precession rate m g l/(I3 ω3) (rad/s). Exact (the slow steady precession) only for
/// a horizontal axle, θ = π/2; at other angles it is the fast-top limit of the slow root, with a
/// relative error of about I1 m g l cos θ/(I3 ω3)² (Goldstein eq. 5.78).
double gyroscopic_precession_rate(const SymmetricTop& top, double spin);

/// ω3 above which a vertical ("sleeping") top is stable: ω3² > 4 m g l I1/I3² (Goldstein §5.7,
/// the condition for u = 1 to be a double root that the motion cannot leave).
double sleeping_top_critical_spin(const SymmetricTop& top);

/// The turning points of the nutation: the roots u1 <= u0 <= u2 in [−1, 1] of
/// f(u) = (1 − u²)(α − β u) − (b − a u)², u = cos θ (Goldstein eq. 5.70), bracketing the initial
/// u0, and the angles they mean.
struct NutationBounds {
  double theta_min;  ///< smallest θ reached (rad) = acos(u2)
  double theta_max;  ///< largest θ reached (rad) = acos(u1)
  double u_min;      ///< u1
  double u_max;      ///< u2
};

/// From the initial nutation angle `theta` (rad, 0 < θ < π), its rate `theta_dot`, the
/// precession rate `phi_dot` and the spin ω3 (rad/s). The roots are found by bisection on
/// monotone pieces of the cubic, to a few ulps of u; where the two roots merge (steady
/// precession) the problem itself is conditioned like √ε. Throws InvalidArgument for θ outside
/// (0, π) or non-finite input.
NutationBounds nutation_bounds(const SymmetricTop& top, double theta, double theta_dot,
                               double phi_dot, double spin);

}  // namespace momenta::rigid_body
