#pragma once
// Indexed triangle meshes and their topology: what the mesh path of the inertia engine reads.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "momenta/math/types.hpp"

namespace momenta::inertia {

/// Vertices (m) and triangles as indices into them. A closed mesh bounding a solid has its
/// triangles counter-clockwise seen from outside (outward normals, right-hand rule).
struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::int32_t, 3>> triangles;
};

/// What analyze_topology finds. A mesh bounds a solid when every edge is shared by exactly two
/// triangles that traverse it in opposite directions.
struct MeshTopology {
  std::size_t boundary_edges = 0;      ///< Edges used by one triangle only (the mesh is open).
  std::size_t non_manifold_edges = 0;  ///< Edges used by three or more triangles.
  std::size_t inconsistent_edges = 0;  ///< Edges two triangles traverse in the same direction.
  std::size_t degenerate_triangles = 0;  ///< Triangles with a repeated vertex index.
  std::string example;                 ///< One offending edge or triangle, described for a message.

  bool is_closed_manifold() const {
    return boundary_edges == 0 && non_manifold_edges == 0 && inconsistent_edges == 0;
  }
};

/// Merges vertices closer than `tolerance` (m), as STL files repeat every vertex per triangle.
/// Degenerate triangles that result are dropped.
TriangleMesh weld_vertices(const TriangleMesh& mesh, double tolerance);

/// Edge-use counts of the mesh (see MeshTopology).
MeshTopology analyze_topology(const TriangleMesh& mesh);

/// Makes `mesh` ready for solid integration: throws MeshError naming `name` and what is wrong
/// (open, non-manifold, inconsistently oriented — with counts and an example) unless it bounds a
/// solid, and reverses every triangle if the mesh is closed but inward-facing (negative volume).
/// Returns true if it flipped the mesh.
bool prepare_solid_mesh(TriangleMesh& mesh, std::string_view name);

}  // namespace momenta::inertia
