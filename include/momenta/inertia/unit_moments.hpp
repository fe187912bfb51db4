#pragma once
// The standard shapes' principal moments of inertia per unit mass about their centres of mass, in
// their own frames S (primitives.hpp), written once for any arithmetic type: numbers
// (primitives.cpp multiplies them by the mass) and symbols (the equations in symbols keep a rod's
// I_G = m L²/12 in m and L when those are symbols). Lengths in m, moments in m² (kg·m² per kg).

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "momenta/math/types.hpp"

namespace momenta::inertia {

/// Principal moments of inertia about the centre of mass along the shape frame's x, y, z.
template <class T>
struct PrincipalMoments {
  T xx, yy, zz;
};

template <class T>
PrincipalMoments<T> slender_rod_unit_moments(const T& length) {
  const T i = length * length / 12;
  return {i, i, T(0)};
}

template <class T>
PrincipalMoments<T> thin_ring_unit_moments(const T& radius) {
  const T r2 = radius * radius;
  return {r2 / 2, r2 / 2, r2};
}

template <class T>
PrincipalMoments<T> annulus_unit_moments(const T& inner_radius, const T& outer_radius) {
  const T r2 = inner_radius * inner_radius + outer_radius * outer_radius;
  return {r2 / 4, r2 / 4, r2 / 2};
}

template <class T>
PrincipalMoments<T> hollow_cylinder_unit_moments(const T& inner_radius, const T& outer_radius,
                                                 const T& length) {
  const T r2 = inner_radius * inner_radius + outer_radius * outer_radius;
  const T transverse = (3 * r2 + length * length) / 12;
  return {transverse, transverse, r2 / 2};
}

template <class T>
PrincipalMoments<T> cylinder_unit_moments(const T& radius, const T& length) {
  const T r2 = radius * radius;
  const T transverse = (3 * r2 + length * length) / 12;
  return {transverse, transverse, r2 / 2};
}

/// A cylinder of `radius` and `length` capped by two hemispheres: the mass shared by volume,
/// 3 L : 4 r between the cylinder and the two hemispheres (a sphere together); each hemisphere's
/// centre of mass lies 3r/8 beyond its flat face, its moment about a diameter there 83/320 m r².
template <class T>
PrincipalMoments<T> capsule_unit_moments(const T& radius, const T& length) {
  const T r2 = radius * radius;
  const T cylinder = 3 * length / (3 * length + 4 * radius);
  const T spheres = 4 * radius / (3 * length + 4 * radius);
  const T offset = length / 2 + 3 * radius / 8;
  const T axial = cylinder * r2 / 2 + spheres * 2 * r2 / 5;
  const T transverse =
      cylinder * (3 * r2 + length * length) / 12 + spheres * (83 * r2 / 320 + offset * offset);
  return {transverse, transverse, axial};
}

template <class T>
PrincipalMoments<T> cylindrical_shell_unit_moments(const T& radius, const T& length) {
  const T r2 = radius * radius;
  const T transverse = r2 / 2 + length * length / 12;
  return {transverse, transverse, r2};
}

template <class T>
PrincipalMoments<T> sphere_unit_moments(const T& radius) {
  const T i = 2 * radius * radius / 5;
  return {i, i, i};
}

/// Between radii a < b: 2/5 (b⁵ − a⁵)/(b³ − a³), the differences factored so that a thin wall
/// keeps its digits.
template <class T>
PrincipalMoments<T> hollow_sphere_unit_moments(const T& inner_radius, const T& outer_radius) {
  const T& a = inner_radius;
  const T& b = outer_radius;
  const T q3 = b * b + a * b + a * a;
  const T q5 = b * b * b * b + b * b * b * a + b * b * a * a + b * a * a * a + a * a * a * a;
  const T i = 2 * q5 / (5 * q3);
  return {i, i, i};
}

template <class T>
PrincipalMoments<T> spherical_shell_unit_moments(const T& radius) {
  const T i = 2 * radius * radius / 3;
  return {i, i, i};
}

/// Edge lengths x, y, z.
template <class T>
PrincipalMoments<T> box_unit_moments(const T& x, const T& y, const T& z) {
  return {(y * y + z * z) / 12, (x * x + z * z) / 12, (x * x + y * y) / 12};
}

/// Width along x, height along y.
template <class T>
PrincipalMoments<T> thin_plate_unit_moments(const T& width, const T& height) {
  const T w2 = width * width, h2 = height * height;
  return {h2 / 12, w2 / 12, (w2 + h2) / 12};
}

/// About the centroid, 3/4 of the height from the apex: 3/10 r² axial, 3/20 r² + 3/80 h² across.
template <class T>
PrincipalMoments<T> cone_unit_moments(const T& base_radius, const T& height) {
  const T r2 = base_radius * base_radius;
  const T transverse = 3 * r2 / 20 + 3 * height * height / 80;
  return {transverse, transverse, 3 * r2 / 10};
}

/// Semi-axes a, b, c along x, y, z.
template <class T>
PrincipalMoments<T> ellipsoid_unit_moments(const T& a, const T& b, const T& c) {
  return {(b * b + c * c) / 5, (a * a + c * c) / 5, (a * a + b * b) / 5};
}

/// A body that is one standard shape, as a model file's `shape:` gives it: the shape's name in
/// part files (docs/inertia-format.md), its sizes in metres by key ("length", "radius",
/// "inner_radius", "outer_radius", "width", "height"; a 3-vector key such as "size" as "size.x",
/// "size.y", "size.z"), and its frame S's orientation R_BS in the body's frame B.
struct PrimitiveShape {
  std::string kind;
  std::vector<std::pair<std::string, double>> sizes;
  Mat3 R_BS = Mat3::Identity();
};

/// The unit moments of the part-file shape `kind` with its sizes read by `size(key)` (keys as in
/// PrimitiveShape); zero for a point mass, nullopt for a kind with no formula here.
template <class T, class Size>
std::optional<PrincipalMoments<T>> unit_moments_of(std::string_view kind, Size size) {
  if (kind == "point_mass") return PrincipalMoments<T>{T(0), T(0), T(0)};
  if (kind == "slender_rod") return slender_rod_unit_moments<T>(size("length"));
  if (kind == "thin_ring") return thin_ring_unit_moments<T>(size("radius"));
  if (kind == "thin_disk") return annulus_unit_moments<T>(T(0), size("radius"));
  if (kind == "annulus") return annulus_unit_moments<T>(size("inner_radius"), size("outer_radius"));
  if (kind == "cylinder") return cylinder_unit_moments<T>(size("radius"), size("length"));
  if (kind == "hollow_cylinder") {
    return hollow_cylinder_unit_moments<T>(size("inner_radius"), size("outer_radius"),
                                           size("length"));
  }
  if (kind == "cylindrical_shell") {
    return cylindrical_shell_unit_moments<T>(size("radius"), size("length"));
  }
  if (kind == "capsule") return capsule_unit_moments<T>(size("radius"), size("length"));
  if (kind == "sphere") return sphere_unit_moments<T>(size("radius"));
  if (kind == "hollow_sphere") {
    return hollow_sphere_unit_moments<T>(size("inner_radius"), size("outer_radius"));
  }
  if (kind == "spherical_shell") return spherical_shell_unit_moments<T>(size("radius"));
  if (kind == "box") return box_unit_moments<T>(size("size.x"), size("size.y"), size("size.z"));
  if (kind == "thin_plate") return thin_plate_unit_moments<T>(size("width"), size("height"));
  if (kind == "cone") return cone_unit_moments<T>(size("radius"), size("height"));
  if (kind == "ellipsoid") {
    return ellipsoid_unit_moments<T>(size("semi_axes.x"), size("semi_axes.y"), size("semi_axes.z"));
  }
  return std::nullopt;
}

}  // namespace momenta::inertia
