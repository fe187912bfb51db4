#pragma once
// Exact mass properties of polyhedra (closed triangle meshes) and of thin shells.

#include "momenta/inertia/amount.hpp"
#include "momenta/inertia/mass_properties.hpp"
#include "momenta/inertia/triangle_mesh.hpp"

namespace momenta::inertia {

/// Mass properties of the uniform solid a closed, outward-oriented mesh bounds (call
/// prepare_solid_mesh first), exact to round-off: divergence theorem over the signed tetrahedra
/// that each triangle spans with a reference point (Mirtich 1996; Eberly; Kallay 2006; the
/// tetrahedron moments of Tonon 2004). The reference point is the bounding-box centre, so a mesh
/// far from the origin loses no digits. Ten monomial integrals are accumulated (about 90 flops
/// per triangle, no allocation) and the tensor is built once; inertia about the centre of mass
/// with off-diagonals −∫xy dm (docs/conventions.md). Density in kg/m³, or a total mass; the
/// volume (m³) is recorded. Throws MeshError if the enclosed volume is not positive and finite
/// (open or inward-facing mesh, non-finite vertex) or a triangle indexes outside the vertices;
/// InvalidArgument if the Amount is not positive.
MassProperties solid_mesh_mass_properties(const TriangleMesh& mesh, Amount amount);

/// Mass properties of a thin shell of uniform surface density (kg/m²), or of a total mass, over
/// the mesh's triangles (sheet-metal parts); the mesh need not be closed and winding does not
/// matter. Each triangle's own area moments are exact (∫ xᵢxⱼ dA = A (Σ vᵢvⱼ + sᵢsⱼ)/12 over its
/// corners v, s their sum). Records volume 0. Throws MeshError if the total area is not positive
/// and finite or an index is out of range; InvalidArgument if the Amount is not positive.
MassProperties shell_mesh_mass_properties(const TriangleMesh& mesh, Amount amount);

}  // namespace momenta::inertia
