// Model files, `controllers:`: feedback laws that read coordinates and drive inputs
// (model/controller.hpp; docs/model-format.md, "Controllers").

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string_view>

#include <fmt/format.h>

#include "model_file/model_file_internal.hpp"
#include "momenta/common/error.hpp"
#include "momenta/model/controller.hpp"

namespace momenta::io::detail {
namespace {

using model::Controller;
using model::ControllerKind;

// The keys every controller takes, and each type's own.
constexpr std::string_view kCommonKeys[] = {"measure", "drives", "sample_time", "sensor",
                                            "actuator"};
const std::vector<EntryType>& controller_types() {
  static const std::vector<EntryType> types = [] {
    std::vector<EntryType> t = {
        {"pid", {"reference", "kp", "ki", "kd", "derivative_filter"}},
        {"state_feedback", {"gain", "state_reference", "feedforward"}},
        {"transfer_function", {"reference", "numerator", "denominator"}},
        {"state_space", {"reference", "A", "B", "C", "D"}},
    };
    for (EntryType& type : t)
      type.keys.insert(type.keys.end(), std::begin(kCommonKeys), std::end(kCommonKeys));
    return t;
  }();
  return types;
}

// One name or a list of names.
std::vector<std::string> names_of(const YamlNode& node) {
  std::vector<std::string> names;
  if (node.is_sequence()) {
    for (const YamlNode& e : node.elements()) names.push_back(e.as_string());
  } else {
    names.push_back(node.as_string());
  }
  if (names.empty()) node.fail("name at least one");
  return names;
}

// A matrix: a number (1×1), a list (one row, or one column where `column`), or a list of rows.
MatX read_matrix(const YamlNode& node, bool column = false) {
  if (!node.is_sequence()) return MatX::Constant(1, 1, node.as_double());
  const std::vector<YamlNode> rows = node.elements();
  if (rows.empty()) node.fail("an empty matrix");
  if (!rows[0].is_sequence()) {
    const VecX flat = node.as_vector();
    return column ? MatX(flat) : MatX(flat.transpose());
  }
  const VecX first = rows[0].as_vector();
  MatX m(static_cast<Eigen::Index>(rows.size()), first.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    m.row(static_cast<Eigen::Index>(i)) =
        rows[i].as_vector(static_cast<std::size_t>(first.size())).transpose();
  }
  return m;
}

std::vector<double> coefficients(const YamlNode& node) {
  const VecX c = node.is_sequence() ? node.as_vector() : VecX::Constant(1, node.as_double());
  return {c.data(), c.data() + c.size()};
}

void read_sensor(const YamlNode& node, model::Sensor& sensor) {
  node.expect_map("a map {quantization, noise, delay, seed}");
  node.check_keys({"quantization", "noise", "delay", "seed"});
  sensor.quantization = node.find_number("quantization", Bound::kNonNegative).value_or(0.0);
  sensor.noise = node.find_number("noise", Bound::kNonNegative).value_or(0.0);
  if (const auto delay = node.find("delay")) {
    const long long n = delay->as_integer();
    if (n < 0 || n > 100000)
      delay->fail(fmt::format("a whole number of samples 0…100000, got {}", n));
    sensor.delay = static_cast<int>(n);
  }
  if (const auto seed = node.find("seed")) {
    const long long n = seed->as_integer();
    if (n < 0 || n > std::numeric_limits<unsigned>::max())
      seed->fail(
          fmt::format("a whole number 0…{}, got {}", std::numeric_limits<unsigned>::max(), n));
    sensor.seed = static_cast<unsigned>(n);
  }
}

void read_actuator(const YamlNode& node, model::Actuator& actuator) {
  node.expect_map("a map {min, max, rate_limit}");
  node.check_keys({"min", "max", "rate_limit"});
  actuator.min = node.find_number("min").value_or(-std::numeric_limits<double>::infinity());
  actuator.max = node.find_number("max").value_or(std::numeric_limits<double>::infinity());
  if (actuator.min > actuator.max) {
    node.fail(fmt::format("min {} exceeds max {}", actuator.min, actuator.max));
  }
  actuator.rate_limit = node.find_number("rate_limit", Bound::kPositive)
                            .value_or(std::numeric_limits<double>::infinity());
}

// `reference:` of a pid or a block: a number (the setpoint) or an input's name.
void read_reference(const YamlNode& e, const Context& ctx, Controller& c) {
  const auto node = e.find("reference");
  if (!node) return;
  if (!node->is_scalar()) node->fail("a number (a setpoint) or the name of an input");
  // A number parses whole as one; anything else names an input.
  const std::string text = node->as_string();
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  const bool number = end != text.c_str() && *end == '\0';
  if (number) {
    c.setpoint = node->as_double();
  } else {
    c.reference = ctx.signals.resolve(*node);
  }
}

Controller read_controller(const YamlNode& e, const std::string_view type, const Context& ctx) {
  Controller c;
  c.name = e.at("name").as_string();
  c.measured = names_of(e.at("measure"));
  c.drives = names_of(e.at("drives"));
  if (const auto T = e.find_number("sample_time", Bound::kPositive)) c.sample_time = *T;
  if (const auto sensor = e.find("sensor")) read_sensor(*sensor, c.sensor);
  if (const auto actuator = e.find("actuator")) read_actuator(*actuator, c.actuator);
  if (type == "pid") {
    c.kind = ControllerKind::pid;
    read_reference(e, ctx, c);
    c.pid.kp = e.find_number("kp").value_or(0.0);
    c.pid.ki = e.find_number("ki").value_or(0.0);
    c.pid.kd = e.find_number("kd").value_or(0.0);
    c.pid.derivative_filter = e.find_number("derivative_filter", Bound::kNonNegative).value_or(0.0);
    if (c.pid.kp == 0.0 && c.pid.ki == 0.0 && c.pid.kd == 0.0)
      e.fail("a pid with kp, ki and kd all zero does nothing: give at least one gain");
  } else if (type == "state_feedback") {
    c.kind = ControllerKind::state_feedback;
    c.gain = read_matrix(e.at("gain"));
    if (const auto x = e.find("state_reference")) c.state_reference = x->as_vector();
    if (const auto u = e.find("feedforward"))
      c.feedforward = u->is_sequence() ? u->as_vector() : VecX::Constant(1, u->as_double());
  } else if (type == "transfer_function") {
    c.kind = ControllerKind::linear;
    read_reference(e, ctx, c);
    try {
      c.block = model::transfer_function_block(coefficients(e.at("numerator")),
                                               coefficients(e.at("denominator")),
                                               "the transfer function");
    } catch (const InvalidArgument& error) {
      e.at("denominator").fail(error.what());
    }
  } else {
    c.kind = ControllerKind::linear;
    read_reference(e, ctx, c);
    c.block.A = e.has("A") ? read_matrix(e.at("A")) : MatX(0, 0);
    c.block.B = e.has("B") ? read_matrix(e.at("B"), true) : MatX::Zero(c.block.A.rows(), 1);
    c.block.C = e.has("C") ? read_matrix(e.at("C")) : MatX::Zero(1, c.block.A.rows());
    c.block.D = e.has("D") ? read_matrix(e.at("D"), true) : MatX::Zero(c.block.C.rows(), 1);
  }
  return c;
}

}  // namespace

void read_controllers(const YamlNode& root, Context& ctx, model::ModelBuilder& builder) {
  for (const YamlNode& e : list_section(root, "controllers")) {
    e.expect_map("a controller: a map with 'name', 'type', 'measure' and 'drives'");
    const YamlNode name = name_node(e);
    const std::string_view type = entry_type(e, controller_types(), "controller").name;
    ctx.controllers.add(name.as_string(), e, name);
    for (std::string_view key : {"measure", "drives"}) {
      if (!e.has(key)) e.fail(fmt::format("a controller needs '{}'", key));
    }
    Controller c = read_controller(e, type, ctx);
    // What it drives is an input the forces and torques name; it is the controller's own, not a
    // signal of time as well.
    const YamlNode drives = e.at("drives");
    for (const std::string& input : c.drives) {
      if (const auto declared = ctx.signals.find(input)) {
        drives.fail(fmt::format(
            "'{}' is already an input of time (line {}); the controller's output takes its "
            "place: remove it from inputs (a disturbance gets its own force and input)",
            input, declared->line()));
      }
      ctx.signals.add(input, e, drives);
      builder.add_signal(model::Signal(input, model::ConstantSignal{0.0}));
    }
    ctx.controllers_read.push_back(std::move(c));
  }
}

model::Model add_controllers(model::Model model, const Context& ctx,
                             const std::vector<model::OutputSpec>& outputs) {
  for (const Controller& c : ctx.controllers_read) {
    try {
      model = model.with_controller(model::with_measured_outputs(c, outputs));
    } catch (const InvalidArgument& e) {
      throw ctx.controllers.find(c.name)->error(one_line(e.what()));
    }
  }
  return model;
}

}  // namespace momenta::io::detail
