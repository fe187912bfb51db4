#pragma once
// What `momenta linearize`, `momenta modes` and `momenta response` share: the model file, the
// operating point (--about), the inputs and outputs, and how matrices print (with the JSON layout
// of output_format.hpp, which every command shares).

#include <complex>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "model_argument.hpp"
#include "momenta/analysis/controllability.hpp"
#include "momenta/analysis/equilibrium.hpp"
#include "momenta/analysis/joint_steady_motion.hpp"
#include "momenta/analysis/linearize.hpp"
#include "momenta/analysis/operating_point.hpp"
#include "momenta/analysis/rolling_steady_motion.hpp"
#include "momenta/analysis/steady_motion.hpp"
#include "momenta/common/number_text.hpp"
#include "momenta/io/model_file.hpp"
#include "output_format.hpp"

namespace momenta::cli {

struct LinearModelOptions {
  ModelArgument model;
  std::string about = "initial";  // auto | initial | equilibrium | steady | STATE.json
  std::vector<std::string> inputs;
  std::vector<std::string> outputs;
  std::vector<std::string> independent;  // constrained models: coordinates to keep as states
  bool open_loop = false;  // models with controllers: the plant alone (LinearizationOptions)
};

/// Adds MODEL, --about and --independent (and --inputs/--outputs when `with_channels`, and
/// --open-loop when `loop_choice`) to a command.
void add_linear_model_options(CLI::App* command, LinearModelOptions& options, bool with_channels,
                              bool loop_choice = true);

/// The model file and its linear analysis about the point --about names
/// (analysis::linear_analysis_about: the rule the report and Python share). An equilibrium's
/// sentence gains its Newton iterations, and an unstable one is noted on stderr.
struct LoadedLinearModel {
  io::ModelFile file;
  analysis::LinearAnalysis result;
};
LoadedLinearModel load_linear_model(const LinearModelOptions& options);
/// The same with the model file already read.
LoadedLinearModel load_linear_model(const LinearModelOptions& options, io::ModelFile file);

/// Throws CLI::ValidationError on --about unless the analysis has inputs and outputs (a
/// spinning body's and a rolling body's steady motions have none): what `response` needs.
void require_channels(const LoadedLinearModel& loaded);

/// `modes` and `linearize` about a steady motion without inputs or outputs: of one body on a
/// ball or free joint (in Euler–Poisson variables, or a precession's roots and nutation) or of a
/// rolling body (seen from its turning frame). Prints it as JSON or as text (with the matrix A
/// when `with_matrix`) and returns true; false for the other kinds, which print nothing here.
bool print_motion_without_channels(const LoadedLinearModel& loaded, bool as_json, bool with_matrix);

/// JSON of a steady precession's roots at its tilt and spin (shared by `modes --about steady` and
/// `steady`): tilt, spin, I1, I3, mgl, slow, fast, minimum_spin, gyroscopic, gyroscopic_error,
/// slow_nutation, fast_nutation (roots that do not exist as null).
nlohmann::ordered_json precession_roots_json(const analysis::SteadyPrecession& p);

/// The whirl of each oscillation of a steady motion in joint coordinates, as text lines and JSON.
void print_whirls(const analysis::JointSteadyMotion& steady);
nlohmann::ordered_json whirls_json(const analysis::JointSteadyMotion& steady);

/// "the inputs move every state (rank 4 of 4)", or "rank 3 of 4: the inputs do not move the
/// mode at -3" (`who`: "inputs" or "outputs"; `verb`: "move" or "show").
std::string reachability_text(const analysis::Reachability& r, const char* who, const char* verb);

/// JSON of a complex number as [re, im].
nlohmann::ordered_json complex_json(std::complex<double> z);
/// Prints a matrix with row and column labels, 6 significant digits.
void print_matrix(const char* name, const MatX& M, const std::vector<std::string>& rows,
                  const std::vector<std::string>& columns);
// number_text and complex_text: momenta/common/number_text.hpp (shared with the Python reprs).

}  // namespace momenta::cli
