#pragma once
// ∂a/∂q and ∂a/∂v of a model's accelerations a(t, q, v), analytic: what the sensitivity equations
// of a run need at every step (identify/trajectory_sensitivities.hpp). The same derivatives
// linearize() puts in A (the residual r_f = ID(q, v, v̇) − Q(q, v) of the free coordinates,
// differentiated by rnea_derivatives and force_element_derivatives, then ∂a_f = −M_ff⁻¹ ∂r_f),
// for models without constraints, at one state and without allocating.

#include <vector>

#include <Eigen/Cholesky>

#include "momenta/dynamics/data.hpp"
#include "momenta/math/types.hpp"
#include "momenta/model/model.hpp"
#include "momenta/system/multibody_system.hpp"

namespace momenta::analysis {

class AccelerationDerivatives {
 public:
  /// Sizes the workspace for `model` (which must outlive this). Throws InvalidArgument for a
  /// model with constraints (their multipliers depend on the state too: linearize() handles
  /// them) or with controllers (their states are not the model's).
  explicit AccelerationDerivatives(const model::Model& model);

  /// ∂a/∂δq (along the configuration's tangent) and ∂a/∂v, each nv × nv, at the state `system`
  /// last evaluated (system.evaluate(t, q, v) first; the system built on the same model). Rows
  /// and columns of prescribed coordinates are zero: their motion is given, not a state. Throws
  /// NumericalError when the free coordinates' mass matrix is not positive definite. No
  /// allocation after the first call.
  void compute(const system::MultibodySystem& system, MatX& da_dq, MatX& da_dv);

  /// After compute(): da = −M_ff⁻¹ r on the free coordinates, zero on the prescribed ones — how
  /// the accelerations move when a generalized force r is left unbalanced at this state
  /// (MultibodySystem::residual of a second model at the first's accelerations, to first order
  /// in r). Sizes r and da nv. No allocation.
  void acceleration_change(const VecX& r, VecX& da);

  /// Velocity indices of the free (not prescribed) coordinates, ascending.
  const std::vector<int>& free() const { return free_; }

 private:
  const model::Model& model_;
  dynamics::Data data_;
  std::vector<int> free_;
  std::vector<double> signal_values_;
  MatX mass_ff_, dr_dq_ff_, dr_dv_ff_, da_ff_;
  VecX r_ff_;
  Eigen::LLT<MatX> llt_;
};

}  // namespace momenta::analysis
