// Model files, `forces:`: springs, dampers, friction, tendons and applied loads.

#include <algorithm>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "model_file/model_file_internal.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"

namespace momenta::io::detail {
namespace {

// Each force element type and the keys it takes (besides `name` and `type`).
const std::vector<EntryType>& force_types() {
  static const std::vector<EntryType> types = {
      {"spring_damper",
       {"body_a", "point_a", "body_b", "point_b", "stiffness", "damping", "free_length"}},
      {"torsional_spring",
       {"joint", "body_a", "body_b", "stiffness", "damping", "rest_angle", "rest_angle_deg"}},
      {"joint_friction", {"joint", "viscous"}},
      {"tendon", {"joints", "offset", "stiffness", "damping", "rest_length"}},
      {"force", {"body", "point", "frame", "vector", "signal"}},
      {"torque", {"body", "frame", "vector", "signal"}},
  };
  return types;
}

double nonnegative(const YamlNode& e, std::string_view key) {
  return e.find_number(key, Bound::kNonNegative).value_or(0.0);
}

// A load's body: declared, and not the world (a load on the ground does nothing).
std::string loaded_body(const YamlNode& e, const Context& ctx) {
  return moving_body(e.at("body"), ctx,
                     "a load on the world does nothing: name the body it acts on");
}

model::LoadFrame read_frame(const YamlNode& e) {
  const auto node = e.find("frame");
  if (!node) return model::LoadFrame::world;
  const std::string frame = node->as_string();
  if (frame == "world") return model::LoadFrame::world;
  if (frame == "body") return model::LoadFrame::body;
  const std::string_view names[] = {"world", "body"};
  node->fail(
      fmt::format("unknown frame '{}'{}; expected world (a fixed direction) or body (a "
                  "follower load)",
                  frame, did_you_mean(frame, names)));
}

std::string optional_signal(const YamlNode& e, const Context& ctx) {
  const auto ref = e.find("signal");
  return ref ? ctx.signals.resolve(*ref) : std::string();
}

// A fixed tendon: `joints`, a list of {joint, coefficient}, each joint 1-dof and named once.
model::FixedTendon read_tendon(const YamlNode& e, const std::string& name, const Context& ctx) {
  model::FixedTendon tendon;
  tendon.name = name;
  const YamlNode list = e.at("joints");
  if (!list.is_sequence() || list.size() == 0) {
    list.fail("a tendon's joints: a list of {joint: NAME, coefficient: c}, at least one");
  }
  for (const YamlNode& term : list.elements()) {
    term.expect_map("a tendon's joint: {joint: NAME, coefficient: c}");
    term.check_keys({"joint", "coefficient"});
    const YamlNode ref = term.at("joint");
    const std::string joint = ctx.joints.resolve(ref);
    const model::JointType t = ctx.joint_types.find(joint)->second;
    if (model::joint_nv(t) != 1) {
      ref.fail(
          fmt::format("joint '{}' is {} with {} degrees of freedom; a tendon's joints are "
                      "1-dof",
                      joint, model::joint_type_name(t), model::joint_nv(t)));
    }
    for (const model::TendonTerm& earlier : tendon.terms) {
      if (earlier.joint == joint) ref.fail(fmt::format("joint '{}' is listed twice", joint));
    }
    const double coefficient = term.find_number("coefficient").value_or(1.0);
    if (coefficient == 0.0) term.at("coefficient").fail("a coefficient of 0: leave the joint out");
    tendon.terms.push_back({joint, coefficient, -1});
  }
  tendon.offset = e.find_number("offset").value_or(0.0);
  tendon.stiffness = nonnegative(e, "stiffness");
  tendon.damping = nonnegative(e, "damping");
  tendon.rest_length = e.find_number("rest_length").value_or(0.0);
  return tendon;
}

model::ForceElement read_element(const YamlNode& e, std::string_view type, const std::string& name,
                                 const Context& ctx) {
  if (type == "spring_damper") {
    model::LinearSpringDamper s;
    s.name = name;
    s.a.body = ctx.bodies.resolve(e.at("body_a"), true);
    s.a.p_BoP_B = e.find_vec3("point_a").value_or(Vec3::Zero());
    s.b.body = ctx.bodies.resolve(e.at("body_b"), true);
    s.b.p_BoP_B = e.find_vec3("point_b").value_or(Vec3::Zero());
    if (s.a.body == s.b.body) {
      e.at("body_b").fail(fmt::format("both ends are on body '{}'", s.a.body));
    }
    s.stiffness = nonnegative(e, "stiffness");
    s.damping = nonnegative(e, "damping");
    s.free_length = nonnegative(e, "free_length");
    return s;
  }
  if (type == "torsional_spring") {
    model::TorsionalSpringDamper s;
    s.name = name;
    s.stiffness = nonnegative(e, "stiffness");
    s.damping = nonnegative(e, "damping");
    if (e.has("joint")) {
      for (const std::string_view key : {"body_a", "body_b"}) {
        if (e.has(key)) e.at(key).fail("give either a 'joint' or two bodies, not both");
      }
      const YamlNode ref = e.at("joint");
      s.joint = ctx.joints.resolve(ref);
      const model::JointType t = ctx.joint_types.find(s.joint)->second;
      if (model::joint_nv(t) != 1) {
        ref.fail(
            fmt::format("joint '{}' is {} with {} degrees of freedom; a torsional spring "
                        "needs a 1-dof joint (revolute, or prismatic as a linear spring)",
                        s.joint, model::joint_type_name(t), model::joint_nv(t)));
      }
      // The rest position: an angle (degrees allowed) on a revolute joint, a length otherwise.
      const auto rest = find_coordinates(e, "rest_angle", t == model::JointType::revolute,
                                         "the joint is prismatic: its rest position is in m");
      s.rest_angle = rest ? (*rest)[0] : 0.0;
    } else {
      if (!e.has("body_a") || !e.has("body_b")) {
        e.fail("a torsional spring needs a 'joint' (1-dof), or two bodies 'body_a' and 'body_b'");
      }
      for (const std::string_view key : {"rest_angle", "rest_angle_deg"}) {
        if (e.has(key)) {
          e.at(key).fail(
              "between two bodies the rest orientation is the initial one: no rest "
              "angle");
        }
      }
      s.body_a = ctx.bodies.resolve(e.at("body_a"), true);
      s.body_b = ctx.bodies.resolve(e.at("body_b"), true);
      if (s.body_a == s.body_b) {
        e.at("body_b").fail(fmt::format("both ends are on body '{}'", s.body_a));
      }
    }
    return s;
  }
  if (type == "joint_friction") {
    model::JointFriction f;
    f.name = name;
    f.joint = ctx.joints.resolve(e.at("joint"));
    f.viscous = e.number("viscous", Bound::kNonNegative);
    return f;
  }
  if (type == "tendon") return read_tendon(e, name, ctx);
  if (type == "force") {
    model::AppliedForce f;
    f.name = name;
    f.at.body = loaded_body(e, ctx);
    f.at.p_BoP_B = e.find_vec3("point").value_or(Vec3::Zero());
    f.frame = read_frame(e);
    f.vector = e.at("vector").as_vec3();
    f.signal = optional_signal(e, ctx);
    return f;
  }
  model::AppliedTorque t;
  t.name = name;
  t.body = loaded_body(e, ctx);
  t.frame = read_frame(e);
  t.vector = e.at("vector").as_vec3();
  t.signal = optional_signal(e, ctx);
  return t;
}

}  // namespace

void read_forces(const YamlNode& root, Context& ctx, model::ModelBuilder& builder) {
  for (const YamlNode& e : list_section(root, "forces")) {
    e.expect_map("a force element: a map with 'name' and 'type'");
    const YamlNode name = name_node(e);
    const std::string_view type = entry_type(e, force_types(), "force element").name;
    ctx.forces.add(name.as_string(), e, name);
    builder.add_force_element(read_element(e, type, name.as_string(), ctx));
  }
}

}  // namespace momenta::io::detail
