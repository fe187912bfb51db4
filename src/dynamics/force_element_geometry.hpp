#pragma once
// What force_element_forces and force_element_derivatives share about the elements' geometry
// (private to src/dynamics).

#include <span>

#include "momenta/dynamics/data.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta/model/force_element.hpp"

namespace momenta::dynamics::detail {

// Below this length (m) a linear spring's direction p_b − p_a is not computed: |d| comes from the
// squared norm, which loses precision once it nears the underflow threshold (|d| ~ 1e-154). No
// model has points this close on purpose; it is the coincident-points case.
inline constexpr double kMinDirectionLength = 1e-100;

// The scale of an applied load: its signal's value, or 1 without a signal.
inline double load_scale(int signal_index, std::span<const double> signal_values) {
  return signal_index < 0 ? 1.0 : signal_values[signal_index];
}

// Rotation vector θ (in B, |θ| ≤ π) of body b relative to body a, measured from R_AB_rest.
inline Vec3 relative_rotation_vector(const Data& data, const model::TorsionalSpringDamper& e) {
  const Mat3 R_AB = data.X_WB[e.body_a_index].R.transpose() * data.X_WB[e.body_b_index].R;
  // R_AB = R_AB_rest · Exp(θ): θ is fixed by its own rotation, so its components are the same
  // in B and in B's rest frame.
  const Mat3 R_rest_B = e.R_AB_rest.transpose() * R_AB;
  return quaternion_log(Quat(R_rest_B));
}

}  // namespace momenta::dynamics::detail
