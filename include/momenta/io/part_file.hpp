#pragma once
// Composite parts: mass properties of a part built from primitives, meshes, explicit inertias and
// holes, described in a YAML part file (format: docs/inertia-format.md).
//
// Every part is placed in the file's own frame B (origin Bo) by a pose; the result describes the
// composite in B: mass, centre of mass p_BoBcm_B and inertia I_BBcm_B about the centre of mass
// (off-diagonals are minus the products of inertia, docs/conventions.md).

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "momenta/inertia/amount.hpp"
#include "momenta/inertia/mass_properties.hpp"
#include "momenta/inertia/triangle_mesh.hpp"

namespace momenta::io {

/// One entry of a part file's `parts:` list, as read and placed in the file's frame B.
struct PartSummary {
  std::string name;   ///< Its `name:`, or "parts[i]" when it has none.
  std::string kind;   ///< The shape ("cylinder", "box", ...), "mesh" or "inertia".
  bool hole = false;  ///< Subtracted from the composite rather than added.
  int line = 0;       ///< 1-based line of the part in the file.
  /// The part alone, in B (its pose applied). A hole's mass here is positive: the mass removed.
  inertia::MassProperties mass_properties;

  // What the part looks like, for drawing it (the HTML report): its sizes in metres by their
  // keys ("radius", "length"; a 3-vector key such as "size" gives "size.x", "size.y", "size.z"),
  // its pose in B, and for a mesh its triangles in the part frame S, in metres.
  std::vector<std::pair<std::string, double>> sizes;
  Mat3 R_BS = Mat3::Identity();
  Vec3 p_BoSo_B = Vec3::Zero();
  std::shared_ptr<const inertia::TriangleMesh> mesh;
};

/// What read_part_file returns: the composite and the parts it was built from.
struct CompositePart {
  std::string name;                ///< The file's `name:`, or the file's stem.
  inertia::MassProperties total;   ///< The composite in B: solids added, holes removed.
  std::vector<PartSummary> parts;  ///< Every part, in file order.
};

/// Settings that override a part file's own.
struct PartFileOptions {
  /// Replaces the file's top-level default `density:` (kg/m³): the density of every solid part
  /// that gives neither `mass:` nor `density:` itself (the CLI's --density).
  std::optional<double> default_density;
};

/// Reads a part file and composes its parts: the solids are summed in file order, then each hole
/// is removed in file order, and the composite is checked to stay physical after every hole
/// (positive mass, positive semi-definite inertia obeying A + B >= C). Mesh paths are relative to
/// the file's folder.
///
/// Throws FileError if the file itself is missing or unreadable. Throws ParseError, one line
/// `file:line:column: key: message`, for every problem with its content: malformed YAML, an
/// unknown key (with a did-you-mean suggestion), a missing or doubled key, a mass, density or size
/// that is zero, negative or not finite, a rotation matrix that is not a rotation (to 1e-6), a
/// quaternion that is not unit (to 1e-6), an unknown Euler sequence, an explicit inertia that no
/// body has, a mesh file that is missing, unreadable or not closed, and the hole after which the
/// composite is no longer physical.
CompositePart read_part_file(const std::filesystem::path& path,
                             const PartFileOptions& options = {});

/// As read_part_file, from YAML text; `file_name` labels messages and `base_dir` resolves relative
/// mesh paths.
CompositePart parse_part_file(const std::string& text, const std::string& file_name,
                              const std::filesystem::path& base_dir,
                              const PartFileOptions& options = {});

/// Mass properties of the part a mesh file (STL or OBJ, see read_mesh_file) describes, in the
/// mesh's own coordinates multiplied by `scale` (0.001 for millimetres). A solid (`shell` false)
/// needs a closed mesh (inside-out is corrected) and a density in kg/m³; a thin shell (`shell`
/// true: sheet metal, of uniform thickness) takes its triangles as a surface of density kg/m²,
/// closed or not. Throws as read_mesh_file, inertia::prepare_solid_mesh and
/// inertia::solid_mesh_mass_properties do: FileError, ParseError, MeshError (naming the file),
/// InvalidArgument.
inertia::MassProperties read_mesh_mass_properties(const std::filesystem::path& path,
                                                  inertia::Amount amount, double scale = 1.0,
                                                  bool shell = false);

}  // namespace momenta::io
