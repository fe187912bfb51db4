#include "momenta/inertia/mass_properties.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include "momenta/common/error.hpp"

namespace momenta::inertia {
namespace {

std::string format_matrix(const Mat3& M) {
  return fmt::format(
      "[[{:.6g}, {:.6g}, {:.6g}], [{:.6g}, {:.6g}, {:.6g}], [{:.6g}, {:.6g}, {:.6g}]]", M(0, 0),
      M(0, 1), M(0, 2), M(1, 0), M(1, 1), M(1, 2), M(2, 0), M(2, 1), M(2, 2));
}

// Replaces the columns [first, last) of `axes`, an orthonormal basis of one eigenspace, by the
// basis of the same space closest to B's coordinate axes: project each coordinate axis onto the
// space, largest projection first, and orthonormalize (Gram–Schmidt).
void align_eigenspace(Mat3& axes, int first, int last) {
  const int dim = last - first;
  if (dim == 3) {
    axes.setIdentity();
    return;
  }
  // dim == 2: the space is the plane normal to the remaining axis n.
  const int other = first == 0 ? 2 : 0;
  const Vec3 n = axes.col(other);
  int best = 0;
  double best_norm = -1;
  for (int k = 0; k < 3; ++k) {
    const double norm = (Vec3::Unit(k) - n * n[k]).norm();
    if (norm > best_norm) {
      best_norm = norm;
      best = k;
    }
  }
  const Vec3 u = (Vec3::Unit(best) - n * n[best]).normalized();
  axes.col(first) = u;
  axes.col(first + 1) = n.cross(u);
}

}  // namespace

Mat3 point_mass_inertia(double mass, const Vec3& d) {
  return mass * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
}

MassProperties::MassProperties(double mass, const Vec3& p_BoBcm_B, const Mat3& I_BBcm_B,
                               double volume)
    : mass_(mass), volume_(volume), p_BoBcm_B_(p_BoBcm_B), I_BBcm_B_(I_BBcm_B) {}

MassProperties MassProperties::from_inertia_about(double mass, const Vec3& p_BoBcm_B,
                                                  const Mat3& I_BQ_B, const Vec3& p_BoQ_B,
                                                  double volume) {
  return MassProperties(mass, p_BoBcm_B, I_BQ_B - point_mass_inertia(mass, p_BoBcm_B - p_BoQ_B),
                        volume);
}

Mat3 MassProperties::inertia_about(const Vec3& p_BoQ_B) const {
  return I_BBcm_B_ + point_mass_inertia(mass_, p_BoBcm_B_ - p_BoQ_B);
}

MassProperties MassProperties::transformed(const Mat3& R_AB, const Vec3& p_AoBo_A) const {
  return MassProperties(mass_, p_AoBo_A + R_AB * p_BoBcm_B_, R_AB * I_BBcm_B_ * R_AB.transpose(),
                        volume_);
}

MassProperties& MassProperties::operator+=(const MassProperties& other) {
  const double mass = mass_ + other.mass_;
  if (mass == 0.0) {
    // Two massless parts: keep the geometry only.
    volume_ += other.volume_;
    return *this;
  }
  const Vec3 com = (mass_ * p_BoBcm_B_ + other.mass_ * other.p_BoBcm_B_) / mass;
  I_BBcm_B_ = inertia_about(com) + other.inertia_about(com);
  p_BoBcm_B_ = com;
  mass_ = mass;
  volume_ += other.volume_;
  return *this;
}

MassProperties& MassProperties::operator-=(const MassProperties& hole) {
  const double mass = mass_ - hole.mass_;
  if (!(mass > 0.0)) {
    throw InvalidInertia(fmt::format(
        "removing a hole of mass {:.6g} kg from a body of mass {:.6g} kg leaves {:.6g} kg; a hole "
        "must be smaller than the material it is cut from",
        hole.mass_, mass_, mass));
  }
  const Vec3 com = (mass_ * p_BoBcm_B_ - hole.mass_ * hole.p_BoBcm_B_) / mass;
  I_BBcm_B_ = inertia_about(com) - hole.inertia_about(com);
  p_BoBcm_B_ = com;
  mass_ = mass;
  volume_ -= hole.volume_;
  return *this;
}

MassProperties operator+(MassProperties a, const MassProperties& b) { return a += b; }
MassProperties operator-(MassProperties a, const MassProperties& hole) { return a -= hole; }

PrincipalAxes MassProperties::principal_axes() const {
  // Symmetrize first: the solver reads one triangle only.
  const Mat3 I = 0.5 * (I_BBcm_B_ + I_BBcm_B_.transpose());
  Eigen::SelfAdjointEigenSolver<Mat3> solver(I);
  PrincipalAxes result{solver.eigenvalues(), solver.eigenvectors()};
  // Group moments equal to a relative 1e-10 and give each repeated group a canonical basis.
  const double scale = std::max(result.moments.cwiseAbs().maxCoeff(), 1e-300);
  const auto same = [&](int i, int j) {
    return std::abs(result.moments[i] - result.moments[j]) <= 1e-10 * scale;
  };
  if (same(0, 1) && same(1, 2)) {
    align_eigenspace(result.R_BP, 0, 3);
  } else if (same(0, 1)) {
    align_eigenspace(result.R_BP, 0, 2);
  } else if (same(1, 2)) {
    align_eigenspace(result.R_BP, 1, 3);
  }
  // A proper rotation: flip the last axis if the basis is left-handed.
  if (result.R_BP.determinant() < 0) result.R_BP.col(2) *= -1.0;
  return result;
}

void MassProperties::check_physical(std::string_view what) const {
  if (!std::isfinite(mass_) || !(mass_ > 0.0)) {
    throw InvalidInertia(
        fmt::format("{}: mass {:.6g} kg is not positive; a body needs a positive "
                    "mass",
                    what, mass_));
  }
  if (!p_BoBcm_B_.allFinite() || !I_BBcm_B_.allFinite()) {
    throw InvalidInertia(fmt::format("{}: centre of mass [{}, {}, {}] or inertia {} is not finite",
                                     what, p_BoBcm_B_.x(), p_BoBcm_B_.y(), p_BoBcm_B_.z(),
                                     format_matrix(I_BBcm_B_)));
  }
  const double scale = std::max(I_BBcm_B_.cwiseAbs().maxCoeff(), 1e-300);
  const double asymmetry = (I_BBcm_B_ - I_BBcm_B_.transpose()).cwiseAbs().maxCoeff();
  if (asymmetry > kValidityTolerance * scale) {
    throw InvalidInertia(fmt::format("{}: inertia {} is not symmetric (largest |I − Iᵀ| = {:.3g})",
                                     what, format_matrix(I_BBcm_B_), asymmetry));
  }
  const Vec3 m = principal_axes().moments;
  const double tolerance = kValidityTolerance * std::max(m[2], 1e-300);
  if (m[0] < -tolerance) {
    throw InvalidInertia(fmt::format(
        "{}: inertia {} about the centre of mass is not positive semi-definite (principal moments "
        "{:.6g}, {:.6g}, {:.6g} kg·m²); check the signs of the products of inertia (off-diagonal "
        "entries are minus the products)",
        what, format_matrix(I_BBcm_B_), m[0], m[1], m[2]));
  }
  if (m[0] + m[1] < m[2] - tolerance) {
    throw InvalidInertia(fmt::format(
        "{}: principal moments {:.6g}, {:.6g}, {:.6g} kg·m² violate the triangle inequality "
        "A + B >= C ({:.6g} < {:.6g}); no mass distribution has this inertia",
        what, m[0], m[1], m[2], m[0] + m[1], m[2]));
  }
}

}  // namespace momenta::inertia
