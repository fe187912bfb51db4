// The live report's controls (docs/report.md, "The live report"): which numbers of the model
// file the page offers to change, with their units and ranges, and the file's text that the
// in-page engine (wasm/) reads them from — by their paths, as sweeps name them.

#include <algorithm>

#include <fmt/format.h>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "momenta/common/error.hpp"
#include "momenta/io/file_template.hpp"
#include "momenta/model/units.hpp"
#include "momenta/report/report.hpp"
#include "momenta/system/output_set.hpp"
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

// A positive quantity: a tenth to ten times the file's value, on a logarithmic slider.
std::optional<Control> scaled(double value, std::string unit) {
  if (!(value > 0.0)) return std::nullopt;  // no scale to offer a range from
  return Control{std::move(unit), value / 10.0, value * 10.0, true};
}

// An initial coordinate or rate: a linear slider about the file's value.
Control about(double value, double half_width, std::string unit) {
  return {std::move(unit), value - half_width, value + half_width, false};
}

// A number of either sign (an amplitude, a force's component, gravity's): a positive one scaled,
// a negative one from twice its size to zero; nothing to offer for a zero.
std::optional<Control> signed_size(double value, std::string unit) {
  if (value > 0.0) return scaled(value, std::move(unit));
  if (value < 0.0) return Control{std::move(unit), 2.0 * value, 0.0, false};
  return std::nullopt;
}

// A time of a signal (a start, a rise time, a width): a tenth to ten times a positive one, else
// a second about it (a ramp may start before the run: the four-bar's crank at −1 s).
Control time_control(double value) {
  return value > 0.0 ? Control{"s", value / 10.0, value * 10.0, true}
                     : about(value, std::max(1.0, std::abs(value)), "s");
}

// Whether body b moves only as prescribed joints move it (every joint from it to the world
// prescribed): its mass changes nothing of the motion.
bool moved_as_prescribed(const model::Model& model, int b) {
  for (; b > 0; b = model.parent(b)) {
    if (!model.joint(b - 1).is_prescribed()) return false;
  }
  return true;
}

std::optional<Control> body_control(const model::Model& model, const std::vector<std::string>& at,
                                    double value) {
  const std::string& key = at.back();
  if (key == "mass") {
    const std::optional<int> b = model.find_body(at[1]);
    if (b && moved_as_prescribed(model, *b)) return std::nullopt;
    return scaled(value, "kg");
  }
  for (const std::string_view length : {"length", "radius", "height", "width", "depth"}) {
    if (key == length) return scaled(value, "m");
  }
  // A principal moment of `inertia: [Ixx, Iyy, Izz]`.
  if (at.size() == 4 && at[2] == "inertia" && io::path_index(at[3])) return scaled(value, "kg·m²");
  return std::nullopt;
}

std::optional<Control> force_control(const model::Model& model, const std::vector<std::string>& at,
                                     double value) {
  const std::string& element = at[1];
  const std::string& key = at[2];
  const bool vector_entry = at.size() == 4 && key == "vector" && io::path_index(at[3]);
  if (at.size() != 3 && !vector_entry) return std::nullopt;
  for (const model::ForceElement& e : model.force_elements()) {
    if (model::force_element_name(e) != element) continue;
    if (std::holds_alternative<model::LinearSpringDamper>(e)) {
      if (key == "stiffness") return scaled(value, "N/m");
      if (key == "damping") return scaled(value, "N·s/m");
      if (key == "free_length") return scaled(value, "m");
    }
    if (const auto* t = std::get_if<model::TorsionalSpringDamper>(&e)) {
      const bool on_length =
          t->joint_index >= 0 && model::q_unit(model, model.joint(t->joint_index).q_index) == "m";
      if (key == "stiffness") return scaled(value, on_length ? "N/m" : "N·m/rad");
      if (key == "damping") return scaled(value, on_length ? "N·s/m" : "N·m·s/rad");
      if (key == "rest_angle")
        return about(value, on_length ? 0.1 : std::numbers::pi, on_length ? "m" : "rad");
      if (key == "rest_angle_deg") return about(value, 180.0, "deg");
    }
    if (const auto* f = std::get_if<model::JointFriction>(&e); f && key == "viscous") {
      return scaled(value, model::joint_damping_unit(model, model.joint(f->joint_index)));
    }
    if (const auto* tendon = std::get_if<model::FixedTendon>(&e)) {
      const model::TendonUnits units = model::tendon_units(model, *tendon);
      if (key == "stiffness") return scaled(value, units.stiffness);
      if (key == "damping") return scaled(value, units.damping);
      if (key == "rest_length" || key == "offset") {
        return about(value, std::max(std::abs(value), units.length == "m" ? 0.1 : 1.0),
                     units.length);
      }
    }
    // A constant applied load's component (with a signal the vector is a direction).
    if (const auto* f = std::get_if<model::AppliedForce>(&e);
        f && vector_entry && f->signal.empty()) {
      return signed_size(value, "N");
    }
    if (const auto* m = std::get_if<model::AppliedTorque>(&e);
        m && vector_entry && m->signal.empty()) {
      return signed_size(value, "N·m");
    }
  }
  return std::nullopt;
}

