// Model files, `constraints:`: loops closed between two bodies, links and wires, rolling and
// knife-edge contacts, couplers, unilateral contacts with the ground (model/constraint.hpp;
// docs/model-format.md).

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "model_file/model_file_internal.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/io/part_node.hpp"
#include "momenta/math/rotation.hpp"

namespace momenta::io::detail {
namespace {

const std::vector<EntryType>& constraint_types() {
  static const std::vector<std::string_view> loop = {"body_a",  "body_b",  "frame_a", "frame_b",
                                                     "point_a", "point_b", "axis_a",  "axis_b"};
  static const std::vector<EntryType> types = {
      {"weld", loop},
      {"point", loop},
      {"hinge", loop},
      {"slider", loop},
      {"distance", {"body_a", "point_a", "body_b", "point_b", "length"}},
      {"rolling",
       {"body", "shape", "radius", "centre", "axis", "normal", "plane_point", "friction"}},
      {"knife_edge", {"body", "point", "direction", "normal"}},
      {"coupler", {"joint_a", "joint_b", "ratio", "offset", "offset_deg"}},
      {"contact",
       {"body", "shape", "point", "axis", "radius", "normal", "plane_point", "other_body",
        "other_point", "other_radius", "restitution", "friction"}},
  };
  return types;
}

// A unit vector (to 1e-6, then normalized).
Vec3 read_unit(const YamlNode& node) {
  const Vec3 a = node.as_vec3();
  if (!a.allFinite() || std::abs(a.norm() - 1.0) > 1e-6) {
    node.fail(fmt::format("[{}, {}, {}] must be a unit vector (its norm is {:.9g})", a.x(), a.y(),
                          a.z(), a.norm()));
  }
  return a.normalized();
}

// A rotation whose z axis is `axis` (any such rotation: the frame's x and y do not matter where
// only its z axis is used).
Mat3 z_along(const Vec3& axis) {
  const Vec3 z = Vec3::UnitZ();
  const Vec3 c = z.cross(axis);
  const double s = c.norm();
  if (s < 1e-12)
    return axis.z() > 0 ? Mat3::Identity()
                        : rotation_from_axis_angle(Vec3::UnitX(), std::numbers::pi);
  return rotation_from_axis_angle(c / s, std::atan2(s, z.dot(axis)));
}

// One end of a loop closure: `frame_<s>` (a pose), or `point_<s>` and `axis_<s>` (a frame at the
// point with its z along the axis; z of the body by default).
model::BodyFrame read_end(const YamlNode& e, const Context& ctx, std::string_view side) {
  model::BodyFrame f;
  f.body = ctx.bodies.resolve(e.at(fmt::format("body_{}", side)), true);
  const std::string frame_key = fmt::format("frame_{}", side);
  const std::string point_key = fmt::format("point_{}", side);
  const std::string axis_key = fmt::format("axis_{}", side);
  if (const auto frame = e.find(frame_key)) {
    for (const std::string& key : {point_key, axis_key}) {
      if (e.has(key))
        e.at(key).fail(fmt::format("give either '{}' or '{}', not both", frame_key, key));
    }
    frame->expect_map("a pose {position: [x, y, z], rotation | quaternion | euler}");
    frame->check_keys({"position", "rotation", "quaternion", "euler"});
    f.X_BF = Transform(read_rotation(*frame), frame->find_vec3("position").value_or(Vec3::Zero()));
    return f;
  }
  const Vec3 axis = e.has(axis_key) ? read_unit(e.at(axis_key)) : Vec3::UnitZ();
  f.X_BF = Transform(z_along(axis), e.find_vec3(point_key).value_or(Vec3::Zero()));
  return f;
}

// A contact's Coulomb friction: one coefficient for both (friction: 0.4), or the two
// (friction: {static: 0.5, kinetic: 0.4}, kinetic ≤ static).
void read_friction(const YamlNode& node, model::Contact& c) {
  if (!node.is_map()) {
    c.static_friction = c.kinetic_friction = node.as_double(Bound::kNonNegative);
  } else {
    node.check_keys({"static", "kinetic"});
    c.static_friction = node.number("static", Bound::kNonNegative);
    c.kinetic_friction =
        node.find_number("kinetic", Bound::kNonNegative).value_or(c.static_friction);
    if (c.kinetic_friction > c.static_friction) {
      node.at("kinetic").fail(fmt::format(
          "{} is above the static coefficient {}: sliding friction is no greater than the "
          "friction that can hold",
          c.kinetic_friction, c.static_friction));
    }
  }
}

// A contact's shape: a sphere of `radius` (0, a point, by default) centred at `point`, or a disk
// (`shape: disk`) of `radius` there with its axis along `axis` (the body's z by default).
void read_contact_shape(const YamlNode& e, model::Contact& c) {
  const std::string shape = e.find_string("shape").value_or("sphere");
  if (shape == "disk") {
    c.shape = model::ContactShape::disk;
    c.radius = e.number("radius", Bound::kPositive);
    const Vec3 axis = e.has("axis") ? read_unit(e.at("axis")) : Vec3::UnitZ();
    c.frame.X_BF.R = z_along(axis);
    return;
  }
  if (shape != "sphere") {
    const std::string_view names[] = {"sphere", "disk"};
    e.at("shape").fail(
        fmt::format("unknown shape '{}'{}; expected sphere (a point where the "
                    "radius is 0) or disk",
                    shape, did_you_mean(shape, names)));
  }
  if (e.has("axis")) e.at("axis").fail("a sphere or point has no axis; give shape: disk");
  c.radius = e.has("radius") ? e.number("radius", Bound::kNonNegative) : 0.0;
}

// A rolling contact that may slip: with friction, `rolling` is a contact of the wheel's rim or
// the ball with the plane (model::Contact), which sticks — rolls — while friction can hold it,
// slides with μk N beyond, and leaves the plane where it would have to pull.
model::Contact rolling_with_friction(const model::RollingContact& rolling,
                                     const YamlNode& friction) {
  model::Contact c;
  c.name = rolling.name;
  c.frame = rolling.frame;
  c.shape = rolling.shape == model::RollingShape::disk ? model::ContactShape::disk
                                                       : model::ContactShape::sphere;
  c.radius = rolling.radius;
  c.plane_normal = rolling.plane_normal;
  c.plane_point = rolling.plane_point;
  read_friction(friction, c);
  if (!c.has_friction()) {
    friction.fail(
        "a rolling contact's friction must be above 0; leave friction out for rolling "
        "that never slips");
  }
  return c;
}

model::Constraint read_constraint(const YamlNode& e, std::string_view type, const std::string& name,
                                  const Context& ctx) {
  if (type == "weld" || type == "point" || type == "hinge" || type == "slider") {
    model::LoopClosure c;
    c.name = name;
    for (const model::LoopType t : {model::LoopType::weld, model::LoopType::point,
                                    model::LoopType::hinge, model::LoopType::slider}) {
      if (model::loop_type_name(t) == type) c.type = t;
    }
    c.a = read_end(e, ctx, "a");
    c.b = read_end(e, ctx, "b");
    if (c.a.body == c.b.body)
      e.at("body_b").fail(fmt::format("both ends are on body '{}'", c.a.body));
    return c;
  }
  if (type == "distance") {
    model::DistanceLink c;
    c.name = name;
    c.a.body = ctx.bodies.resolve(e.at("body_a"), true);
    c.a.X_BF.p = e.find_vec3("point_a").value_or(Vec3::Zero());
    c.b.body = ctx.bodies.resolve(e.at("body_b"), true);
    c.b.X_BF.p = e.find_vec3("point_b").value_or(Vec3::Zero());
    if (c.a.body == c.b.body)
      e.at("body_b").fail(fmt::format("both ends are on body '{}'", c.a.body));
    c.length = e.number("length", Bound::kPositive);
    return c;
  }
  if (type == "rolling") {
    model::RollingContact c;
    c.name = name;
    c.frame.body = moving_body(e.at("body"), ctx, "the world cannot roll: name the wheel's body");
    const std::string shape = e.find_string("shape").value_or("disk");
    if (shape == "sphere") {
      c.shape = model::RollingShape::sphere;
      if (e.has("axis")) e.at("axis").fail("a sphere has no axis");
    } else if (shape != "disk") {
      const std::string_view names[] = {"disk", "sphere"};
      e.at("shape").fail(fmt::format("unknown shape '{}'{}; expected disk or sphere", shape,
                                     did_you_mean(shape, names)));
    }
    c.radius = e.number("radius", Bound::kPositive);
    const Vec3 axis = e.has("axis") ? read_unit(e.at("axis")) : Vec3::UnitZ();
    c.frame.X_BF = Transform(z_along(axis), e.find_vec3("centre").value_or(Vec3::Zero()));
    if (e.has("normal")) c.plane_normal = read_unit(e.at("normal"));
    c.plane_point = e.find_vec3("plane_point").value_or(Vec3::Zero());
    if (e.has("friction")) return rolling_with_friction(c, e.at("friction"));
    return c;
  }
  if (type == "contact") {
    model::Contact c;
    c.name = name;
    c.frame.body = moving_body(e.at("body"), ctx, "the world cannot touch the ground: name a body");
    c.frame.X_BF.p = e.find_vec3("point").value_or(Vec3::Zero());
    read_contact_shape(e, c);
    if (e.has("other_body")) {
      c.other.body = moving_body(e.at("other_body"), ctx,
                                 "leave other_body out for the ground plane, or name a body");
      c.other_plane = e.has("normal") || e.has("plane_point");
      if (c.other_plane) {
        // The other body's plane, in its frame.
        for (const char* key : {"other_point", "other_radius"}) {
          if (e.has(key)) {
            e.at(key).fail(
                "a contact with another body's plane (normal, plane_point) has no other sphere; "
                "give the plane or the sphere");
          }
        }
        if (e.has("normal")) c.plane_normal = read_unit(e.at("normal"));
        c.plane_point = e.find_vec3("plane_point").value_or(Vec3::Zero());
      } else {  // the other body's sphere
        c.other.X_BF.p = e.find_vec3("other_point").value_or(Vec3::Zero());
        c.other_radius =
            e.has("other_radius") ? e.number("other_radius", Bound::kNonNegative) : 0.0;
      }
    } else {
      for (const char* key : {"other_point", "other_radius"}) {
        if (e.has(key)) e.at(key).fail("give other_body: the body whose sphere this is");
      }
      if (e.has("normal")) c.plane_normal = read_unit(e.at("normal"));
      c.plane_point = e.find_vec3("plane_point").value_or(Vec3::Zero());
    }
    if (e.has("restitution")) {
      c.restitution = e.number("restitution", Bound::kNonNegative);
      if (c.restitution > 1.0) {
        e.at("restitution")
            .fail(fmt::format("{} is above 1: a contact cannot give back more than the approach "
                              "speed (0 plastic, 1 elastic)",
                              c.restitution));
      }
    }
    if (e.has("friction")) read_friction(e.at("friction"), c);
    return c;
  }
  if (type == "knife_edge") {
    model::KnifeEdge c;
    c.name = name;
    c.frame.body = moving_body(e.at("body"), ctx, "a knife edge on the world does nothing");
    // The blade along the frame's x axis.
    const Vec3 blade = e.has("direction") ? read_unit(e.at("direction")) : Vec3::UnitX();
    const Mat3 R = z_along(blade) * rotation_from_axis_angle(Vec3::UnitY(), -std::numbers::pi / 2);
    c.frame.X_BF = Transform(R, e.find_vec3("point").value_or(Vec3::Zero()));
    if (e.has("normal")) c.plane_normal = read_unit(e.at("normal"));
    return c;
  }
  model::JointCoupler c;
  c.name = name;
  c.joint_a = ctx.joints.resolve(e.at("joint_a"));
  c.joint_b = ctx.joints.resolve(e.at("joint_b"));
  c.ratio = e.number("ratio", Bound::kFinite);
  const auto offset = find_coordinates(e, "offset", true, "");
  c.offset = offset ? (*offset)[0] : 0.0;
  return c;
}

}  // namespace

void read_constraints(const YamlNode& root, Context& ctx, model::ModelBuilder& builder) {
  for (const YamlNode& e : list_section(root, "constraints")) {
    e.expect_map("a constraint: a map with 'name' and 'type'");
    const YamlNode name = name_node(e);
    const std::string_view type = entry_type(e, constraint_types(), "constraint").name;
    if (ctx.forces.contains(name.as_string())) {
      name.fail(fmt::format("a force element is already named '{}' (their CSV columns would clash)",
                            name.as_string()));
    }
    ctx.constraints.add(name.as_string(), e, name);
    builder.add_constraint(read_constraint(e, type, name.as_string(), ctx));
  }
}

}  // namespace momenta::io::detail
