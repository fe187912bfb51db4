#pragma once
// Mass properties of the standard shapes, in closed form.
//
// Each shape is described in its own frame S: origin at its centroid, axis of symmetry along z,
// thin shapes (plates, disks, rings) lying in the xy-plane — except the cone, whose origin is its
// apex (see solid_cone). Lengths in m. Every function throws InvalidArgument naming the shape and
// the offending size when a size is not positive and finite (or an inner radius negative or not
// below the outer), or when the Amount is not positive. Solids record their volume (m³) in the
// result; thin shapes (rods, rings, plates, shells) and point masses record 0.

#include "momenta/inertia/amount.hpp"
#include "momenta/inertia/mass_properties.hpp"

namespace momenta::inertia {

/// A point mass at the origin: zero inertia about its centre of mass.
MassProperties point_mass(double mass);

/// A slender rod of the given length along z (density in kg/m).
MassProperties slender_rod(Amount amount, double length);

/// A thin ring (hoop) of the given radius in the xy-plane (density in kg/m).
MassProperties thin_ring(Amount amount, double radius);

/// A thin disk of the given radius in the xy-plane (density in kg/m²).
MassProperties thin_disk(Amount amount, double radius);

/// A thin annulus (washer) between two radii in the xy-plane (density in kg/m²). inner_radius may
/// be 0 (a disk).
MassProperties annulus(Amount amount, double inner_radius, double outer_radius);

/// A solid cylinder along z (density in kg/m³).
MassProperties solid_cylinder(Amount amount, double radius, double length);

/// A solid capsule along z (density in kg/m³): a cylinder of `radius` and `length` capped at both
/// ends by hemispheres of the same radius, so its overall length is length + 2 radius (MuJoCo's
/// capsule geom, size = [radius, length / 2]). Each hemisphere's centre of mass lies 3r/8 beyond
/// its flat face and its moment about a diameter through that centre is 83/320 m r².
MassProperties capsule(Amount amount, double radius, double length);

/// A thick-walled tube along z between two radii (density in kg/m³). inner_radius may be 0.
MassProperties hollow_cylinder(Amount amount, double inner_radius, double outer_radius,
                               double length);

/// A thin-walled cylindrical shell (open tube) along z (density in kg/m²).
MassProperties cylindrical_shell(Amount amount, double radius, double length);

/// A solid sphere (density in kg/m³).
MassProperties solid_sphere(Amount amount, double radius);

/// A thick spherical shell between two radii (density in kg/m³). inner_radius may be 0; a thin
/// wall keeps its digits (the differences of powers are factored).
MassProperties hollow_sphere(Amount amount, double inner_radius, double outer_radius);

/// A thin spherical shell (density in kg/m²): I = 2/3 m r².
MassProperties spherical_shell(Amount amount, double radius);

/// A solid rectangular box with edge lengths size = (x, y, z) (density in kg/m³).
MassProperties box(Amount amount, const Vec3& size);

/// A thin rectangular plate with edges width (x) and height (y) in the xy-plane (density kg/m²).
MassProperties thin_rectangular_plate(Amount amount, double width, double height);

/// A solid right circular cone (density in kg/m³). Its frame's origin is the APEX, the axis runs
/// along +z from the apex to the base at z = height; the centre of mass is at z = 3/4 height.
/// Use inertia_about(Vec3::Zero()) for the inertia about the apex.
MassProperties solid_cone(Amount amount, double base_radius, double height);

/// A solid ellipsoid with semi-axes (a, b, c) along x, y, z (density in kg/m³).
MassProperties ellipsoid(Amount amount, const Vec3& semi_axes);

}  // namespace momenta::inertia
