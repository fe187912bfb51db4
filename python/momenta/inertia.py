"""Mass properties: primitives by mass or density, meshes, part files, composition and holes.

Each shape is described in its own frame (origin at its centroid, axis of symmetry along z; the
cone's origin is its apex) and takes exactly one of mass= (kg) or density= (kg/m³ for solids,
kg/m² for plates and shells, kg/m for rods and rings):

    from momenta import inertia
    disk = inertia.solid_cylinder(0.1, 0.02, density=7850)
    hole = inertia.solid_cylinder(0.01, 0.02, density=7850).transformed(numpy.eye(3), [0.05, 0, 0])
    part = disk - hole
    part.principal_axes()
"""

from ._core.inertia import (
    CompositePart,
    MassProperties,
    PartSummary,
    annulus,
    box,
    cylindrical_shell,
    ellipsoid,
    hollow_cylinder,
    hollow_sphere,
    mesh,
    part,
    point_mass,
    slender_rod,
    solid_cone,
    solid_cylinder,
    solid_sphere,
    spherical_shell,
    thin_disk,
    thin_rectangular_plate,
    thin_ring,
)

__all__ = [name for name in dir() if not name.startswith("_")]
