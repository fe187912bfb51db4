#include "part_input.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/inertia/amount.hpp"
#include "momenta/io/mesh_file.hpp"
#include "option_checks.hpp"

namespace momenta::cli {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string e = path.extension().string();
  std::transform(e.begin(), e.end(), e.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

ReadPart read_part_file(const PartInput& o) {
  // Options that only make sense for a single mesh are usage errors here.
  if (o.mass)
    throw CLI::ValidationError("--mass",
                               "applies to mesh files; a part file gives masses per part");
  if (o.scale)
    throw CLI::ValidationError(
        "--scale", "applies to mesh files; use 'units:' or a mesh part's 'scale:' in a part file");
  if (o.shell)
    throw CLI::ValidationError(
        "--shell", "applies to mesh files; use a mesh part's 'shell: true' in a part file");
  io::CompositePart part = io::read_part_file(o.file, {.default_density = o.density});
  ReadPart r;
  r.name = part.name;
  r.total = part.total;
  r.parts = std::move(part.parts);
  return r;
}

ReadPart read_mesh(const PartInput& o, bool keep_mesh) {
  if (o.density && o.mass) {
    throw CLI::ValidationError("--density", "give --density or --mass, not both");
  }
  const std::filesystem::path path = o.file;
  // Without a density or mass the result is per unit density: volume and centre of mass are
  // exact, mass and inertia scale with the density.
  ReadPart r;
  r.is_mesh = true;
  r.per_unit_density = !o.density && !o.mass;
  const inertia::Amount amount =
      o.mass ? inertia::Amount::mass(*o.mass) : inertia::Amount::density(o.density.value_or(1.0));
  if (!o.mass) r.density = o.density.value_or(1.0);
  r.shell = o.shell;
  r.name = path.stem().string();
  r.total = io::read_mesh_mass_properties(path, amount, o.scale.value_or(1.0), o.shell);
  if (keep_mesh) {
    io::PartSummary mesh;
    mesh.name = r.name;
    mesh.kind = "mesh";
    mesh.mass_properties = r.total;
    mesh.mesh =
        std::make_shared<inertia::TriangleMesh>(io::read_mesh_file(path, o.scale.value_or(1.0)));
    r.parts.push_back(std::move(mesh));
  }
  return r;
}

}  // namespace

void add_part_input_options(CLI::App* command, PartInput& input, const std::string& file_help) {
  command->add_option("FILE", input.file, file_help)->required();
  command
      ->add_option("--density", input.density,
                   "Density, kg/m³ (kg/m² with --shell). Mesh: its material (default: 1, per unit "
                   "density). Part file: replaces the file's default density of solids")
      ->check(positive_finite());
  command->add_option("--mass", input.mass, "Mesh only: its total mass, kg (instead of --density)")
      ->check(positive_finite());
  command
      ->add_option("--scale", input.scale,
                   "Mesh only: multiplies its coordinates into metres (0.001 for millimetres)")
      ->check(positive_finite());
  command->add_flag("--shell", input.shell,
                    "Mesh only: a thin shell of uniform surface density (sheet metal) over its "
                    "triangles, rather than the solid it bounds");
}

ReadPart read_part(const PartInput& input, bool keep_mesh) {
  const std::string extension = lower_extension(input.file);
  if (extension == ".yaml" || extension == ".yml") return read_part_file(input);
  if (extension == ".stl" || extension == ".obj") return read_mesh(input, keep_mesh);
  throw InvalidArgument(fmt::format(
      "{}: unsupported file extension '{}': expected .yaml or .yml (a part file), .stl or .obj "
      "(a mesh)",
      input.file, std::filesystem::path(input.file).extension().string()));
}

void note_per_unit_density(const ReadPart& part) {
  if (!part.per_unit_density) return;
  fmt::print(stderr,
             "momenta: note: no --density or --mass given: mass and inertia are per unit density "
             "(1 kg/m{}); volume and centre of mass do not depend on it\n",
             part.shell ? "²" : "³");
}

}  // namespace momenta::cli
