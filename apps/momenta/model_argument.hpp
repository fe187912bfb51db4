#pragma once
// The MODEL argument every model command takes, with the options a robot description needs:
// --package-path for a URDF's package:// meshes, --link-density for its links without <inertial>,
// --keyframe for an MJCF key's state as the model's initial state.

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "momenta/io/model_file.hpp"

namespace momenta::cli {

struct ModelArgument {
  std::string file;
  std::vector<std::string> package_path;
  std::optional<double> link_density;   // kg/m³
  std::optional<std::string> keyframe;  // an MJCF key's state as the initial state
};

/// What MODEL is, for a command's help when it says no more.
inline constexpr const char* kModelFileHelp =
    "A model file: momenta's YAML (docs/model-format.md), URDF (.urdf) or MJCF (.xml, .mjcf; "
    "docs/model-formats.md)";

/// Adds MODEL (required, described by `help`), --package-path, --link-density and --keyframe to
/// `command`.
void add_model_argument(CLI::App* command, ModelArgument& model,
                        const std::string& help = kModelFileHelp);

/// Reads and accepts the model (frontend::load_model) with the options given.
io::ModelFile load_model(const ModelArgument& model);

}  // namespace momenta::cli
