#pragma once
// A body's ten inertial parameters: the vector π the joint forces of a tree are linear in
// (Atkeson, An & Hollerbach 1986; Khalil & Dombre 2002, §9.3; docs/identification.md).
//
// Body b's ten, about its origin Bo and expressed in B, in this order:
//   m, h_x, h_y, h_z, I_xx, I_xy, I_xz, I_yy, I_yz, I_zz
// with h = m p_BoBcm_B the first moment (kg·m) and I the inertia tensor about Bo (kg·m²) — its
// off-diagonals minus the products of inertia (docs/conventions.md). The model's π stacks the
// bodies 1 … num_bodies()−1 (the world has none): parameter k belongs to body 1 + k / 10.

#include <array>
#include <string>
#include <string_view>

#include "momenta/math/spatial.hpp"
#include "momenta/model/model.hpp"

namespace momenta::identify {

using model::Model;
using Vec10 = Eigen::Matrix<double, 10, 1>;

inline constexpr int kParametersPerBody = 10;

/// The ten's names, in π's order (a parameter's full name is "<body>.<name>").
inline constexpr std::array<std::string_view, kParametersPerBody> kParameterNames = {
    "m", "h_x", "h_y", "h_z", "I_xx", "I_xy", "I_xz", "I_yy", "I_yz", "I_zz"};

/// The ten's units, in π's order.
inline constexpr std::array<std::string_view, kParametersPerBody> kParameterUnits = {
    "kg", "kg·m", "kg·m", "kg·m", "kg·m²", "kg·m²", "kg·m²", "kg·m²", "kg·m²", "kg·m²"};

/// The ten of one spatial inertia, and back.
Vec10 parameters_of(const SpatialInertia& I);
SpatialInertia spatial_inertia_of(const Vec10& pi);

/// 10 (num_bodies − 1): the size of a model's π.
int num_inertial_parameters(const Model& model);

/// The model's own π, from each body's spatial inertia.
VecX inertial_parameters(const Model& model);

/// "<body>.<name>" of parameter k of a model's π (0 ≤ k < num_inertial_parameters).
std::string parameter_name(const Model& model, int k);

/// Whether ten parameters are those of a body that can exist: positive mass, and an inertia
/// about the centre of mass whose principal moments are positive and obey the triangle
/// inequalities (each at most the sum of the other two) — to inertia::kValidityTolerance of the
/// largest moment, as a model file's bodies are checked.
struct PhysicalConsistency {
  double mass = 0.0;                      ///< kg.
  Vec3 center_of_mass = Vec3::Zero();     ///< p_BoBcm_B, m (zero where the mass is not positive).
  Vec3 principal_moments = Vec3::Zero();  ///< About the centre of mass, ascending, kg·m².
  bool positive_mass = false;
  bool positive_moments = false;
  bool triangle_inequalities = false;
  bool consistent() const { return positive_mass && positive_moments && triangle_inequalities; }
  /// "consistent", or what fails, in words.
  std::string verdict() const;
};
PhysicalConsistency physical_consistency(const Vec10& pi);

}  // namespace momenta::identify
