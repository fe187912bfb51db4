#include "momenta/identify/inertial_regressor.hpp"

#include <array>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/rnea.hpp"

namespace momenta::identify {
namespace {

using Mat6x10 = Eigen::Matrix<double, 6, kParametersPerBody>;

// The spatial inertia of each unit parameter vector e_k: F = Σ_k π_k (I_k A + V ×* I_k V).
const std::array<SpatialInertia, kParametersPerBody>& unit_inertias() {
  static const std::array<SpatialInertia, kParametersPerBody> units = [] {
    std::array<SpatialInertia, kParametersPerBody> out;
    for (int k = 0; k < kParametersPerBody; ++k) out[k] = spatial_inertia_of(Vec10::Unit(k));
    return out;
  }();
  return units;
}

// K(V, A): body's net wrench F = I A + V ×* I V = K π, column k for the unit parameter e_k.
Mat6x10 wrench_regressor(const Vec6& V, const Vec6& A) {
  Mat6x10 K;
  const auto& units = unit_inertias();
  for (int k = 0; k < kParametersPerBody; ++k) {
    K.col(k) = units[k] * A + cross_force(V, units[k] * V);
  }
  return K;
}

void check_size(const char* name, Eigen::Index size, int expected, const char* what) {
  if (size != expected) {
    throw InvalidArgument(fmt::format("inertial_regressor: {} has size {}; the model needs {} ({})",
                                      name, size, expected, what));
  }
}

}  // namespace

InertialRegressor::InertialRegressor(const Model& model)
    : model_(model), data_(model), Y_(MatX::Zero(model.nv(), num_inertial_parameters(model))) {}

const MatX& InertialRegressor::compute(VecRef q, VecRef v, VecRef vdot) {
  check_size("q", q.size(), model_.nq(), "nq");
  check_size("v", v.size(), model_.nv(), "nv");
  check_size("vdot", vdot.size(), model_.nv(), "nv");
  // RNEA's forward pass leaves each body's V_WB_B, A_gf (gravity as the base's upward
  // acceleration), X_PB and, for joints off the coordinate axes, S.
  dynamics::rnea(model_, data_, q, v, vdot);
  Y_.setZero();
  const auto& joints = model_.joint_constants();
  for (int body = 1; body < model_.num_bodies(); ++body) {
    Mat6x10 K = wrench_regressor(data_.V_WB_B[body], data_.A_gf[body]);
    const int column = kParametersPerBody * (body - 1);
    // Up the path to the root: each joint on it feels this body's wrench carried to its child.
    for (int b = body; b > 0;) {
      const int j = b - 1;  // joint j carries body j + 1
      const auto& c = joints[j];
      if (c.S_basis >= 0) {
        Y_.row(c.v_index).segment<kParametersPerBody>(column) = K.row(c.S_basis);
      } else {
        Y_.block(c.v_index, column, c.nv, kParametersPerBody).noalias() =
            data_.S[j].leftCols(c.nv).transpose() * K;
      }
      if (c.parent == 0) break;
      for (int k = 0; k < kParametersPerBody; ++k) K.col(k) = data_.X_PB[b].act_force(K.col(k));
      b = c.parent;
    }
  }
  return Y_;
}

VecX InertialRegressor::armature_torque(VecRef vdot) const {
  check_size("vdot", vdot.size(), model_.nv(), "nv");
  VecX tau = VecX::Zero(model_.nv());
  for (const auto& c : model_.joint_constants()) {
    for (int k = 0; k < c.nv; ++k) tau[c.v_index + k] = c.armature * vdot[c.v_index + k];
  }
  return tau;
}

MatX inertial_regressor(const Model& model, VecRef q, VecRef v, VecRef vdot) {
  InertialRegressor regressor(model);
  return regressor.compute(q, v, vdot);
}

}  // namespace momenta::identify
