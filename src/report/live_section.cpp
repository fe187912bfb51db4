// The live report's controls (docs/report.md, "The live report"): which numbers of the model
// file the page offers to change, with their units and ranges, and the file's text that the
// in-page engine (wasm/) reads them from — by their paths, as sweeps name them.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "momenta/io/file_template.hpp"
#include "momenta/model/units.hpp"
#include "momenta/report/report.hpp"
#include "sections.hpp"

namespace momenta::report::detail {
namespace {

// A slider: the unit shown, and its range around the file's value.
struct Control {
  std::string unit;
  double min = 0.0;
  double max = 0.0;
  bool logarithmic = false;
};

std::vector<std::string> segments(const std::string& path) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = path.find('.', start);
    parts.push_back(path.substr(start, dot - start));
    if (dot == std::string::npos) return parts;
    start = dot + 1;
  }
}

bool is_index(const std::string& segment) {
  return !segment.empty() &&
         std::all_of(segment.begin(), segment.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// A positive quantity: a tenth to ten times the file's value, on a logarithmic slider.
std::optional<Control> scaled(double value, std::string unit) {
  if (!(value > 0.0)) return std::nullopt;  // no scale to offer a range from
  return Control{std::move(unit), value / 10.0, value * 10.0, true};
}

// An initial coordinate or rate: a linear slider about the file's value.
Control about(double value, double half_width, std::string unit) {
  return {std::move(unit), value - half_width, value + half_width, false};
}

std::optional<Control> body_control(const std::string& key, double value) {
  if (key == "mass") return scaled(value, "kg");
  for (const std::string_view length : {"length", "radius", "height", "width", "depth"}) {
    if (key == length) return scaled(value, "m");
  }
  return std::nullopt;
}

std::optional<Control> force_control(const model::Model& model, const std::string& element,
                                     const std::string& key, double value) {
  for (const model::ForceElement& e : model.force_elements()) {
    if (const auto* s = std::get_if<model::LinearSpringDamper>(&e); s && s->name == element) {
      if (key == "stiffness") return scaled(value, "N/m");
      if (key == "damping") return scaled(value, "N·s/m");
      if (key == "free_length") return scaled(value, "m");
    }
    if (const auto* s = std::get_if<model::TorsionalSpringDamper>(&e); s && s->name == element) {
      if (key == "stiffness") return scaled(value, "N·m/rad");
      if (key == "damping") return scaled(value, "N·m·s/rad");
    }
  }
  return std::nullopt;
}

// A joint's initial coordinate or rate (`q0`, `v0`, their `_deg` forms, an entry of either).
std::optional<Control> joint_control(const model::Model& model, const std::vector<std::string>& at,
                                     double value) {
  const int j = model.joint_index(at[1]);
  if (j < 0) return std::nullopt;
  const model::Joint& joint = model.joint(j);
  const std::string& key = at[2];
  // A rotation given by its Euler angles (`q0: {euler: {sequence, angles_deg: [...]}}`).
  if (key == "q0" && at.size() == 6 && is_index(at[5])) {
    if (at[4] == "angles_deg") return about(value, 180.0, "deg");
    if (at[4] == "angles") return about(value, std::numbers::pi, "rad");
    return std::nullopt;
  }
  // Otherwise the number itself, or an entry of a list of them.
  if (!(at.size() == 3 || (at.size() == 4 && is_index(at[3])))) return std::nullopt;
  const int k = at.size() == 4 ? std::stoi(at[3]) : 0;
  if (key == "q0_deg") return about(value, 180.0, "deg");
  if (key == "v0_deg") return about(value, std::max(360.0, 2.0 * std::abs(value)), "deg/s");
  if (key == "q0" && joint.nq() > k) {
    const std::string unit = model::q_unit(model, joint.q_index + k);
    if (unit == "1") return std::nullopt;  // a quaternion's component: no number to slide alone
    return about(value, unit == "rad" ? std::numbers::pi : std::max(1.0, 2.0 * std::abs(value)),
                 unit);
  }
  if (key == "v0" && joint.nv() > k) {
    return about(value, std::max(10.0, 2.0 * std::abs(value)),
                 model::v_unit(model, joint.v_index + k));
  }
  return std::nullopt;
}

std::optional<Control> control_of(const io::ModelFile& file, const io::FileNumber& number) {
  const std::vector<std::string> at = segments(number.path);
  if (at.size() == 2 && at[0] == "simulation" && at[1] == "duration") {
    return scaled(number.value, "s");
  }
  if (at.size() < 3) return std::nullopt;
  if (at[0] == "bodies") return body_control(at.back(), number.value);
  if (at[0] == "forces" && at.size() == 3) {
    return force_control(file.model, at[1], at[2], number.value);
  }
  if (at[0] == "joints") return joint_control(file.model, at, number.value);
  return std::nullopt;
}

}  // namespace

json live_json(const io::ModelFile& file) {
  // The engine reads model files (YAML): a URDF or MJCF, or a model made in code, has no numbers
  // by path to offer, and the page says so.
  const std::filesystem::path path = file.file;
  if (path.extension() != ".yaml" && path.extension() != ".yml") {
    return {{"available", false},
            {"reason", "the page changes the numbers of a model file (.yaml); this model is " +
                           (file.file.empty() ? std::string("made in code") : file.file)}};
  }
  const io::ModelTemplate model_template(path);
  json parameters = json::array();
  for (const io::FileNumber& number : model_template.numbers()) {
    const std::optional<Control> control = control_of(file, number);
    if (!control) continue;
    parameters.push_back({{"path", number.path},
                          {"value", number.value},
                          {"line", number.line},
                          {"unit", control->unit},
                          {"min", control->min},
                          {"max", control->max},
                          {"scale", control->logarithmic ? "log" : "linear"}});
    if (parameters.size() == kMaxLiveParameters) break;
  }
  return {{"available", true},
          {"file", path.filename().string()},
          {"text", model_template.text()},
          {"parameters", std::move(parameters)}};
}

}  // namespace momenta::report::detail
