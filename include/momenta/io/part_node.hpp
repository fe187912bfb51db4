#pragma once
// The pieces of the part-file reader that other readers reuse: one part node (a shape, a mesh or
// an explicit inertia, placed by a pose) and a pose's rotation. Model files read a body's mass
// properties with them (docs/model-format.md); part files are described in
// docs/inertia-format.md.

#include <cstddef>
#include <filesystem>
#include <optional>

#include "momenta/io/part_file.hpp"
#include "momenta/io/yaml_reader.hpp"
#include "momenta/math/types.hpp"

namespace momenta::io {

/// The rotation R_BS given by the map `node`: the identity when it has none of the keys, else
/// exactly one of `rotation` (3×3 rows; orthonormal with determinant +1 to 1e-6, then replaced by
/// the nearest rotation), `quaternion` ([w, x, y, z], unit to 1e-6) or `euler` ({sequence,
/// angles | angles_deg}, SciPy's convention). Throws ParseError at the offending key.
Mat3 read_rotation(const YamlNode& node);

/// Reads one part map — exactly one of `shape`, `mesh` or `inertia`, with its amount (`mass` or
/// `density`), sizes and pose (`position`, `rotation` | `quaternion` | `euler`) — and places it in
/// the enclosing frame B. `index` names a part without `name:` ("parts[index]"); `unit` converts
/// the node's lengths to metres; `default_density` (kg/m³) applies to solids that give neither
/// `mass` nor `density`; mesh paths are relative to `base_dir`. The part's keys are checked (with
/// a did-you-mean) against those part files allow, `name` and `hole` included. Throws ParseError
/// `file:line:column: key path: message` for every problem, as read_part_file does.
PartSummary read_part(const YamlNode& part, std::size_t index, double unit,
                      std::optional<double> default_density, const std::filesystem::path& base_dir);

}  // namespace momenta::io
