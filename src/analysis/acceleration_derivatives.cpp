#include "momenta/analysis/acceleration_derivatives.hpp"

#include <cstddef>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/force_element_derivatives.hpp"
#include "momenta/dynamics/rnea_derivatives.hpp"

namespace momenta::analysis {

AccelerationDerivatives::AccelerationDerivatives(const model::Model& model)
    : model_(model), data_(model) {
  if (model.has_constraints()) {
    throw InvalidArgument(
        "acceleration derivatives of a model with constraints: its multipliers depend on the "
        "state too (linearize() takes them into account)");
  }
  if (model.has_controllers()) {
    throw InvalidArgument(
        "acceleration derivatives of a model with controllers: their states are not the "
        "model's (linearize() closes the loops)");
  }
  for (int i = 0; i < model.nv(); ++i) {
    if (!model.joint(model.joint_of_v(i)).is_prescribed()) free_.push_back(i);
  }
  const auto nf = static_cast<Eigen::Index>(free_.size());
  signal_values_.resize(model.signals().size());
  mass_ff_.resize(nf, nf);
  dr_dq_ff_.resize(nf, nf);
  dr_dv_ff_.resize(nf, nf);
  da_ff_.resize(nf, nf);
  r_ff_.resize(nf);
  // llt_ sizes itself on the first compute() (Eigen's LLT(n) leaves its status unset).
}

void AccelerationDerivatives::compute(const system::MultibodySystem& system, MatX& da_dq,
                                      MatX& da_dv) {
  const auto samples = system.signal_samples();
  for (std::size_t s = 0; s < signal_values_.size(); ++s) signal_values_[s] = samples[s].value;

  // r = ID(q, v, v̇) − Q(q, v): inverse dynamics without the elements, less their force.
  const VecX& vdot = system.data().vdot;
  dynamics::rnea_derivatives(model_, data_, system.evaluated_q(), system.evaluated_v(), vdot);
  dynamics::force_element_derivatives(model_, data_, signal_values_);
  const auto nf = static_cast<Eigen::Index>(free_.size());
  for (Eigen::Index a = 0; a < nf; ++a) {
    const int i = free_[static_cast<std::size_t>(a)];
    for (Eigen::Index b = 0; b < nf; ++b) {
      const int j = free_[static_cast<std::size_t>(b)];
      mass_ff_(a, b) = data_.M(i, j);
      dr_dq_ff_(a, b) = data_.dtau_dq(i, j) - data_.dQ_dq(i, j);
      dr_dv_ff_(a, b) = data_.dtau_dv(i, j) - data_.dQ_dv(i, j);
    }
  }
  llt_.compute(mass_ff_);
  if (llt_.info() != Eigen::Success) {
    throw NumericalError(
        "acceleration derivatives: the free coordinates' mass matrix is not positive definite");
  }

  da_dq.setZero();
  da_dv.setZero();
  da_ff_ = llt_.solve(dr_dq_ff_);
  for (Eigen::Index a = 0; a < nf; ++a) {
    for (Eigen::Index b = 0; b < nf; ++b) {
      da_dq(free_[static_cast<std::size_t>(a)], free_[static_cast<std::size_t>(b)]) = -da_ff_(a, b);
    }
  }
  da_ff_ = llt_.solve(dr_dv_ff_);
  for (Eigen::Index a = 0; a < nf; ++a) {
    for (Eigen::Index b = 0; b < nf; ++b) {
      da_dv(free_[static_cast<std::size_t>(a)], free_[static_cast<std::size_t>(b)]) = -da_ff_(a, b);
    }
  }
}

void AccelerationDerivatives::acceleration_change(const VecX& r, VecX& da) {
  const auto nf = static_cast<Eigen::Index>(free_.size());
  for (Eigen::Index a = 0; a < nf; ++a) r_ff_[a] = r[free_[static_cast<std::size_t>(a)]];
  llt_.solveInPlace(r_ff_);
  da.setZero();
  for (Eigen::Index a = 0; a < nf; ++a) da[free_[static_cast<std::size_t>(a)]] = -r_ff_[a];
}

}  // namespace momenta::analysis
