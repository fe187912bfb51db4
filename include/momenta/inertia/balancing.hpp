#pragma once
// Rotor balancing: how unbalanced a rigid rotor is about its axis of rotation, the bearing
// reactions that unbalance causes, the masses that cancel it in one or two correction planes,
// and the balance-grade verdict of ISO 21940-11. What each quantity means and how it maps to the
// fixed-axis rotation equations of Beer & Johnston ch. 18: docs/balancing.md.
//
// Frames. The rotor is described in its part frame B. The rotation axis is the line through the
// point A (p_BoAo_B) along the unit vector a (in B). The axis frame R is rotor-fixed: z_R = a,
// x_R the direction of B's x axis projected on the plane normal to a (B's y axis when x is along
// a), y_R = z_R × x_R; its origin is Ao. Axial positions z (bearings, correction planes) are
// measured along a from Ao; angles in the plane of rotation from x_R towards y_R. Everything that
// rotates with the rotor (unbalances, corrections, the reactions of a steady spin) is given by
// its components in R: a rotating vector of constant amplitude and phase.
//
// Sign convention: the products of inertia here are P_xz = ∫ x z dm and P_yz = ∫ y z dm (the
// tensor's off-diagonal entries are minus these, docs/conventions.md).

#include <array>
#include <cmath>
#include <span>

#include "momenta/inertia/mass_properties.hpp"
#include "momenta/math/types.hpp"

