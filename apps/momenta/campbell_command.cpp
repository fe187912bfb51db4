// `momenta campbell MODEL --speed-range A B`: the Campbell diagram of a model's spinning body —
// its whirl frequencies seen from space against the spin speed, forward and backward, and the
// critical speeds where a forward whirl crosses the 1× line. Calls momenta::analysis
// (steady_motion.hpp); documented in docs/cli.md and docs/analysis.md.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "linear_model_options.hpp"
#include "model_argument.hpp"
#include "momenta/analysis/joint_steady_motion.hpp"
#include "momenta/analysis/steady_motion.hpp"
#include "momenta/common/error.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "option_checks.hpp"
#include "output_format.hpp"

namespace momenta::cli {
namespace {

using json = nlohmann::ordered_json;

struct CampbellOptions {
  ModelArgument model;
  std::vector<double> speed_range;  // rev/min
  int points = 41;
  bool json = false;
  std::optional<std::string> csv;
  bool force = false;
};

std::string csv_text(const analysis::CampbellDiagram& d) {
  const std::vector<std::string> names = analysis::whirl_column_names(d.points.front());
  std::string text = "speed_rpm,speed_rad_s";
  for (const std::string& n : names) text += fmt::format(",{}_rad_s", n);
  text += "\n";
  for (const analysis::CampbellPoint& p : d.points) {
    text += fmt::format("{:.17g},{:.17g}", p.speed / kRpm, p.speed);
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (k < p.frequencies.size() && p.stable) {
        text += fmt::format(",{:.17g}", p.frequencies[k]);
      } else {
        text += ",";  // unstable there: no whirl frequency
      }
    }
    text += "\n";
  }
  return text;
}

void run(const CampbellOptions& o) {
  if (!(o.speed_range[0] > 0.0) || !(o.speed_range[1] > o.speed_range[0])) {
    throw CLI::ValidationError("--speed-range", "expects 0 < A < B (rev/min)");
  }
  check_csv_target(o.csv, o.force);
  const io::ModelFile file = load_model(o.model);
  const analysis::RotorCampbell rotor = analysis::model_campbell_diagram(
      file.model, o.speed_range[0] * kRpm, o.speed_range[1] * kRpm, o.points);
  const analysis::CampbellDiagram& d = rotor.diagram;
  if (o.json) {
    json j;
    j["model"] = file.name;
    j[rotor.joint_coordinates ? "turning" : "body"] = rotor.rotor;
    json points = json::array();
    for (const analysis::CampbellPoint& p : d.points) {
      points.push_back({{"speed_rad_s", p.speed},
                        {"speed_rpm", p.speed / kRpm},
                        {"stable", p.stable},
                        {"frequencies_rad_s", p.frequencies},
                        {"whirl", p.whirl}});
    }
    j["points"] = std::move(points);
    json critical = json::array();
    for (const analysis::CriticalSpeed& c : d.critical_speeds) {
      critical.push_back(
          {{"speed_rad_s", c.speed}, {"speed_rpm", c.speed / kRpm}, {"whirl", c.whirl}});
    }
    j["critical_speeds"] = std::move(critical);
    fmt::print("{}\n", json_text(j, ListSpacing::spaced));
    return;
  }
  const std::string csv = csv_text(d);
  if (emit_csv(o.csv, csv)) return;
  if (rotor.joint_coordinates) {
    fmt::print(
        "{}: Campbell diagram of the rotor turning on {} ({} speeds), whirl frequencies in the "
        "joints' frames\n\n",
        file.name, rotor.rotor, d.points.size());
  } else {
    fmt::print(
        "{}: Campbell diagram of body '{}' ({} speeds), whirl frequencies seen from space\n\n",
        file.name, rotor.rotor, d.points.size());
  }
  const std::vector<std::string> names = analysis::whirl_column_names(d.points.front());
  fmt::print("  {:>10} {:>12}", "rev/min", "Ω rad/s");
  for (const std::string& n : names) fmt::print(" {:>14}", n);
  fmt::print("\n");
  for (const analysis::CampbellPoint& p : d.points) {
    fmt::print("  {:>10.6g} {:>12.6g}", p.speed / kRpm, p.speed);
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (p.stable && k < p.frequencies.size()) {
        fmt::print(" {:>14.6g}", p.frequencies[k]);
      } else {
        fmt::print(" {:>14}", "unstable");
      }
    }
    fmt::print("\n");
  }
  if (d.critical_speeds.empty()) {
    fmt::print("\nno critical speed in this range: no forward whirl crosses the 1× line\n");
  }
  for (const analysis::CriticalSpeed& c : d.critical_speeds) {
    fmt::print("\ncritical speed {:.10g} rad/s = {:.10g} rev/min ({} whirl at 1×)\n", c.speed,
               c.speed / kRpm, c.whirl);
  }
  if (o.csv) fmt::print("table written to {}\n", *o.csv);
}

}  // namespace

void add_campbell_command(CLI::App& app) {
  auto options = std::make_shared<CampbellOptions>();
  CLI::App* command = app.add_subcommand(
      "campbell",
      "Campbell diagram of a rotor: its whirl frequencies (forward and backward) against the "
      "spin speed, and the critical speeds");
  add_model_argument(command, options->model,
                     "A model file: one body on a spherical or free joint, spinning about its "
                     "axis of symmetry, or a rotor turning on its joint (a steady motion in joint "
                     "coordinates)");
  command->add_option("--speed-range", options->speed_range, "From A to B rev/min")
      ->expected(2)
      ->required()
      ->check(finite());
  command->add_option("--points", options->points, "Speeds in the table (default 41)")
      ->check(CLI::Range(2, 100000));
  auto* csv = command
                  ->add_option("--csv", options->csv,
                               "Write the table as CSV to FILE ('-': to stdout); an existing file "
                               "is never overwritten without --force")
                  ->check(not_a_folder());
  command->add_flag("--json", options->json, "Print JSON instead of text")->excludes(csv);
  command->add_flag("--force", options->force, "Overwrite the --csv file if it exists");
  command->footer(
      "Example:\n"
      "  momenta campbell examples/sleeping_top.yaml --speed-range 2000 6000\n"
      "  momenta campbell examples/rotor_on_bearings.yaml --speed-range 500 4000\n"
      "The initial state sets the spin (a steady motion: along the vertical for a top; the "
      "turning joint's v0 for a rotor in joint coordinates); it is scaled to each speed "
      "(docs/analysis.md).");
  command->callback([options] { run(*options); });
}

}  // namespace momenta::cli
