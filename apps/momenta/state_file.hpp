#pragma once
// A state file, STATE.json {"q": [...], "v": [...], "t": 0}: the operating point of `linearize
// --about FILE` (written by `steady --state`); and the instant `kinematics` and `diagram` look
// at, from a state file or a run to a time.

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "momenta/analysis/linearize.hpp"
#include "momenta/integrate/integrator.hpp"
#include "momenta/io/model_file.hpp"

namespace momenta::cli {

/// Reads a state file for `model`. Throws FileError when it cannot be opened, InvalidArgument
/// naming the file and the key for anything else (not JSON, an unknown key, q or v of the wrong
/// size or not numbers, t not a number).
analysis::OperatingPoint read_state_file(const std::string& path, const model::Model& model);

/// --time T or --state FILE: which instant of a model's motion a command looks at.
struct InstantOptions {
  std::optional<double> time;  ///< s
  std::optional<std::string> state;
};

/// Adds --time and --state (mutually exclusive) to a command.
void add_instant_options(CLI::App* command, InstantOptions& options);

/// The state the options name: the state file's, or the model's initial state run to --time with
/// the file's `simulation:` settings (simulate::state_at); t = 0 without either.
integrate::State instant_of(const io::ModelFile& file, const InstantOptions& options);

}  // namespace momenta::cli
