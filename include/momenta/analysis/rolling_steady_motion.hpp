#pragma once
// Steady motions of a body of revolution rolling on a level floor — a coin or a wheel on a
// steady circle, leaning into the turn (upright on a straight line), a disk rolling on the floor
// at the end of an axle pivoted above it (Beer & Johnston, Dynamics, Sample Problem 18.2) — and
// the linear analysis about them.
//
// Symmetry. Turning the whole motion about a vertical axis, sliding it across the floor and
// spinning the body about its own axis change nothing in its dynamics: the floor is level, the
// body round about its axis e with its centre of mass G on it (and a pivot, if any, on that axis
// too). A steady motion is the orbit of one such motion: the body keeps its lean while it turns
// about a vertical axis at the precession rate Ω and spins about e at σ relative to the turning
// frame; G moves at a constant speed on a circle of radius ρ (a straight line when Ω = 0). Its
// angular velocity is ω = Ω n + σ e, n the upward vertical.
//
// Finding them. At a given lean, the rates (Ω, σ, the velocity of G) with which the body rolls
// without slipping form a plane (a line on a pivot). One more condition — the speed, the radius,
// the precession or the spin — leaves a line (a point on a pivot), and on it the dynamics ask one
// thing: the accelerations the model gives equal those of the steady motion. Both are quadratic
// in the rates (the equations of motion are, and so is the rate at which a steady motion's joint
// velocities turn), so three evaluations of the model along the line give the residual's
// polynomial exactly; its real roots are the steady motions: two at most, one on a pivot, where
// the floor's normal force takes whatever moment the motion needs.
//
// Linearization (a relative equilibrium: Marsden & Ratiu, Introduction to Mechanics and
// Symmetry, §9.8; Routh's steady motions). Seen from the frame that moves with the steady motion,
// x̃ = g(t)⁻¹ x, a perturbed motion obeys the autonomous x̃̇ = f(x̃) − ξ(x̃), ξ the steady motion's
// generator; the steady state is its equilibrium, and the eigenvalues of its linearization, in
// the independent coordinates linearize() chooses for the constraints, are those of the
// perturbed motion. The symmetry leaves zero eigenvalues: a perturbation along it, or to a
// neighbouring steady motion, does not grow or oscillate (it drifts at most linearly).
//
// Docs: docs/analysis.md (steady motions of rolling bodies); CLI `momenta steady` and
// `momenta modes --about steady` (docs/cli.md).

#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "momenta/analysis/linearize.hpp"
#include "momenta/analysis/state_space.hpp"
#include "momenta/math/types.hpp"
#include "momenta/model/model.hpp"

