#include "momenta/system/output_set.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <variant>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/dynamics/constraints.hpp"
#include "momenta/dynamics/force_elements.hpp"
#include "momenta/dynamics/point_kinematics.hpp"
#include "momenta/dynamics/reactions.hpp"
#include "momenta/dynamics/relative_kinematics.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta/model/units.hpp"
#include "momenta/system/multibody_system.hpp"

namespace momenta::system {

using model::OutputQuantity;
using model::OutputSpec;

namespace {

// The Euler angles of body `body` seen from `frame`'s (R_FB) in spec.sequence, or their rates
// E⁻¹ w_FB_F; at gimbal lock the rates are undefined and the run stops, saying so.
Vec3 euler_value(const model::Model& model, const dynamics::Data& data,
                 const model::OutputSpec& spec, int body, int frame, double t) {
  const Mat3 R_FB = data.X_WB[frame].R.transpose() * data.X_WB[body].R;
  const Vec3 angles = euler_from_rotation(spec.sequence, R_FB);
  if (spec.quantity == OutputQuantity::body_euler_angles) return angles;
  const Mat3 E = euler_rate_matrix(spec.sequence, angles);
  if (!(std::abs(E.determinant()) > 1e-9)) {
    throw NumericalError(fmt::format(
        "output '{}': the {} Euler angles of body '{}' are at gimbal lock at t = {:.9g} s (middle "
        "angle {:.9g} rad): their rates are not defined there. Choose another sequence, or "
        "record angular_velocity",
        spec.name, spec.sequence, model.body(body).name, t, angles[1]));
  }
  return E.partialPivLu().solve(dynamics::relative_rotation(model, data, body, frame).w_FB_F);
}

bool is_vector(OutputQuantity quantity) {
  const model::OutputTargetKind kind = model::output_target_kind(quantity);
  return (kind == model::OutputTargetKind::body && !model::is_euler_quantity(quantity)) ||
         quantity == OutputQuantity::reaction_force || quantity == OutputQuantity::reaction_moment;
}

// Names of the model's items of one kind, for did-you-mean suggestions.
std::vector<std::string_view> candidate_names(const model::Model& model,
                                              model::OutputTargetKind kind) {
  std::vector<std::string_view> names;
  switch (kind) {
    case model::OutputTargetKind::joint:
      for (const model::Joint& j : model.joints()) names.push_back(j.name);
      break;
    case model::OutputTargetKind::body:
      for (const model::Body& b : model.bodies()) names.push_back(b.name);
      break;
    case model::OutputTargetKind::signal:
      for (const model::Signal& s : model.signals()) names.push_back(s.name());
      break;
    case model::OutputTargetKind::force_element:
      for (const model::ForceElement& e : model.force_elements())
        names.push_back(model::force_element_name(e));
      break;
    case model::OutputTargetKind::constraint:
      for (const model::Constraint& c : model.constraints())
        names.push_back(model::constraint_name(c));
      break;
  }
  return names;
}

// Index of the target, or a message naming the output and the nearest name.
int resolve_target(const model::Model& model, const OutputSpec& spec,
                   model::OutputTargetKind kind) {
  const std::vector<std::string_view> names = candidate_names(model, kind);
  const auto it = std::find(names.begin(), names.end(), spec.target);
  if (it != names.end()) return static_cast<int>(it - names.begin());
  throw InvalidArgument(fmt::format(
      "output '{}': {} of unknown {} '{}'{}", spec.name, model::output_quantity_name(spec.quantity),
      model::output_target_kind_name(kind), spec.target, did_you_mean(spec.target, names)));
}

// Position and velocity of the point p_BoP_B of body b, in W, after forward_kinematics(q, v).
void point_motion(const dynamics::Data& data, int b, const Vec3& p_BoP_B, Vec3& p_WoP_W,
                  Vec3& v_WP_W) {
  const Transform& X = data.X_WB[b];
  const Vec6& V = data.V_WB_B[b];
  p_WoP_W = X.apply(p_BoP_B);
  v_WP_W = X.R * (V.tail<3>() + V.head<3>().cross(p_BoP_B));
}

// The point quantity an output asks for, from P's motion seen in its frame (the world by
// default, where the relative terms are the absolute motion).
Vec3 point_quantity(OutputQuantity quantity, const dynamics::RelativeKinematics& k) {
  switch (quantity) {
    case OutputQuantity::body_position:
      return k.p_FoP_F;
    case OutputQuantity::body_velocity:
      return k.v_relative;
    case OutputQuantity::body_acceleration:
      return k.a_relative;
    case OutputQuantity::transport_velocity:
      return k.v_transport();
    case OutputQuantity::transport_acceleration:
      return k.a_transport();
    case OutputQuantity::coriolis_acceleration:
      return k.a_coriolis;
    case OutputQuantity::centripetal_acceleration:
      return k.a_centripetal;
    case OutputQuantity::euler_acceleration:
      return k.a_euler;
    default:
      return Vec3::Zero();
  }
}

}  // namespace

OutputSet::OutputSet(const model::Model& model, std::vector<OutputSpec> specs)
    : specs_(std::move(specs)), nq_(model.nq()), nv_(model.nv()) {
  static constexpr std::array<const char*, 3> kAxes = {"x", "y", "z"};
  std::set<std::string, std::less<>> seen;
  for (int s = 0; s < static_cast<int>(specs_.size()); ++s) {
    const OutputSpec& spec = specs_[s];
    const std::string_view quantity = model::output_quantity_name(spec.quantity);
    if (spec.name.empty()) {
      throw InvalidArgument(
          fmt::format("output {} ({} of '{}'): the name is empty", s, quantity, spec.target));
    }
    const model::OutputTargetKind kind = model::output_target_kind(spec.quantity);
    const int index = resolve_target(model, spec, kind);
    if (kind != model::OutputTargetKind::body && !spec.point.isZero(0.0)) {
      throw InvalidArgument(fmt::format(
          "output '{}': a point [{}, {}, {}] applies only to body quantities, not to the {} of {} "
          "'{}'",
          spec.name, spec.point.x(), spec.point.y(), spec.point.z(), quantity,
          model::output_target_kind_name(kind), spec.target));
    }
    int frame = 0;  // the world
    if (!spec.relative_to.empty()) {
      if (kind != model::OutputTargetKind::body) {
        throw InvalidArgument(fmt::format(
            "output '{}': frame '{}' applies only to body quantities, not to the {} of {} '{}'",
            spec.name, spec.relative_to, quantity, model::output_target_kind_name(kind),
            spec.target));
      }
      const std::optional<int> f = model.find_body(spec.relative_to);
      if (!f) {
        throw InvalidArgument(fmt::format(
            "output '{}': frame of unknown body '{}'{}", spec.name, spec.relative_to,
            did_you_mean(spec.relative_to, candidate_names(model, model::OutputTargetKind::body))));
      }
      frame = *f;
    } else if (model::is_rotating_frame_term(spec.quantity)) {
      throw InvalidArgument(fmt::format(
          "output '{}': the {} is a term of the motion seen from a moving frame; name the body "
          "whose frame that is (OutputSpec::relative_to, 'frame:' in a model file)",
          spec.name, quantity));
    }
    if (!spec.point.allFinite()) {
      throw InvalidArgument(fmt::format("output '{}': the point [{}, {}, {}] is not finite",
                                        spec.name, spec.point.x(), spec.point.y(), spec.point.z()));
    }

    // How many values the quantity has, and how its columns are suffixed.
    int count = 1;
    bool by_axis = false;
    std::vector<std::string_view> labels;  // a constraint's force labels
    if (kind == model::OutputTargetKind::constraint) {
      labels = model::constraint_force_labels(model.constraints()[index]);
      count = static_cast<int>(labels.size());
    } else if (is_vector(spec.quantity)) {
      count = 3;
      by_axis = true;
    } else if (model::is_euler_quantity(spec.quantity)) {
      count = 3;  // suffixed .0 .1 .2, in the sequence's order
      check_euler_sequence(spec.sequence);
    } else if (kind == model::OutputTargetKind::joint) {
      const model::Joint& joint = model.joint(index);
      count = spec.quantity == OutputQuantity::joint_position ? joint.nq() : joint.nv();
      if (count == 0) {
        throw InvalidArgument(fmt::format("output '{}': joint '{}' is {}: it has no coordinates",
                                          spec.name, joint.name,
                                          model::joint_type_name(joint.type)));
      }
    } else if (kind == model::OutputTargetKind::force_element) {
      const model::ForceElement& element = model.force_elements()[index];
      if (!std::holds_alternative<model::LinearSpringDamper>(element) &&
          !std::holds_alternative<model::FixedTendon>(element)) {
        throw InvalidArgument(
            fmt::format("output '{}': {} applies to a linear spring-damper or a tendon, and '{}' "
                        "is neither",
                        spec.name, quantity, spec.target));
      }
    }
    if (spec.component < -1 || spec.component >= count || (count == 1 && spec.component > 0)) {
      throw InvalidArgument(fmt::format(
          "output '{}': component {} is out of range: the {} of '{}' has {} value{}{}", spec.name,
          spec.component, quantity, spec.target, count, count == 1 ? "" : "s",
          count == 1 ? "" : fmt::format(" (components 0 to {})", count - 1)));
    }

    // One column per value, or one for the chosen component.
    const int first = spec.component >= 0 ? spec.component : 0;
    const int last = spec.component >= 0 ? spec.component + 1 : count;
    for (int k = first; k < last; ++k) {
      std::string column = spec.name;
      if (spec.component < 0 && count > 1) {
        column += !labels.empty() ? fmt::format(".{}", labels[k])
                  : by_axis       ? fmt::format(".{}", kAxes[k])
                                  : fmt::format(".{}", k);
      }
      if (!seen.insert(column).second) {
        throw InvalidArgument(fmt::format(
            "output '{}': column '{}' is already taken by another output", spec.name, column));
      }
      columns_.push_back(std::move(column));
      units_.push_back(model::output_unit(model, spec.quantity, index, k));
      resolved_.push_back({s, index, k, frame});
    }
    needs_reactions_ = needs_reactions_ || spec.quantity == OutputQuantity::reaction_force ||
                       spec.quantity == OutputQuantity::reaction_moment;
  }
  q_.resize(nq_);
  v_.resize(nv_);
  vdot_.resize(nv_);
}

void OutputSet::evaluate(MultibodySystem& system, double t, const VecX& q, const VecX& v,
                         std::span<double> values) const {
  if (values.size() != columns_.size()) {
    throw InvalidArgument(fmt::format("OutputSet::evaluate: {} values for {} columns",
                                      values.size(), columns_.size()));
  }
  const model::Model& model = system.model();
  system.evaluate(t, q, v);
  const dynamics::Data& data = system.data();
  const VecX& tau_elements = system.element_forces();

  // Every column but the reactions, from what evaluate() left in data.
  for (std::size_t c = 0; c < resolved_.size(); ++c) {
    const Column& column = resolved_[c];
    const OutputSpec& spec = specs_[column.spec];
    const int k = column.component;
    double& out = values[c];
    switch (spec.quantity) {
      case OutputQuantity::joint_position: {
        const model::Joint& joint = model.joint(column.index);
        out = system.evaluated_q()[joint.q_index + k];
        break;
      }
      case OutputQuantity::joint_velocity: {
        const model::Joint& joint = model.joint(column.index);
        out = system.evaluated_v()[joint.v_index + k];
        break;
      }
      case OutputQuantity::joint_effort: {
        // A prescribed joint's data.tau is everything it transmits along its motion (what the
        // prescription needs); a free joint's is what the force elements apply.
        const model::Joint& joint = model.joint(column.index);
        const int i = joint.v_index + k;
        out = joint.is_prescribed() ? data.tau[i] : tau_elements[i];
        break;
      }
      case OutputQuantity::body_position:
      case OutputQuantity::body_velocity:
      case OutputQuantity::body_acceleration:
      case OutputQuantity::transport_velocity:
      case OutputQuantity::transport_acceleration:
      case OutputQuantity::coriolis_acceleration:
      case OutputQuantity::centripetal_acceleration:
      case OutputQuantity::euler_acceleration:
        out = point_quantity(
            spec.quantity,
            dynamics::relative_kinematics(model, data, column.index, spec.point, column.frame))[k];
        break;
      case OutputQuantity::body_angular_velocity:
      case OutputQuantity::body_angular_acceleration: {
        const dynamics::RelativeRotation r =
            dynamics::relative_rotation(model, data, column.index, column.frame);
        out = (spec.quantity == OutputQuantity::body_angular_velocity ? r.w_FB_F : r.alpha_FB_F)[k];
        break;
      }
      case OutputQuantity::body_euler_angles:
      case OutputQuantity::body_euler_rates:
        out = euler_value(model, data, spec, column.index, column.frame, t)[k];
        break;
      case OutputQuantity::signal:
        out = system.signal_samples()[column.index].value;
        break;
      case OutputQuantity::spring_length:
      case OutputQuantity::spring_tension: {
        const model::ForceElement& element = model.force_elements()[column.index];
        if (const auto* tendon = std::get_if<model::FixedTendon>(&element)) {
          const VecX& q_now = system.evaluated_q();
          const double length = dynamics::tendon_length(model, *tendon, q_now);
          out = spec.quantity == OutputQuantity::spring_length
                    ? length
                    : tendon->stiffness * (length - tendon->rest_length) +
                          tendon->damping *
                              dynamics::tendon_rate(model, *tendon, system.evaluated_v());
          break;
        }
        const auto& spring = std::get<model::LinearSpringDamper>(element);
        Vec3 p_a, v_a, p_b, v_b;
        point_motion(data, spring.a.body_index, spring.a.p_BoP_B, p_a, v_a);
        point_motion(data, spring.b.body_index, spring.b.p_BoP_B, p_b, v_b);
        const Vec3 d = p_b - p_a;
        const double length = d.norm();
        if (spec.quantity == OutputQuantity::spring_length) {
          out = length;
        } else {
          // ℓ̇ = d·ḋ/ℓ; at ℓ = 0 the direction is undefined and the damper carries nothing.
          const double rate = length > 0.0 ? d.dot(v_b - v_a) / length : 0.0;
          out = spring.stiffness * (length - spring.free_length) + spring.damping * rate;
        }
        break;
      }
      case OutputQuantity::constraint_force: {
        const ConstraintSolver& solver = *system.constraints();
        std::array<double, 6> forces{};
        dynamics::constraint_forces(model, data, solver.rows(), solver.multipliers(), column.index,
                                    forces);
        out = forces[k];
        break;
      }
      case OutputQuantity::reaction_force:
      case OutputQuantity::reaction_moment:
        break;  // below
    }
  }
  if (!needs_reactions_) return;

  // Reactions: Newton–Euler on each subtree for the motion evaluate() found, at the state with
  // the prescribed coordinates applied (evaluate() applied them to its own copy).
  q_ = q;
  v_ = v;
  system.apply_prescribed_motion(t, q_, v_);
  vdot_ = system.data().vdot;
  dynamics::joint_reactions(model, system.data(), q_, v_, vdot_, system.external_wrenches());
  for (std::size_t c = 0; c < resolved_.size(); ++c) {
    const Column& column = resolved_[c];
    const OutputSpec& spec = specs_[column.spec];
    if (spec.quantity != OutputQuantity::reaction_force &&
        spec.quantity != OutputQuantity::reaction_moment)
      continue;
    const dynamics::JointReaction r =
        dynamics::joint_reaction(model, system.data(), column.index, spec.frame);
    values[c] =
        (spec.quantity == OutputQuantity::reaction_force ? r.force : r.moment)[column.component];
  }
}

}  // namespace momenta::system
