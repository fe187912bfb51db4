#pragma once
// Opening a model file the way every front end does (the momenta command line, the Python
// module): the file read and built (io), then accepted by the system layer (the mass matrix
// invertible at the initial state); an error about one of its bodies, joints, elements or
// signals is reported at the line that declares it.

#include <filesystem>

#include "momenta/io/model_file.hpp"

namespace momenta::frontend {

/// Checks that a model file's model can be simulated (the system layer accepts it: the mass
/// matrix invertible at the initial state) and that every event of its `simulation:` section
/// watches a quantity the run has; an error about one of its items or events is rethrown as
/// ParseError at the line that declares it, others as they are. A model made in code is wrapped
/// in a ModelFile with no item locations.
void accept_model(const io::ModelFile& file);

/// Reads `path` (io::read_model_file, with `options` for a URDF's meshes and massless links) and
/// checks that it can be simulated (accept_model). Throws ParseError `file:line:column: message`
/// for anything wrong with it, FileError when it cannot be read.
io::ModelFile load_model(const std::filesystem::path& path,
                         const io::ModelFileOptions& options = {});

}  // namespace momenta::frontend
