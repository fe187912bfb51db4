#pragma once
// The text mesh formats read in double precision by their own (small) grammars: Wavefront OBJ
// (v and f; everything else a mass-properties reader may ignore) and ASCII STL. Internal to io:
// read_mesh_file (mesh_file.hpp) is the public entry.

#include <string>
#include <string_view>

#include "momenta/inertia/triangle_mesh.hpp"

namespace momenta::io::detail {

/// The triangles of an OBJ text: vertices `v x y z` (a fourth number is the homogeneous w, more
/// are vertex colours), faces `f` of three or more vertex references (`i`, `i/t`, `i//n`,
/// `i/t/n`; negative i counts back from the last vertex), polygons triangulated in their plane
/// (a fan when convex, ear clipping when not). Lines, points and every other statement are
/// skipped; `skipped` counts the lines and points. Throws ParseError `file:line:column: ...` for
/// a malformed number, a reference to a vertex that does not exist, or a face of fewer than three
/// vertices.
inertia::TriangleMesh parse_obj(std::string_view text, const std::string& file,
                                std::size_t& skipped);

/// The triangles of an ASCII STL text (one or more `solid ... endsolid`), each facet's three
/// vertices as written (not welded). Throws ParseError `file:line:column: ...` for anything that
/// does not follow the grammar, or a number that is not finite.
inertia::TriangleMesh parse_ascii_stl(std::string_view text, const std::string& file);

}  // namespace momenta::io::detail
