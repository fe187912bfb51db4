#pragma once
// Reading a model file for a command: the file read and built (io), then accepted by the system
// layer (the mass matrix invertible at the initial state); an error about one of its bodies,
// joints, elements or signals is reported at the line that declares it.

#include <string>

#include "momenta/io/model_file.hpp"

namespace momenta::cli {

/// Reads `path` and checks that it can be simulated. Throws ParseError
/// `file:line:column: message` for anything wrong with it, FileError when it cannot be read.
io::ModelFile load_model(const std::string& path);

}  // namespace momenta::cli
