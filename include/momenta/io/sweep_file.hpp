#pragma once
// Sweep files: a model (or part) file, the numbers of it that vary, the job and the metrics —
// YAML, documented in docs/sweeps.md. Read with the same file:line:column messages as model
// files; what needs the model itself (parameter paths, values the model refuses, metric columns)
// is checked by sweep::SweepRunner, also at this file's lines.

#include <filesystem>
#include <string>

#include "momenta/sweep/sweep_spec.hpp"

namespace momenta::io {

/// Reads and checks a sweep file. The model, part and trajectories paths in it are relative to
/// its folder. Throws FileError when it cannot be read, ParseError `file:line:column: key:
/// message` for anything wrong in it: an unknown key (with a did-you-mean), a parameter with no
/// values or two kinds of values, a range with count < 2 or a log range through 0, a
/// distribution with σ ≤ 0 or bounds the wrong way round, an unknown metric, a design that does
/// not fit its parameters.
sweep::SweepSpec read_sweep_file(const std::filesystem::path& path);

/// The same from the file's text, named `file_name` in messages, its paths relative to
/// `base_dir` (the fuzzing harness's entry).
sweep::SweepSpec parse_sweep_file(const std::string& text, const std::string& file_name,
                                  const std::filesystem::path& base_dir);

}  // namespace momenta::io
