#pragma once
// Mass properties of a rigid body: mass, centre of mass and inertia tensor about the centre of
// mass.
//
// Frame notation (docs/conventions.md): a MassProperties describes a body B in a frame, also
// called B, with origin Bo. The centre of mass is p_BoBcm_B; the inertia is I_BBcm_B, about Bcm,
// expressed in B. The inertia tensor holds the moments of inertia on its diagonal and minus the
// products of inertia off it: I_xy = −∫ x y dm.

#include <string_view>

#include "momenta/math/spatial.hpp"
#include "momenta/math/types.hpp"

namespace momenta::inertia {

/// Principal moments and axes of an inertia tensor.
struct PrincipalAxes {
  Vec3 moments;  ///< Principal moments, ascending, kg·m².
  Mat3 R_BP;     ///< Columns are the principal axes expressed in B; a proper rotation (det +1).
};

/// Relative tolerance of the physical-validity checks, against the largest principal moment. It
/// admits idealized bodies (a point mass, a slender rod: moments that are exactly zero) and the
/// round-off of meshes, while rejecting tensors that no mass distribution has.
inline constexpr double kValidityTolerance = 1e-9;

class MassProperties {
 public:
  /// Nothing: zero mass, the identity for composition.
  MassProperties() = default;

  /// `mass` in kg, `p_BoBcm_B` in m, `I_BBcm_B` in kg·m² about the centre of mass, `volume` in m³
  /// (0 where it has no meaning, such as a point mass). Nothing is checked here; call
  /// check_physical() on anything read from a user.
  MassProperties(double mass, const Vec3& p_BoBcm_B, const Mat3& I_BBcm_B, double volume = 0.0);

  /// From an inertia about a point Q (p_BoQ_B) instead of about the centre of mass.
  static MassProperties from_inertia_about(double mass, const Vec3& p_BoBcm_B, const Mat3& I_BQ_B,
                                           const Vec3& p_BoQ_B, double volume = 0.0);

  double mass() const { return mass_; }
  double volume() const { return volume_; }
  const Vec3& center_of_mass() const { return p_BoBcm_B_; }
  const Mat3& inertia_about_com() const { return I_BBcm_B_; }

  /// Inertia about the point Q at p_BoQ_B, expressed in B (parallel-axis theorem, products
  /// included): I_BQ = I_BBcm + m (|d|² 1 − d dᵀ) with d = p_QBcm.
  Mat3 inertia_about(const Vec3& p_BoQ_B) const;

  /// The spatial inertia about Bo, expressed in B (Featherstone 2008 §2.13): mass, first moment
  /// m p_BoBcm_B and the inertia about Bo.
  SpatialInertia spatial_inertia() const {
    return {mass_, mass_ * p_BoBcm_B_, inertia_about(Vec3::Zero())};
  }

  /// The same body described in frame A, where B sits at pose (R_AB, p_AoBo_A) in A.
  MassProperties transformed(const Mat3& R_AB, const Vec3& p_AoBo_A) const;

  /// The same body with its inertia re-expressed in a frame A rotated by R_AB about Bo.
  MassProperties re_expressed(const Mat3& R_AB) const { return transformed(R_AB, Vec3::Zero()); }

  /// Composite of two bodies described in the same frame.
  MassProperties& operator+=(const MassProperties& other);

  /// Removes a part (a hole) described in the same frame. Throws InvalidInertia if the
  /// remaining mass is not positive.
  MassProperties& operator-=(const MassProperties& hole);

  /// Principal moments (ascending) and axes. Where moments repeat (to a relative 1e-10) the
  /// axes of that eigenspace are chosen as close as possible to B's own axes, so a sphere's
  /// principal axes are B's axes and a cylinder's are B's axes when it is aligned with them.
  PrincipalAxes principal_axes() const;

  /// Throws InvalidInertia, naming `what` and showing the numbers, unless the mass is positive and
  /// finite, the centre of mass finite, and the inertia symmetric, positive semi-definite and
  /// satisfying the triangle inequality A + B >= C, each to kValidityTolerance.
  void check_physical(std::string_view what) const;

 private:
  double mass_ = 0.0;
  double volume_ = 0.0;
  Vec3 p_BoBcm_B_ = Vec3::Zero();
  Mat3 I_BBcm_B_ = Mat3::Zero();
};

MassProperties operator+(MassProperties a, const MassProperties& b);
MassProperties operator-(MassProperties a, const MassProperties& hole);

/// The parallel-axis term m (|d|² 1 − d dᵀ): the inertia of a point mass m at offset d.
Mat3 point_mass_inertia(double mass, const Vec3& d);

}  // namespace momenta::inertia
