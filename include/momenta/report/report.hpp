#pragma once
// The HTML report: one self-contained file (every script, style and number inlined; no network)
// that shows a simulation — the motion in 3-D, every recorded column plotted, the linear
// analysis, the conservation audit — or a part's mass properties. The page's front-end lives in
// web/ and is embedded in the library at build time. What each panel shows: docs/report.md.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "momenta/inertia/balancing.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/io/part_file.hpp"
#include "momenta/math/types.hpp"
#include "momenta/model/parameter_source.hpp"
#include "momenta/simulate/simulation.hpp"

namespace momenta::report {

/// A run to report: the model file it came from, its table (the columns of simulate::Simulation,
/// one row per recorded step) and what the run did.
struct SimulationRun {
  const io::ModelFile* file = nullptr;
  std::vector<std::string> columns;
  std::vector<std::string> units;  ///< each column's (simulate::Simulation::column_units)
  std::vector<std::vector<double>> rows;
  simulate::SimulationOptions options;
  simulate::SimulationSummary summary;
  /// Why the run ended early (a non-finite state, an interrupt); empty when it ran to the end.
  /// The report then shows the rows up to that time and the reason at the top.
  std::string stop_reason;
};

/// What the linear-analysis panel linearizes about, and for which channels.
struct LinearSettings {
  /// "auto" (the initial state where it is at rest, else the static equilibrium found from it,
  /// the panel saying which and why), "initial" (the initial state, with a note when it is not
  /// at rest), "equilibrium", or "steady" (a rotor's steady motion in joint
  /// coordinates, analysis/joint_steady_motion.hpp: its turning positions left out).
  std::string about = "auto";
  std::vector<std::string> inputs;   ///< as analysis::LinearizationOptions::inputs
  std::vector<std::string> outputs;  ///< as analysis::LinearizationOptions::outputs
  /// When set, a Campbell panel: the rotor's whirl frequencies from the first speed to the
  /// second (rad/s), at `campbell_points` speeds (analysis::model_campbell_diagram).
  std::optional<std::array<double, 2>> campbell;
  int campbell_points = 41;
};

/// Checks `settings` before a run whose report will use them: `about` one of initial,
/// equilibrium, steady, and the --inputs and --outputs names known to the model
/// (analysis::check_linearization_names). Throws InvalidArgument. (A linearization that fails
/// for the model's own reasons leaves the report's panel empty, saying why; a misspelt name is
/// the caller's mistake and is refused here.)
void check_linear_settings(const io::ModelFile& file, const LinearSettings& settings);

/// The run a simulation left in `table`: with the summary it returned, or — when `stop_reason` is
/// set (it threw) — a summary of the rows up to the failure (integrator, step, rows, t_end).
SimulationRun make_run(const io::ModelFile& file, const simulate::Simulation& simulation,
                       simulate::TableSink&& table, simulate::SimulationSummary summary,
                       std::string stop_reason);

/// Runs the model as `momenta simulate` would with `options` (reactions recorded), keeping the
/// table in memory. A run that stops on a non-finite state returns the rows up to then, with
/// the error's message as stop_reason; other errors are thrown.
SimulationRun simulate_for_report(const io::ModelFile& file, simulate::SimulationOptions options);

/// The report page of a run: the summary, the 3-D view, the plots and, when the model can be
/// linearized about the point `linear` names, the linear analysis (poles and zeros, Bode, step
/// responses, animated mode shapes); when it cannot (no free joint, a singular mass matrix, a
/// channel the model lacks, a state that is not a steady motion), the panel says why; with
/// `linear.campbell`, the Campbell diagram (or why there is none). Throws InvalidArgument for an
/// `about` other than "auto", "initial", "equilibrium" or "steady", or a run with no file or no
/// rows.
std::string simulation_report_html(const SimulationRun& run, const LinearSettings& linear = {});

/// The data simulation_report_html embeds in its page, as JSON text: what the report's in-page
/// engine (wasm/) computes again for a changed model, and what its tests compare with the page's.
std::string simulation_report_json(const SimulationRun& run, const LinearSettings& linear = {});

/// One of the long arrays of a report's data (frames, plot columns, responses), set apart from
/// its JSON text: its values, and whether the page keeps them in float32 (`single`: what it only
/// draws, as the page's base64 "f32:" text holds them) or float64.
struct ReportArray {
  std::vector<double> values;
  bool single = false;
};
/// simulation_report_json's data with its long arrays apart, for a consumer that takes them as
/// typed arrays (the in-page engine): the JSON text writes `marker` followed by k where the page
/// embeds the k-th array as base64 text. The marker is the caller's and should be a string no
/// model's name or text can hold (the engine's page gives a random one each run); it must not be
/// empty or hold a character JSON escapes.
struct ReportDataParts {
  std::string json;
  std::vector<ReportArray> arrays;
};
/// Which panels' data: every panel's; the motion's — the summary and its audit, the 3-D view's
/// scene and frames, the plots and the control loops, which a live page redraws first — or the
/// analysis' — the linear analysis, the equations, the Campbell and the free-body diagrams, which
/// it redraws next. The two together hold what `all` holds (each with `kind`).
enum class ReportPanels { all, motion, analysis };

ReportDataParts simulation_report_parts(const SimulationRun& run, const std::string& marker,
                                        const LinearSettings& linear = {},
                                        ReportPanels panels = ReportPanels::all);

/// The equations a report embeds, as its page's engine gives their symbols the values of a model
/// its reader changed: each symbol by name with its sources (model/parameter_source.hpp), and the
/// numbers the form depends on that no symbol stands for (symbolic::FormNumber).
struct EquationSymbolSources {
  std::string name;
  std::vector<model::ParameterSource> sources;
};
struct EquationFormNumber {
  std::string name;
  model::ParameterSource source;
  double value = 0.0;
};
/// Each symbol's value in the changed model; the symbols that are 0 there (their terms leave the
/// equations, which hold with the 0 put in: `zeroed`); and why the equations change form
/// otherwise ([] when they keep it): a length's sign turned along its axis, symbols one name
/// stands for no longer equal, or a form number changed. Where the form changes the equations
/// hold for the file alone, whatever the values.
struct EquationNumbers {
  std::vector<double> values;
  std::vector<std::string> zeroed;
  std::vector<std::string> form_changes;
};
EquationNumbers equation_numbers(const model::Model& model,
                                 const std::vector<EquationSymbolSources>& symbols,
                                 const std::vector<EquationFormNumber>& form);

/// The report page of a part: the composite with its centre of mass, principal axes and
/// equivalent inertia ellipsoid drawn over its parts (holes shown as holes), the table of parts,
/// and the inertia tensor about the centre of mass and, when given, about the point `about`
/// (in the part's frame, m). `source` names the file.
std::string inertia_report_html(const io::CompositePart& part, const std::string& source,
                                const std::optional<Vec3>& about = std::nullopt);

/// What `momenta balance` found, for its page.
struct BalanceFindings {
  inertia::RotorAxis axis;
  inertia::Unbalance unbalance;
  std::optional<std::array<double, 2>> bearings;  ///< z_A, z_B, m
  std::vector<inertia::CorrectionMass> corrections;
  std::optional<double> radius;  ///< of the correction masses, m
  bool remove = false;           ///< corrections drilled out (opposite) rather than added
  std::vector<double> speeds;    ///< rad/s, with the reactions at each (before, after)
  std::vector<inertia::BearingReactions> reactions, reactions_after;
  std::optional<inertia::GradeCheck> grade, grade_after;
};

/// The rotor's page: the mass-properties page of the part with the rotation axis, the bearing
/// planes and the correction masses drawn, and a balancing section — the unbalance, the
/// corrections, the grade verdict and the bearing forces against speed.
std::string balance_report_html(const io::CompositePart& rotor, const std::string& source,
                                const BalanceFindings& findings);

/// What a sweep's page shows: its columns and rows, read from its results file.
struct SweepResults {
  std::string title;                             ///< the sweep's name
  std::string source;                            ///< the sweep file
  std::vector<std::string> parameters, metrics;  ///< column names
  /// Their units (SweepRunner::parameter_units, metric_units); "" where unknown. May be empty.
  std::vector<std::string> parameter_units, metric_units;
  std::vector<long> runs;
  std::vector<bool> ok;
  std::vector<std::vector<double>>
      values;  ///< parameters then metrics, one value per run (NaN: none)
};

/// The sweep's page (`momenta sweep --report`): runs and failures, a scatter plot of any column
/// against any other (chosen on the page), and parallel coordinates of every parameter and
/// metric, one line per run coloured by the first metric.
std::string sweep_report_html(const SweepResults& results);

/// What an identification's page shows (`momenta identify --report`), filled by the front end
/// from identify::InertiaEstimate (the report layer sits beside identify, not above it).
struct IdentificationResults {
  std::string title;                      ///< the model's name
  std::string model_source, data_source;  ///< the files
  int samples = 0, degrees_of_freedom = 0, num_parameters = 0;
  std::vector<double> time;  ///< each sample's time (s); empty: the data has no time column
  std::vector<std::string> efforts, effort_units;     ///< one per coordinate: the columns fitted
  std::vector<std::vector<double>> measured, fitted;  ///< per effort, one value per sample
  std::vector<double> noise, residual_rms;            ///< per effort
  struct Estimate {
    std::string name, unit;  ///< the base parameter in words, its unit
    double estimate = 0, standard_error = 0, lower = 0, upper = 0, model = 0;
  };
  std::vector<Estimate> estimates;
  std::vector<std::vector<double>> correlation;  ///< of the estimates, row by row
  std::vector<std::string> never_felt, regrouped;
  std::vector<double> excitation;  ///< relative singular values of the scaled regressor
  double condition_number = 0;
  std::string least_determined;     ///< the least-determined combination, in words
  double poor_excitation = 100;     ///< above this condition number, named poorly exciting
  std::vector<double> whiteness_p;  ///< per effort: Ljung–Box p of its residuals
  int whiteness_lags = 0;
  double whiteness_level = 0.01;  ///< below it, a residual is called correlated
  struct Body {
    std::string name, verdict;
    bool consistent = false;
  };
  std::vector<Body> bodies;
};

/// The identification's page: measured and fitted efforts against time, their residuals with the
/// noise found, the estimates with their 95 % intervals beside the model's values, the
/// correlation matrix as a heat map, what the data cannot tell and each body's consistency.
std::string identification_report_html(const IdentificationResults& results);

/// What a grey-box fit's page shows (`momenta identify FILE.yaml --report`): filled by the front
/// end from identify::GreyBoxEstimate.
struct GreyBoxResults {
  std::string title;         ///< the identification file's name
  std::string model_source;  ///< the model file
  bool converged = false;
  std::string termination;  ///< how the fit ended, in words
  int iterations = 0, degrees_of_freedom = 0;
  long runs = 0, evaluations = 0, linearizations = 0;  ///< linearizations: of Bode tests
  double seconds = 0;
  bool noise_estimated = false;
  struct Parameter {
    std::string name, path;
    double estimate = 0, standard_error = 0, lower = 0, upper = 0,
           start = 0;  ///< ±inf: not determined
    bool at_bound = false;
    bool profiled = false;  ///< lower/upper from the profile likelihood, else Fisher's
    bool lower_bounded = true, upper_bounded = true;  ///< false: the data leave that end open
  };
  std::vector<std::string> interval_notes;  ///< why each profiled interval is, in words
  /// Time logs shorter than their model's slowest time scale (identify::GreyBoxEstimate).
  std::vector<std::string> warnings;
  std::vector<Parameter> parameters;
  std::vector<std::vector<double>> correlation;  ///< of the estimates, row by row
  std::vector<double> singular_values;           ///< of the scaled sensitivities, descending
  double condition_number = 0;
  bool identifiable = true;
  std::vector<std::string> undetermined;  ///< a sentence per undetermined direction
  std::string advice;                     ///< what to do about them
  std::string least_determined;           ///< when poorly determined
  double poorly_determined = 1e3;         ///< above this condition number
  struct Channel {
    std::string experiment, column, channel, unit;
    std::vector<double> time, measured, fitted, at_start;
    double noise = 0, residual_rms = 0, whiteness_p = 1;
    bool noise_given = false;
    /// The samples' axis: "time" (s), or "frequency" (Hz, drawn on a log scale) for a Bode test.
    std::string abscissa = "time", abscissa_unit = "s";
  };
  std::vector<Channel> channels;
  double whiteness_level = 0.01;  ///< below it, a residual is called correlated
};

/// The grey-box fit's page: per measured channel the log, the fitted model's response and the
/// start's, the residual with ±2σ; the estimates with their intervals; the correlations as a
/// heat map; what the data cannot determine, in words.
std::string grey_box_report_html(const GreyBoxResults& results);

/// Writes `html` to `path`. An existing file is kept (FileError naming it and --force) unless
/// `overwrite`; a failed write leaves no partial file (written to a temporary name, then renamed).
void write_report(const std::filesystem::path& path, const std::string& html, bool overwrite);

}  // namespace momenta::report
