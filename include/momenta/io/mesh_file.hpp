#pragma once
// Reading triangle meshes from STL (binary and ASCII) and OBJ files.

#include <filesystem>

#include "momenta/inertia/triangle_mesh.hpp"

namespace momenta::io {

/// Reads a triangle mesh from an STL (binary or ASCII) or OBJ file, through assimp, and multiplies
/// every coordinate by `scale` (0.001 for a mesh drawn in mm). Every mesh in the file is merged,
/// moved by its node transforms (a mirroring transform has its triangles' winding reversed so
/// outward stays outward); polygons are triangulated; points and lines are ignored. Nothing else
/// alters the geometry: vertices exactly repeated (STL stores each triangle's corners apart) are
/// welded so the topology can be checked, no normals are generated, no triangle is dropped but
/// those whose corners coincide. Coordinates pass through single precision (assimp's, and binary
/// STL's own). Call inertia::prepare_solid_mesh on the result before solid integration.
///
/// Throws InvalidArgument if `scale` is not positive and finite; FileError naming the file if it
/// is missing, not a regular file, unreadable or empty; ParseError naming the file if the
/// extension is neither .stl nor .obj, if a binary STL's size disagrees with the triangle count in
/// its header (84 + 50 n bytes: both numbers are given), if an ASCII STL lacks its closing
/// 'endsolid', if assimp cannot read it, or if it holds no triangles.
inertia::TriangleMesh read_mesh_file(const std::filesystem::path& path, double scale = 1.0);

}  // namespace momenta::io
