#include "momenta/model/units.hpp"

#include <cmath>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace momenta::model {
namespace {

// The joint whose coordinates include index i of q (configuration) or of v (velocity).
const Joint* joint_of(const Model& model, int i, bool velocity) {
  for (const Joint& j : model.joints()) {
    const int first = velocity ? j.v_index : j.q_index;
    const int count = velocity ? j.nv() : j.nq();
    if (i >= first && i < first + count) return &j;
  }
  return nullptr;
}

// A unit's factors with their exponents, in the order written: "N·m/rad" → N 1, m 1, rad −1;
// "kg·m²" → kg 1, m 2; "N/(m·s)" → N 1, m −1, s −1.
using Factors = std::vector<std::pair<std::string, int>>;

void add_factor(Factors& factors, std::string_view name, int exponent) {
  for (auto& [factor, power] : factors) {
    if (factor == name) {
      power += exponent;
      return;
    }
  }
  factors.emplace_back(std::string(name), exponent);
}

Factors factors_of(std::string_view unit, int sign = 1) {
  Factors factors;
  if (unit.empty() || unit == "1") return factors;
  int side = sign;  // the numerator's sign until the first '/'
  std::string name;
  const auto flush = [&] {
    int exponent = 1;
    for (const auto& [mark, power] : {std::pair<std::string_view, int>{"²", 2}, {"³", 3}}) {
      if (name.size() > mark.size() && name.ends_with(mark)) {
        name.resize(name.size() - mark.size());
        exponent = power;
      }
    }
    if (!name.empty() && name != "1") add_factor(factors, name, side * exponent);
    name.clear();
  };
  for (std::size_t k = 0; k < unit.size(); ++k) {
    if (unit.substr(k).starts_with("·")) {
      flush();
      k += std::string_view("·").size() - 1;
    } else if (unit[k] == '/') {
      flush();
      side = -sign;
    } else if (unit[k] != '(' && unit[k] != ')') {
      name += unit[k];
    }
  }
  flush();
  return factors;
}

std::string written(const Factors& factors, int sign) {
  std::vector<std::string> parts;
  for (const auto& [name, power] : factors) {
    const int p = sign * power;
    if (p <= 0) continue;
    parts.push_back(name + (p == 2 ? "²" : p == 3 ? "³" : p == 1 ? "" : "^" + std::to_string(p)));
  }
  std::string text;
  for (const std::string& part : parts) text += (text.empty() ? "" : "·") + part;
  return parts.size() > 1 && sign < 0 ? "(" + text + ")" : text;
}

}  // namespace

std::string unit_ratio(const std::string& numerator, const std::string& denominator) {
  Factors factors = factors_of(numerator);
  for (const auto& [name, power] : factors_of(denominator, -1)) add_factor(factors, name, power);
  const std::string above = written(factors, 1), below = written(factors, -1);
  if (below.empty()) return above.empty() ? "1" : above;
  return (above.empty() ? "1" : above) + "/" + below;
}

std::string q_unit(const Model& model, int i) {
  const Joint* j = joint_of(model, i, false);
  if (j == nullptr) return "";
  return std::string(joint_traits(j->type).q_units[static_cast<std::size_t>(i - j->q_index)]);
}

std::string v_unit(const Model& model, int i) {
  const Joint* j = joint_of(model, i, true);
  if (j == nullptr) return "";
  return std::string(joint_traits(j->type).v_units[static_cast<std::size_t>(i - j->v_index)]);
}

std::string effort_unit(const Model& model, int i) {
  const Joint* j = joint_of(model, i, true);
  if (j == nullptr) return "";
  return is_rotation_rate(j->type, i - j->v_index) ? "N·m" : "N";
}

namespace {
// The unit every speed of the joint has, or "" where they differ or there are none.
std::string common_speed_unit(const Model& model, const Joint& joint) {
  if (joint.nv() == 0) return "";
  const std::string speed = v_unit(model, joint.v_index);
  for (int k = 1; k < joint.nv(); ++k) {
    if (v_unit(model, joint.v_index + k) != speed) return "";
  }
  return speed;
}
}  // namespace

std::string joint_damping_unit(const Model& model, const Joint& joint) {
  const std::string speed = common_speed_unit(model, joint);
  if (speed.empty()) return "";
  return speed == "rad/s" ? "N·m·s/rad" : "N·s/m";
}