namespace momenta::analysis {

/// True when `model` is one rigid body on a free or spherical joint to the world with one rolling
/// contact of a disk (the models whose steady motions are found here). Whether the floor is level
/// and the body round is checked by the functions below, with a message.
bool rolling_steady_applies(const model::Model& model);

/// The one quantity a user fixes, besides the lean, to pick a steady motion.
enum class RollingCondition {
  speed,       ///< of the centre of mass along the rolling direction, m/s
  radius,      ///< of the centre of mass's circle, m (> 0: the turn's centre on the lean side)
  precession,  ///< Ω, rad/s about the upward vertical
  spin,        ///< ω·e, rad/s: the angular velocity's component along the disk's axis
};

/// "speed", "radius", "precession", "spin".
const char* rolling_condition_name(RollingCondition condition);

/// One steady motion of a rolling body. Directions at the state: `heading` is the rolling
/// direction e × n / |e × n| (the rolling constraint's longitudinal direction), `lateral` =
/// n × heading, the side the lean is measured towards.
struct RollingSteadyMotion {
  OperatingPoint
      point;          ///< the model's state on it (t = 0); a circle's centre on the world's z axis
  double lean = 0.0;  ///< rad: the disk's plane from the vertical, > 0 leaning towards `lateral`
  double precession = 0.0;  ///< Ω, rad/s about the upward vertical
  double spin = 0.0;        ///< ω·e, rad/s
  double relative_spin = 0.0;  ///< σ = ω·e − Ω n·e, rad/s: the spin relative to the turning frame
  double speed = 0.0;          ///< of G along `heading`, m/s
  /// Of G's circle, m: > 0 with the turn's centre on the lateral side; ±∞ on a straight line.
  double radius = 0.0;
  double contact_radius = 0.0;  ///< of the contact point's circle, m (signed as `radius`)
  Vec3 heading_W = Vec3::Zero();
  Vec3 lateral_W = Vec3::Zero();
  /// The floor's force on the body at the contact, N: normal (up), longitudinal (along heading),
  /// lateral — the rolling constraint's output columns.
  Vec3 contact_force = Vec3::Zero();
  /// max |v̇ − v̇_steady| over the coordinates against the rates' scale (g/r + |ω|² + (v/r)²,
  /// lengths over the disk's radius r): 0 to round-off on a steady motion.
  double residual = 0.0;
};

/// What a model's rolling body is: names, and whether a pivot holds it.
struct RollingBodyInfo {
  std::string body, joint, contact;
  bool pivoted = false;  ///< on a spherical joint (the lean is then the pivot's, not a choice)
  double radius = 0.0;   ///< the disk's, m
  double mass = 0.0;     ///< kg
  double axial_moment = 0.0, transverse_moment = 0.0;  ///< about G, kg·m² (I₃ and I₁)
};

/// The rolling body of `model`. Throws InvalidArgument unless rolling_steady_applies and the floor
/// is level (normal against gravity, to 1e-9), the body round about the disk's axis (two equal
/// moments about G across it, G on it, to 1e-9) and a pivot on that axis.
RollingBodyInfo rolling_body_info(const model::Model& model);

/// The steady motions of `model`'s rolling body at the lean (rad; required for a free body,
/// refused on a pivot, |lean| < 90°) with `condition` = `value` (radius: any nonzero value,
/// ±∞ for a straight line): each real root — two at most, "slow" then "fast" (ascending |Ω|) —
/// its state placed with the turn's centre on the world's vertical axis and checked (residual
/// ≤ 1e-8). A radius fixes no sense of travel: of a motion and its reverse in time (−Ω, −σ, −v)
/// the one rolling forwards (speed > 0) is returned. Empty when no steady motion has that value
/// (the roots are complex). Throws InvalidArgument for another model, a lean missing or out of
/// range, a non-finite value, or a condition that leaves a whole family steady (an upright disk
/// rolls straight at any speed: give the speed); NumericalError when a root's rates exceed 1e5
/// times √(g/r) (gravity's share of the dynamics is round-off there) or no root holds to 1e-8.
std::vector<RollingSteadyMotion> find_rolling_steady_motions(const model::Model& model,
                                                             std::optional<double> lean,
                                                             RollingCondition condition,
                                                             double value);

/// The steady motion `model` is in at `point` (made consistent with the constraints first): the
/// precession, spin and velocity read from the state (ω in span{n, e}) and checked. Throws
/// InvalidArgument when ω has a part outside span{n, e} or the residual is above 1e-8, naming it.
RollingSteadyMotion rolling_steady_motion(const model::Model& model, const OperatingPoint& point);

/// The linear analysis about a steady motion.
struct RollingSteadyModes {
  RollingSteadyMotion motion;
  /// ẋ = A x of the perturbation seen from the moving frame (B, C, D empty), with its state
  /// names: the independent configuration tangents, then the independent velocities.
  StateSpace reduced{MatX(), MatX(), MatX(), MatX()};
  /// The velocity index (into v) of each configuration state of `reduced`, in order.
  std::vector<int> coordinates;
  /// The eigenvalues of A that move the body relative to its motion — the wobble of a rolling
  /// disk — each conjugate pair once (imaginary part ≥ 0), ascending |λ|.
  std::vector<std::complex<double>> eigenvalues;
  /// ±iΩ of a turning free body (once, imaginary part > 0): the mode that only moves the body
  /// across the floor. Seen from the turning frame, a circle whose centre is displaced turns at
  /// Ω: a neighbouring steady motion, not an oscillation of the body. Empty otherwise.
  std::vector<std::complex<double>> circle_shift;
  /// How many eigenvalues are zero (to 1e-4 of the rates' scale: a zero in a Jordan block of two
  /// splits by the square root of the differences' 1e-10): the symmetry's directions and the
  /// neighbouring steady motions.
  int zero_eigenvalues = 0;
  bool stable = false;       ///< no eigenvalue with a positive real part (beyond 1e-4 of the scale)
  double growth_rate = 0.0;  ///< the largest real part, 1/s (0 when stable)
};

/// Linearizes the perturbed motion about `motion` (from find_rolling_steady_motions or
/// rolling_steady_motion on the same model). Throws as linearize() does for the constraints.
RollingSteadyModes rolling_steady_modes(const model::Model& model,
                                        const RollingSteadyMotion& motion);

}  // namespace momenta::analysis
