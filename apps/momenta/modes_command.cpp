// `momenta modes MODEL`: eigenvalues, natural frequencies, damping ratios and mode shapes of a
// model file linearized about an operating point, and its undamped normal modes where the
// stiffness is symmetric. Calls momenta::analysis; documented in docs/cli.md.

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "commands.hpp"
#include "linear_model_options.hpp"
#include "momenta/analysis/modes.hpp"
#include "momenta/analysis/modes_text.hpp"
#include "momenta/common/error.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "option_spelling.hpp"

namespace momenta::cli {
namespace {

using json = nlohmann::ordered_json;

struct ModesOptions {
  LinearModelOptions model;
  bool json = false;
};

double hz(double omega) { return omega / (2 * std::numbers::pi); }

void run(const ModesOptions& o) {
  const LoadedLinearModel loaded = load_linear_model(o.model);
  if (print_motion_without_channels(loaded, o.json, false)) return;
  const analysis::LinearModel& lin = loaded.result.linear;
  const analysis::Modes m = analysis::modes(lin.system);
  // Undamped normal modes exist where K is symmetric (a conservative model at an equilibrium).
  std::optional<analysis::NormalModes> normal;
  std::string why_not;
  if (loaded.result.joint_steady) {
    why_not = "a steady motion: its gyroscopic terms couple the coordinates";
  } else {
    try {
      normal = analysis::undamped_modes(lin);
    } catch (const InvalidArgument& e) {
      why_not = e.spelled(command_line_spelling);
    }
  }
  if (o.json) {
    json j;
    j["model"] = loaded.file.name;
    j["about"] = loaded.result.about;
    j["state_names"] = m.state_names;
    json modes = json::array();
    for (const analysis::Mode& mode : m.modes) {
      json shape = json::array();
      for (Eigen::Index i = 0; i < mode.shape.size(); ++i)
        shape.push_back(complex_json(mode.shape[i]));
      modes.push_back({{"eigenvalue", complex_json(mode.eigenvalue)},
                       {"z", lin.system.is_discrete() ? complex_json(mode.z) : json(nullptr)},
                       {"natural_frequency_rad_s", finite_or_null(mode.natural_frequency)},
                       {"natural_frequency_hz", finite_or_null(hz(mode.natural_frequency))},
                       {"damping_ratio", finite_or_null(mode.damping_ratio)},
                       {"damped_frequency_rad_s", finite_or_null(mode.damped_frequency)},
                       {"shape", std::move(shape)}});
    }
    j["modes"] = std::move(modes);
    if (loaded.result.joint_steady) j["steady_motion"] = whirls_json(*loaded.result.joint_steady);
    if (normal) {
      j["coordinate_names"] = normal->coordinate_names;
      json nm = json::array();
      for (const analysis::NormalMode& mode : normal->modes) {
        nm.push_back({{"squared_frequency", finite_or_null(mode.squared_frequency)},
                      {"natural_frequency_rad_s", finite_or_null(mode.natural_frequency)},
                      {"natural_frequency_hz", finite_or_null(hz(mode.natural_frequency))},
                      {"shape", json(std::vector<double>(mode.shape.data(),
                                                         mode.shape.data() + mode.shape.size()))}});
      }
      j["normal_modes"] = std::move(nm);
    } else {
      j["normal_modes"] = nullptr;
    }
    fmt::print("{}\n", json_text(j));
    return;
  }
  fmt::print("{}: modes about {} ({} states)\n", loaded.file.name, loaded.result.about,
             m.state_names.size());
  // Modes of a state that is not at rest describe the motion linearized at that instant only.
  // A state that moves is no equilibrium either, even without acceleration (a sleeping top).
  const double worst = analysis::largest_acceleration(lin);
  const double fastest = analysis::largest_speed(lin);
  if (!loaded.result.joint_steady &&
      (worst > analysis::kAtRestAcceleration || fastest > analysis::kAtRestSpeed)) {
    fmt::print(
        "note: this state is not an equilibrium (largest acceleration {:.4g}, largest speed "
        "{:.4g}): the modes describe the motion linearized at this instant; --about equilibrium "
        "finds a state at rest, and --about steady analyses a spinning body's steady motion\n",
        worst, fastest);
  }
  if (lin.system.is_discrete()) {
    fmt::print(
        "sampled every {:g} s (the controllers'): each eigenvalue z of A is shown as the s it "
        "samples, s = ln(z)/T\n",
        lin.system.sample_time());
  }
  fmt::print("\n");
  fmt::print("{}", analysis::modes_table(m));
  if (normal) {
    fmt::print("\nundamped normal modes (K φ = ω² M φ):\n{}",
               analysis::normal_modes_table(*normal));
  } else if (loaded.result.joint_steady) {
    print_whirls(*loaded.result.joint_steady);
  } else {
    fmt::print("\nno undamped normal modes: {}\n", why_not);
  }
}

}  // namespace

void add_modes_command(CLI::App& app) {
  auto options = std::make_shared<ModesOptions>();
  CLI::App* command = app.add_subcommand(
      "modes",
      "Eigenvalues, natural frequencies (rad/s and Hz), damping ratios and mode shapes "
      "of a model file linearized about an operating point");
  add_linear_model_options(command, options->model, false);
  command->add_flag("--json", options->json, "Print JSON instead of text");
  command->footer(
      "Examples:\n"
      "  momenta modes examples/double_pendulum.yaml --about equilibrium\n"
      "  momenta modes examples/quarter_car.yaml --json\n"
      "ζ is −Re λ/|λ| (1 for a stable real pole, −1 unstable, blank at λ = 0).");
  command->callback([options] { run(*options); });
}

}  // namespace momenta::cli
