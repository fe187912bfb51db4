#pragma once
// Reading triangle meshes from STL (binary and ASCII) and OBJ files.

#include <filesystem>

#include "momenta/inertia/triangle_mesh.hpp"

namespace momenta::io {

/// Reads a mesh file and multiplies every coordinate by `scale` (0.001 for a mesh drawn in mm).
/// Vertices repeated per triangle (STL) are welded so the topology can be checked. Throws
/// FileError if the file is missing or unreadable, ParseError naming the file (and line where
/// known) if it is malformed — an empty file, a binary STL whose triangle count disagrees with its
/// size, an unsupported extension.
inertia::TriangleMesh read_mesh_file(const std::filesystem::path& path, double scale = 1.0);

}  // namespace momenta::io