std::string joint_armature_unit(const Model& model, const Joint& joint) {
  const std::string speed = common_speed_unit(model, joint);
  if (speed.empty()) return "";
  return speed == "rad/s" ? "kg·m²" : "kg";
}

std::string signal_unit(const Model& model, int signal_index) {
  for (const Joint& j : model.joints()) {
    for (std::size_t k = 0; k < j.prescribed_signal_indices.size(); ++k) {
      if (j.prescribed_signal_indices[k] != signal_index) continue;
      // A spherical or free joint's signals are a rotation vector (rad), then a position (m).
      if (j.type == JointType::spherical || j.type == JointType::free) {
        return k < 3 ? "rad" : "m";
      }
      // Driven by a controller, it commands the coordinate's acceleration (model/controller.hpp).
      const std::string unit = q_unit(model, j.q_index + static_cast<int>(k));
      return model.is_driven(signal_index) && !unit.empty() ? unit + "/s²" : unit;
    }
  }
  for (const ForceElement& element : model.force_elements()) {
    if (const auto* f = std::get_if<AppliedForce>(&element);
        f && f->signal_index == signal_index && std::abs(f->vector.norm() - 1.0) < 1e-12) {
      return "N";
    }
    if (const auto* m = std::get_if<AppliedTorque>(&element);
        m && m->signal_index == signal_index && std::abs(m->vector.norm() - 1.0) < 1e-12) {
      return "N·m";
    }
  }
  // A controller's reference: what it measures.
  for (const ResolvedController& c : model.controllers()) {
    if (c.reference != signal_index || c.measured.empty()) continue;
    const int i = c.measured.front();
    return i < model.nq() ? q_unit(model, i) : v_unit(model, i - model.nq());
  }
  return "";
}

TendonUnits tendon_units(const Model& model, const FixedTendon& tendon) {
  const Joint& first = model.joint(tendon.terms.front().joint_index);
  if (v_unit(model, first.v_index) == "rad/s") {
    return {"rad", "rad/s", "N·m", "N·m/rad", "N·m·s/rad"};
  }
  return {"m", "m/s", "N", "N/m", "N·s/m"};
}

namespace {
// A spring-damper's or a tendon's length or tension.
std::string spring_unit(const Model& model, OutputQuantity quantity, int element) {
  const auto* tendon =
      std::get_if<FixedTendon>(&model.force_elements()[static_cast<std::size_t>(element)]);
  const bool length = quantity == OutputQuantity::spring_length;
  if (tendon == nullptr) return length ? "m" : "N";
  const TendonUnits units = tendon_units(model, *tendon);
  return length ? units.length : units.tension;
}
}  // namespace

std::string output_unit(const Model& model, OutputQuantity quantity, int target, int component) {
  using Q = OutputQuantity;
  switch (quantity) {
    case Q::joint_position:
      return q_unit(model, model.joint(target).q_index + component);
    case Q::joint_velocity:
      return v_unit(model, model.joint(target).v_index + component);
    case Q::joint_effort:
      return effort_unit(model, model.joint(target).v_index + component);
    case Q::spring_length:
    case Q::spring_tension:
      return spring_unit(model, quantity, target);
    case Q::body_position:
      return "m";
    case Q::body_velocity:
    case Q::transport_velocity:
      return "m/s";
    case Q::body_acceleration:
    case Q::transport_acceleration:
    case Q::coriolis_acceleration:
    case Q::centripetal_acceleration:
    case Q::euler_acceleration:
      return "m/s²";
    case Q::body_angular_velocity:
    case Q::body_euler_rates:
      return "rad/s";
    case Q::body_euler_angles:
      return "rad";
    case Q::body_angular_acceleration:
      return "rad/s²";
    case Q::reaction_force:
      return "N";
    case Q::reaction_moment:
      return "N·m";
    case Q::signal:
      return signal_unit(model, target);
    case Q::constraint_force: {
      const Constraint& constraint = model.constraints()[static_cast<std::size_t>(target)];
      const std::string_view label =
          constraint_force_labels(constraint)[static_cast<std::size_t>(component)];
      if (const auto* coupler = std::get_if<JointCoupler>(&constraint)) {
        const Joint& joint =
            model.joint(label == "effort_a" ? coupler->joint_a_index : coupler->joint_b_index);
        return effort_unit(model, joint.v_index);
      }
      return label.starts_with("reaction.M") ? "N·m" : "N";
    }
  }
  return "";
}

}  // namespace momenta::model
