#pragma once
// Exact mass properties of polyhedra (closed triangle meshes) and of thin shells.

#include "momenta/inertia/amount.hpp"
#include "momenta/inertia/mass_properties.hpp"
#include "momenta/inertia/triangle_mesh.hpp"

namespace momenta::inertia {

/// Mass properties of the uniform solid a closed, outward-oriented mesh bounds (call
/// prepare_solid_mesh first), exact to round-off: divergence theorem over signed tetrahedra from
/// the origin (Mirtich 1996; Eberly; Kallay 2006). Density in kg/m³. The volume is recorded.
MassProperties solid_mesh_mass_properties(const TriangleMesh& mesh, Amount amount);

/// Mass properties of a thin shell of uniform surface density (kg/m²) over the mesh's triangles
/// (sheet-metal parts); the mesh need not be closed. Each triangle's own area moments are exact.
MassProperties shell_mesh_mass_properties(const TriangleMesh& mesh, Amount amount);

}  // namespace momenta::inertia
