// The unit of each results column of a sweep: a parameter's from where its number sits in the
// model or part file, a metric's from what it measures (runner.hpp).

#include "column_units.hpp"

#include <algorithm>
#include <array>
#include <string_view>
#include <variant>

#include "momenta/io/yaml_reader.hpp"
#include "momenta/model/units.hpp"

namespace momenta::sweep::detail {
namespace {

// The keys of a dotted path, indices ("[2]") dropped: "bodies.body.mass" → bodies, body, mass.
std::vector<std::string> keys_of(const std::string& path) {
  std::vector<std::string> keys;
  std::string key;
  bool in_index = false;
  for (char c : path + ".") {
    if (c == '[') in_index = true;
    if (!in_index && c != '.') key += c;
    if (c == ']') in_index = false;
    if (c == '.' && !key.empty()) {
      keys.push_back(key);
      key.clear();
    }
  }
  return keys;
}

bool is_length_key(std::string_view key) {
  static constexpr std::array<std::string_view, 17> lengths = {
      "position",  "com",      "radius",       "length",       "width",   "height",
      "depth",     "size",     "free_length",  "point",        "point_a", "point_b",
      "thickness", "diameter", "inner_radius", "outer_radius", "offset"};
  return std::find(lengths.begin(), lengths.end(), key) != lengths.end();
}

// A joint's or force element's number, by what the model says it is.
std::string model_item_unit(const model::Model& model, const std::vector<std::string>& keys) {
  const std::string& leaf = keys.back();
  if (keys.size() < 3) return "";
  if (keys[0] == "joints") {
    const auto j = model.find_joint(keys[1]);
    if (!j) return "";
    const model::Joint& joint = model.joint(*j);
    if (joint.nv() == 0) return "";
    if (leaf == "q0") return model::q_unit(model, joint.q_index);
    if (leaf == "v0") return model::v_unit(model, joint.v_index);
    if (leaf == "damping") return model::joint_damping_unit(model, joint);
    return "";
  }
  if (keys[0] == "forces") {
    for (const model::ForceElement& e : model.force_elements()) {
      if (model::force_element_name(e) != keys[1]) continue;
      if (const auto* tendon = std::get_if<model::FixedTendon>(&e)) {
        const model::TendonUnits units = model::tendon_units(model, *tendon);
        if (leaf == "stiffness") return units.stiffness;
        if (leaf == "damping") return units.damping;
        if (leaf == "rest_length" || leaf == "offset") return units.length;
        return "";
      }
      const bool torsional = std::holds_alternative<model::TorsionalSpringDamper>(e);
      if (leaf == "stiffness") return torsional ? "N·m/rad" : "N/m";
      if (leaf == "damping") return torsional ? "N·m·s/rad" : "N·s/m";
      if (leaf == "rest_angle") return "rad";
      if (leaf == "force" || leaf == "vector") {
        return std::holds_alternative<model::AppliedTorque>(e) ? "N·m" : "N";
      }
    }
  }
  return "";
}

}  // namespace

std::string parameter_unit(const std::string& path, const model::Model* model,
                           const std::string& part_length_unit) {
  const std::vector<std::string> keys = keys_of(path);
  if (keys.empty()) return "";
  const std::string& leaf = keys.back();
  if (leaf.size() > 4 && leaf.ends_with("_deg")) return "deg";
  if (leaf == "mass") return "kg";
  if (leaf == "density") return "kg/m³";
  if (leaf == "inertia") return "kg·m²";
  if (model == nullptr) return is_length_key(leaf) ? part_length_unit : "";
  if (keys[0] == "gravity") return "m/s²";
  if (keys[0] == "simulation" && (leaf == "duration" || leaf == "step")) return "s";
  const std::string item = model_item_unit(*model, keys);
  if (!item.empty()) return item;
  return is_length_key(leaf) ? "m" : "";
}

std::vector<std::string> metric_units(const Metric& metric, std::size_t columns,
                                      const std::string& recorded_unit) {
  using K = Metric::Kind;
  std::string unit;
  switch (metric.kind) {
    case K::kFinal:
    case K::kInitial:
    case K::kMax:
    case K::kMin:
    case K::kMaxAbs:
    case K::kMean:
    case K::kRms:
      unit = recorded_unit;
      break;
    case K::kRiseTime:
    case K::kSettlingTime:
    case K::kPeakTime:
      unit = "s";
      break;
    case K::kOvershoot:
      unit = "%";
      break;
    case K::kMaxReaction:
      unit = "N";
      break;
    case K::kMaxAuditDrift:
    case K::kDampingRatios:
      unit = "1";
      break;
    case K::kPoles:
      unit = "1/s";
      break;
    case K::kNaturalFrequencies:
      unit = "rad/s";
      break;
    case K::kMass:
      unit = "kg";
      break;
    case K::kCentreOfMass:
      unit = "m";
      break;
    case K::kInertia:
    case K::kPrincipalMoments:
      unit = "kg·m²";
      break;
  }
  return std::vector<std::string>(columns, unit);
}

std::string part_length_unit(const std::filesystem::path& part_file) {
  const io::YamlNode root = io::YamlNode::load_file(part_file);
  if (!root.is_map()) return "m";
  return root.find_string("units").value_or("m");
}

}  // namespace momenta::sweep::detail
