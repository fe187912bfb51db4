// Model files, `outputs:`: the named quantities `momenta simulate` records and `momenta linearize`
// takes as outputs, checked against the built model.

#include <algorithm>
#include <array>
#include <map>
#include <string_view>
#include <utility>
#include <variant>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "model_file/model_file_internal.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/math/rotation.hpp"

namespace momenta::io::detail {
namespace {

using model::OutputQuantity;
using Q = OutputQuantity;

// The quantities of each kind of target, by their names in the file.
struct Target {
  std::string_view key;  // "body", "joint", "signal", "spring"
  std::vector<std::pair<std::string_view, OutputQuantity>> quantities;
};

const std::array<Target, 6>& targets() {
  static const std::array<Target, 6> table = {{
      {"body",
       {{"position", Q::body_position},
        {"velocity", Q::body_velocity},
        {"acceleration", Q::body_acceleration},
        {"angular_velocity", Q::body_angular_velocity},
        {"angular_acceleration", Q::body_angular_acceleration},
        {"euler_angles", Q::body_euler_angles},
        {"euler_rates", Q::body_euler_rates},
        {"transport_velocity", Q::transport_velocity},
        {"transport_acceleration", Q::transport_acceleration},
        {"coriolis_acceleration", Q::coriolis_acceleration},
        {"centripetal_acceleration", Q::centripetal_acceleration},
        {"euler_acceleration", Q::euler_acceleration}}},
      {"joint",
       {{"position", Q::joint_position},
        {"velocity", Q::joint_velocity},
        {"effort", Q::joint_effort},
        {"reaction_force", Q::reaction_force},
        {"reaction_moment", Q::reaction_moment}}},
      {"signal", {{"signal", Q::signal}}},
      {"spring", {{"spring_length", Q::spring_length}, {"spring_tension", Q::spring_tension}}},
      {"tendon", {{"length", Q::spring_length}, {"tension", Q::spring_tension}}},
      {"constraint", {{"force", Q::constraint_force}}},
  }};
  return table;
}

bool is_body(OutputQuantity q) {
  return model::output_target_kind(q) == model::OutputTargetKind::body;
}
bool is_vector(OutputQuantity q) {
  return (is_body(q) && !model::is_euler_quantity(q)) || q == Q::reaction_force ||
         q == Q::reaction_moment;
}
bool is_reaction(OutputQuantity q) { return q == Q::reaction_force || q == Q::reaction_moment; }
bool at_point(OutputQuantity q) {
  return is_body(q) && q != Q::body_angular_velocity && q != Q::body_angular_acceleration &&
         !model::is_euler_quantity(q);
}

OutputQuantity read_quantity(const YamlNode& e, const Target& target) {
  const auto node = e.find("quantity");
  if (!node) {
    if (target.key == "signal") return Q::signal;
    if (target.key == "constraint") return Q::constraint_force;
    e.fail(fmt::format("an output of a {} needs a 'quantity'", target.key));
  }
  const std::string name = node->as_string();
  std::vector<std::string_view> names;
  for (const auto& [n, q] : target.quantities) {
    if (n == name) return q;
    names.push_back(n);
  }
  node->fail(fmt::format("'{}' is not a quantity of a {}{}; a {} has {}", name, target.key,
                         did_you_mean(name, names), target.key, fmt::join(names, ", ")));
}

model::ReactionFrame read_reaction_frame(const YamlNode& node) {
  const std::string frame = node.as_string();
  constexpr std::array<std::pair<std::string_view, model::ReactionFrame>, 4> kFrames = {
      {{"world", model::ReactionFrame::world},
       {"joint", model::ReactionFrame::joint},
       {"child", model::ReactionFrame::child},
       {"parent", model::ReactionFrame::parent}}};
  for (const auto& [n, f] : kFrames) {
    if (n == frame) return f;
  }
  const std::array<std::string_view, 4> names = {"world", "joint", "child", "parent"};
  node.fail(
      fmt::format("unknown frame '{}'{}; expected world, joint (the child-side joint frame "
                  "J'), child or parent",
                  frame, did_you_mean(frame, names)));
}

// x | y | z of a vector; a coordinate index 0 .. n−1 of a joint quantity.
int read_component(const YamlNode& node, const model::OutputSpec& spec, const model::Model& model) {
  if (is_vector(spec.quantity)) {
    const std::string axis = node.as_string();
    if (axis == "x" || axis == "y" || axis == "z") return axis[0] - 'x';
    node.fail(fmt::format("component '{}' of a vector must be x, y or z", axis));
  }
  if (spec.quantity == Q::signal || spec.quantity == Q::spring_length ||
      spec.quantity == Q::spring_tension) {
    node.fail("this quantity is a single number: it has no components");
  }
  if (model::is_euler_quantity(spec.quantity)) {
    const long long i = node.as_integer();
    if (i < 0 || i > 2)
      node.fail(fmt::format("component {} of the Euler angles must be 0, 1 or 2", i));
    return static_cast<int>(i);
  }
  if (spec.quantity == Q::constraint_force) {
    const auto labels =
        model::constraint_force_labels(model.constraints()[*model.find_constraint(spec.target)]);
    const std::string label = node.as_string();
    for (std::size_t i = 0; i < labels.size(); ++i)
      if (labels[i] == label) return static_cast<int>(i);
    node.fail(fmt::format("'{}' is not a force of constraint '{}'{}; it has {}", label, spec.target,
                          did_you_mean(label, labels), fmt::join(labels, ", ")));
  }
  const model::Joint& joint = model.joint(model.joint_index(spec.target));
  const bool q = spec.quantity == Q::joint_position;
  const int n = q ? joint.nq() : joint.nv();
  std::string names;
  for (int i = 0; i < n; ++i) {
    names += fmt::format("{}{} ({})", i == 0 ? "" : ", ", i,
                         q ? model.q_name(joint.q_index + i) : model.v_name(joint.v_index + i));
  }
  const long long i = node.as_integer();
  if (i < 0 || i >= n) {
    node.fail(fmt::format("coordinate {} is out of range: joint '{}' has {}{}", i, joint.name,
                          n == 0 ? "none" : fmt::format("{}: ", n), names));
  }
  return static_cast<int>(i);
}

model::OutputSpec read_output(const YamlNode& e, const Context& ctx, const model::Model& model) {
  e.expect_map(
      "an output: a map with a target ('body', 'joint', 'signal', 'spring', 'tendon', "
      "'constraint')");
  e.check_keys({"name", "quantity", "body", "joint", "signal", "spring", "tendon", "constraint",
                "point", "component", "frame", "sequence"});
  const auto key = e.which_of({"body", "joint", "signal", "spring", "tendon", "constraint"});
  if (!key) {
    e.fail(
        "an output needs one target: 'body', 'joint', 'signal', 'spring' (a spring_damper), "
        "'tendon' or 'constraint'");
  }
  const Target& target = *std::find_if(targets().begin(), targets().end(),
                                       [&](const Target& t) { return t.key == *key; });
  model::OutputSpec spec;
  spec.quantity = read_quantity(e, target);

  // The target, by name.
  const YamlNode ref = e.at(*key);
  if (*key == "body") {
    spec.target = ctx.bodies.resolve(ref);
  } else if (*key == "joint") {
    spec.target = ctx.joints.resolve(ref);
  } else if (*key == "signal") {
    spec.target = ctx.signals.resolve(ref);
  } else if (*key == "constraint") {
    spec.target = ctx.constraints.resolve(ref);
  } else {
    spec.target = ctx.forces.resolve(ref);
    const auto& elements = model.force_elements();
    const auto element = std::find_if(elements.begin(), elements.end(), [&](const auto& f) {
      return model::force_element_name(f) == spec.target;
    });
    const bool tendon = *key == "tendon";
    if (tendon ? !std::holds_alternative<model::FixedTendon>(*element)
               : !std::holds_alternative<model::LinearSpringDamper>(*element)) {
      ref.fail(fmt::format("force element '{}' is not a {}", spec.target,
                           tendon ? "tendon"
                                  : "spring_damper: only those (and tendons) have a "
                                    "length and a tension"));
    }
  }

  // Where, in which frame, which component.
  if (const auto point = e.find("point")) {
    if (!at_point(spec.quantity)) {
      point->fail(
          "only a body's position, velocity and acceleration (and their rotating-frame terms) are "
          "taken at a point");
    }
    spec.point = point->as_vec3();
  }
  if (const auto frame = e.find("frame")) {
    if (is_reaction(spec.quantity)) {
      spec.frame = read_reaction_frame(*frame);
    } else if (is_body(spec.quantity)) {
      spec.relative_to = ctx.bodies.resolve(*frame, true);
      if (spec.relative_to == model::kWorldBodyName) spec.relative_to.clear();
    } else {
      frame->fail("only body quantities (a body's frame) and reactions take a 'frame'");
    }
  } else if (model::is_rotating_frame_term(spec.quantity)) {
    e.fail(
        fmt::format("'{}' is a term of the motion seen from a moving frame: give the body "
                    "whose frame that is, 'frame: <body>'",
                    model::output_quantity_name(spec.quantity)));
  }
  if (const auto sequence = e.find("sequence")) {
    if (!model::is_euler_quantity(spec.quantity)) {
      sequence->fail("only euler_angles and euler_rates take a 'sequence'");
    }
    spec.sequence = sequence->as_string();
    try {
      check_euler_sequence(spec.sequence);
    } catch (const InvalidArgument& error) {
      sequence->fail(error.what());
    }
  }
  if (const auto component = e.find("component")) {
    spec.component = read_component(*component, spec, model);
  }
  spec.name = e.find_string("name").value_or(
      spec.quantity == Q::signal || spec.quantity == Q::constraint_force
          ? spec.target
          : fmt::format("{}.{}", spec.target, e.at("quantity").as_string()));
  return spec;
}

}  // namespace

std::vector<model::OutputSpec> read_outputs(const YamlNode& root, const Context& ctx,
                                            const model::Model& model) {
  std::vector<model::OutputSpec> specs;
  std::map<std::string, int, std::less<>> line_of_name;
  for (const YamlNode& e : list_section(root, "outputs")) {
    model::OutputSpec spec = read_output(e, ctx, model);
    const auto [it, inserted] = line_of_name.emplace(spec.name, e.line());
    if (!inserted) {
      (e.has("name") ? e.at("name") : e)
          .fail(fmt::format("a second output named '{}' (the first is at line {}): give each a "
                            "distinct 'name'",
                            spec.name, it->second));
    }
    specs.push_back(std::move(spec));
  }
  return specs;
}

}  // namespace momenta::io::detail
