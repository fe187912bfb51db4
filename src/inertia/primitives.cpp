#include "momenta/inertia/primitives.hpp"

#include <cmath>
#include <numbers>
#include <string_view>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/inertia/unit_moments.hpp"

namespace momenta::inertia {
namespace {

constexpr double kPi = std::numbers::pi;

// Throws unless a size is positive and finite.
void require_size(std::string_view shape, std::string_view name, double value) {
  if (!std::isfinite(value) || !(value > 0.0)) {
    throw InvalidArgument(
        fmt::format("{}: {} {} m is not positive and finite", shape, name, value));
  }
}

// Throws unless 0 <= inner < outer (outer already checked).
void require_inner(std::string_view shape, double inner, double outer) {
  if (!std::isfinite(inner) || inner < 0.0) {
    throw InvalidArgument(
        fmt::format("{}: inner_radius {} m is not non-negative and finite", shape, inner));
  }
  if (!(inner < outer)) {
    throw InvalidArgument(
        fmt::format("{}: inner_radius {} m is not below outer_radius {} m", shape, inner, outer));
  }
}

// A body of mass m centred on its frame's origin, its principal moments m × the unit moments.
MassProperties centred(double m, const PrincipalMoments<double>& unit, double volume) {
  return MassProperties(m, Vec3::Zero(), (m * Vec3(unit.xx, unit.yy, unit.zz)).asDiagonal(),
                        volume);
}

}  // namespace

MassProperties point_mass(double mass) {
  if (!std::isfinite(mass) || !(mass > 0.0)) {
    throw InvalidArgument(fmt::format("point_mass: mass {} kg is not positive and finite", mass));
  }
  return MassProperties(mass, Vec3::Zero(), Mat3::Zero(), 0.0);
}

MassProperties slender_rod(Amount amount, double length) {
  require_size("slender_rod", "length", length);
  const double m = amount.mass_for(length, "slender_rod");
  return centred(m, slender_rod_unit_moments(length), 0.0);
}

MassProperties thin_ring(Amount amount, double radius) {
  require_size("thin_ring", "radius", radius);
  const double m = amount.mass_for(2.0 * kPi * radius, "thin_ring");
  return centred(m, thin_ring_unit_moments(radius), 0.0);
}

MassProperties thin_disk(Amount amount, double radius) {
  require_size("thin_disk", "radius", radius);
  const double m = amount.mass_for(kPi * radius * radius, "thin_disk");
  return centred(m, annulus_unit_moments(0.0, radius), 0.0);
}

MassProperties annulus(Amount amount, double inner_radius, double outer_radius) {
  require_size("annulus", "outer_radius", outer_radius);
  require_inner("annulus", inner_radius, outer_radius);
  // r_o² − r_i² factored, so a narrow washer keeps its digits.
  const double area = kPi * (outer_radius - inner_radius) * (outer_radius + inner_radius);
  const double m = amount.mass_for(area, "annulus");
  return centred(m, annulus_unit_moments(inner_radius, outer_radius), 0.0);
}

MassProperties solid_cylinder(Amount amount, double radius, double length) {
  require_size("solid_cylinder", "radius", radius);
  require_size("solid_cylinder", "length", length);
  const double volume = kPi * radius * radius * length;
  const double m = amount.mass_for(volume, "solid_cylinder");
  return centred(m, cylinder_unit_moments(radius, length), volume);
}

MassProperties capsule(Amount amount, double radius, double length) {
  require_size("capsule", "radius", radius);
  require_size("capsule", "length", length);
  const double r2 = radius * radius;
  const double cylinder_volume = kPi * r2 * length;
  const double spheres_volume = 4.0 / 3.0 * kPi * r2 * radius;
  const double volume = cylinder_volume + spheres_volume;
  const double m = amount.mass_for(volume, "capsule");
  return centred(m, capsule_unit_moments(radius, length), volume);
}

MassProperties hollow_cylinder(Amount amount, double inner_radius, double outer_radius,
                               double length) {
  require_size("hollow_cylinder", "outer_radius", outer_radius);
  require_inner("hollow_cylinder", inner_radius, outer_radius);
  require_size("hollow_cylinder", "length", length);
  const double volume =
      kPi * (outer_radius - inner_radius) * (outer_radius + inner_radius) * length;
  const double m = amount.mass_for(volume, "hollow_cylinder");
  return centred(m, hollow_cylinder_unit_moments(inner_radius, outer_radius, length), volume);
}

MassProperties cylindrical_shell(Amount amount, double radius, double length) {
  require_size("cylindrical_shell", "radius", radius);
  require_size("cylindrical_shell", "length", length);
  const double m = amount.mass_for(2.0 * kPi * radius * length, "cylindrical_shell");
  return centred(m, cylindrical_shell_unit_moments(radius, length), 0.0);
}

MassProperties solid_sphere(Amount amount, double radius) {
  require_size("solid_sphere", "radius", radius);
  const double volume = 4.0 / 3.0 * kPi * radius * radius * radius;
  const double m = amount.mass_for(volume, "solid_sphere");
  return centred(m, sphere_unit_moments(radius), volume);
}

MassProperties hollow_sphere(Amount amount, double inner_radius, double outer_radius) {
  require_size("hollow_sphere", "outer_radius", outer_radius);
  require_inner("hollow_sphere", inner_radius, outer_radius);
  const double a = inner_radius;
  const double b = outer_radius;
  // b³ − a³ = (b − a)(b² + ab + a²), factored so that a thin wall keeps its digits.
  const double volume = 4.0 / 3.0 * kPi * (b - a) * (b * b + a * b + a * a);
  const double m = amount.mass_for(volume, "hollow_sphere");
  return centred(m, hollow_sphere_unit_moments(a, b), volume);
}

MassProperties spherical_shell(Amount amount, double radius) {
  require_size("spherical_shell", "radius", radius);
  const double m = amount.mass_for(4.0 * kPi * radius * radius, "spherical_shell");
  return centred(m, spherical_shell_unit_moments(radius), 0.0);
}

MassProperties box(Amount amount, const Vec3& size) {
  require_size("box", "size x", size.x());
  require_size("box", "size y", size.y());
  require_size("box", "size z", size.z());
  const double volume = size.x() * size.y() * size.z();
  const double m = amount.mass_for(volume, "box");
  return centred(m, box_unit_moments(size.x(), size.y(), size.z()), volume);
}

MassProperties thin_rectangular_plate(Amount amount, double width, double height) {
  require_size("thin_rectangular_plate", "width", width);
  require_size("thin_rectangular_plate", "height", height);
  const double m = amount.mass_for(width * height, "thin_rectangular_plate");
  return centred(m, thin_plate_unit_moments(width, height), 0.0);
}

MassProperties solid_cone(Amount amount, double base_radius, double height) {
  require_size("solid_cone", "base_radius", base_radius);
  require_size("solid_cone", "height", height);
  const double volume = kPi * base_radius * base_radius * height / 3.0;
  const double m = amount.mass_for(volume, "solid_cone");
  // About the centroid, 3/4 h from the apex (about the apex the transverse moment is
  // 3/20 m r² + 3/5 m h²).
  const PrincipalMoments<double> unit = cone_unit_moments(base_radius, height);
  return MassProperties(m, Vec3(0.0, 0.0, 0.75 * height),
                        (m * Vec3(unit.xx, unit.yy, unit.zz)).asDiagonal(), volume);
}

MassProperties ellipsoid(Amount amount, const Vec3& semi_axes) {
  require_size("ellipsoid", "semi-axis a", semi_axes.x());
  require_size("ellipsoid", "semi-axis b", semi_axes.y());
  require_size("ellipsoid", "semi-axis c", semi_axes.z());
  const double volume = 4.0 / 3.0 * kPi * semi_axes.x() * semi_axes.y() * semi_axes.z();
  const double m = amount.mass_for(volume, "ellipsoid");
  return centred(m, ellipsoid_unit_moments(semi_axes.x(), semi_axes.y(), semi_axes.z()), volume);
}

}  // namespace momenta::inertia
