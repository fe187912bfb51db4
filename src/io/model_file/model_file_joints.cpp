// Model files, `joints:`: what carries each body, where, and how it starts; and the check that the
// joints form a tree rooted at the world.

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <string_view>

#include <fmt/format.h>

#include "model_file/model_file_internal.hpp"
#include "momenta/common/error.hpp"
#include "momenta/io/part_node.hpp"
#include "momenta/math/rotation.hpp"

namespace momenta::io::detail {
namespace {

using model::JointType;

// Axes are read to the precision quaternions are (docs/conventions.md), then normalized so the
// builder's 1e-9 check sees a unit vector.
constexpr double kUnitTolerance = 1e-6;

constexpr std::array<std::string_view, 17> kJointKeys = {
    "name",   "type", "parent", "child",  "in_parent", "in_child", "axis",       "axis2", "q0",
    "q0_deg", "v0",   "v0_deg", "v0_rpm", "damping",   "armature", "prescribed", "limits"};

bool has_axis(JointType t) { return model::joint_traits(t).axes >= 1; }

// The joint types with at least `axes` axes, as a list for messages: "revolute, prismatic, …".
std::string joints_with_axes(int axes) {
  std::string list;
  for (const model::JointTraits& t : model::kJointTraits) {
    if (t.axes >= axes) list += fmt::format("{}{}", list.empty() ? "" : ", ", t.name);
  }
  return list;
}

// Joints whose coordinates are all angles: the only ones whose q0 / v0 may be in degrees.
bool all_in(const auto& units, int count, std::string_view unit) {
  for (int k = 0; k < count; ++k)
    if (units[static_cast<std::size_t>(k)] != unit) return false;
  return count > 0;
}
bool angles_only_q(JointType t) {
  return all_in(model::joint_traits(t).q_units, model::joint_nq(t), "rad");
}
bool angles_only_v(JointType t) {
  return all_in(model::joint_traits(t).v_units, model::joint_nv(t), "rad/s");
}

// `in_parent` / `in_child`: {position, rotation | quaternion | euler}.
Transform read_pose(const YamlNode& node) {
  node.expect_map("a pose {position: [x, y, z], rotation | quaternion | euler}");
  node.check_keys({"position", "rotation", "quaternion", "euler"});
  return {read_rotation(node), node.find_vec3("position").value_or(Vec3::Zero())};
}

Vec3 read_axis(const YamlNode& node) {
  const Vec3 a = node.as_vec3();
  if (std::abs(a.norm() - 1.0) > kUnitTolerance) {
    node.fail(fmt::format("axis [{}, {}, {}] must be a unit vector (its norm is {:.9g})", a.x(),
                          a.y(), a.z(), a.norm()));
  }
  return a.normalized();
}

// A quaternion [w, x, y, z] (unit to 1e-6), stored normalized in q at `at`.
void read_quaternion(const YamlNode& node, const Eigen::Vector4d& wxyz, VecX& q, int at) {
  try {
    const Quat r = quaternion_from_wxyz(wxyz, "this");
    q.segment<4>(at) << r.w(), r.x(), r.y(), r.z();
  } catch (const InvalidArgument& e) {
    node.fail(one_line(e.what()));
  }
}

// q0 of a spherical or free joint given as a pose map: the orientation (and the free joint's
// position) of J' in J.
VecX read_pose_q0(const YamlNode& node, JointType type) {
  const bool free = type == JointType::free;
  if (free) {
    node.check_keys({"position", "rotation", "quaternion", "euler"});
  } else {
    node.check_keys({"rotation", "quaternion", "euler"});
  }
  const Quat r(read_rotation(node));
  VecX q(free ? 7 : 4);
  const int k = free ? 3 : 0;
  if (free) q.head<3>() = node.find_vec3("position").value_or(Vec3::Zero());
  q.segment<4>(k) << r.w(), r.x(), r.y(), r.z();
  return q;
}

std::string_view coordinate_units(JointType t) { return model::joint_traits(t).q_layout; }

// q0 and v0: a number (one coordinate) or a list, in SI or, for angles only, in degrees; a
// spherical or free joint's q0 may be a pose map.
void read_initial_state(const YamlNode& e, model::Joint& j, Context& ctx) {
  const std::string type(model::joint_type_name(j.type));
  const std::string not_angles = fmt::format("a {} joint's coordinates are not all angles", type);
  const auto size_check = [&](const VecX& values, std::string_view key, int expected) {
    if (values.size() != expected) {
      e.at(key).fail(fmt::format(
          "{} values given; a {} joint has {}{}", values.size(), type, expected,
          key.starts_with("q0") ? fmt::format(" {}", coordinate_units(j.type)) : std::string()));
    }
  };
  const bool quaternion_q = j.type == JointType::spherical || j.type == JointType::free;
  if (quaternion_q && e.has("q0") && e.at("q0").is_map()) {
    j.q0 = read_pose_q0(e.at("q0"), j.type);
  } else if (auto q0 = find_coordinates(e, "q0", angles_only_q(j.type), not_angles)) {
    const std::string_view key = e.has("q0") ? "q0" : "q0_deg";
    size_check(*q0, key, j.nq());
    if (quaternion_q) {
      const int k = j.type == JointType::free ? 3 : 0;
      read_quaternion(e.at(key), Eigen::Vector4d(q0->segment<4>(k)), *q0, k);
    }
    j.q0 = *q0;
    // An angle past a whole turn written in radians is more often degrees meant: said, not
    // refused (a wound spring's 10 rad is meant).
    if (key == "q0" && angles_only_q(j.type)) {
      for (Eigen::Index i = 0; i < q0->size(); ++i) {
        const double angle = (*q0)[i];
        if (std::abs(angle) <= 2.0 * std::numbers::pi) continue;
        const YamlNode node = e.at("q0");
        ctx.warnings.push_back(
            ParseError(node.file(), node.line(), node.column(),
                       fmt::format("{}: {} rad is {:.3g} turns; if degrees are meant, write "
                                   "q0_deg: {}",
                                   node.key_path(), angle, angle / (2.0 * std::numbers::pi), angle))
                .what());
        break;
      }
    }
  }
  if (auto v0 = find_coordinates(e, "v0", angles_only_v(j.type), not_angles, true)) {
    size_check(*v0, e.which_of({"v0", "v0_deg", "v0_rpm"}).value_or("v0"), j.nv());
    j.v0 = *v0;
  }
}

// `prescribed: signal` or `prescribed: [s1, s2]`: one signal per velocity coordinate (a ball
// joint's rotation vector; a free joint's rotation vector then position).
void read_prescribed(const YamlNode& e, model::Joint& j, const Context& ctx) {
  const YamlNode node = e.at("prescribed");
  const std::string type(model::joint_type_name(j.type));
  if (j.nv() == 0) node.fail("a fixed joint has no motion to prescribe");
  const std::vector<YamlNode> refs = node.is_sequence() ? node.elements() : std::vector{node};
  // Its signals driven by controllers, the joint is commanded (its acceleration the controllers'
  // outputs) and starts at its own q0 and v0; else its signals give its whole motion.
  const bool commanded = std::all_of(refs.begin(), refs.end(), [&](const YamlNode& ref) {
    return std::any_of(
        ctx.controllers_read.begin(), ctx.controllers_read.end(), [&](const model::Controller& c) {
          return std::find(c.drives.begin(), c.drives.end(), ref.as_string()) != c.drives.end();
        });
  });
  for (const std::string_view key : {"q0", "q0_deg", "v0", "v0_deg", "v0_rpm"}) {
    if (e.has(key) && !commanded) {
      e.at(key).fail(
          "a prescribed joint takes its initial state from its signals: remove it (a joint whose "
          "signals controllers drive takes one: they command its acceleration)");
    }
  }
  if (static_cast<int>(refs.size()) != j.nv()) {
    const char* hint = j.type == model::JointType::spherical ? " (its rotation vector φx, φy, φz)"
                       : j.type == model::JointType::free
                           ? " (its rotation vector φx, φy, φz, then its position x, y, z)"
                           : "";
    node.fail(
        fmt::format("{} signals given; a {} joint needs {}{}", refs.size(), type, j.nv(), hint));
  }
  for (const YamlNode& ref : refs) j.prescribed_signals.push_back(ctx.signals.resolve(ref));
}

// limits: {lower, upper (or lower_deg, upper_deg on a revolute joint), restitution}: stops on a
// revolute or prismatic joint's coordinate, one bound at least, the initial coordinate between.
void read_limits(const YamlNode& e, model::Joint& j) {
  const YamlNode node = e.at("limits");
  node.expect_map("stops: a map with 'lower' and/or 'upper' and 'restitution'");
  if (j.type != JointType::revolute && j.type != JointType::prismatic) {
    node.fail(fmt::format(
        "limits are stops on one coordinate: a revolute or prismatic joint's, not a {} joint's",
        model::joint_type_name(j.type)));
  }
  if (j.is_prescribed()) {
    node.fail(
        "a prescribed joint moves as its signal says: a stop cannot hold it (remove "
        "'prescribed' or 'limits')");
  }
  const bool angle = j.type == JointType::revolute;
  node.check_keys(angle ? std::vector<std::string_view>{"lower", "upper", "lower_deg", "upper_deg",
                                                        "restitution"}
                        : std::vector<std::string_view>{"lower", "upper", "restitution"});
  model::JointLimits limits;
  const auto bound = [&](std::string_view si, std::string_view deg, double& out) {
    if (node.has(si) && node.has(deg)) {
      node.at(deg).fail(fmt::format("give '{}' or '{}', not both", si, deg));
    }
    if (const auto x = node.find_number(si)) out = *x;
    if (const auto x = node.find_number(deg)) out = *x * std::numbers::pi / 180.0;
  };
  bound("lower", "lower_deg", limits.lower);
  bound("upper", "upper_deg", limits.upper);
  if (!std::isfinite(limits.lower) && !std::isfinite(limits.upper)) {
    node.fail(angle ? "give 'lower' and/or 'upper' (rad), or 'lower_deg' and/or 'upper_deg'"
                    : "give 'lower' and/or 'upper' (m)");
  }
  if (!(limits.lower < limits.upper)) {
    node.fail(fmt::format("lower {} is not below upper {}", limits.lower, limits.upper));
  }
  if (const auto e_node = node.find("restitution")) {
    const double r = node.find_number("restitution", Bound::kNonNegative).value();
    if (r > 1.0) {
      e_node->fail(fmt::format(
          "the coefficient of restitution {} is above 1 (0: a plastic stop, 1: an elastic one)",
          r));
    }
    limits.restitution = r;
  }
  const double q0 = j.q0.size() > 0 ? j.q0[0] : 0.0;
  if (q0 < limits.lower || q0 > limits.upper) {
    node.fail(fmt::format("the initial coordinate {} {} is outside the limits [{}, {}]", q0,
                          angle ? "rad" : "m", limits.lower, limits.upper));
  }
  j.limits = limits;
}

model::Joint read_joint(const YamlNode& e, Context& ctx) {
  e.expect_map("a joint: a map with 'name', 'type', 'parent' and 'child'");
  e.check_keys(kJointKeys);
  model::Joint j;
  const YamlNode name = name_node(e);
  j.name = name.as_string();
  ctx.joints.add(j.name, e, name);

  const YamlNode type_node = e.at("type");
  try {
    j.type = model::joint_type_from_name(type_node.as_string());
  } catch (const InvalidArgument& error) {
    type_node.fail(one_line(error.what()));
  }
  ctx.joint_types.emplace(j.name, j.type);
  const std::string type(model::joint_type_name(j.type));
  const auto refuse = [&](std::string_view key, std::string_view why) {
    if (e.has(key)) e.at(key).fail(fmt::format("a {} joint has no '{}' ({})", type, key, why));
  };
  if (!has_axis(j.type)) refuse("axis", fmt::format("only {} do", joints_with_axes(1)));
  if (model::joint_traits(j.type).axes < 2) {
    refuse("axis2", fmt::format("only the {} joint has two axes", joints_with_axes(2)));
  }
  if (j.nv() == 0) {
    for (const std::string_view key : {"q0", "q0_deg", "v0", "v0_deg", "v0_rpm", "damping",
                                       "armature", "prescribed", "limits"}) {
      refuse(key, "it has no degrees of freedom");
    }
  }

  // Parent and child: declared bodies (the parent may be the world).
  const YamlNode child = e.at("child");
  if (child.as_string() == model::kWorldBodyName) {
    child.fail("the world cannot be a child (swap parent and child)");
  }
  j.parent = ctx.bodies.resolve(e.at("parent"), /*allow_world=*/true);
  j.child = ctx.bodies.resolve(child);
  if (j.parent == j.child) child.fail(fmt::format("connects body '{}' to itself", j.child));

  // Frames, axes, initial state, damping, prescribed motion.
  if (const auto pose = e.find("in_parent")) j.X_PJ = read_pose(*pose);
  if (const auto pose = e.find("in_child")) j.X_CJ = read_pose(*pose);
  if (const auto axis = e.find("axis")) j.axis = read_axis(*axis);
  if (const auto axis2 = e.find("axis2")) j.axis2 = read_axis(*axis2);
  read_initial_state(e, j, ctx);
  j.damping = e.find_number("damping", Bound::kNonNegative).value_or(0.0);
  j.armature = e.find_number("armature", Bound::kNonNegative).value_or(0.0);
  if (e.has("prescribed")) read_prescribed(e, j, ctx);
  if (e.has("limits")) read_limits(e, j);
  return j;
}

// Every body carried by exactly one joint, and every body reached from the world.
void check_tree(const std::vector<model::Joint>& joints, const std::vector<YamlNode>& nodes,
                const Context& ctx) {
  std::map<std::string, std::size_t, std::less<>> carrier;  // body -> joint
  for (std::size_t k = 0; k < joints.size(); ++k) {
    const auto [it, inserted] = carrier.emplace(joints[k].child, k);
    if (!inserted) {
      const model::Joint& first = joints[it->second];
      nodes[k].at("child").fail(fmt::format(
          "body '{}' is already the child of joint '{}' (line {}): every body hangs on one "
          "joint, the bodies form a tree (closed loops are not supported)",
          joints[k].child, first.name, nodes[it->second].line()));
    }
  }
  for (const std::string& body : ctx.bodies.names()) {
    if (!carrier.count(body)) {
      ctx.bodies.find(body)->fail(
          fmt::format("body '{}' is not attached to anything: add a joint with it as the child "
                      "(type fixed to weld it)",
                      body));
    }
  }
  // Walk from each body towards the world; coming back to a body on the way is a cycle.
  for (const std::string& body : ctx.bodies.names()) {
    std::vector<std::string> path{body};
    std::string at = body;
    while (at != model::kWorldBodyName) {
      at = joints[carrier.find(at)->second].parent;
      const auto seen = std::find(path.begin(), path.end(), at);
      if (seen != path.end()) {
        std::string cycle = *seen;
        for (auto p = seen + 1; p != path.end(); ++p) cycle += " <- " + *p;
        cycle += " <- " + *seen;
        nodes[carrier.find(*seen)->second].fail(fmt::format(
            "the joints form a cycle ({}): the bodies must form a tree rooted at the world",
            cycle));
      }
      path.push_back(at);
    }
  }
}

}  // namespace

void read_joints(const YamlNode& root, Context& ctx, model::ModelBuilder& builder) {
  const std::vector<YamlNode> nodes = list_section(root, "joints");
  std::vector<model::Joint> joints;
  for (const YamlNode& e : nodes) joints.push_back(read_joint(e, ctx));
  check_tree(joints, nodes, ctx);
  for (model::Joint& j : joints) builder.add_joint(std::move(j));
}

}  // namespace momenta::io::detail
