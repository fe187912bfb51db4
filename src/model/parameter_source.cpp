#include "momenta/model/parameter_source.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <variant>
#include <vector>

#include "momenta/common/error.hpp"
#include "momenta/common/number_text.hpp"

namespace momenta::model {
namespace {

using SourceKind = ParameterSource::Kind;

constexpr std::array<std::pair<SourceKind, std::string_view>, 25> kKindNames{{
    {SourceKind::gravity, "gravity"},
    {SourceKind::gravity_direction, "gravity_direction"},
    {SourceKind::body_mass, "body_mass"},
    {SourceKind::body_center_of_mass, "body_center_of_mass"},
    {SourceKind::body_inertia, "body_inertia"},
    {SourceKind::body_shape_size, "body_shape_size"},
    {SourceKind::joint_parent_offset, "joint_parent_offset"},
    {SourceKind::joint_child_offset, "joint_child_offset"},
    {SourceKind::joint_damping, "joint_damping"},
    {SourceKind::joint_armature, "joint_armature"},
    {SourceKind::element_stiffness, "element_stiffness"},
    {SourceKind::element_damping, "element_damping"},
    {SourceKind::element_rest, "element_rest"},
    {SourceKind::element_free_length, "element_free_length"},
    {SourceKind::element_stretch_at_zero, "element_stretch_at_zero"},
    {SourceKind::element_viscous, "element_viscous"},
    {SourceKind::element_offset, "element_offset"},
    {SourceKind::element_coefficient, "element_coefficient"},
    {SourceKind::element_load, "element_load"},
    {SourceKind::element_load_direction, "element_load_direction"},
    {SourceKind::constraint_frame_origin, "constraint_frame_origin"},
    {SourceKind::constraint_length, "constraint_length"},
    {SourceKind::constraint_radius, "constraint_radius"},
    {SourceKind::constraint_ratio, "constraint_ratio"},
    {SourceKind::constraint_offset, "constraint_offset"},
}};

[[noreturn]] void no_such(const ParameterSource& source, std::string_view what) {
  throw InvalidArgument(fmt::format("parameter source {} [{}, {}, {}]: {}",
                                    parameter_source_kind_name(source.kind), source.index,
                                    source.row, source.column, what));
}

int checked(const ParameterSource& source, int index, int count, std::string_view what) {
  if (index < 0 || index >= count) no_such(source, fmt::format("no {} {}", what, index));
  return index;
}

int axis(const ParameterSource& source, int k) { return checked(source, k, 3, "axis"); }

const Body& body_of(const Model& model, const ParameterSource& s) {
  return model.body(checked(s, s.index, model.num_bodies(), "body"));
}

const Joint& joint_of(const Model& model, const ParameterSource& s) {
  return model.joint(checked(s, s.index, model.num_joints(), "joint"));
}

const ForceElement& element_of(const Model& model, const ParameterSource& s) {
  const auto& elements = model.force_elements();
  return elements[static_cast<std::size_t>(
      checked(s, s.index, static_cast<int>(elements.size()), "force element"))];
}

const Constraint& constraint_of(const Model& model, const ParameterSource& s) {
  const auto& constraints = model.constraints();
  return constraints[static_cast<std::size_t>(
      checked(s, s.index, static_cast<int>(constraints.size()), "constraint"))];
}

// The element as the kind it must be for the field asked.
template <class T>
const T& element_as(const Model& model, const ParameterSource& s) {
  const T* element = std::get_if<T>(&element_of(model, s));
  if (element == nullptr) no_such(s, "the force element has no such number");
  return *element;
}

template <class T>
const T& constraint_as(const Model& model, const ParameterSource& s) {
  const T* constraint = std::get_if<T>(&constraint_of(model, s));
  if (constraint == nullptr) no_such(s, "the constraint has no such number");
  return *constraint;
}

// A component of v/|v|; 0 for the zero vector (it has no direction).
double direction(const Vec3& v, int k) {
  const double size = v.norm();
  return size > 0 ? v[k] / size : 0.0;
}

// The centre of mass as the equations show it: round-off of the body's size (the larger of the
// offset and the radius of gyration) is 0.
double center_of_mass(const Body& body, int k) {
  const inertia::MassProperties& mp = body.mass_properties;
  const Mat3& Ic = mp.inertia_about_com();
  const double length =
      std::max(mp.center_of_mass().norm(), std::sqrt(Ic.trace() / (2 * mp.mass())));
  return shown_value(mp.center_of_mass()[k], length);
}

// The moments and products about the centre of mass, round-off of the largest 0.
double inertia_component(const Body& body, int r, int c) {
  const Mat3& Ic = body.mass_properties.inertia_about_com();
  return shown_value(Ic(r, c), Ic.cwiseAbs().maxCoeff());
}

// The bodies' poses in W with every coordinate 0 (a rotation's quaternion as the identity).
std::vector<Transform> poses_at_zero(const Model& model) {
  std::vector<Transform> X_WB(static_cast<std::size_t>(model.num_bodies()));
  std::vector<double> zeros(static_cast<std::size_t>(std::max(model.nq(), 1)), 0.0);
  for (const Joint& j : model.joints()) {
    const bool quaternion = j.type == JointType::spherical || j.type == JointType::free;
    const Transform X_JJ = quaternion ? Transform{} : joint_transform(j, zeros.data());
    X_WB[static_cast<std::size_t>(j.child_index)] =
        X_WB[static_cast<std::size_t>(j.parent_index)] * j.X_PJ * X_JJ * j.X_CJ.inverse();
  }
  return X_WB;
}

// A spring along a line: its length at q = 0, the component along its axis with the sign its
// length has, less its free length.
double stretch_at_zero(const Model& model, const ParameterSource& s) {
  const auto& spring = element_as<LinearSpringDamper>(model, s);
  const std::vector<Transform> X_WB = poses_at_zero(model);
  const auto world_point = [&](const BodyPoint& p) {
    const Transform& X = X_WB[static_cast<std::size_t>(p.body_index)];
    return Vec3(X.p + X.R * p.p_BoP_B);
  };
  const double offsets = s.sign * (world_point(spring.b) - world_point(spring.a))[axis(s, s.row)];
  const double d0 = offsets - spring.free_length;
  const double scale = std::max({1.0, std::abs(offsets), std::abs(spring.free_length)});
  return std::abs(d0) <= 1e-12 * scale ? 0.0 : d0;
}

double element_field(const Model& model, const ParameterSource& s) {
  const ForceElement& element = element_of(model, s);
  const auto field = [&](auto member_of) -> double {
    return std::visit(
        [&](const auto& e) -> double {
          const auto value = member_of(e);
          if (!value) no_such(s, "the force element has no such number");
          return *value;
        },
        element);
  };
  switch (s.kind) {
    case SourceKind::element_stiffness:
      return field([](const auto& e) -> std::optional<double> {
        if constexpr (requires { e.stiffness; }) return e.stiffness;
        return std::nullopt;
      });
    case SourceKind::element_damping:
      return field([](const auto& e) -> std::optional<double> {
        if constexpr (requires { e.damping; }) return e.damping;
        return std::nullopt;
      });
    case SourceKind::element_rest:
      return field([](const auto& e) -> std::optional<double> {
        if constexpr (requires { e.rest_angle; }) return e.rest_angle;
        if constexpr (requires { e.rest_length; }) return e.rest_length;
        return std::nullopt;
      });
    case SourceKind::element_free_length:
      return element_as<LinearSpringDamper>(model, s).free_length;
    case SourceKind::element_stretch_at_zero:
      return stretch_at_zero(model, s);
    case SourceKind::element_viscous:
      return element_as<JointFriction>(model, s).viscous;
    case SourceKind::element_offset:
      return element_as<FixedTendon>(model, s).offset;
    case SourceKind::element_coefficient: {
      const auto& terms = element_as<FixedTendon>(model, s).terms;
      return terms[static_cast<std::size_t>(
                       checked(s, s.row, static_cast<int>(terms.size()), "tendon term"))]
          .coefficient;
    }
    case SourceKind::element_load:
      return field([](const auto& e) -> std::optional<double> {
        if constexpr (requires { e.vector; }) return e.vector.norm();
        return std::nullopt;
      });
    case SourceKind::element_load_direction: {
      const int k = axis(s, s.row);
      return field([k](const auto& e) -> std::optional<double> {
        if constexpr (requires { e.vector; }) return direction(e.vector, k);
        return std::nullopt;
      });
    }
    default:
      no_such(s, "not a force element's number");
  }
}

double constraint_field(const Model& model, const ParameterSource& s) {
  switch (s.kind) {
    case SourceKind::constraint_frame_origin: {
      const int k = axis(s, s.row);
      const Constraint& constraint = constraint_of(model, s);
      if (const auto* c = std::get_if<LoopClosure>(&constraint))
        return (s.column == 0 ? c->a : c->b).X_BF.p[k];
      if (const auto* c = std::get_if<DistanceLink>(&constraint))
        return (s.column == 0 ? c->a : c->b).X_BF.p[k];
      if (const auto* c = std::get_if<RollingContact>(&constraint)) return c->frame.X_BF.p[k];
      if (const auto* c = std::get_if<KnifeEdge>(&constraint)) return c->frame.X_BF.p[k];
      no_such(s, "the constraint has no frame");
    }
    case SourceKind::constraint_length:
      return constraint_as<DistanceLink>(model, s).length;
    case SourceKind::constraint_radius:
      return constraint_as<RollingContact>(model, s).radius;
    case SourceKind::constraint_ratio:
      return constraint_as<JointCoupler>(model, s).ratio;
    case SourceKind::constraint_offset:
      return constraint_as<JointCoupler>(model, s).offset;
    default:
      no_such(s, "not a constraint's number");
  }
}

}  // namespace

double parameter_signed_value(const Model& model, const ParameterSource& s) {
  switch (s.kind) {
    case SourceKind::gravity:
      return model.gravity().norm();
    case SourceKind::gravity_direction:
      return direction(model.gravity(), axis(s, s.row));
    case SourceKind::body_mass:
      return body_of(model, s).mass_properties.mass();
    case SourceKind::body_center_of_mass:
      return center_of_mass(body_of(model, s), axis(s, s.row));
    case SourceKind::body_inertia:
      return inertia_component(body_of(model, s), axis(s, s.row), axis(s, s.column));
    case SourceKind::body_shape_size: {
      const Body& body = body_of(model, s);
      if (!body.shape) no_such(s, "the body is no standard shape");
      const auto& sizes = body.shape->sizes;
      return sizes[static_cast<std::size_t>(
                       checked(s, s.row, static_cast<int>(sizes.size()), "size"))]
          .second;
    }
    case SourceKind::joint_parent_offset:
      return joint_of(model, s).X_PJ.p[axis(s, s.row)];
    case SourceKind::joint_child_offset:
      return joint_of(model, s).X_CJ.p[axis(s, s.row)];
    case SourceKind::joint_damping:
      return joint_of(model, s).damping;
    case SourceKind::joint_armature:
      return joint_of(model, s).armature;
    case SourceKind::element_stiffness:
    case SourceKind::element_damping:
    case SourceKind::element_rest:
    case SourceKind::element_free_length:
    case SourceKind::element_stretch_at_zero:
    case SourceKind::element_viscous:
    case SourceKind::element_offset:
    case SourceKind::element_coefficient:
    case SourceKind::element_load:
    case SourceKind::element_load_direction:
      return element_field(model, s);
    case SourceKind::constraint_frame_origin:
    case SourceKind::constraint_length:
    case SourceKind::constraint_radius:
    case SourceKind::constraint_ratio:
    case SourceKind::constraint_offset:
      return constraint_field(model, s);
  }
  no_such(s, "unknown kind");
}

double parameter_value(const Model& model, const ParameterSource& source) {
  const double value = parameter_signed_value(model, source);
  return source.magnitude ? std::abs(value) : value;
}

std::string_view parameter_source_kind_name(ParameterSource::Kind kind) {
  for (const auto& [k, name] : kKindNames)
    if (k == kind) return name;
  return "unknown";
}

std::optional<ParameterSource::Kind> parameter_source_kind(std::string_view name) {
  for (const auto& [k, n] : kKindNames)
    if (n == name) return k;
  return std::nullopt;
}

}  // namespace momenta::model
