#include "model_residual.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/force_element_derivatives.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta/dynamics/rnea_derivatives.hpp"

namespace momenta::analysis::detail {

ModelResidual::ModelResidual(const model::Model& model)
    : model_(model),
      system_(model),
      data_(model),
      offset_value_(model.signals().size(), 0.0),
      offset_rate_(model.signals().size(), 0.0),
      offset_acceleration_(model.signals().size(), 0.0),
      q_(model.nq()),
      v_(model.nv()),
      vdot_(model.nv()) {
  for (const model::Joint& j : model.joints()) {
    if (j.is_prescribed()) continue;
    for (int k = 0; k < j.nv(); ++k) free_.push_back(j.v_index + k);
  }
  // With nothing free there is no state to linearize or balance.
  if (free_.empty()) {
    throw InvalidArgument(OptionMessage{
        "the model has no degree of freedom to linearize or balance: every joint is fixed or "
        "prescribed (a prescribed joint's motion is an input, not a state). Simulate it instead, "
        "with ‹reactions›, to see the loads its motion needs"});
  }
}

void ModelResidual::set_offset(int signal, double value, double rate, double acceleration) {
  clear_offsets();
  offset_value_[static_cast<std::size_t>(signal)] = value;
  offset_rate_[static_cast<std::size_t>(signal)] = rate;
  offset_acceleration_[static_cast<std::size_t>(signal)] = acceleration;
  system_.set_signal_offsets(offset_value_, offset_rate_, offset_acceleration_);
}

void ModelResidual::clear_offsets() {
  std::fill(offset_value_.begin(), offset_value_.end(), 0.0);
  std::fill(offset_rate_.begin(), offset_rate_.end(), 0.0);
  std::fill(offset_acceleration_.begin(), offset_acceleration_.end(), 0.0);
  system_.set_signal_offsets(offset_value_, offset_rate_, offset_acceleration_);
}

void ModelResidual::residual(double t, const VecX& q, const VecX& v, const VecX& a_free, VecX& r) {
  // The force elements at (t, q, v) with the signals' offsets; the evaluation also leaves the
  // prescribed accelerations in data().vdot.
  system_.evaluate(t, q, v);

  // The state with prescribed coordinates from their (offset) signals; free accelerations given.
  q_ = q;
  v_ = v;
  system_.apply_prescribed_motion(t, q_, v_);
  vdot_ = system_.data().vdot;
  for (int k = 0; k < nf(); ++k) vdot_[free_[static_cast<std::size_t>(k)]] = a_free[k];

  // Inverse dynamics with the elements' body wrenches, minus their joint forces.
  const VecX& tau = dynamics::rnea(model_, data_, q_, v_, vdot_, system_.external_wrenches());
  const VecX& tau_elements = system_.element_forces();
  r.resize(nf());
  for (int k = 0; k < nf(); ++k) {
    const int i = free_[static_cast<std::size_t>(k)];
    r[k] = tau[i] - tau_elements[i];
  }
}

void ModelResidual::residual_and_scale(double t, const VecX& q, const VecX& v, const VecX& a_free,
                                       VecX& r, double& scale) {
  residual(t, q, v, a_free, r);
  // What r sums: rnea without the elements (gravity and inertia), and the elements' share, which
  // is the difference between that and r.
  const VecX& tau_plain = dynamics::rnea(model_, data_, q_, v_, vdot_);
  double plain = 0.0, elements = 0.0;
  for (int k = 0; k < nf(); ++k) {
    const int i = free_[static_cast<std::size_t>(k)];
    plain = std::max(plain, std::abs(tau_plain[i]));
    elements = std::max(elements, std::abs(tau_plain[i] - r[k]));
  }
  scale = plain + elements;
}

void ModelResidual::derivatives(double t, const VecX& q, const VecX& v, const VecX& a_free,
                                MatX& dr_dq, MatX& dr_dv) {
  // The state and accelerations residual() differentiates, and the signals' values there.
  residual(t, q, v, a_free, r_);
  signal_values_.clear();
  for (const model::SignalSample& s : system_.signal_samples()) signal_values_.push_back(s.value);

  // r = ID(q, v, v̇) − Q(q, v): inverse dynamics without the elements, less the elements' force.
  dynamics::rnea_derivatives(model_, data_, q_, v_, vdot_);
  dynamics::force_element_derivatives(model_, data_, signal_values_);
  dr_dq_all_.resize(nf(), model_.nv());
  dr_dq.resize(nf(), nf());
  dr_dv.resize(nf(), nf());
  for (int a = 0; a < nf(); ++a) {
    const int i = free_[static_cast<std::size_t>(a)];
    for (int j = 0; j < model_.nv(); ++j)
      dr_dq_all_(a, j) = data_.dtau_dq(i, j) - data_.dQ_dq(i, j);
    for (int b = 0; b < nf(); ++b) {
      const int j = free_[static_cast<std::size_t>(b)];
      dr_dq(a, b) = dr_dq_all_(a, j);
      dr_dv(a, b) = data_.dtau_dv(i, j) - data_.dQ_dv(i, j);
    }
  }
}

void ModelResidual::constraint_derivatives(const VecX& lambda,
                                           dynamics::ConstraintDerivatives& out) {
  dynamics::constraint_derivatives(model_, data_, q_, v_, vdot_, lambda, out);
}

MatX ModelResidual::free_mass(double t, const VecX& q) {
  q_ = q;
  v_.setZero();
  system_.apply_prescribed_motion(t, q_, v_);
  const MatX& M = dynamics::crba(model_, data_, q_);
  MatX M_ff(nf(), nf());
  for (int a = 0; a < nf(); ++a)
    for (int b = 0; b < nf(); ++b)
      M_ff(a, b) = M(free_[static_cast<std::size_t>(a)], free_[static_cast<std::size_t>(b)]);
  return M_ff;
}

bool is_angle_coordinate(const model::Model& model, int i) {
  const model::Joint& j = model.joint(model.joint_of_v(i));
  return model::is_rotation_rate(j.type, i - j.v_index);
}

void displace(const model::Model& model, const VecX& q, int i, double s, VecX& tangent,
              VecX& q_out) {
  tangent.setZero(model.nv());
  tangent[i] = s;
  model::integrate(model, q, tangent, 1.0, q_out);
}

VecX checked_configuration(const model::Model& model, const VecX& q, const VecX& v,
                           const std::string& what) {
  model::check_state_sizes(model, q, v, what);
  if (!q.allFinite() || !v.allFinite()) {
    throw InvalidArgument(fmt::format("{}: q or v has a non-finite entry", what));
  }
  for (const model::Joint& j : model.joints()) {
    int offset = -1;
    if (j.type == model::JointType::spherical) offset = 0;
    if (j.type == model::JointType::free) offset = 3;
    if (offset < 0) continue;
    const double norm = q.segment<4>(j.q_index + offset).norm();
    if (std::abs(norm - 1.0) > 1e-6) {
      throw InvalidArgument(fmt::format(
          "{}: joint '{}' quaternion (q[{}..{}]) has norm {:.9g}; it must be unit (to 1e-6)", what,
          j.name, j.q_index + offset, j.q_index + offset + 3, norm));
    }
  }
  VecX q_unit = q;
  model::normalize(model, q_unit);
  return q_unit;
}

}  // namespace momenta::analysis::detail
