#pragma once
// Indexed triangle meshes and their topology: what the mesh path of the inertia engine reads.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
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
  std::size_t boundary_edges = 0;        ///< Edges used by one triangle only (the mesh is open).
  std::size_t non_manifold_edges = 0;    ///< Edges used by three or more triangles.
  std::size_t inconsistent_edges = 0;    ///< Edges two triangles traverse in the same direction.
  std::size_t degenerate_triangles = 0;  ///< Triangles with a repeated vertex index.
  std::size_t components = 0;  ///< Connected pieces (triangles joined through shared vertices).
  /// Volume (m³) the triangles enclose, positive when they face outward; by the divergence
  /// theorem about the bounding-box centre, so independent of that point only for a closed mesh.
  double signed_volume = 0.0;
  /// The worst defect found (non-manifold, then open, then inconsistent, then degenerate),
  /// described with its vertex indices and coordinates for a message; empty when there is none.
  std::string example;

  bool is_closed_manifold() const {
    return boundary_edges == 0 && non_manifold_edges == 0 && inconsistent_edges == 0;
  }
};

/// Merges vertices within `tolerance` (m) of one another, as STL files repeat every vertex per
/// triangle; `tolerance` 0 merges exact duplicates only. Each merged vertex keeps the coordinates
/// of its first occurrence, vertices keep their order of first occurrence, and triangles whose
/// corners merge (a repeated index) are dropped. Grid hashing: O(n) expected time.
/// Throws InvalidArgument if `tolerance` is negative or not finite, MeshError if a vertex is not
/// finite or a triangle indexes outside the vertices.
TriangleMesh weld_vertices(const TriangleMesh& mesh, double tolerance);

/// Edge-use counts, components and signed volume of the mesh (see MeshTopology), in O(n) time.
/// Throws MeshError if a triangle indexes outside the vertices.
MeshTopology analyze_topology(const TriangleMesh& mesh);

/// Makes `mesh` ready for solid integration. Welds exact duplicate vertices (dropping the
/// degenerate triangles that leaves), then throws MeshError naming `name` and what is wrong — open
/// (boundary edges), non-manifold, inconsistently oriented, with counts and an example edge —
/// unless every edge is shared by exactly two triangles traversing it in opposite directions; and
/// throws MeshError if the mesh has no triangles, a non-finite vertex, or encloses no volume
/// (|signed volume| below 1e-12 of the summed unsigned tetrahedron volumes). Reverses every
/// triangle if the mesh is closed but inside-out (negative signed volume) and returns true then,
/// false otherwise. A mesh of several closed pieces is accepted as long as their total volume is
/// positive: an inward-facing piece inside an outward one is a cavity.
bool prepare_solid_mesh(TriangleMesh& mesh, std::string_view name);

/// The centre of the mesh's axis-aligned bounding box (zero for an empty mesh): the origin the
/// volume sums are taken about, so that round-off does not grow with the mesh's distance from
/// its own frame's origin.
Vec3 bounding_box_centre(const TriangleMesh& mesh);

}  // namespace momenta::inertia
