#include "momenta/identify/inertial_parameters.hpp"

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include "momenta/common/error.hpp"
#include "momenta/inertia/mass_properties.hpp"

namespace momenta::identify {

Vec10 parameters_of(const SpatialInertia& I) {
  Vec10 pi;
  pi << I.mass, I.h[0], I.h[1], I.h[2], I.I_O(0, 0), I.I_O(0, 1), I.I_O(0, 2), I.I_O(1, 1),
      I.I_O(1, 2), I.I_O(2, 2);
  return pi;
}

SpatialInertia spatial_inertia_of(const Vec10& pi) {
  Mat3 I_O;
  I_O << pi[4], pi[5], pi[6],  //
      pi[5], pi[7], pi[8],     //
      pi[6], pi[8], pi[9];
  return {pi[0], Vec3(pi[1], pi[2], pi[3]), I_O};
}

int num_inertial_parameters(const Model& model) {
  return kParametersPerBody * (model.num_bodies() - 1);
}

VecX inertial_parameters(const Model& model) {
  VecX pi(num_inertial_parameters(model));
  for (int b = 1; b < model.num_bodies(); ++b) {
    pi.segment<kParametersPerBody>(kParametersPerBody * (b - 1)) =
        parameters_of(model.spatial_inertia(b));
  }
  return pi;
}

std::string parameter_name(const Model& model, int k) {
  if (k < 0 || k >= num_inertial_parameters(model)) {
    throw InvalidArgument(fmt::format("inertial parameter {}: the model has {} (0 … {})", k,
                                      num_inertial_parameters(model),
                                      num_inertial_parameters(model) - 1));
  }
  return fmt::format("{}.{}", model.body(1 + k / kParametersPerBody).name,
                     kParameterNames[k % kParametersPerBody]);
}

PhysicalConsistency physical_consistency(const Vec10& pi) {
  PhysicalConsistency c;
  c.mass = pi[0];
  c.positive_mass = std::isfinite(c.mass) && c.mass > 0.0;
  if (!c.positive_mass) return c;
  const SpatialInertia I = spatial_inertia_of(pi);
  c.center_of_mass = I.h / c.mass;
  // Parallel axes back to the centre.
  const Mat3 I_C = I.I_O - inertia::point_mass_inertia(c.mass, c.center_of_mass);
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(I_C, Eigen::EigenvaluesOnly);
  c.principal_moments = eigen.eigenvalues();  // ascending
  const double scale = std::max(std::abs(c.principal_moments[2]), 1e-300);
  const double slack = inertia::kValidityTolerance * scale;
  const Vec3& J = c.principal_moments;
  c.positive_moments = J[0] >= -slack;
  c.triangle_inequalities = J[2] <= J[0] + J[1] + slack;
  return c;
}

std::string PhysicalConsistency::verdict() const {
  if (!positive_mass) return fmt::format("mass {:.6g} kg is not positive", mass);
  if (!positive_moments) {
    return fmt::format("a principal moment about the centre of mass is negative ({:.6g} kg·m²)",
                       principal_moments[0]);
  }
  if (!triangle_inequalities) {
    return fmt::format(
        "the principal moments {:.6g}, {:.6g}, {:.6g} kg·m² break the triangle inequality "
        "(the largest exceeds the sum of the other two)",
        principal_moments[0], principal_moments[1], principal_moments[2]);
  }
  return "consistent";
}

}  // namespace momenta::identify
