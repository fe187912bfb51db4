#pragma once
// Steady motions in joint coordinates: a rotor turning at constant speed on its joint while
// everything else rests — a rigid rotor on elastic bearings, a disk on a flexible shaft, a
// gyroscope in a gimbal, a sleeping top held by a universal joint and a spin joint.
//
// Such a state is not an equilibrium of the joint coordinates (the rotor's angle grows), but it is
// one of the others when the dynamics do not depend on that angle: the angle is *cyclic* (an
// axisymmetric rotor on its own axis). Linearizing there with the cyclic angles left out — Routh's
// reduction (Goldstein §8.3; Meirovitch, Methods of Analytical Dynamics §4.10) — gives constant
// A, B, C, D whose eigenvalues are those of the perturbed steady motion. The remaining coordinates
// are measured in the frames of their joints; for joints to the world (a rotor's bearings), those
// are inertial, so the frequencies are as seen from space.
//
// Whirl. A mode of a rotor traces, at each body, a small ellipse across the spin axis n: the
// centre of mass moves by δp and the body tilts by δθ. Its sense about n, summed over the bodies
// with weights m_b (for δp) and the transverse moment of inertia (for δθ), says whether the mode
// whirls forward (with the spin) or backward; a mode with no net sense (an axial or torsional
// one) is "none". For x(t) = Re(u e^{iωt}), u = a + i b: x × ẋ = −ω a × b.
//
// Docs: docs/analysis.md (steady motions; Campbell diagrams). Covered: the turning coordinates
// are free (not prescribed) scalar coordinates — revolute, prismatic, and the scalar coordinates
// of cylindrical, universal and planar joints.

#include <complex>
#include <string>
#include <vector>

#include "momenta/analysis/linearize.hpp"
#include "momenta/analysis/state_space.hpp"
#include "momenta/analysis/steady_motion.hpp"
#include "momenta/math/types.hpp"
#include "momenta/model/model.hpp"

namespace momenta::analysis {

/// One oscillation of a steady motion's linearization.
struct SteadyMode {
  std::complex<double> eigenvalue;  ///< 1/s; imaginary part > 0 (its conjugate left out)
  double frequency = 0.0;           ///< |Im λ|, rad/s
  /// "forward" (whirling with the spin), "backward", or "none" (no net whirl: axial, torsional,
  /// or no spin axis).
  std::string whirl;
};

/// A steady motion in joint coordinates and the linear model about it.
struct JointSteadyMotion {
  OperatingPoint point;
  /// Velocity indices of the turning (cyclic) coordinates, and their names.
  std::vector<int> turning;
  std::vector<std::string> turning_names;
  /// The spin axis in the world (unit): the angular velocity the first turning coordinate gives
  /// its child body, normalized; zero when it turns no body (a prismatic coordinate).
  Vec3 spin_axis_W = Vec3::Zero();
  /// The spin speed: the first turning coordinate's rate, rad/s (or m/s).
  double speed = 0.0;
  /// max over coordinates of |v̇ᵢ| against the rates' scale (ρ(A)² and the turning rates²,
  /// times the model's length for lengths): 0 to round-off at a steady motion.
  double residual = 0.0;
  /// How much the linearization changes when the turning angles are shifted (by 1 and 2.5 rad or
  /// lengths), relative to its largest entry: round-off for cyclic coordinates.
  double cyclic_residual = 0.0;
  /// The linearization about the point (every state), as linearize() gives it.
  LinearModel full;
  /// The reduced model: the turning coordinates' positions removed from the states (their rates
  /// stay, each with a zero eigenvalue: the conserved momentum of a free rotor).
  StateSpace reduced{MatX(), MatX(), MatX(), MatX()};
  /// The velocity index of each position state of `reduced` (the free coordinates that do not
  /// turn), in order: what a mode shape's first entries move.
  std::vector<int> reduced_coordinates;
  /// The oscillations of `reduced`, ascending frequency, with their whirl.
  std::vector<SteadyMode> modes;
  bool stable = false;       ///< no eigenvalue with positive real part (beyond 1e-9 of the rates)
  double growth_rate = 0.0;  ///< the largest real part, 1/s (0 when stable)
};

/// The steady motion of `model` at `point`: the coordinates with a nonzero rate turn, the rest
/// rest. Linearizes with `options` (when it names no output and the model has no output columns:
/// the non-turning configuration states). Throws InvalidArgument when nothing turns, a turning
/// coordinate is prescribed or part of a ball or free joint, something else moves, the point is
/// not steady (residual above 1e-8: naming the coordinate with the largest acceleration), a
/// turning coordinate is not cyclic (naming it and the change), or an output reads a turning
/// position (it grows; not an output of the reduced model).
JointSteadyMotion joint_steady_motion(const model::Model& model, const OperatingPoint& point,
                                      const LinearizationOptions& options = {});

/// The same motion with its turning rates scaled so that the first is `speed` (sign kept),
/// linearized and classified, without the cyclic check (done once for the model by
/// joint_steady_motion).
JointSteadyMotion joint_steady_motion_at(const model::Model& model, const JointSteadyMotion& motion,
                                         double speed, const LinearizationOptions& options = {});

/// The Campbell diagram of a rotor in joint coordinates: its whirl frequencies (the reduced
/// linearization's, seen from the joints' frames) at `points` speeds from `from` to `to` (rad/s,
/// > 0), and the critical speeds where a forward whirl crosses the 1× line, refined by bisection
/// to 1e-12 relative. Throws as campbell_diagram(SpinningBody) for a bad range.
CampbellDiagram campbell_diagram(const model::Model& model, const JointSteadyMotion& motion,
                                 double from, double to, int points);

/// A model's Campbell diagram, whichever kind its rotor is.
struct RotorCampbell {
  /// What turns: the spinning body (Euler–Poisson) or the turning coordinates, comma-separated.
  std::string rotor;
  /// True for a rotor in joint coordinates (frequencies in the joints' frames); false for one
  /// body on a ball or free joint (frequencies seen from space).
  bool joint_coordinates = false;
  CampbellDiagram diagram;
};

/// The Campbell diagram of `model`'s rotor at its initial state: of its one body when it is on a
/// ball or free joint to the world (campbell_diagram(SpinningBody, …)), else of its steady motion
/// in joint coordinates. Throws as those do.
RotorCampbell model_campbell_diagram(const model::Model& model, double from, double to, int points);

}  // namespace momenta::analysis