// A joint's initial coordinate or rate (`q0`, `v0`, their `_deg` forms, an entry of either), its
// damping and armature.
std::optional<Control> joint_control(const model::Model& model, const std::vector<std::string>& at,
                                     double value) {
  const std::optional<int> j = model.find_joint(at[1]);
  if (!j) return std::nullopt;
  const model::Joint& joint = model.joint(*j);
  const std::string& key = at[2];
  // A rotation given by its Euler angles (`q0: {euler: {sequence, angles_deg: [...]}}`).
  if (key == "q0" && at.size() == 6 && io::path_index(at[5])) {
    if (at[4] == "angles_deg") return about(value, 180.0, "deg");
    if (at[4] == "angles") return about(value, std::numbers::pi, "rad");
    return std::nullopt;
  }
  // Otherwise the number itself, or an entry of a list of them.
  if (!(at.size() == 3 || (at.size() == 4 && io::path_index(at[3])))) return std::nullopt;
  const int k = at.size() == 4 ? static_cast<int>(*io::path_index(at[3])) : 0;
  if (key == "damping") return scaled(value, model::joint_damping_unit(model, joint));
  if (key == "armature") return scaled(value, model::joint_armature_unit(model, joint));
  if (key == "q0_deg") return about(value, 180.0, "deg");
  if (key == "v0_deg") return about(value, std::max(360.0, 2.0 * std::abs(value)), "deg/s");
  if (key == "v0_rpm") return about(value, std::max(60.0, 2.0 * std::abs(value)), "rpm");
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

// A signal's numbers: its times in s, its frequencies in Hz, its phase in rad (or deg), its
// values in the unit of what it drives (model::signal_unit), a ramp's slope per second.
std::optional<Control> input_control(const model::Model& model, const std::vector<std::string>& at,
                                     double value) {
  const std::optional<int> s = model.find_signal(at[1]);
  if (!s || at.size() != 3) return std::nullopt;
  const std::string& key = at[2];
  for (const std::string_view time :
       {"start", "rise_time", "width", "period", "duration", "stop"}) {
    if (key == time) return time_control(value);
  }
  if (key == "frequency" || key == "f0" || key == "f1") return scaled(value, "Hz");
  if (key == "phase") return about(value, std::numbers::pi, "rad");
  if (key == "phase_deg") return about(value, 180.0, "deg");
  const std::string unit = model::signal_unit(model, *s);
  if (key == "slope") return signed_size(value, unit.empty() ? "1/s" : unit + "/s");
  for (const std::string_view level : {"value", "initial", "final", "amplitude", "offset"}) {
    if (key == level) return signed_size(value, unit);
  }
  return std::nullopt;
}

// The unit of what a controller measures (its first quantity): a coordinate's, a rate's or an
// output's.
std::string measured_unit(const model::Model& model, const model::ResolvedController& c) {
  if (c.measured.empty()) return "";
  const int i = c.measured.front();
  if (i < model.nq()) return model::q_unit(model, i);
  if (i < model.nq() + model.nv()) return model::v_unit(model, i - model.nq());
  const model::OutputSpec& spec =
      c.spec.measured_outputs[static_cast<std::size_t>(i - model.nq() - model.nv())];
  const system::OutputSet output(model, {spec});
  return output.column_units().empty() ? "" : output.column_units().front();
}

// A PID's gains: kp the output's unit per the measured one's, ki per second more, kd a second
// less; a constant reference in the measured unit, its filter's time constant and sample time
// in s.
std::optional<Control> controller_control(const model::Model& model,
                                          const std::vector<std::string>& at, double value) {
  if (at.size() != 3) return std::nullopt;
  const std::string& key = at[2];
  for (const model::ResolvedController& c : model.controllers()) {
    if (c.spec.name != at[1]) continue;
    if (key == "sample_time" || key == "derivative_filter") return scaled(value, "s");
    if (c.spec.kind != model::ControllerKind::pid || c.drives.empty()) return std::nullopt;
    const std::string measured = measured_unit(model, c);
    const std::string output = model::signal_unit(model, c.drives.front());
    if (key == "reference") return about(value, std::max(1.0, 2.0 * std::abs(value)), measured);
    if (measured.empty() || output.empty()) return std::nullopt;
    const std::string kp = model::unit_ratio(output, measured);
    if (key == "kp") return scaled(value, kp);
    if (key == "ki") return scaled(value, model::unit_ratio(kp, "s"));
    if (key == "kd") return scaled(value, model::unit_ratio(kp, "1/s"));
  }
  return std::nullopt;
}

std::optional<Control> control_of(const io::ModelFile& file, const std::string& path,
                                  double value) {
  const std::vector<std::string> at = io::path_segments(path);
  const model::Model& model = file.model;
  if (at.size() == 2 && at[0] == "simulation" && at[1] == "duration") return scaled(value, "s");
  if (at.size() == 2 && at[0] == "gravity") return signed_size(value, "m/s²");
  if (at.size() < 3) return std::nullopt;
  if (at[0] == "bodies") return body_control(model, at, value);
  if (at[0] == "forces") return force_control(model, at, value);
  if (at[0] == "joints") return joint_control(model, at, value);
  if (at[0] == "inputs") return input_control(model, at, value);
  if (at[0] == "controllers") return controller_control(model, at, value);
  return std::nullopt;
}

json control_json(const std::string& path, double value, int line, const Control& control) {
  return {{"path", path},
          {"value", value},
          {"line", line},
          {"unit", control.unit},
          {"min", control.min},
          {"max", control.max},
          {"scale", control.logarithmic ? "log" : "linear"}};
}

// The numbers the file's `live:` section lists, with its ranges where it gives them (else the
// page's own, or about the value for a number momenta has no rule for).
json listed_controls(const io::ModelFile& file, const io::ModelTemplate& model_template) {
  json parameters = json::array();
  for (const io::ModelFile::LiveNumber& listed : file.live_numbers) {
    const double value = model_template.number_at(listed.path).value();
    Control control = control_of(file, listed.path, value)
                          .value_or(about(value, std::max(1.0, std::abs(value)), ""));
    if (listed.min || listed.max) {
      control.min = listed.min.value_or(std::min(control.min, value));
      control.max = listed.max.value_or(std::max(control.max, value));
      control.logarithmic = control.logarithmic && control.min > 0.0;
      if (value < control.min || value > control.max) {
        throw ParseError(
            file.file, listed.line, listed.column,
            fmt::format("live: '{}' is {} in the file, outside the range given [{}, {}]",
                        listed.path, value, control.min, control.max));
      }
    }
    parameters.push_back(control_json(listed.path, value, listed.line, control));
  }
  return parameters;
}

// The page's own choice: every number of the file it has a rule for, in the file's order.
json chosen_controls(const io::ModelFile& file, const io::ModelTemplate& model_template) {
  json parameters = json::array();
  for (const io::FileNumber& number : model_template.numbers()) {
    const std::optional<Control> control = control_of(file, number.path, number.value);
    if (!control) continue;
    parameters.push_back(control_json(number.path, number.value, number.line, *control));
    if (parameters.size() == kMaxLiveParameters) break;
  }
  return parameters;
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
  json parameters = file.live_numbers.empty() ? chosen_controls(file, model_template)
                                              : listed_controls(file, model_template);
  return {{"available", true},
          {"file", path.filename().string()},
          {"text", model_template.text()},
          {"parameters", std::move(parameters)}};
}

}  // namespace momenta::report::detail
