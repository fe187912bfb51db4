#include "momenta/model/model.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/math/lie_group.hpp"
#include "momenta/math/rotation.hpp"

namespace momenta::model {
namespace {

template <class Items, class NameOf>
std::optional<int> find_by_name(const Items& items, std::string_view name, NameOf name_of) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (name_of(items[i]) == name) return static_cast<int>(i);
  }
  return std::nullopt;
}

template <class Items, class NameOf>
int index_or_throw(const Items& items, std::string_view name, NameOf name_of,
                   std::string_view what) {
  if (auto i = find_by_name(items, name, name_of)) return *i;
  std::vector<std::string_view> names;
  names.reserve(items.size());
  for (const auto& item : items) names.push_back(name_of(item));
  throw InvalidArgument(
      fmt::format("the model has no {} named '{}'{}", what, name, did_you_mean(name, names)));
}

// The quaternion stored at q[i..i+4), as [w, x, y, z].
Quat quaternion_at(const VecX& q, int i) { return Quat(q[i], q[i + 1], q[i + 2], q[i + 3]); }

void store_quaternion(const Quat& r, VecX& q, int i) {
  q[i] = r.w();
  q[i + 1] = r.x();
  q[i + 2] = r.y();
  q[i + 3] = r.z();
}

// Offset of the quaternion in a joint's q, and of its angular velocity in v; −1 without one.
int quaternion_offset(JointType type) {
  if (type == JointType::spherical) return 0;
  if (type == JointType::free) return 3;
  return -1;
}

}  // namespace

Model Model::with_initial_state(const VecX& q, const VecX& v) const {
  if (q.size() != nq_ || v.size() != nv_) {
    throw InvalidArgument(
        fmt::format("an initial state of {} coordinates and {} speeds for a model of {} and {}",
                    q.size(), v.size(), nq_, nv_));
  }
  for (int i = 0; i < nq_; ++i) {
    if (!std::isfinite(q[i])) {
      throw InvalidArgument(fmt::format("initial coordinate {} is {}", q_names_[i], q[i]));
    }
  }
  for (int i = 0; i < nv_; ++i) {
    if (!std::isfinite(v[i])) {
      throw InvalidArgument(fmt::format("initial speed {} is {}", v_names_[i], v[i]));
    }
  }
  Model model = *this;
  model.q0_ = q;
  model.v0_ = v;
  return model;
}

Model Model::with_signal_shape(int s, Signal::Shape shape) const {
  if (s < 0 || s >= static_cast<int>(signals_.size())) {
    throw InvalidArgument(fmt::format("signal {} of a model with {} signals", s, signals_.size()));
  }
  Model model = *this;
  model.signals_[static_cast<std::size_t>(s)] =
      Signal(signals_[static_cast<std::size_t>(s)].name(), std::move(shape));
  return model;
}

Model Model::with_controller(const Controller& controller) const {
  ResolvedController r = resolve_controller(controller, *this);
  check_controller_fits(r, *this);
  Model model = *this;
  model.controllers_.push_back(std::move(r));
  return model;
}

std::optional<int> Model::find_body(std::string_view name) const {
  return find_by_name(bodies_, name, [](const Body& b) -> std::string_view { return b.name; });
}
std::optional<int> Model::find_joint(std::string_view name) const {
  return find_by_name(joints_, name, [](const Joint& j) -> std::string_view { return j.name; });
}
bool Model::is_driven(int s) const {
  for (const ResolvedController& c : controllers_) {
    for (int d : c.drives) {
      if (d == s) return true;
    }
  }
  return false;
}
std::optional<int> Model::joint_prescribed_by(int s) const {
  for (int j = 0; j < static_cast<int>(joints_.size()); ++j) {
    for (int p : joints_[static_cast<std::size_t>(j)].prescribed_signal_indices) {
      if (p == s) return j;
    }
  }
  return std::nullopt;
}
std::optional<Model::Coordinate> Model::prescribed_coordinate(int s) const {
  const std::optional<int> j = joint_prescribed_by(s);
  if (!j) return std::nullopt;
  const Joint& joint = joints_[static_cast<std::size_t>(*j)];
  if (joint.type == JointType::spherical || joint.type == JointType::free) return std::nullopt;
  const auto& signals = joint.prescribed_signal_indices;
  const auto k = static_cast<int>(std::find(signals.begin(), signals.end(), s) - signals.begin());
  return Coordinate{joint.q_index + k, joint.v_index + k};
}

std::optional<int> Model::find_signal(std::string_view name) const {
  return find_by_name(signals_, name, [](const Signal& s) -> std::string_view { return s.name(); });
}
std::optional<int> Model::find_constraint(std::string_view name) const {
  return find_by_name(constraints_, name,
                      [](const Constraint& c) -> std::string_view { return constraint_name(c); });
}
int Model::body_index(std::string_view name) const {
  return index_or_throw(
      bodies_, name, [](const Body& b) -> std::string_view { return b.name; }, "body");
}
int Model::joint_index(std::string_view name) const {
  return index_or_throw(
      joints_, name, [](const Joint& j) -> std::string_view { return j.name; }, "joint");
}
int Model::signal_index(std::string_view name) const {
  return index_or_throw(
      signals_, name, [](const Signal& s) -> std::string_view { return s.name(); }, "signal");
}

