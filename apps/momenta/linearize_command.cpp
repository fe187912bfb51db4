// `momenta linearize MODEL`: the continuous-time state space (A, B, C, D) of a model file about
// an operating point, as text or JSON. Parses the options and calls momenta::analysis::linearize.
// Documented in docs/cli.md.

#include <memory>

#include <fmt/format.h>

#include "commands.hpp"
#include "linear_model_options.hpp"
#include "momenta/analysis/controllability.hpp"
#include "momenta/analysis/modes.hpp"
#include "momenta/frontend/model_loading.hpp"

namespace momenta::cli {
namespace {

using json = nlohmann::ordered_json;

struct LinearizeOptions {
  LinearModelOptions model;
  bool json = false;
};

void run(const LinearizeOptions& o) {
  const LoadedLinearModel loaded = load_linear_model(o.model);
  if (print_motion_without_channels(loaded, o.json, true)) return;
  const analysis::LinearModel& lin = loaded.result.linear;
  const analysis::StateSpace& sys = lin.system;
  const analysis::Modes m = analysis::modes(sys);
  const analysis::Reachability reach = analysis::controllability(sys);
  const analysis::Reachability seen = analysis::observability(sys);
  if (o.json) {
    json j;
    j["model"] = loaded.file.name;
    j["about"] = loaded.result.about;
    j["t"] = lin.point.t;
    j["q"] = json(std::vector<double>(lin.point.q.data(), lin.point.q.data() + lin.point.q.size()));
    j["v"] = json(std::vector<double>(lin.point.v.data(), lin.point.v.data() + lin.point.v.size()));
    j["state_names"] = sys.state_names();
    j["input_names"] = sys.input_names();
    j["output_names"] = sys.output_names();
    j["A"] = matrix_json(sys.A());
    j["B"] = matrix_json(sys.B());
    j["C"] = matrix_json(sys.C());
    j["D"] = matrix_json(sys.D());
    // A's eigenvalues: s, or z of a sampled loop (with their s = ln z / T beside).
    json eig = json::array(), equivalent = json::array();
    for (const analysis::Mode& mode : m.modes) {
      eig.push_back(complex_json(mode.z));
      equivalent.push_back(complex_json(mode.eigenvalue));
    }
    j["sample_time"] = sys.sample_time();
    j["eigenvalues"] = std::move(eig);
    if (sys.is_discrete()) j["s_equivalent"] = std::move(equivalent);
    j["controllable_rank"] = reach.rank;
    j["observable_rank"] = seen.rank;
    j["states_shifted"] = lin.states_shifted;
    j["output_values"] = json(std::vector<double>(
        lin.output_values.data(), lin.output_values.data() + lin.output_values.size()));
    if (loaded.result.joint_steady) j["steady_motion"] = whirls_json(*loaded.result.joint_steady);
    fmt::print("{}\n", json_text(j));
    return;
  }
  fmt::print("{}: linearized about {} (t = {:g} s)\n", loaded.file.name, loaded.result.about,
             lin.point.t);
  fmt::print("states  ({}): {}\n", sys.state_count(), fmt::join(sys.state_names(), ", "));
  fmt::print("inputs  ({}): {}\n", sys.input_count(), fmt::join(sys.input_names(), ", "));
  fmt::print("outputs ({}): {}\n", sys.output_count(), fmt::join(sys.output_names(), ", "));
  if (sys.is_discrete()) {
    fmt::print(
        "sampled every {:g} s (the controllers' sample time; the plant held between): "
        "x[k+1] = A x[k] + B u[k]\n",
        sys.sample_time());
  }
  fmt::print("\n");
  print_matrix("A", sys.A(), sys.state_names(), sys.state_names());
  print_matrix("B", sys.B(), sys.state_names(), sys.input_names());
  print_matrix("C", sys.C(), sys.output_names(), sys.state_names());
  print_matrix("D", sys.D(), sys.output_names(), sys.input_names());
  std::vector<std::string> eig, equivalent;
  for (const analysis::Mode& mode : m.modes) {
    eig.push_back(complex_text(mode.z));
    equivalent.push_back(complex_text(mode.eigenvalue));
  }
  if (sys.is_discrete()) {
    fmt::print("eigenvalues z: {}\n", fmt::join(eig, ", "));
    fmt::print("  as s = ln(z)/T (1/s): {}\n", fmt::join(equivalent, ", "));
  } else {
    fmt::print("eigenvalues (1/s): {}\n", fmt::join(eig, ", "));
  }
  if (sys.input_count() > 0) {
    fmt::print("controllability: {}\n", reachability_text(reach, "inputs", "move"));
  }
  if (sys.output_count() > 0) {
    fmt::print("observability: {}\n", reachability_text(seen, "outputs", "show"));
  }
  if (lin.states_shifted) {
    fmt::print(
        "note: a prescribed input's rate or acceleration enters; the states are shifted by "
        "it (docs/analysis.md)\n");
  }
}

}  // namespace

void add_linearize_command(CLI::App& app) {
  auto options = std::make_shared<LinearizeOptions>();
  CLI::App* command =
      app.add_subcommand("linearize",
                         "Continuous-time state space ẋ = A x + B u, y = C x + D u of a model file "
                         "about an operating point");
  add_linear_model_options(command, options->model, true);
  command->add_flag("--json", options->json, "Print JSON instead of text");
  command->footer(
      "Examples:\n"
      "  momenta linearize examples/quarter_car.yaml --inputs road --outputs body_y\n"
      "  momenta linearize examples/pendulum.yaml --about equilibrium --json\n"
      "States are the free joints' tangent coordinates, then their velocities; SI units.");
  command->callback([options] { run(*options); });
}

}  // namespace momenta::cli
