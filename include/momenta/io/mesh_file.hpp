#pragma once
// Reading triangle meshes from STL (binary and ASCII), OBJ and COLLADA (.dae) files.

#include <filesystem>

#include "momenta/inertia/triangle_mesh.hpp"

namespace momenta::io {

/// Reads a triangle mesh from an STL (binary or ASCII), OBJ or COLLADA file and multiplies every
/// coordinate by `scale` (0.001 for a mesh drawn in mm). OBJ and ASCII STL are read by their own
/// grammars in double precision (mesh_text_formats.hpp): coordinates written with 17 digits arrive
/// exactly. Binary STL, single precision by the format, and COLLADA are read through assimp
/// (COLLADA's <unit meter> applied, its <up_axis> not: the mesh keeps the coordinates it is
/// written in, as robot descriptions place it). Every mesh in the file is
/// merged, moved by its node transforms (a mirroring transform has its triangles' winding reversed
/// so outward stays outward); polygons are triangulated; points and lines are ignored. Nothing else
/// alters the geometry: vertices exactly repeated (STL stores each triangle's corners apart) are
/// welded so the topology can be checked, no normals are generated, no triangle is dropped but
/// those whose corners coincide. Call inertia::prepare_solid_mesh on the result before solid
/// integration.
///
/// Throws InvalidArgument if `scale` is not positive and finite; FileError naming the file if it
/// is missing, not a regular file, unreadable or empty; ParseError naming the file if the
/// extension is not .stl, .obj or .dae, if a binary STL's size disagrees with the triangle count in
/// its header (84 + 50 n bytes: both numbers are given), if an ASCII STL lacks its closing
/// 'endsolid', if a text file breaks its grammar (file:line:column: a malformed number, a face
/// referring to a vertex that does not exist), if assimp cannot read a binary STL or COLLADA file,
/// if it holds no triangles, or if a coordinate is not finite.
inertia::TriangleMesh read_mesh_file(const std::filesystem::path& path, double scale = 1.0);

/// The same with a scale per axis (a robot description's mesh scale): each factor's magnitude
/// within 1e-9 … 1e9; a negative factor mirrors the mesh, and a mirroring scale (an odd number of
/// negative factors) has its triangles' winding turned back so outward stays outward. Throws as
/// above.
inertia::TriangleMesh read_mesh_file(const std::filesystem::path& path, const Vec3& scale);

}  // namespace momenta::io
