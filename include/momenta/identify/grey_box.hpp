#pragma once
// Grey-box identification (docs/identification.md): numbers of a model file — a spring rate, a
// damping, a mass, an initial angle — estimated from measured responses by nonlinear least
// squares on simulated runs. Each experiment is a log: its time column, measured outputs (model
// output columns or coordinates) and measured inputs that drive the model's signals as tables.
//
// The fit. The residuals are (y_model − y_measured) / σ_c over every sample of every channel;
// Ceres' Levenberg–Marquardt (trust region, dense QR) minimizes their sum of squares, with the
// Jacobian from the forward sensitivity equations (identify/trajectory_sensitivities.hpp), never
// from differences of whole runs. A positive parameter is estimated as ln p (it stays positive
// and its steps are relative); bounds are Ceres' box constraints. Where a channel's noise σ_c is
// not given it is estimated: a first fit weighted by each channel's spread, then σ_c from its
// residuals (N_c − n_p N_c / N degrees of freedom) and a second fit from the first optimum.
//
// How sure. At the optimum, J = ∂r/∂p; the covariance is s² (JᵀJ)⁻¹ (s² = 1 with every noise
// given, else χ²/(N − n_p)), from J's singular value decomposition so that a direction the data
// do not determine gives an infinite standard error instead of a number. 95 % intervals with
// Student's t (N − n_p) where noise was estimated, the normal quantile where it was given. Where
// the cost is clearly not quadratic over such an interval (kNotQuadratic) the interval is the
// profile likelihood's instead: where the cost, the others refitted, has risen by q² s²
// (src/identify/profile_likelihood.hpp).
// Identifiability: the singular values of J with each column scaled by its parameter's size
// (∂r/∂ln p), their condition number, and each direction whose singular value is below 10⁻⁶ of
// the largest in words — which parameters move together without changing any output.

#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "momenta/identify/frequency_response_data.hpp"
#include "momenta/identify/trajectory_sensitivities.hpp"
#include "momenta/io/file_template.hpp"
#include "momenta/io/measured_data.hpp"
#include "momenta/math/types.hpp"

