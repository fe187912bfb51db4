#pragma once
// Steady motions of a spinning rigid body and the linear analysis about them.
//
// A spinning body is not at an equilibrium of its joint coordinates — its attitude turns
// steadily — so linearizing "about the initial state" mixes the steady rotation into the
// perturbation (a sleeping top comes out unstable). Here the body is described by what stays
// constant in a steady motion: its angular velocity ω and the upward vertical γ, both in the
// body frame B (Euler–Poisson; Arnold, Mathematical Methods of Classical Mechanics, §28–29):
//
//     I ω̇ = (I ω) × ω + m g γ × p        (Euler's equations with the weight's moment)
//     γ̇   = γ × ω                         (a space-fixed vector seen from the turning body)
//
// with I the inertia about the fixed point O and p the centre of mass from O, in B. A steady
// motion is an equilibrium of these equations; the eigenvalues of their linearization are
// those of the perturbations seen from the body. Two of them are zero: |γ| and the angular
// momentum about the vertical, (I ω)·γ, are conserved for every motion. A free body (a
// satellite; a free joint) feels no moment from gravity: the same with ω alone, I about the
// centre of mass.
//
// Covered: one rigid body on a spherical joint to the world (tops, a ball-jointed gyroscope, a
// spherical pendulum), or on a free joint. Steady motions: the permanent rotations about the
// vertical (the sleeping top, an upright spinning body) and, for a free body, the spin about a
// principal axis. Docs: docs/analysis.md (steady motions).

#include <complex>
#include <string>
#include <vector>

#include "momenta/analysis/linearize.hpp"
#include "momenta/math/types.hpp"
#include "momenta/model/model.hpp"

