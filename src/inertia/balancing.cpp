#include "momenta/inertia/balancing.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::inertia {
namespace {

void check_finite(const char* what, double value) {
  if (!std::isfinite(value))
    throw InvalidArgument(fmt::format("{} = {}: must be finite", what, value));
}

// Two axial planes far enough apart to solve for loads or masses in them.
void check_planes(const char* what, double z1, double z2) {
  check_finite(what, z1);
  check_finite(what, z2);
  const double scale = std::max({std::abs(z1), std::abs(z2), 1e-3});
  if (std::abs(z2 - z1) <= 1e-9 * scale) {
    throw InvalidArgument(fmt::format(
        "{} at z = {} m and z = {} m coincide: two planes apart along the axis are needed (one "
        "plane cancels the static unbalance only)",
        what, z1, z2));
  }
}

// The rotor-fixed axis frame: z along the axis, x from B's x (or y) projected off it.
Mat3 axis_frame(const Vec3& direction_B) {
  const double length = direction_B.norm();
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw InvalidArgument(fmt::format(
        "the rotation axis [{}, {}, {}] has no direction: give a non-zero, finite vector",
        direction_B.x(), direction_B.y(), direction_B.z()));
  }
  const Vec3 z = direction_B / length;
  Vec3 x = Vec3::UnitX() - z.x() * z;
  if (x.norm() < 1e-6) x = Vec3::UnitY() - z.y() * z;
  x.normalize();
  Mat3 R_BR;
  R_BR << x, z.cross(x), z;
  return R_BR;
}

// The pair (u_1, u_2) in the planes z1, z2 with u_1 + u_2 = sum and z1 u_1 + z2 u_2 = moment.
std::array<Vec2, 2> split_between_planes(const Vec2& sum, const Vec2& moment, double z1,
                                         double z2) {
  const Vec2 second = (moment - z1 * sum) / (z2 - z1);
  return {sum - second, second};
}

}  // namespace

Unbalance unbalance(const MassProperties& part, const RotorAxis& axis) {
  if (!(part.mass() > 0.0) || !std::isfinite(part.mass())) {
    throw InvalidInertia(
        fmt::format("a rotor of mass {} kg: the mass must be positive and finite", part.mass()));
  }
  for (int k = 0; k < 3; ++k) check_finite("the axis point", axis.p_BoAo_B[k]);
  Unbalance u;
  u.R_BR = axis_frame(axis.direction_B);
  u.mass = part.mass();
  // The part in the axis frame R (origin Ao): centre of mass and inertia about Ao.
  const Mat3 R_RB = u.R_BR.transpose();
  const Vec3 p_AoBcm_R = R_RB * (part.center_of_mass() - axis.p_BoAo_B);
  const Mat3 I_Ao_R = R_RB * part.inertia_about(axis.p_BoAo_B) * u.R_BR;
  u.axial_com = p_AoBcm_R.z();
  u.eccentricity = p_AoBcm_R.head<2>().norm();
  u.static_unbalance = u.mass * p_AoBcm_R.head<2>();
  // The tensor's off-diagonal entries are minus the products.
  u.products = Vec2(-I_Ao_R(0, 2), -I_Ao_R(1, 2));
  u.couple_unbalance = u.products - u.axial_com * u.static_unbalance;
  u.polar_moment = I_Ao_R(2, 2);
  // The principal axis of inertia (about the centre of mass) nearest to the rotation axis.
  const PrincipalAxes principal = part.principal_axes();
  const Vec3 a_B = u.R_BR.col(2);
  double nearest = 0.0;
  for (int k = 0; k < 3; ++k) nearest = std::max(nearest, std::abs(principal.R_BP.col(k).dot(a_B)));
  u.principal_axis_tilt = std::acos(std::min(1.0, nearest));
  return u;
}

Unbalance with_corrections(const Unbalance& rotor, std::span<const CorrectionMass> corrections) {
  Unbalance u = rotor;
  for (const CorrectionMass& c : corrections) {
    u.static_unbalance += c.mass_radius;
    u.products += c.z * c.mass_radius;
  }
  u.couple_unbalance = u.products - u.axial_com * u.static_unbalance;
  return u;
}

std::array<CorrectionMass, 2> two_plane_correction(const Unbalance& rotor, double z1, double z2) {
  check_planes("the correction planes", z1, z2);
  // The corrections' own static unbalance and products cancel the rotor's.
  const auto [u1, u2] = split_between_planes(-rotor.static_unbalance, -rotor.products, z1, z2);
  return {CorrectionMass{z1, u1}, CorrectionMass{z2, u2}};
}

CorrectionMass single_plane_correction(const Unbalance& rotor, double z) {
  check_finite("the correction plane", z);
  return {z, -rotor.static_unbalance};
}

BearingReactions bearing_reactions(const Unbalance& rotor, double z_A, double z_B, double omega,
                                   double alpha) {
  check_planes("the bearings", z_A, z_B);
  check_finite("ω", omega);
  check_finite("α", alpha);
  const double w2 = omega * omega;
  const Vec2& U = rotor.static_unbalance;
  const Vec2& P = rotor.products;
  // What the rotor needs: force F and moment (M_x, M_y) about Ao, in R.
  const Vec2 F(-w2 * U.x() - alpha * U.y(), -w2 * U.y() + alpha * U.x());
  const double M_x = w2 * P.y() - alpha * P.x();
  const double M_y = -w2 * P.x() - alpha * P.y();
  const auto [A, B] = split_between_planes(F, Vec2(M_y, -M_x), z_A, z_B);
  return {A, B, alpha * rotor.polar_moment};
}

Vec2 static_bearing_loads(const Unbalance& rotor, double z_A, double z_B, double g) {
  check_planes("the bearings", z_A, z_B);
  check_finite("g", g);
  const double W = rotor.mass * g;
  const double B = W * (rotor.axial_com - z_A) / (z_B - z_A);
  return {W - B, B};
}

GradeCheck check_grade(const Unbalance& rotor, double grade_mm_per_s, double omega, double z_A,
                       double z_B) {
  if (!(grade_mm_per_s > 0.0) || !std::isfinite(grade_mm_per_s)) {
    throw InvalidArgument(fmt::format(
        "balance grade G = {} mm/s: must be positive (ISO 21940-11 grades run G 0.4 … G 4000)",
        grade_mm_per_s));
  }
  if (!(omega > 0.0) || !std::isfinite(omega)) {
    throw InvalidArgument(fmt::format(
        "the service speed ω = {} rad/s: the grade needs the maximum service speed, positive",
        omega));
  }
  check_planes("the bearings", z_A, z_B);
  GradeCheck check;
  check.grade = grade_mm_per_s;
  check.omega = omega;
  // e_per ω = G (G in m/s): U_per = m e_per.
  check.permissible = rotor.mass * (grade_mm_per_s * 1e-3) / omega;
  const auto [UA, UB] = split_between_planes(rotor.static_unbalance, rotor.products, z_A, z_B);
  check.plane_A = UA;
  check.plane_B = UB;
  // Allocation: in the ratio of the distances to the other bearing, within 30 %–70 %.
  const double share_A = (z_B - rotor.axial_com) / (z_B - z_A);
  check.overhung = share_A < 0.0 || share_A > 1.0;
  const double share = check.overhung ? 0.5 : std::clamp(share_A, 0.3, 0.7);
  check.permissible_A = share * check.permissible;
  check.permissible_B = (1.0 - share) * check.permissible;
  check.pass = UA.norm() <= check.permissible_A && UB.norm() <= check.permissible_B;
  return check;
}

}  // namespace momenta::inertia
