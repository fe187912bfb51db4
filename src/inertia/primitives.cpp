#include "momenta/inertia/primitives.hpp"

#include <cmath>
#include <numbers>
#include <string_view>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

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

// A body centred on its frame's origin with a diagonal inertia about it.
MassProperties centred(double mass, double ixx, double iyy, double izz, double volume) {
  return MassProperties(mass, Vec3::Zero(), Vec3(ixx, iyy, izz).asDiagonal(), volume);
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
  const double i = m * length * length / 12.0;
  return centred(m, i, i, 0.0, 0.0);
}

MassProperties thin_ring(Amount amount, double radius) {
  require_size("thin_ring", "radius", radius);
  const double m = amount.mass_for(2.0 * kPi * radius, "thin_ring");
  const double r2 = radius * radius;
  return centred(m, m * r2 / 2.0, m * r2 / 2.0, m * r2, 0.0);
}

MassProperties thin_disk(Amount amount, double radius) {
  require_size("thin_disk", "radius", radius);
  const double m = amount.mass_for(kPi * radius * radius, "thin_disk");
  const double r2 = radius * radius;
  return centred(m, m * r2 / 4.0, m * r2 / 4.0, m * r2 / 2.0, 0.0);
}

MassProperties annulus(Amount amount, double inner_radius, double outer_radius) {
  require_size("annulus", "outer_radius", outer_radius);
  require_inner("annulus", inner_radius, outer_radius);
  // r_o² − r_i² factored, so a narrow washer keeps its digits.
  const double area = kPi * (outer_radius - inner_radius) * (outer_radius + inner_radius);
  const double m = amount.mass_for(area, "annulus");
  const double r2 = inner_radius * inner_radius + outer_radius * outer_radius;
  return centred(m, m * r2 / 4.0, m * r2 / 4.0, m * r2 / 2.0, 0.0);
}

MassProperties solid_cylinder(Amount amount, double radius, double length) {
  require_size("solid_cylinder", "radius", radius);
  require_size("solid_cylinder", "length", length);
  const double volume = kPi * radius * radius * length;
  const double m = amount.mass_for(volume, "solid_cylinder");
  const double r2 = radius * radius;
  const double axial = m * r2 / 2.0;
  const double transverse = m * (3.0 * r2 + length * length) / 12.0;
  return centred(m, transverse, transverse, axial, volume);
}

MassProperties capsule(Amount amount, double radius, double length) {
  require_size("capsule", "radius", radius);
  require_size("capsule", "length", length);
  const double r2 = radius * radius;
  const double cylinder_volume = kPi * r2 * length;
  const double spheres_volume = 4.0 / 3.0 * kPi * r2 * radius;
  const double volume = cylinder_volume + spheres_volume;
  const double m = amount.mass_for(volume, "capsule");
  // The mass shared by volume between the cylinder and the two hemispheres (a sphere together).
  const double m_cylinder = m * (cylinder_volume / volume), m_spheres = m - m_cylinder;
  const double axial = m_cylinder * r2 / 2.0 + m_spheres * 2.0 * r2 / 5.0;
  const double offset = length / 2.0 + 3.0 * radius / 8.0;  // each hemisphere's centre of mass
  const double transverse = m_cylinder * (3.0 * r2 + length * length) / 12.0 +
                            m_spheres * (83.0 / 320.0 * r2 + offset * offset);
  return centred(m, transverse, transverse, axial, volume);
}

MassProperties hollow_cylinder(Amount amount, double inner_radius, double outer_radius,
                               double length) {
  require_size("hollow_cylinder", "outer_radius", outer_radius);
  require_inner("hollow_cylinder", inner_radius, outer_radius);
  require_size("hollow_cylinder", "length", length);
  const double volume =
      kPi * (outer_radius - inner_radius) * (outer_radius + inner_radius) * length;
  const double m = amount.mass_for(volume, "hollow_cylinder");
  const double r2 = inner_radius * inner_radius + outer_radius * outer_radius;
  const double axial = m * r2 / 2.0;
  const double transverse = m * (3.0 * r2 + length * length) / 12.0;
  return centred(m, transverse, transverse, axial, volume);
}

MassProperties cylindrical_shell(Amount amount, double radius, double length) {
  require_size("cylindrical_shell", "radius", radius);
  require_size("cylindrical_shell", "length", length);
  const double m = amount.mass_for(2.0 * kPi * radius * length, "cylindrical_shell");
  const double r2 = radius * radius;
  const double axial = m * r2;
  const double transverse = m * r2 / 2.0 + m * length * length / 12.0;
  return centred(m, transverse, transverse, axial, 0.0);
}

