#pragma once
// Model files: a multibody system described in YAML — bodies, joints, force elements, input
// signals, outputs and simulation settings (format: docs/model-format.md).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "momenta/model/model.hpp"
#include "momenta/simulate/output.hpp"

namespace momenta::io {

/// The file's `simulation:` section: defaults that `momenta simulate` options override.
struct SimulationSettings {
  std::optional<double> duration;         ///< s, > 0
  std::optional<double> step;             ///< fixed step, or an adaptive method's largest, s
  std::optional<std::string> integrator;  ///< a name integrate::make_integrator knows
  std::optional<double> relative_tolerance;
  std::optional<double> absolute_tolerance;
  std::optional<long> every;  ///< record every n-th step
};

/// What a model file describes.
struct ModelFile {
  std::string name;                           ///< The file's `name:`, or the file's stem.
  std::string description;                    ///< The file's `description:`, or empty.
  model::Model model;                         ///< Built and validated.
  std::vector<simulate::OutputSpec> outputs;  ///< The `outputs:` section, in file order.
  SimulationSettings simulation;
};

/// Reads, checks and builds a model file. Paths inside it (part files, meshes, CSV tables) are
/// relative to its folder.
///
/// Throws FileError when the file, or a file it names, is missing or unreadable. Throws
/// ParseError, one line `file:line:column: key path: message`, for every problem with its
/// content: malformed YAML; an unknown key (with a did-you-mean suggestion); a missing or doubled
/// key; a number that is not finite or out of range (a negative mass, a zero length); a name that
/// is unknown (with a did-you-mean) or repeated; a joint tree with a cycle, a body without a
/// joint or a massless leaf carrying degrees of freedom (singular mass matrix); a non-unit axis
/// or quaternion; a signal table whose times do not increase; an output that does not fit its
/// target. Problems found only when the model is assembled are reported at the line of the
/// body, joint or element they name.
ModelFile read_model_file(const std::filesystem::path& path);

/// As read_model_file, from YAML text; `file_name` labels messages and `base_dir` resolves
/// relative paths.
ModelFile parse_model_file(const std::string& text, const std::string& file_name,
                           const std::filesystem::path& base_dir);

}  // namespace momenta::io