VecX neutral(const Model& model) {
  VecX q = VecX::Zero(model.nq());
  for (const Joint& joint : model.joints()) {
    const int k = quaternion_offset(joint.type);
    if (k >= 0) q[joint.q_index + k] = 1.0;
  }
  return q;
}

void integrate(const Model& model, const VecX& q, const VecX& v, double dt, VecX& q_out) {
  if (&q_out != &q) q_out.resize(model.nq());
  for (const Joint& joint : model.joints()) {
    const int iq = joint.q_index;
    const int iv = joint.v_index;
    switch (joint.type) {
      case JointType::fixed:
        break;
      case JointType::spherical:
        // Right multiplication: ω is in the child frame J'.
        store_quaternion(quaternion_at(q, iq) * quaternion_exp(v.segment<3>(iv) * dt), q_out, iq);
        break;
      case JointType::free:
        q_out.segment<3>(iq) = q.segment<3>(iq) + v.segment<3>(iv + 3) * dt;
        store_quaternion(quaternion_at(q, iq + 3) * quaternion_exp(v.segment<3>(iv) * dt), q_out,
                         iq + 3);
        break;
      case JointType::revolute:
      case JointType::prismatic:
      case JointType::cylindrical:
      case JointType::universal:
      case JointType::planar:
        q_out.segment(iq, joint.nq()) = q.segment(iq, joint.nq()) + v.segment(iv, joint.nv()) * dt;
        break;
    }
  }
}

VecX integrate(const Model& model, const VecX& q, const VecX& v, double dt) {
  VecX out(model.nq());
  integrate(model, q, v, dt, out);
  return out;
}

void difference(const Model& model, const VecX& q0, const VecX& q1, VecX& d) {
  d.resize(model.nv());
  for (const Joint& joint : model.joints()) {
    const int iq = joint.q_index;
    const int iv = joint.v_index;
    switch (joint.type) {
      case JointType::fixed:
        break;
      case JointType::spherical:
        d.segment<3>(iv) =
            quaternion_log(quaternion_at(q0, iq).conjugate() * quaternion_at(q1, iq));
        break;
      case JointType::free:
        d.segment<3>(iv) =
            quaternion_log(quaternion_at(q0, iq + 3).conjugate() * quaternion_at(q1, iq + 3));
        d.segment<3>(iv + 3) = q1.segment<3>(iq) - q0.segment<3>(iq);
        break;
      case JointType::revolute:
      case JointType::prismatic:
      case JointType::cylindrical:
      case JointType::universal:
      case JointType::planar:
        d.segment(iv, joint.nv()) = q1.segment(iq, joint.nq()) - q0.segment(iq, joint.nq());
        break;
    }
  }
}

VecX difference(const Model& model, const VecX& q0, const VecX& q1) {
  VecX d(model.nv());
  difference(model, q0, q1, d);
  return d;
}

void configuration_rate(const Model& model, const VecX& q, const VecX& v, VecX& qdot) {
  qdot.resize(model.nq());
  for (const Joint& joint : model.joints()) {
    const int iq = joint.q_index;
    const int iv = joint.v_index;
    const int k = quaternion_offset(joint.type);
    if (k < 0) {
      qdot.segment(iq, joint.nq()) = v.segment(iv, joint.nv());
      continue;
    }
    if (joint.type == JointType::free) qdot.segment<3>(iq) = v.segment<3>(iv + 3);
    // q̇ = ½ q ⊗ [0; ω].
    const Quat rate = quaternion_at(q, iq + k) * Quat(0.0, v[iv], v[iv + 1], v[iv + 2]);
    store_quaternion(Quat(0.5 * rate.coeffs()), qdot, iq + k);
  }
}

void local_coordinate_rate(const Model& model, const VecX& delta, const VecX& v, VecX& delta_rate) {
  delta_rate = v;
  for (const Joint& joint : model.joints()) {
    if (quaternion_offset(joint.type) < 0) continue;
    const int iv = joint.v_index;
    delta_rate.segment<3>(iv) = so3_right_jacobian_inverse(delta.segment<3>(iv)) * v.segment<3>(iv);
  }
}

void normalize(const Model& model, VecX& q) {
  for (const Joint& joint : model.joints()) {
    const int k = quaternion_offset(joint.type);
    if (k < 0) continue;
    auto quat = q.segment<4>(joint.q_index + k);
    const double n = quat.norm();
    if (!(n > 0) || !std::isfinite(n)) {
      throw NumericalError(
          fmt::format("joint '{}': quaternion [{}, {}, {}, {}] cannot be normalized", joint.name,
                      quat[0], quat[1], quat[2], quat[3]));
    }
    quat /= n;
  }
}

void check_state_sizes(const Model& model, const VecX& q, const VecX& v, std::string_view what) {
  if (q.size() != model.nq() || v.size() != model.nv()) {
    throw InvalidArgument(
        fmt::format("{}: q has size {} and v size {}; the model needs nq = {}, nv = {}", what,
                    q.size(), v.size(), model.nq(), model.nv()));
  }
}

const std::string& force_element_name(const ForceElement& element) {
  return std::visit([](const auto& e) -> const std::string& { return e.name; }, element);
}

}  // namespace momenta::model
