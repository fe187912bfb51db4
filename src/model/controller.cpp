#include "momenta/model/controller.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/model/model.hpp"

namespace momenta::model {

const char* controller_kind_name(ControllerKind kind) {
  switch (kind) {
    case ControllerKind::pid:
      return "pid";
    case ControllerKind::state_feedback:
      return "state_feedback";
    case ControllerKind::linear:
      return "linear";
    case ControllerKind::external:
      break;
  }
  return "external";
}

LinearBlock transfer_function_block(const std::vector<double>& num, const std::vector<double>& den,
                                    std::string_view what) {
  // Leading zeros carry no degree.
  auto trimmed = [](const std::vector<double>& p) {
    std::size_t first = 0;
    while (first + 1 < p.size() && p[first] == 0.0) ++first;
    return std::vector<double>(p.begin() + static_cast<std::ptrdiff_t>(first), p.end());
  };
  const std::vector<double> b = trimmed(num), a = trimmed(den);
  for (const std::vector<double>* p : {&b, &a}) {
    for (double c : *p) {
      if (!std::isfinite(c)) throw InvalidArgument(fmt::format("{}: a coefficient is {}", what, c));
    }
  }
  if (a.empty() || a[0] == 0.0) {
    throw InvalidArgument(fmt::format("{}: the denominator is zero", what));
  }
  if (b.empty()) throw InvalidArgument(fmt::format("{}: the numerator is empty", what));
  const int n = static_cast<int>(a.size()) - 1;
  if (static_cast<int>(b.size()) - 1 > n) {
    throw InvalidArgument(fmt::format(
        "{}: the numerator's degree {} exceeds the denominator's {} (an improper transfer "
        "function cannot be realized: add poles, e.g. a derivative filter)",
        what, b.size() - 1, n));
  }
  // Monic denominator s^n + a1 s^(n−1) + … + an; numerator padded to n + 1 coefficients.
  std::vector<double> an(a.size()), bn(a.size(), 0.0);
  for (std::size_t i = 0; i < a.size(); ++i) an[i] = a[i] / a[0];
  for (std::size_t i = 0; i < b.size(); ++i) bn[a.size() - b.size() + i] = b[i] / a[0];
  // Controllable canonical form: ż1 = −a1 z1 − … − an zn + e, ż(i+1) = zi; the direct term
  // b0 and C_i = b_i − b0 a_i.
  LinearBlock block;
  block.A = MatX::Zero(n, n);
  block.B = MatX::Zero(n, 1);
  block.C = MatX::Zero(1, n);
  block.D = MatX::Constant(1, 1, bn[0]);
  for (int i = 0; i < n; ++i) {
    block.A(0, i) = -an[static_cast<std::size_t>(i) + 1];
    block.C(0, i) =
        bn[static_cast<std::size_t>(i) + 1] - bn[0] * an[static_cast<std::size_t>(i) + 1];
    if (i + 1 < n) block.A(i + 1, i) = 1.0;
  }
  if (n > 0) block.B(0, 0) = 1.0;
  return block;
}

namespace {

// Throws naming the controller.
[[noreturn]] void fail(const Controller& c, const std::string& what) {
  throw InvalidArgument(fmt::format("controller '{}': {}", c.name, what));
}

void require_finite(const Controller& c, const MatX& m, std::string_view what) {
  if (!m.allFinite()) fail(c, fmt::format("{} has an entry that is not finite", what));
}

// Why a controller cannot measure `spec` (a quantity that is not of the state alone, or more
// than one value), or "" when it can.
std::string unmeasurable(const OutputSpec& spec, const Model& model) {
  using Q = OutputQuantity;
  switch (spec.quantity) {
    case Q::joint_position:
    case Q::joint_velocity: {
      const auto j = model.find_joint(spec.target);
      const int n = !j                                   ? 0
                    : spec.quantity == Q::joint_position ? model.joint(*j).nq()
                                                         : model.joint(*j).nv();
      return spec.component >= 0 || n == 1
                 ? ""
                 : "has one value per coordinate: choose one with 'component'";
    }
    case Q::body_position:
    case Q::body_velocity:
    case Q::body_angular_velocity:
    case Q::body_euler_angles:
    case Q::body_euler_rates:
    case Q::transport_velocity:
      return spec.component >= 0 ? "" : "has three values: choose one with 'component'";
    case Q::spring_length:
    case Q::spring_tension:
      return "";
    default:
      return "depends on the accelerations or the inputs the loop sets (an algebraic loop): "
             "measure a position- or velocity-level quantity";
  }
}

// Index into [q; v; outputs] of a measured name: a coordinate, else one of the measured outputs.
int measured_index(const Controller& c, const Model& model, const std::string& name) {
  std::vector<std::string_view> names;
  for (int i = 0; i < model.nq(); ++i) {
    if (model.q_name(i) == name) return i;
    names.push_back(model.q_name(i));
  }
  for (int i = 0; i < model.nv(); ++i) {
    if (model.v_name(i) == name) return model.nq() + i;
    names.push_back(model.v_name(i));
  }
  for (std::size_t k = 0; k < c.measured_outputs.size(); ++k) {
    const OutputSpec& spec = c.measured_outputs[k];
    if (spec.name != name) {
      names.push_back(spec.name);
      continue;
    }
    if (const std::string why = unmeasurable(spec, model); !why.empty())
      fail(c, fmt::format("measures output '{}', which {}", name, why));
    return model.nq() + model.nv() + static_cast<int>(k);
  }
  fail(c, fmt::format("measures '{}', which is no coordinate or output of the model{}; it can "
                      "measure: {}",
                      name, did_you_mean(name, names), fmt::join(names, ", ")));
}

int signal_of(const Controller& c, const Model& model, const std::string& name,
              std::string_view role) {
  if (const auto i = model.find_signal(name)) return *i;
  std::vector<std::string_view> names;
  for (const Signal& s : model.signals()) names.push_back(s.name());
  fail(c, fmt::format(
              "{} '{}', which is no input of the model{}{}", role, name, did_you_mean(name, names),
              names.empty() ? "" : fmt::format("; its inputs: {}", fmt::join(names, ", "))));
}

void check_sizes(const Controller& c) {
  const auto n = static_cast<Eigen::Index>(c.measured.size());
  const auto m = static_cast<Eigen::Index>(c.drives.size());
  switch (c.kind) {
    case ControllerKind::pid:
    case ControllerKind::linear:
      if (n != 1)
        fail(c,
             fmt::format("a {} measures one coordinate, not {}", controller_kind_name(c.kind), n));
      if (m != 1 && c.kind == ControllerKind::pid)
        fail(c, fmt::format("a pid drives one input, not {}", m));
      break;
    case ControllerKind::state_feedback:
      if (n == 0) fail(c, "measures nothing: name the state's coordinates");
      if (m == 0) fail(c, "drives nothing: name the inputs K's rows act on");
      break;
    case ControllerKind::external:
      if (n != 0)
        fail(c, "an external law reads the whole state (q, v): it measures nothing by name");
      if (m == 0) fail(c, "drives nothing: name the inputs its law sets");
      if (!c.law || !*c.law) fail(c, "an external controller needs its law (a function)");
      if (c.sensor.quantization != 0.0 || c.sensor.noise != 0.0 || c.sensor.delay != 0)
        fail(c,
             "an external law reads the state as it is: quantize, add noise or delay in the law");
      break;
  }
  if (c.kind == ControllerKind::state_feedback) {
    if (c.gain.rows() != m || c.gain.cols() != n) {
      fail(c, fmt::format("K is {}×{}; it must be {}×{} (one row per driven input, one column per "
                          "measured coordinate)",
                          c.gain.rows(), c.gain.cols(), m, n));
    }
    require_finite(c, c.gain, "K");
    if (c.state_reference.size() != 0 && c.state_reference.size() != n)
      fail(c, fmt::format("x_ref has {} entries for {} measured coordinates",
                          c.state_reference.size(), n));
    if (c.feedforward.size() != 0 && c.feedforward.size() != m)
      fail(c, fmt::format("u_ff has {} entries for {} driven inputs", c.feedforward.size(), m));
    require_finite(c, c.state_reference, "x_ref");
    require_finite(c, c.feedforward, "u_ff");
  }
  if (c.kind == ControllerKind::linear) {
    const LinearBlock& b = c.block;
    const Eigen::Index k = b.A.rows();
    if (b.A.cols() != k || b.B.rows() != k || b.B.cols() != 1 || b.C.cols() != k ||
        b.C.rows() != m || b.D.rows() != m || b.D.cols() != 1) {
      fail(c, fmt::format("the block's matrices do not fit: A {}×{}, B {}×{}, C {}×{}, D {}×{} "
                          "(want A n×n, B n×1, C {}×n, D {}×1 for one error and {} driven "
                          "input{})",
                          b.A.rows(), b.A.cols(), b.B.rows(), b.B.cols(), b.C.rows(), b.C.cols(),
                          b.D.rows(), b.D.cols(), m, m, m, m == 1 ? "" : "s"));
    }
    for (const MatX* x : {&b.A, &b.B, &b.C, &b.D}) require_finite(c, *x, "the block");
  }
}

void check_laws(const Controller& c) {
  if (!(c.sample_time >= 0.0) || !std::isfinite(c.sample_time)) {
    fail(c, fmt::format("sample_time {} s must be positive and finite (or absent: continuous)",
                        c.sample_time));
  }
  const PidGains& g = c.pid;
  for (double x : {g.kp, g.ki, g.kd, g.derivative_filter, c.setpoint}) {
    if (!std::isfinite(x)) fail(c, fmt::format("a gain or the setpoint is {}", x));
  }
  if (g.derivative_filter < 0.0)
    fail(c, fmt::format("derivative_filter {} s must not be negative", g.derivative_filter));
  const Actuator& a = c.actuator;
  if (std::isnan(a.min) || std::isnan(a.max) || a.min > a.max)
    fail(c,
         fmt::format("the actuator's limits [{}, {}] are not a range (min ≤ max)", a.min, a.max));
  if (!(a.rate_limit > 0.0)) fail(c, fmt::format("rate_limit {} must be positive", a.rate_limit));
  const Sensor& s = c.sensor;
  if (!(s.quantization >= 0.0) || !std::isfinite(s.quantization))
    fail(c, fmt::format("quantization {} must be zero or positive", s.quantization));
  if (!(s.noise >= 0.0) || !std::isfinite(s.noise))
    fail(c, fmt::format("noise {} must be zero or positive", s.noise));
  if (s.delay < 0) fail(c, fmt::format("delay {} samples must not be negative", s.delay));
  if (!c.discrete()) {
    const char* needs = s.noise > 0.0                                            ? "sensor noise"
                        : s.delay > 0                                            ? "a delay"
                        : a.rate_limit < std::numeric_limits<double>::infinity() ? "a rate limit"
                                                                                 : nullptr;
    if (needs != nullptr) {
      fail(c, fmt::format("{} needs a sample_time (white noise, a delay of samples and a limit "
                          "per sample are defined for a discrete controller)",
                          needs));
    }
  }
}

}  // namespace

ResolvedController resolve_controller(const Controller& controller, const Model& model) {
  const Controller& c = controller;
  if (c.name.empty()) throw InvalidArgument("a controller needs a name");
  check_sizes(c);
  check_laws(c);
  ResolvedController r;
  r.spec = c;
  for (const std::string& name : c.measured) r.measured.push_back(measured_index(c, model, name));
  // Of the outputs offered, the ones measured stay (each once, in the order first measured).
  const int coordinates = model.nq() + model.nv();
  std::vector<OutputSpec> kept;
  for (int& i : r.measured) {
    if (i < coordinates) continue;
    const OutputSpec& spec = c.measured_outputs[static_cast<std::size_t>(i - coordinates)];
    const auto at = std::find_if(kept.begin(), kept.end(),
                                 [&](const OutputSpec& k) { return k.name == spec.name; });
    i = coordinates + static_cast<int>(at - kept.begin());
    if (at == kept.end()) kept.push_back(spec);
  }
  r.spec.measured_outputs = std::move(kept);
  for (const std::string& name : c.drives) {
    const int s = signal_of(c, model, name, "drives");
    // Driving a prescribed joint's signal commands its coordinate's acceleration: one coordinate
    // per signal, which a ball or free joint's rotation vector is not.
    if (const auto j = model.joint_prescribed_by(s); j && !model.prescribed_coordinate(s)) {
      const Joint& joint = model.joint(*j);
      fail(c, fmt::format("drives '{}', which prescribes the {} joint '{}': a controller commands "
                          "the acceleration of one coordinate (a revolute, prismatic, cylindrical, "
                          "universal or planar joint's), not of a rotation vector",
                          name, joint_type_name(joint.type), joint.name));
    }
    r.drives.push_back(s);
  }
  if (!c.reference.empty()) r.reference = signal_of(c, model, c.reference, "follows the reference");

  // The pid's derivative: the measured position's own rate where there is one and no filter.
  if (c.kind == ControllerKind::pid && c.pid.kd != 0.0 && c.pid.derivative_filter == 0.0 &&
      !c.discrete()) {
    const int i = r.measured[0];
    const int j = i < model.nq() ? model.joint_of_q(i) : -1;
    if (j < 0 || model.joint(j).nq() != model.joint(j).nv()) {
      fail(c, fmt::format("the derivative of '{}' needs a derivative_filter (Tf > 0, s): a "
                          "continuous pid differentiates a position-level coordinate by its rate, "
                          "which '{}' does not have",
                          c.measured[0], c.measured[0]));
    }
    r.measured_rate = model.joint(j).v_index + (i - model.joint(j).q_index);
  }
  return r;
}

Controller with_measured_outputs(Controller controller, const std::vector<OutputSpec>& outputs) {
  controller.measured_outputs = outputs;
  return controller;
}

void check_controller_fits(const ResolvedController& controller, const Model& model) {
  for (const ResolvedController& other : model.controllers()) {
    if (other.spec.name == controller.spec.name)
      throw InvalidArgument(fmt::format("a second controller named '{}'", controller.spec.name));
    for (int s : controller.drives) {
      if (std::find(other.drives.begin(), other.drives.end(), s) != other.drives.end()) {
        throw InvalidArgument(fmt::format(
            "controller '{}' drives '{}', which controller '{}' drives too", controller.spec.name,
            model.signals()[static_cast<std::size_t>(s)].name(), other.spec.name));
      }
    }
  }
}

}  // namespace momenta::model
