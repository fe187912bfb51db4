// `momenta export MODEL --mjcf FILE | --urdf FILE [--force]`: a model written out for MuJoCo or
// ROS, drawn in its consistent initial state (MJCF) or where every q = 0 (URDF). Calls
// io::write_mjcf / io::write_urdf; documented in docs/cli.md and docs/model-formats.md.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "commands.hpp"
#include "model_argument.hpp"
#include "momenta/common/error.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "momenta/io/model_export.hpp"
#include "momenta/report/report.hpp"
#include "momenta/simulate/state_at.hpp"
#include "option_checks.hpp"

namespace momenta::cli {
namespace {

struct ExportOptions {
  ModelArgument model;
  std::optional<std::string> mjcf, urdf;
  bool force = false;
};

void run(const ExportOptions& o) {
  const std::string& output = o.mjcf ? *o.mjcf : *o.urdf;
  // Refused before any work: the user's file is never overwritten without --force.
  if (std::filesystem::exists(output) && !o.force) {
    throw FileError(
        fmt::format("{}: the output file exists; pass --force to overwrite it", output));
  }
  const io::ModelFile file = load_model(o.model);
  const io::ExportedModel written =
      o.mjcf ? io::write_mjcf(file, simulate::state_at(file.model, 0.0, {}).q)
             : io::write_urdf(file);
  report::write_report(output, written.text, o.force);
  fmt::print("wrote {} ({}: {} bodies, {} degrees of freedom)\n", output, o.mjcf ? "MJCF" : "URDF",
             file.model.num_bodies() - 1, file.model.nv());
  for (const std::string& lost : written.not_written) {
    fmt::print(stderr, "not written: {}\n", lost);
  }
}

}  // namespace

void add_export_command(CLI::App& app) {
  auto options = std::make_shared<ExportOptions>();
  CLI::App* command = app.add_subcommand(
      "export",
      "Write a model as MJCF (MuJoCo) or URDF (ROS, Pinocchio): its bodies' masses, inertias and "
      "frames exactly, its joints, damping, springs (MJCF), loops (MJCF), couplers and the "
      "ground's "
      "contacts with spheres, cylinders and boxes (MJCF)");
  add_model_argument(command, options->model);
  auto* mjcf = command->add_option("--mjcf", options->mjcf, "Write MJCF to this file")
                   ->check(not_a_folder());
  auto* urdf = command->add_option("--urdf", options->urdf, "Write URDF to this file")
                   ->check(not_a_folder());
  mjcf->excludes(urdf);
  command->add_flag("--force", options->force, "Overwrite the output file if it exists");
  command->footer(
      "Examples:\n"
      "  momenta export examples/constraints/four_bar.yaml --mjcf four_bar.xml\n"
      "  momenta export examples/double_pendulum.yaml --urdf double_pendulum.urdf\n"
      "What each format keeps: docs/model-formats.md.");
  command->callback([options] {
    if (!options->mjcf && !options->urdf) {
      throw CLI::RequiredError("export needs --mjcf FILE or --urdf FILE");
    }
    run(*options);
  });
}

}  // namespace momenta::cli