MassProperties solid_sphere(Amount amount, double radius) {
  require_size("solid_sphere", "radius", radius);
  const double volume = 4.0 / 3.0 * kPi * radius * radius * radius;
  const double m = amount.mass_for(volume, "solid_sphere");
  const double i = 0.4 * m * radius * radius;
  return centred(m, i, i, i, volume);
}

MassProperties hollow_sphere(Amount amount, double inner_radius, double outer_radius) {
  require_size("hollow_sphere", "outer_radius", outer_radius);
  require_inner("hollow_sphere", inner_radius, outer_radius);
  const double a = inner_radius;
  const double b = outer_radius;
  // b³ − a³ = (b − a)(b² + ab + a²) and (b⁵ − a⁵)/(b³ − a³) factored, so a thin wall keeps its
  // digits (the differences cancel to (b − a) exactly).
  const double q3 = b * b + a * b + a * a;
  const double q5 = b * b * b * b + b * b * b * a + b * b * a * a + b * a * a * a + a * a * a * a;
  const double volume = 4.0 / 3.0 * kPi * (b - a) * q3;
  const double m = amount.mass_for(volume, "hollow_sphere");
  const double i = 0.4 * m * q5 / q3;
  return centred(m, i, i, i, volume);
}

MassProperties spherical_shell(Amount amount, double radius) {
  require_size("spherical_shell", "radius", radius);
  const double m = amount.mass_for(4.0 * kPi * radius * radius, "spherical_shell");
  const double i = 2.0 / 3.0 * m * radius * radius;
  return centred(m, i, i, i, 0.0);
}

MassProperties box(Amount amount, const Vec3& size) {
  require_size("box", "size x", size.x());
  require_size("box", "size y", size.y());
  require_size("box", "size z", size.z());
  const double volume = size.x() * size.y() * size.z();
  const double m = amount.mass_for(volume, "box");
  const Vec3 s2 = size.cwiseProduct(size);
  return centred(m, m * (s2.y() + s2.z()) / 12.0, m * (s2.x() + s2.z()) / 12.0,
                 m * (s2.x() + s2.y()) / 12.0, volume);
}

MassProperties thin_rectangular_plate(Amount amount, double width, double height) {
  require_size("thin_rectangular_plate", "width", width);
  require_size("thin_rectangular_plate", "height", height);
  const double m = amount.mass_for(width * height, "thin_rectangular_plate");
  const double w2 = width * width;
  const double h2 = height * height;
  return centred(m, m * h2 / 12.0, m * w2 / 12.0, m * (w2 + h2) / 12.0, 0.0);
}

MassProperties solid_cone(Amount amount, double base_radius, double height) {
  require_size("solid_cone", "base_radius", base_radius);
  require_size("solid_cone", "height", height);
  const double volume = kPi * base_radius * base_radius * height / 3.0;
  const double m = amount.mass_for(volume, "solid_cone");
  const double r2 = base_radius * base_radius;
  // About the centroid (at 3/4 h from the apex): I_axial = 3/10 m r², I_transverse =
  // 3/20 m r² + 3/80 m h²; about the apex the transverse moment is 3/20 m r² + 3/5 m h².
  const double axial = 0.3 * m * r2;
  const double transverse = m * (3.0 / 20.0 * r2 + 3.0 / 80.0 * height * height);
  return MassProperties(m, Vec3(0.0, 0.0, 0.75 * height),
                        Vec3(transverse, transverse, axial).asDiagonal(), volume);
}

MassProperties ellipsoid(Amount amount, const Vec3& semi_axes) {
  require_size("ellipsoid", "semi-axis a", semi_axes.x());
  require_size("ellipsoid", "semi-axis b", semi_axes.y());
  require_size("ellipsoid", "semi-axis c", semi_axes.z());
  const double volume = 4.0 / 3.0 * kPi * semi_axes.x() * semi_axes.y() * semi_axes.z();
  const double m = amount.mass_for(volume, "ellipsoid");
  const Vec3 s2 = semi_axes.cwiseProduct(semi_axes);
  return centred(m, m * (s2.y() + s2.z()) / 5.0, m * (s2.x() + s2.z()) / 5.0,
                 m * (s2.x() + s2.y()) / 5.0, volume);
}

}  // namespace momenta::inertia