namespace momenta::identify {

/// A relative singular value (σ_k / σ_1 of the scaled sensitivities) below this: the data do not
/// determine that combination of the parameters.
inline constexpr double kUndetermined = 1e-6;
/// A condition number above this: some combination is poorly determined (named).
inline constexpr double kPoorlyDetermined = 1e3;
/// A Fisher interval whose ends are this far from where the cost has risen by q² — |z/q − 1| at
/// either end, z the signed root of the rise along the line the other parameters follow — is
/// the sign of a cost far from quadratic: the profile likelihood's interval is reported instead.
inline constexpr double kNotQuadratic = 0.1;

/// A number of the model file to estimate.
struct GreyBoxParameter {
  std::string path;             ///< dotted, as a sweep's (io/file_template.hpp)
  std::string name;             ///< for people: the file's `name:`, else the path
  std::optional<double> guess;  ///< where the fit starts; nothing: the model file's value
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  /// Estimated as ln p: nothing means "when the start is > 0 and no lower bound below 0 is
  /// given" (a damping, a mass, a stiffness); false for a number of either sign (an angle).
  std::optional<bool> positive;
  /// The name of the one experiment this number belongs to (an initial angle, a payload that
  /// differs between tests): estimated for that experiment alone, as a parameter of its own, and
  /// not written into the identified model. Empty: one value shared by every experiment.
  std::string experiment;
  int line = 0, column = 0;  ///< where the identification file declares it
};

/// A measured column that drives a model signal.
struct MeasuredInput {
  std::string column;
  std::string signal;
};

/// A measured column compared with a model channel (ChannelSet).
struct MeasuredOutput {
  std::string column;
  std::string channel;
  std::optional<double> noise;  ///< σ, the channel's unit; nothing: estimated
};

/// A Bode test of one input–output pair (identify/frequency_response_data.hpp), fitted by the
/// model's linearization about its initial state.
struct FrequencyExperiment {
  MeasuredFrequencyResponse data;
  std::string input;   ///< a signal or a prescribed coordinate
  std::string output;  ///< an output column or a coordinate
};

struct GreyBoxExperiment {
  std::string name;
  io::MeasuredTable data;  ///< with a `time` column (a time log)
  std::vector<MeasuredInput> inputs;
  /// A time log's measured columns; a Bode test's two channels, `magnitude` (dB) and `phase`
  /// (degrees), with their noise.
  std::vector<MeasuredOutput> outputs;
  /// Set: the experiment is this Bode test, and `data` and `inputs` are not used.
  std::optional<FrequencyExperiment> frequency_response;
  std::vector<io::NumberOverride> set;  ///< the model's numbers for this experiment alone
};

struct GreyBoxSettings {
  SensitivityOptions sensitivity;
  int max_iterations = 100;
  /// Where the Jacobian comes from: the sensitivity equations (the default), or — the obvious
  /// alternative, kept to measure against (bench/grey_box_bench.cpp) — forward differences of
  /// whole runs, n_p + 1 runs per Jacobian with steps √rtol · |p_i|.
  enum class Jacobian { sensitivities, run_differences };
  Jacobian jacobian = Jacobian::sensitivities;
  /// Which intervals come from the profile likelihood: those whose cost is not quadratic over
  /// the Fisher interval (kNotQuadratic), every determined parameter's, or none.
  enum class Profile { where_not_quadratic, always, never };
  Profile profile = Profile::where_not_quadratic;
};

struct GreyBoxProblem {
  std::string name;
  std::filesystem::path model;
  std::vector<GreyBoxParameter> parameters;
  std::vector<GreyBoxExperiment> experiments;
  GreyBoxSettings settings;
};

/// One measured channel of one experiment, fitted.
struct FittedChannel {
  std::string experiment, column, channel, unit;
  /// What the samples are taken over: "time" (s), or "frequency" (Hz) for a Bode test.
  std::string abscissa = "time", abscissa_unit = "s";
  /// The log's times (a Bode test's frequencies) (the model ran on the even grid they round to,
  /// within 1e-6 of a spacing); guessed: the model at the start values.
  VecX time, measured, fitted, guessed;
  double noise = 0.0;  ///< σ used in the final fit
  bool noise_given = false;
  double rms = 0.0;          ///< of the residuals
  double whiteness_p = 1.0;  ///< Ljung–Box over min(20, N/5) lags
};

struct GreyBoxEstimate {
  std::vector<std::string> names, paths;
  std::vector<std::string> experiments;  ///< per parameter: the one it belongs to, or empty
  VecX start, value, standard_error, lower95, upper95;  ///< SE infinite where not determined
  /// How far the cost is from quadratic over each Fisher interval: the larger |z/q − 1| of its
  /// two ends (0 where quadratic; infinite where the line leaves a bound or a run fails; NaN for
  /// an undetermined parameter). Above kNotQuadratic the interval is the profile's.
  VecX not_quadratic;
  /// Per parameter: lower95/upper95 are the profile likelihood's (else p ± q·SE, Fisher's).
  std::vector<bool> profiled;
  /// Per parameter, each end: false where the data do not bound it on that side (the profile
  /// stays below q² up to a bound, to 0 for a positive parameter, or its fits fail) — the end
  /// is then that bound, 0 or the last value reached.
  std::vector<bool> lower_bounded, upper_bounded;
  VecX fisher_lower95, fisher_upper95;  ///< p ± q·SE, beside a profile's
  long profile_fits = 0;                ///< fits with one parameter held, for the profiles
  /// A sentence per profiled parameter: why its interval is the profile's, and any end the data
  /// do not bound.
  std::vector<std::string> interval_notes;
  std::vector<bool> positive, at_bound;
  MatX correlation;  ///< NaN-free: undetermined pairs 0, the diagonal 1
  int degrees_of_freedom = 0;
  bool noise_estimated = false;

  // Identifiability of the scaled sensitivities.
  VecX singular_values;  ///< descending
  double condition_number = 0.0;
  bool identifiable = true;
  std::vector<std::string> undetermined;  ///< a sentence per undetermined direction
  std::string least_determined;           ///< the weakest combination, when poorly determined

  std::vector<FittedChannel> channels;
  /// A sentence per time log shorter than its model's slowest time scale (1/|λ| of its slowest
  /// mode that is not a rigid-body one, about its initial state at the estimates): the numbers
  /// that mode carries are poorly determined by it.
  std::vector<std::string> warnings;

  // The optimizer.
  bool converged = false;
  std::string termination;  ///< in words
  int iterations = 0;
  long simulations = 0;                         ///< runs without sensitivities
  long sensitivity_simulations = 0;             ///< runs with them
  long evaluations = 0;                         ///< calls of a model's dynamics, all runs
  long linearizations = 0;                      ///< of Bode tests' models (p and p ± h)
  double initial_cost = 0.0, final_cost = 0.0;  ///< ½ Σ r²
  double wall_seconds = 0.0;
};

/// An interval's end as the text and the page print it: the number, or −∞ / ∞ where the data
/// leave that end open.
std::string interval_end_text(double x);

/// Fits `problem`. Throws InvalidArgument naming the parameter path (with a did-you-mean), the
/// column, signal or channel, and the experiment, for anything that does not fit the model; what
/// the model file's reader throws for values it refuses at the start.
GreyBoxEstimate fit_grey_box(const GreyBoxProblem& problem);

/// The model file's text with every estimated number replaced by its estimate, comments and
/// layout kept (a number the file did not give is added under its key's map). The text the
/// identified model is written as (`momenta identify -o`).
std::string identified_model_text(const GreyBoxProblem& problem, const GreyBoxEstimate& estimate);

}  // namespace momenta::identify
