"""Mass properties: primitives by mass or density, meshes, part files, composition and holes.

Each shape is described in its own frame (origin at its centroid, axis of symmetry along z; the
cone's origin is its apex) and takes exactly one of mass= (kg) or density= (kg/m³ for solids,
kg/m² for plates and shells, kg/m for rods and rings):

    from momenta import inertia
    disk = inertia.solid_cylinder(0.1, 0.02, density=7850)
    hole = inertia.solid_cylinder(0.01, 0.02, density=7850).transformed(numpy.eye(3), [0.05, 0, 0])
    part = disk - hole
    part.principal_axes()

Rotor balancing (docs/balancing.md) on the same objects:

    u = inertia.unbalance(inertia.part("examples/parts/two_disk_shaft.yaml").total)
    inertia.bearing_reactions(u, 0.0, 1.0, omega=314.16).A     # N, turning with the rotor
    inertia.two_plane_correction(u, 0.25, 0.75)[0].mass_at(0.15)
    inertia.check_grade(u, 2.5, 314.16, 0.0, 1.0).passed
"""

from ._core.inertia import (
    BearingReactions,
    CompositePart,
    CorrectionMass,
    GradeCheck,
    MassProperties,
    PartSummary,
    Unbalance,
    annulus,
    bearing_reactions,
    box,
    check_grade,
    cylindrical_shell,
    ellipsoid,
    hollow_cylinder,
    hollow_sphere,
    mesh,
    part,
    point_mass,
    single_plane_correction,
    slender_rod,
    solid_cone,
    solid_cylinder,
    solid_sphere,
    spherical_shell,
    static_bearing_loads,
    thin_disk,
    thin_rectangular_plate,
    thin_ring,
    two_plane_correction,
    unbalance,
    with_corrections,
)

__all__ = [name for name in dir() if not name.startswith("_")]
