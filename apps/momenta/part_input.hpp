#pragma once
// A rigid part named on the command line: a composite part file (.yaml) or a closed triangle
// mesh (.stl, .obj) with its density or mass, scale and shell options. Shared by `inertia` and
// `balance`, which read parts the same way.

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "momenta/inertia/mass_properties.hpp"
#include "momenta/io/part_file.hpp"

namespace momenta::cli {

struct PartInput {
  std::string file;
  std::optional<double> density;
  std::optional<double> mass;
  std::optional<double> scale;
  bool shell = false;
};

/// What was read: the composite (or the mesh as one part) and how.
struct ReadPart {
  std::string name;
  inertia::MassProperties total;
  std::vector<io::PartSummary> parts;  ///< a part file's parts; a mesh's one, when drawn
  std::optional<double> density;       ///< a mesh file's density (kg/m³, or kg/m² for a shell)
  bool per_unit_density = false;       ///< a mesh given neither density nor mass
  bool shell = false;
  bool is_mesh = false;
};

/// Adds FILE, --density, --mass, --scale and --shell to `command`.
void add_part_input_options(CLI::App* command, PartInput& input, const std::string& file_help);

/// Reads the part. `keep_mesh` keeps a mesh file's triangles as its one part (for a drawing).
/// Usage errors (a mesh option on a part file, --density with --mass) are CLI::ValidationError;
/// an unsupported extension InvalidArgument; the readers' errors pass through.
ReadPart read_part(const PartInput& input, bool keep_mesh);

/// The note for a mesh read per unit density (stderr), or nothing.
void note_per_unit_density(const ReadPart& part);

}  // namespace momenta::cli
