#pragma once
// Where a linear analysis is taken about — the one rule the command line (`--about`), the HTML
// report's linear panel and Python share.
//
//   initial      the model's initial state, whatever it does there;
//   equilibrium  the static equilibrium Newton finds from the initial configuration;
//   steady       the steady motion at the initial state: of one body on a ball or free joint
//                (Euler–Poisson: a sleeping top, a satellite's spin; or a symmetric top's steady
//                precession at a tilt, Routh's reduction to its nutation), of a rolling body
//                (seen from its turning frame), or of rotors turning on their joints (the
//                turning positions left out);
//   a state      a given (t, q, v);
//   auto         the initial state where it is at rest; where it moves, its steady motion if it
//                is one, else the static equilibrium found from it, else the initial state —
//                the sentence says which and why.
//
// Each answer carries the sentence that says what it was taken about, and a linear model for
// every kind (the one a panel of poles and modes shows) with the map from a mode's shape to the
// joints' motion. Docs: docs/analysis.md (operating points).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "momenta/analysis/equilibrium.hpp"
#include "momenta/analysis/joint_steady_motion.hpp"
#include "momenta/analysis/linearize.hpp"
#include "momenta/analysis/rolling_steady_motion.hpp"
#include "momenta/analysis/steady_motion.hpp"
#include "momenta/model/model.hpp"

namespace momenta::analysis {

/// Which operating point to take a linear analysis about.
enum class OperatingPointChoice { automatic, initial, equilibrium, steady, given };

/// The choice a name says: "auto", "initial", "equilibrium", "steady"; nullopt for any other
/// (a front end may read it as a state file's path).
std::optional<OperatingPointChoice> operating_point_choice(std::string_view name);

/// "auto", "initial", "equilibrium", "steady", "given".
const char* operating_point_choice_name(OperatingPointChoice choice);

/// What the linear analysis was taken about, as the models of each kind are analysed.
enum class LinearAnalysisKind {
  joint_coordinates,  ///< linearize() about a point (initial, equilibrium, given)
  joint_steady,       ///< rotors turning on their joints: joint_steady_motion()
  rolling_steady,     ///< a rolling body's steady motion: rolling_steady_modes()
  spinning_body,      ///< one body on a ball or free joint, Euler–Poisson: steady_motion_modes()
  steady_precession,  ///< a symmetric top's steady precession: steady_precession()
};

/// "joint_coordinates", "joint_steady", "rolling_steady", "spinning_body", "steady_precession".
const char* linear_analysis_kind_name(LinearAnalysisKind kind);

/// A linear analysis about the chosen point.
struct LinearAnalysis {
  LinearAnalysisKind kind = LinearAnalysisKind::joint_coordinates;
  /// What it was taken about, as a sentence to follow "linearized about": "the initial state",
  /// "the static equilibrium", "the steady motion: spin.angle turning at 300, …", or the given
  /// state's name; with `auto`, why it is that point.
  std::string about;
  /// The linear model a panel of poles and modes shows, for every kind: linearize()'s
  /// (joint_coordinates), the reduced model with the full one's point (joint_steady), the motion
  /// seen from the turning frame (rolling_steady), Euler–Poisson's A over (ω, γ) in the body
  /// (spinning_body), or the nutation δθ, δθ̇ about the precession (steady_precession, A =
  /// [0 1; −ω_n² 0]). Only joint_coordinates and joint_steady have inputs and outputs.
  LinearModel linear;
  /// How a mode's shape φ (a complex state vector of linear.system) moves the joints: the
  /// tangent δv = Re(shape_to_tangent φ), nv × states — the configuration states' coordinates,
  /// or for a spinning body its tilt δθ = δγ × γ (the vertical's change seen from the body), for a
  /// precession the nutation about the line of nodes.
  MatX shape_to_tangent;
  /// The initial state's largest acceleration and speed (initial, given and auto; 0 otherwise):
  /// above kAtRestAcceleration or kAtRestSpeed, the state is not at rest and its modes describe
  /// the motion linearized at that instant only.
  double largest_acceleration = 0.0;
  double largest_speed = 0.0;

  std::optional<Equilibrium> equilibrium;            ///< equilibrium (and auto's fallback)
  std::optional<JointSteadyMotion> joint_steady;     ///< joint_steady
  std::optional<RollingSteadyModes> rolling_steady;  ///< rolling_steady
  std::optional<SpinningBody> spinning_body;         ///< spinning_body, steady_precession
  std::optional<SteadyMotionModes> spinning_modes;   ///< spinning_body
  std::optional<SteadyPrecession> precession;        ///< steady_precession

  /// Whether it has inputs and outputs (joint_coordinates, joint_steady).
  bool has_channels() const;
};

/// The linear analysis of `model` about the point `choice` names (`given` is that point for
/// OperatingPointChoice::given, named `given_name`). `options` name the inputs and outputs of
/// the kinds that have them. Throws InvalidArgument when the choice does not apply (steady on a
/// state that is not a steady motion, naming why; given without a state), NumericalError when no
/// equilibrium is found (equilibrium; auto falls back), and what linearize() throws.
LinearAnalysis linear_analysis_about(const model::Model& model, OperatingPointChoice choice,
                                     const LinearizationOptions& options = {},
                                     const std::optional<OperatingPoint>& given = std::nullopt,
                                     const std::string& given_name = "the given state");

}  // namespace momenta::analysis