namespace momenta::analysis {

/// The body and its state in the Euler–Poisson variables.
struct SpinningBody {
  std::string body;
  std::string joint;
  bool fixed_point = true;  ///< spherical joint (a top); false: a free body
  Mat3 I_B;                 ///< inertia about O (fixed point) or the centre of mass, kg·m², in B
  double mass = 0.0;        ///< kg
  Vec3 p_OBcm_B;            ///< centre of mass from O, m (zero for a free body)
  double g = 0.0;           ///< gravity's magnitude, m/s² (0 for a free body)
  Vec3 w_B;                 ///< angular velocity in B, rad/s
  Vec3 up_B;                ///< γ: the upward unit vertical in B (−g direction; z when g = 0)
};

/// True when `model` is one rigid body on a spherical or free joint to the world: the models whose
/// steady motions are analysed here (others, in joint coordinates: joint_steady_motion.hpp).
bool euler_poisson_applies(const model::Model& model);

/// The body of `model` as a spinning body at `point`. Throws InvalidArgument unless the model is
/// one body on a spherical or free joint to the world (naming what it has).
SpinningBody spinning_body(const model::Model& model, const OperatingPoint& point);

/// How the perturbations of a steady motion behave.
struct SteadyMotionModes {
  /// State names: w_x, w_y, w_z (rad/s) and, for a fixed point, up_x, up_y, up_z, in B.
  std::vector<std::string> state_names;
  MatX A;  ///< the linearization of Euler–Poisson at the state
  /// |f(state)| relative to |ω|² (the rates' scale): 0 to round-off for a steady motion.
  double residual = 0.0;
  /// Eigenvalues of A, seen from the body, the conserved quantities' zeros left out; each
  /// conjugate pair once (imaginary part ≥ 0), ascending |λ|.
  std::vector<std::complex<double>> eigenvalues;
  /// For a body symmetric about its spin axis (two equal moments about it, the centre of mass on
  /// it): each oscillation seen from space, rad/s, > 0, with its whirl — "forward" (turning with
  /// the spin) or "backward". Empty otherwise.
  std::vector<double> space_frequencies;
  std::vector<std::string> whirl;
  bool stable = false;       ///< no eigenvalue with a positive real part (beyond round-off)
  double growth_rate = 0.0;  ///< the largest real part, 1/s (0 when stable)
  /// Why: gyroscopic stabilization of an upright body, Euler's axis rule for a free body, …
  std::string verdict;
};

/// Linear analysis of the steady motion at `body`'s state. Throws InvalidArgument when the state
/// is not a steady motion (residual above 1e-8): naming the residual, and what a steady motion
/// of such a body is (ω along the vertical; for a free body, along a principal axis).
SteadyMotionModes steady_motion_modes(const SpinningBody& body);

/// The Euler–Poisson rates f = (ω̇, γ̇) at the body's state (ω̇ only for a free body).
VecX euler_poisson_rates(const SpinningBody& body);

/// Whether the body is symmetric about the unit axis e (in B): e a principal axis, the two
/// moments across it equal and the centre of mass on it, to 1e-9.
bool symmetric_about(const SpinningBody& body, const Vec3& e_B);

/// One speed of a Campbell diagram: the whirl frequencies seen from space at spin speed Ω.
struct CampbellPoint {
  double speed = 0.0;               ///< Ω, rad/s
  std::vector<double> frequencies;  ///< rad/s, seen from space
  std::vector<std::string> whirl;   ///< "forward" / "backward", per frequency
  bool stable = true;
};

/// A name for each whirl of a point, as the Campbell table's columns: "backward_1", "forward_1",
/// "none_1", … numbered within each kind in the point's order.
std::vector<std::string> whirl_column_names(const CampbellPoint& point);

/// A critical speed: a forward whirl's frequency equals the spin speed (the 1× line, where an
/// unbalance, which turns with the rotor, excites it).
struct CriticalSpeed {
  double speed = 0.0;  ///< rad/s
  std::string whirl;   ///< of the whirl that crosses
};

struct CampbellDiagram {
  std::vector<CampbellPoint> points;
  std::vector<CriticalSpeed> critical_speeds;
};

/// The Campbell diagram of a spinning body symmetric about its spin axis (the state's ω, along the
/// vertical for a top): the state's spin scaled to each of `points` speeds from `from` to `to`
/// (rad/s, > 0), each analysed by steady_motion_modes; the critical speeds where a whirl frequency
/// crosses Ω, each refined by bisection to 1e-12 relative. Throws InvalidArgument for a body
/// that is not symmetric about its spin axis, or a bad range.
CampbellDiagram campbell_diagram(const SpinningBody& body, double from, double to, int points);

/// A symmetric top (body on a fixed point, symmetric about its axis e) in steady precession at
/// the tilt θ from the upward vertical with spin ω₃ = ω·e: with Euler angles, I₁φ̇² cos θ −
/// I₃ω₃φ̇ + m g l = 0 (Beer & Johnston §18.10, Goldstein §5.7; I₁, I₃ about the fixed point,
/// l the centre of mass's distance along e). A steady motion of the precessing frame, not of
/// Euler–Poisson's: the top's axis keeps its tilt while it turns about the vertical.
struct SteadyPrecession {
  double tilt = 0.0;            ///< θ, rad
  double spin = 0.0;            ///< ω₃, rad/s
  Vec3 axis_B = Vec3::UnitZ();  ///< e: the symmetry axis in the body frame (unit)
  double I1 = 0.0, I3 = 0.0, mgl = 0.0;
  /// The two precession rates, rad/s, slow ≤ fast in magnitude; NaN when the spin is below
  /// minimum_spin (no steady precession at this tilt). At θ = 90° the one root m g l/(I₃ω₃).
  double slow = 0.0, fast = 0.0;
  /// The spin below which no steady precession exists at this tilt, 2√(I₁ m g l cos θ)/I₃ (0
  /// when cos θ ≤ 0: a top below its pivot precesses at any spin).
  double minimum_spin = 0.0;
  /// The sleeping top's critical spin 2√(I₁ m g l)/I₃: upright, it is stable above it (0 for a
  /// top whose centre of mass is below the fixed point).
  double critical_spin = 0.0;
  /// The gyroscopic approximation m g l/(I₃ ω₃) of the slow root (NaN without spin), and its
  /// relative error (NaN where there is no slow root or no approximation; 0 without gravity).
  double gyroscopic = 0.0;
  double gyroscopic_error = 0.0;
  /// Linearized nutation frequency about each steady precession, rad/s (Routh's reduction to θ):
  /// ω_n² = [(I₃ω₃ − 2 I₁ φ̇ cos θ)² + I₁² φ̇² sin² θ]/I₁².
  double slow_nutation = 0.0, fast_nutation = 0.0;
  /// The state's own precession rate: its ω = φ̇ ẑ + ψ̇ e split along the vertical and the axis.
  double precession = 0.0;
  /// How far the state is from the nearer steady precession: the part of ω outside span{ẑ, e}
  /// and the mismatch of φ̇ with the nearer root, relative to |ω|.
  double residual = 0.0;
};

/// find_steady_precession's answer: the roots at the tilt and spin asked for (`precession` and
/// `residual` left 0), and a state of the model on each root that exists (slow, then fast).
struct FoundPrecession {
  SteadyPrecession roots;
  std::vector<OperatingPoint> states;
};

/// The steady precessions of `model`'s symmetric top (one body on a spherical joint to the world,
/// symmetric about the axis through its centre of mass) at the tilt θ (rad, from the upward
/// vertical, 0 ≤ θ ≤ π) and spin ω₃ (rad/s) asked for: both roots of I₁ cos θ φ̇² − I₃ω₃ φ̇ +
/// m g l = 0, the spin range where they exist, the critical spin of the sleeping top, the
/// gyroscopic approximation with its error and the nutation frequencies; and for each root the
/// state (q, v) of the model precessing steadily on it, its axis tilted about a horizontal axis.
/// At θ = 0 the roots are the limit: the sleeping top's precession frequencies for a small tilt.
/// Throws InvalidArgument for another model, or a tilt or spin out of range.
FoundPrecession find_steady_precession(const model::Model& model, double tilt, double spin);

/// The steady precession of `body` at its tilt and spin. Throws InvalidArgument unless the body
/// is on a fixed point, symmetric about an axis (its centre of mass on it) and tilted (the
/// sleeping top, at θ = 0, is steady_motion_modes' case).
SteadyPrecession steady_precession(const SpinningBody& body);

}  // namespace momenta::analysis
