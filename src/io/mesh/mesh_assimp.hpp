#pragma once
// The mesh formats read through assimp: binary STL (single precision by the format itself) and
// COLLADA. Internal to io: read_mesh_file (mesh_file.hpp) is the public entry. The report's
// in-page engine (wasm/) is built without assimp and links mesh_assimp_absent.cpp instead, whose
// read_with_assimp says so; the text formats (mesh_text_formats.hpp) are read by both builds.

#include <cstddef>
#include <string>
#include <string_view>

#include "momenta/inertia/triangle_mesh.hpp"
#include "momenta/math/types.hpp"

namespace momenta::io::detail {

/// Every triangle of the file at `name` (`format`, "STL" or "COLLADA", names it in messages), in
/// its world coordinates (node transforms applied), scaled; points and lines counted in
/// `skipped`. Triangulation only: no vertex joining, normal generation or degenerate removal.
/// Throws ParseError where assimp cannot read the file, MeshError where its indices are wrong.
inertia::TriangleMesh read_with_assimp(const std::string& name, std::string_view format,
                                       const Vec3& scale, std::size_t& skipped);

}  // namespace momenta::io::detail
