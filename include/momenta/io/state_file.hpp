#pragma once
// A state file, STATE.json {"q": [...], "v": [...], "t": 0}: a model's state written by `momenta
// steady --state` and read by `--about STATE.json` and `--state STATE.json` (docs/cli.md).

#include <filesystem>
#include <string>

#include "momenta/math/types.hpp"

namespace momenta::io {

/// A state of a model: time (s; 0 where the file gives none), coordinates and velocities.
struct StateFile {
  double t = 0.0;
  VecX q;  ///< size nq
  VecX v;  ///< size nv
};

/// Parses the text of a state file (named `name` in messages) for a model of `nq` coordinates and
/// `nv` velocities. Throws ParseError `name:line:column: why` for text that is not a JSON value —
/// empty, binary, NaN or Infinity, a number past double precision, text after the value — and
/// InvalidArgument naming the key for an unknown key, q or v missing, of the wrong size or not
/// numbers, t not a number, or a number beyond ±kLargestNumber (yaml_reader.hpp), the bound of
/// every number in an input file.
StateFile parse_state_file(const std::string& text, const std::string& name, int nq, int nv);

/// Reads the state file at `path` (FileError when it is missing, a folder or unreadable), then
/// parses it as parse_state_file does.
StateFile read_state_file(const std::filesystem::path& path, int nq, int nv);

}  // namespace momenta::io
