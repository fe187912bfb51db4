#include "linear_model_options.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "output_format.hpp"
#include "rolling_steady_output.hpp"
#include "state_file.hpp"

namespace momenta::cli {
namespace {
using json = nlohmann::ordered_json;
}  // namespace

void add_linear_model_options(CLI::App* command, LinearModelOptions& o, bool with_channels,
                              bool loop_choice) {
  add_model_argument(command, o.model);
  if (loop_choice) {
    command->add_flag("--open-loop", o.open_loop,
                      "Models with controllers: linearize the plant alone, each input a "
                      "controller drives an input (default: the closed loop, the controllers' "
                      "states in A)");
  }
  command
      ->add_option("--about", o.about,
                   "Operating point: 'initial' (the file's initial state), 'equilibrium' (the "
                   "static equilibrium Newton finds from it), 'steady' (the steady motion at "
                   "the initial state: of one spinning body on a ball or free joint, of a "
                   "rolling body, or of a rotor turning on its joint, its angle left out), "
                   "'auto' (the initial state at rest, else its steady motion, else the "
                   "equilibrium: the report's default) or a STATE.json file "
                   "{\"q\": [...], \"v\": [...], \"t\": 0}")
      ->capture_default_str();
  command
      ->add_option("--independent", o.independent,
                   "Models with constraints: coordinates to keep as states where the "
                   "constraints allow, comma-separated (default: the first joints')")
      ->delimiter(',');
  if (with_channels) {
    command
        ->add_option("--inputs", o.inputs,
                     "Inputs: signals or prescribed coordinates, comma-separated (default: "
                     "every signal)")
        ->delimiter(',');
    command
        ->add_option("--outputs", o.outputs,
                     "Outputs: the file's output columns, states or joint coordinates, "
                     "comma-separated (default: the file's outputs, else every coordinate)")
        ->delimiter(',');
  }
}

LoadedLinearModel load_linear_model(const LinearModelOptions& o) {
  return load_linear_model(o, load_model(o.model));
}

LoadedLinearModel load_linear_model(const LinearModelOptions& o, io::ModelFile file) {
  const model::Model& model = file.model;
  analysis::LinearizationOptions options;
  options.inputs = o.inputs;
  options.outputs = o.outputs;
  options.independent = o.independent;
  options.close_loops = !o.open_loop;
  options.output_specs = file.outputs;
  const std::optional<analysis::OperatingPointChoice> choice =
      analysis::operating_point_choice(o.about);
  std::optional<analysis::OperatingPoint> given;
  if (!choice) {
    if (!std::filesystem::exists(o.about)) {
      throw FileError(fmt::format(
          "--about '{}': not 'auto', 'initial', 'equilibrium', 'steady' or an existing state file",
          o.about));
    }
    given = read_state_file(o.about, model);
  }
  analysis::LinearAnalysis result = analysis::linear_analysis_about(
      model, choice.value_or(analysis::OperatingPointChoice::given), options, given, o.about);
  if (result.equilibrium) {
    // Asked for by name, the sentence gains its iterations; auto's says why it moved there.
    const analysis::Equilibrium& e = *result.equilibrium;
    if (choice == analysis::OperatingPointChoice::equilibrium) {
      result.about += fmt::format(" ({} Newton iterations)", e.iterations);
    }
    if (!e.stable()) {
      std::vector<std::string> growth;
      for (const auto& z : e.unstable_eigenvalues) growth.push_back(complex_text(z));
      fmt::print(stderr,
                 "momenta: note: the equilibrium is unstable: eigenvalues with positive real "
                 "part {}\n",
                 fmt::join(growth, ", "));
    }
  }
  return LoadedLinearModel{std::move(file), std::move(result)};
}

void require_channels(const LoadedLinearModel& loaded) {
  switch (loaded.result.kind) {
    case analysis::LinearAnalysisKind::joint_coordinates:
    case analysis::LinearAnalysisKind::joint_steady:
      return;
    case analysis::LinearAnalysisKind::spinning_body:
    case analysis::LinearAnalysisKind::steady_precession:
      throw CLI::ValidationError(
          "--about",
          "steady: a body spinning on a ball or free joint is analysed in Euler–Poisson "
          "variables, which have no inputs or outputs (`momenta modes` and `momenta linearize` "
          "show them); for a response, hold the rotor by a universal joint and a revolute spin "
          "joint (examples/rotor_on_bearings.yaml)");
    case analysis::LinearAnalysisKind::rolling_steady:
      throw CLI::ValidationError(
          "--about",
          "steady: a rolling body's steady motion is linearized seen from its turning frame, "
          "without inputs or outputs (`momenta modes` and `momenta linearize` show it)");
  }
}

namespace {

// What the spinning body's printers read: the file, the body and its modes or precession.
struct SpinningBodyView {
  const io::ModelFile& file;
  const analysis::SpinningBody& body;
  const std::optional<analysis::SteadyMotionModes>& modes;
  const std::optional<analysis::SteadyPrecession>& precession;
};

void print_precession_text(const SpinningBodyView& s) {
  const analysis::SteadyPrecession& p = *s.precession;
  const double deg = 180.0 / M_PI;
  fmt::print(
      "{}: steady precession of the symmetric top '{}' on spherical joint '{}': tilt {:.6g}° from "
      "the vertical, spin ω₃ = {:.6g} rad/s\n",
      s.file.name, s.body.body, s.body.joint, p.tilt * deg, p.spin);
  fmt::print("  I₁ = {:.6g}, I₃ = {:.6g} kg·m² about the fixed point, m g l = {:.6g} N·m\n\n", p.I1,
             p.I3, p.mgl);
  fmt::print("precession rates, roots of I₁ cos θ φ̇² − I₃ ω₃ φ̇ + m g l = 0:\n");
  fmt::print("  slow {} rad/s, fast {} rad/s\n", number_text(p.slow, 0), number_text(p.fast, 0));
  fmt::print("  the state precesses at {} rad/s (residual {:.3g})\n", number_text(p.precession, 0),
             p.residual);
  if (p.minimum_spin > 0.0) {
    fmt::print("  steady precession at this tilt needs ω₃ ≥ 2√(I₁ m g l cos θ)/I₃ = {:.6g} rad/s\n",
               p.minimum_spin);
  }
  fmt::print(
      "  gyroscopic approximation m g l/(I₃ ω₃) = {:.6g} rad/s, {:.3g} relative to the slow "
      "root\n",
      p.gyroscopic, p.gyroscopic_error);
  fmt::print(
      "nutation about it (linearized, Routh's reduction to θ): {:.6g} rad/s about the slow "
      "precession, {:.6g} rad/s about the fast\n",
      p.slow_nutation, p.fast_nutation);
  fmt::print(
      "\nstable: a steady precession of a symmetric top is a minimum of its effective "
      "potential in θ; small disturbances nutate about it\n");
}

json precession_json(const SpinningBodyView& s) {
  json j = {{"model", s.file.name},
            {"about", "steady"},
            {"motion", "steady precession"},
            {"body", s.body.body},
            {"joint", s.body.joint}};
  j.update(precession_roots_json(*s.precession));
  j["precession"] = s.precession->precession;
  j["residual"] = s.precession->residual;
  return j;
}

void print_steady_motion_text(const SpinningBodyView& s, bool with_matrix) {
  const analysis::SpinningBody& b = s.body;
  const analysis::SteadyMotionModes& m = *s.modes;
  fmt::print("{}: steady motion of body '{}' on {} joint '{}' (Euler–Poisson residual {:.3g})\n",
             s.file.name, b.body, b.fixed_point ? "spherical" : "free", b.joint, m.residual);
  fmt::print("  ω = [{:.6g}, {:.6g}, {:.6g}] rad/s in the body frame", b.w_B.x(), b.w_B.y(),
             b.w_B.z());
  if (b.fixed_point) {
    fmt::print("; the vertical in it [{:.6g}, {:.6g}, {:.6g}]", b.up_B.x(), b.up_B.y(), b.up_B.z());
  }
  fmt::print("\n\n");
  if (with_matrix) {
    print_matrix("A (d/dt of the state, Euler–Poisson)", m.A, m.state_names, m.state_names);
    fmt::print("\n");
  }
  fmt::print("eigenvalues seen from the body (1/s; the conserved quantities' zeros left out):\n");
  for (const auto& lambda : m.eigenvalues) {
    fmt::print("  {:>26}   {:.6g} rad/s\n", complex_text(lambda, 0), std::abs(lambda.imag()));
  }
  if (!m.space_frequencies.empty()) {
    fmt::print("seen from space (the body is symmetric about its spin axis):\n");
    for (std::size_t k = 0; k < m.space_frequencies.size(); ++k) {
      fmt::print("  {:.17g} rad/s ({:.6g} Hz), {} whirl\n", m.space_frequencies[k],
                 m.space_frequencies[k] / (2 * M_PI), m.whirl[k]);
    }
  }
  fmt::print("\n{}\n", m.verdict);
}

json steady_motion_json(const SpinningBodyView& s) {
  const analysis::SteadyMotionModes& m = *s.modes;
  json j;
  j["model"] = s.file.name;
  j["about"] = "steady";
  j["body"] = s.body.body;
  j["joint"] = s.body.joint;
  j["residual"] = m.residual;
  j["w_B"] = {s.body.w_B.x(), s.body.w_B.y(), s.body.w_B.z()};
  if (s.body.fixed_point) j["up_B"] = {s.body.up_B.x(), s.body.up_B.y(), s.body.up_B.z()};
  j["state_names"] = m.state_names;
  json A = json::array();
  for (Eigen::Index i = 0; i < m.A.rows(); ++i) {
    json row = json::array();
    for (Eigen::Index k = 0; k < m.A.cols(); ++k) row.push_back(m.A(i, k));
    A.push_back(std::move(row));
  }
  j["A"] = std::move(A);
  json eig = json::array();
  for (const auto& lambda : m.eigenvalues) eig.push_back(complex_json(lambda));
  j["eigenvalues_body"] = std::move(eig);
  json space = json::array();
  for (std::size_t k = 0; k < m.space_frequencies.size(); ++k) {
    space.push_back({{"frequency_rad_s", m.space_frequencies[k]}, {"whirl", m.whirl[k]}});
  }
  j["space_frequencies"] = std::move(space);
  j["stable"] = m.stable;
  j["growth_rate"] = m.growth_rate;
  j["verdict"] = m.verdict;
  return j;
}

}  // namespace

void print_whirls(const analysis::JointSteadyMotion& steady) {
  const Vec3& n = steady.spin_axis_W;
  fmt::print(
      "\nwhirl of each oscillation about the spin axis [{:.6g}, {:.6g}, {:.6g}] (world), in "
      "the joints' frames:\n",
      n.x(), n.y(), n.z());
  for (const analysis::SteadyMode& mode : steady.modes) {
    fmt::print("  {:.17g} rad/s ({:.6g} Hz), {}\n", mode.frequency, mode.frequency / (2 * M_PI),
               mode.whirl == "none" ? std::string("no whirl") : mode.whirl + " whirl");
  }
  fmt::print("{}\n", steady.stable ? "stable: no eigenvalue with a positive real part"
                                   : fmt::format("unstable: perturbations grow like e^({:.6g} t)",
                                                 steady.growth_rate));
}

json precession_roots_json(const analysis::SteadyPrecession& p) {
  return {{"tilt", p.tilt},
          {"spin", p.spin},
          {"I1", p.I1},
          {"I3", p.I3},
          {"mgl", p.mgl},
          {"slow", finite_or_null(p.slow)},
          {"fast", finite_or_null(p.fast)},
          {"minimum_spin", p.minimum_spin},
          {"gyroscopic", finite_or_null(p.gyroscopic)},
          {"gyroscopic_error", finite_or_null(p.gyroscopic_error)},
          {"slow_nutation", finite_or_null(p.slow_nutation)},
          {"fast_nutation", finite_or_null(p.fast_nutation)}};
}

json whirls_json(const analysis::JointSteadyMotion& steady) {
  json j;
  j["turning"] = steady.turning_names;
  j["speed"] = steady.speed;
  j["spin_axis_W"] = {steady.spin_axis_W.x(), steady.spin_axis_W.y(), steady.spin_axis_W.z()};
  j["residual"] = steady.residual;
  j["cyclic_residual"] = steady.cyclic_residual;
  json modes = json::array();
  for (const analysis::SteadyMode& mode : steady.modes) {
    modes.push_back({{"frequency_rad_s", mode.frequency}, {"whirl", mode.whirl}});
  }
  j["whirls"] = std::move(modes);
  j["stable"] = steady.stable;
  j["growth_rate"] = steady.growth_rate;
  return j;
}

namespace {

void print_spinning_body(const LoadedLinearModel& loaded, bool as_json, bool with_matrix) {
  const analysis::LinearAnalysis& r = loaded.result;
  const SpinningBodyView steady{loaded.file, *r.spinning_body, r.spinning_modes, r.precession};
  if (steady.precession) {
    if (as_json) {
      fmt::print("{}\n", json_text(precession_json(steady)));
    } else {
      print_precession_text(steady);
    }
    return;
  }
  if (as_json) {
    fmt::print("{}\n", json_text(steady_motion_json(steady)));
  } else {
    print_steady_motion_text(steady, with_matrix);
  }
}

}  // namespace

bool print_motion_without_channels(const LoadedLinearModel& loaded, bool as_json,
                                   bool with_matrix) {
  switch (loaded.result.kind) {
    case analysis::LinearAnalysisKind::spinning_body:
    case analysis::LinearAnalysisKind::steady_precession:
      print_spinning_body(loaded, as_json, with_matrix);
      return true;
    case analysis::LinearAnalysisKind::rolling_steady:
      print_rolling_steady_modes(loaded.file, *loaded.result.rolling_steady, as_json, with_matrix);
      return true;
    case analysis::LinearAnalysisKind::joint_coordinates:
    case analysis::LinearAnalysisKind::joint_steady:
      return false;
  }
  return false;
}

json complex_json(std::complex<double> z) { return json::array({z.real() + 0.0, z.imag() + 0.0}); }

std::string reachability_text(const analysis::Reachability& r, const char* who, const char* verb) {
  if (r.complete()) {
    return fmt::format("the {} {} every state (rank {} of {})", who, verb, r.rank, r.states);
  }
  std::vector<std::string> hidden;
  for (const std::complex<double>& p : r.hidden_poles) hidden.push_back(complex_text(p));
  return fmt::format("rank {} of {}: the {} do not {} the mode{} at {}", r.rank, r.states, who,
                     verb, hidden.size() == 1 ? "" : "s", fmt::join(hidden, ", "));
}

void print_matrix(const char* name, const MatX& M, const std::vector<std::string>& rows,
                  const std::vector<std::string>& columns) {
  fmt::print("{} ({}×{}):\n", name, M.rows(), M.cols());
  if (M.rows() == 0 || M.cols() == 0) return;
  std::size_t width = 0;
  for (const std::string& r : rows) width = std::max(width, r.size());
  // Each column as wide as its whole name (road.position and road.position_rate stay apart).
  std::vector<std::size_t> widths;
  for (const std::string& c : columns) widths.push_back(std::max<std::size_t>(13, c.size()));
  fmt::print("  {:<{}}", "", width);
  for (std::size_t k = 0; k < columns.size(); ++k) fmt::print(" {:>{}}", columns[k], widths[k]);
  fmt::print("\n");
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    fmt::print("  {:<{}}", rows[static_cast<std::size_t>(i)], width);
    for (Eigen::Index k = 0; k < M.cols(); ++k) {
      fmt::print(" {:>{}.6g}", M(i, k) + 0.0, widths[static_cast<std::size_t>(k)]);
    }
    fmt::print("\n");
  }
}

}  // namespace momenta::cli