namespace momenta::inertia {

/// The rotation axis of a rotor, in its part frame B.
struct RotorAxis {
  Vec3 p_BoAo_B = Vec3::Zero();      ///< a point on the axis, m
  Vec3 direction_B = Vec3::UnitZ();  ///< along the axis; any length but zero
};

/// How unbalanced a rotor is about its axis (components in the axis frame R).
struct Unbalance {
  Mat3 R_BR;                  ///< the axis frame R in B (columns x_R, y_R, z_R)
  double mass = 0.0;          ///< kg
  double axial_com = 0.0;     ///< z of the centre of mass, m
  double eccentricity = 0.0;  ///< e: the centre of mass's distance from the axis, m
  /// U_s = m (x_cm, y_cm): the static unbalance, kg·m. Its direction is the heavy side.
  Vec2 static_unbalance = Vec2::Zero();
  /// P = (P_xz, P_yz) about Ao, kg·m²: with U_s, all that makes the bearings react.
  Vec2 products = Vec2::Zero();
  /// P − z_cm U_s: the products about the centre of mass's plane, the couple unbalance, kg·m².
  Vec2 couple_unbalance = Vec2::Zero();
  double polar_moment = 0.0;  ///< I_zz about the axis, kg·m²
  /// The angle between the axis and the principal axis of inertia nearest to it, rad: with e,
  /// what a balancing machine calls the dynamic unbalance. 0 for a rotor whose axis is principal.
  double principal_axis_tilt = 0.0;
};

/// The unbalance of `part` about `axis`. Throws InvalidArgument for a zero or non-finite axis
/// direction, InvalidInertia for a part with no positive mass.
Unbalance unbalance(const MassProperties& part, const RotorAxis& axis);

/// A correction mass, as its mass-radius product m·r (kg·m) in the plane z, at the angle of the
/// vector (components in R). Negative masses are not used: removing mass is adding it opposite.
struct CorrectionMass {
  double z = 0.0;                   ///< the correction plane, m
  Vec2 mass_radius = Vec2::Zero();  ///< m·r as a rotating vector, kg·m
  double mass_at(double radius) const { return mass_radius.norm() / radius; }
};

/// The rotor with point masses added at the corrections (m·r at radius 1 m: only m·r and z
/// enter the unbalance): its static unbalance and products. Mass, e and tilt are left as they
/// were; use it for the residual unbalance after a correction.
Unbalance with_corrections(const Unbalance& rotor, std::span<const CorrectionMass> corrections);

/// Two-plane correction: the masses in the planes z1 ≠ z2 that cancel both the static and the
/// couple unbalance (after them, U_s = 0 and P = 0: the bearings carry no rotating load at any
/// speed). Throws InvalidArgument when the planes coincide (to 1e-9 of the larger |z| or 1 µm).
std::array<CorrectionMass, 2> two_plane_correction(const Unbalance& rotor, double z1, double z2);

/// Single-plane (static) correction in the plane z: the mass cancelling U_s. It leaves the
/// couple P − z U_s about Ao, which is the couple unbalance when z is the centre of mass's plane.
CorrectionMass single_plane_correction(const Unbalance& rotor, double z);

/// The rotating loads at two bearing planes. The rotor turns about the fixed axis at ω (rad/s)
/// with angular acceleration α (rad/s²); the bearings at z_A ≠ z_B supply the radial forces that
/// keep it on the axis. In R (turning with the rotor), the net force the rotor needs is
/// F = m (−ω² x_cm − α y_cm, −ω² y_cm + α x_cm) and the moment about Ao
/// M_x = ω² P_yz − α P_xz, M_y = −ω² P_xz − α P_yz, M_z = α I_zz (Beer & Johnston §18.5,
/// with their I_xz = P_xz): bearing forces R_A + R_B = F, z_A R_A + z_B R_B = (M_y, −M_x).
/// Gravity and the drive's own loads are not in them.
struct BearingReactions {
  Vec2 A = Vec2::Zero();      ///< N, components in R
  Vec2 B = Vec2::Zero();      ///< N, components in R
  double drive_torque = 0.0;  ///< α I_zz, N·m: the axial moment the drive supplies
};

/// Throws InvalidArgument when the bearing planes coincide, or ω, α are not finite.
BearingReactions bearing_reactions(const Unbalance& rotor, double z_A, double z_B, double omega,
                                   double alpha = 0.0);

/// The static (gravity) loads on the bearings of a horizontal shaft, N, upward: m g split by the
/// lever rule about the centre of mass's plane.
Vec2 static_bearing_loads(const Unbalance& rotor, double z_A, double z_B, double g);

/// The balance grade check of ISO 21940-11 (formerly ISO 1940-1): the permissible residual
/// unbalance U_per = m e_per with e_per ω = G, and its allocation to the bearing planes.
struct GradeCheck {
  double grade = 0.0;        ///< G, mm/s
  double omega = 0.0;        ///< the maximum service speed, rad/s
  double permissible = 0.0;  ///< U_per, kg·m
  /// The residual unbalance carried to each bearing plane (U_A + U_B = U_s, z_A U_A + z_B U_B =
  /// P), kg·m: what each bearing feels, ω² U per plane.
  Vec2 plane_A = Vec2::Zero();
  Vec2 plane_B = Vec2::Zero();
  /// U_per allocated to each plane, kg·m: for a centre of mass between the bearings in the
  /// ratio of the distances to the other bearing, each share held within 30 %–70 % of U_per
  /// (ISO 21940-11's rule for inboard rotors); for an overhung rotor (centre of mass outside them)
  /// this simple rule does not apply, and both planes are allowed U_per / 2 (conservative) with
  /// `overhung` set.
  double permissible_A = 0.0;
  double permissible_B = 0.0;
  bool overhung = false;
  bool pass = false;  ///< |U_A| ≤ U_per,A and |U_B| ≤ U_per,B
};

/// Throws InvalidArgument for G or ω not positive and finite, or coinciding bearing planes.
GradeCheck check_grade(const Unbalance& rotor, double grade_mm_per_s, double omega, double z_A,
                       double z_B);

/// The angle of a rotating vector in R, rad in (−π, π]: from x_R towards y_R.
inline double angle_of(const Vec2& v) { return std::atan2(v.y(), v.x()); }

}  // namespace momenta::inertia
