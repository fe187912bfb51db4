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

}  // namespace momenta::analysis
