// momenta.ModelBuilder: a model made in code, with the model file's vocabulary (keys and type
// names as docs/model-format.md gives them), built and checked by model::ModelBuilder.

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <limits>
#include <map>
#include <numbers>

#include "bindings.hpp"
#include "model_handle.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta/model/model_builder.hpp"

namespace momenta::python {
namespace {

// limits={'lower': x, 'upper': y, 'restitution': e}: a joint's stops (either bound may be absent).
model::JointLimits joint_limits_arg(const py::object& limits) {
  if (!py::isinstance<py::dict>(limits)) {
    throw InvalidArgument("limits: a dict {'lower': ..., 'upper': ..., 'restitution': ...}");
  }
  const py::dict d = limits.cast<py::dict>();
  model::JointLimits l;
  for (const auto& [key, value] : d) {
    const std::string k = key.cast<std::string>();
    const double x = value.cast<double>();
    if (k == "lower") {
      l.lower = x;
    } else if (k == "upper") {
      l.upper = x;
    } else if (k == "restitution") {
      l.restitution = x;
    } else {
      throw InvalidArgument(fmt::format(
          "limits: unknown key '{}'; the keys are 'lower', 'upper' and 'restitution'", k));
    }
  }
  return l;
}

using namespace model;

std::string suggestion(std::string_view word, const std::vector<std::string>& known) {
  const std::vector<std::string_view> views(known.begin(), known.end());
  return did_you_mean(word, views);
}

// The builder and the name the model will carry.
struct Builder {
  ModelBuilder builder;
  std::string name;
  std::vector<std::string> signals;  // the signals added so far (add_signal, add_controller)
  // Added to the built model after the outputs, which a controller may measure.
  std::vector<Controller> controllers;
  std::vector<std::string> outputs;  // each add_output's entry as JSON, the file's `outputs:`
};

// One name or a list of names.
std::vector<std::string> names_arg(const py::handle& object, std::string_view what) {
  if (py::isinstance<py::str>(object)) return {object.cast<std::string>()};
  try {
    return object.cast<std::vector<std::string>>();
  } catch (const py::cast_error&) {
    throw py::type_error(fmt::format("{}: expected a name or a list of names", what));
  }
}

// A matrix from a number, a list (one row, or a column where `column`) or a 2-D array.
MatX block_matrix_arg(const py::handle& object, std::string_view name, bool column = false) {
  const auto a = as_float_array(object, name);
  if (a.ndim() == 0) return MatX::Constant(1, 1, *a.data());
  if (a.ndim() == 1) {
    const Eigen::Map<const VecX> v(a.data(), a.shape(0));
    return column ? MatX(v) : MatX(v.transpose());
  }
  return matrix_arg(object, name, -1, -1);
}

// The controller add_controller describes (keywords as the model file's `controllers:`).
Controller controller_arg(const std::string& name, const std::string& type,
                          const py::handle& measure, const py::handle& drives,
                          const py::dict& given) {
  Controller c;
  c.name = name;
  c.measured = names_arg(measure, "measure");
  c.drives = names_arg(drives, "drives");
  const auto has = [&](const char* key) { return given.contains(key) && !given[key].is_none(); };
  const auto number = [&](const char* key, double fallback) {
    return has(key) ? given[key].cast<double>() : fallback;
  };
  if (has("reference")) {
    const py::handle r = given["reference"];
    if (py::isinstance<py::str>(r)) {
      c.reference = r.cast<std::string>();
    } else {
      c.setpoint = r.cast<double>();
    }
  }
  c.sample_time = number("sample_time", 0.0);
  c.sensor.quantization = number("quantization", 0.0);
  c.sensor.noise = number("noise", 0.0);
  c.sensor.delay = has("delay") ? given["delay"].cast<int>() : 0;
  c.sensor.seed = has("seed") ? given["seed"].cast<unsigned>() : 1u;
  c.actuator.min = number("u_min", -std::numeric_limits<double>::infinity());
  c.actuator.max = number("u_max", std::numeric_limits<double>::infinity());
  c.actuator.rate_limit = number("rate_limit", std::numeric_limits<double>::infinity());
  if (type == "pid") {
    c.kind = ControllerKind::pid;
    c.pid = {number("kp", 0.0), number("ki", 0.0), number("kd", 0.0),
             number("derivative_filter", 0.0)};
  } else if (type == "state_feedback") {
    c.kind = ControllerKind::state_feedback;
    if (!has("gain")) throw py::value_error("add_controller(): a state_feedback needs gain=K");
    c.gain = block_matrix_arg(given["gain"], "gain");
    ArgStorage keep;
    if (has("state_reference"))
      c.state_reference = vector_arg(given["state_reference"], "state_reference", -1, "", keep);
    if (has("feedforward"))
      c.feedforward = block_matrix_arg(given["feedforward"], "feedforward", true).col(0);
  } else if (type == "transfer_function") {
    c.kind = ControllerKind::linear;
    if (!has("numerator") || !has("denominator"))
      throw py::value_error(
          "add_controller(): a transfer_function needs numerator= and denominator=");
    const auto coefficients = [&](const char* key) {
      const MatX m = block_matrix_arg(given[key], key);
      return std::vector<double>(m.data(), m.data() + m.size());
    };
    c.block = transfer_function_block(coefficients("numerator"), coefficients("denominator"),
                                      fmt::format("controller '{}': the transfer function", name));
  } else if (type == "state_space") {
    c.kind = ControllerKind::linear;
    c.block.A = has("A") ? block_matrix_arg(given["A"], "A") : MatX(0, 0);
    c.block.B =
        has("B") ? block_matrix_arg(given["B"], "B", true) : MatX::Zero(c.block.A.rows(), 1);
    c.block.C = has("C") ? block_matrix_arg(given["C"], "C") : MatX::Zero(1, c.block.A.rows());
    c.block.D =
        has("D") ? block_matrix_arg(given["D"], "D", true) : MatX::Zero(c.block.C.rows(), 1);
  } else {
    const std::vector<std::string> types = {"pid", "state_feedback", "transfer_function",
                                            "state_space"};
    throw py::value_error(fmt::format("add_controller(): unknown type '{}'{}; types: {}", type,
                                      suggestion(type, types), fmt::join(types, ", ")));
  }
  return c;
}

// A pose {"position": [x, y, z], "rotation": 3 × 3} (either key optional); None: the identity.
Transform pose_arg(const py::object& pose, std::string_view name) {
  Transform X;
  if (pose.is_none()) return X;
  if (!py::isinstance<py::dict>(pose)) {
    throw py::type_error(fmt::format(
        "{}: expected a dict {{'position': [x, y, z], 'rotation': 3 × 3 matrix}}", name));
  }
  for (const auto& [key, value] : pose.cast<py::dict>()) {
    const std::string k = py::str(key);
    if (k == "position") {
      X.p = vec3_arg(value, fmt::format("{}['position']", name));
    } else if (k == "rotation") {
      X.R = mat3_arg(value, fmt::format("{}['rotation']", name));
    } else {
      throw py::value_error(fmt::format("{}: unknown key '{}'{}; expected position, rotation", name,
                                        k, suggestion(k, {"position", "rotation"})));
    }
  }
  return X;
}

// A vector argument, or a number for a one-coordinate joint; None: empty.
VecX optional_vector(const py::object& x, std::string_view name) {
  if (x.is_none()) return {};
  if (py::isinstance<py::float_>(x) || py::isinstance<py::int_>(x)) {
    return VecX::Constant(1, x.cast<double>());
  }
  ArgStorage storage;
  return vector_arg(x, name, -1, "", storage);
}

// q0 or q0_deg (v0 or v0_deg): at most one, degrees only where every coordinate is an angle
// (`units`: the joint's q or v units; "rad" or "rad/s" for an angle).
VecX initial_coordinates(const py::object& si, const py::object& degrees, JointType type,
                         const char* key, const std::vector<std::string_view>& units,
                         std::string_view angle_unit) {
  const std::string deg_key = fmt::format("{}_deg", key);
  if (degrees.is_none()) return optional_vector(si, key);
  if (!si.is_none()) {
    throw py::value_error(fmt::format("give {} or {}, not both", key, deg_key));
  }
  const bool angles = !units.empty() && std::all_of(units.begin(), units.end(),
                                                    [&](auto u) { return u == angle_unit; });
  if (!angles) {
    throw py::value_error(
        fmt::format("{}: a {} joint's coordinates are not all angles; give {} in SI", deg_key,
                    joint_type_name(type), key));
  }
  return optional_vector(degrees, deg_key) * (std::numbers::pi / 180.0);
}

LoadFrame load_frame(const std::string& frame) {
  if (frame == "world") return LoadFrame::world;
  if (frame == "body") return LoadFrame::body;
  throw InvalidArgument(
      fmt::format("frame '{}': expected 'world' or 'body' (a follower load)", frame));
}

// Reads the keyword parameters of one signal shape into its fields; unknown keys are refused
// with a did-you-mean.
class SignalParameters {
 public:
  SignalParameters(std::string signal, const py::kwargs& kwargs) : signal_(std::move(signal)) {
    for (const auto& [key, value] : kwargs) values_[py::str(key)] = value;
  }
  void read(const char* key, double& field) {
    known_.push_back(key);
    if (auto it = values_.find(key); it != values_.end()) {
      field = it->second.cast<double>();
      values_.erase(it);
    }
  }
  void read(const char* key, std::vector<double>& field) {
    known_.push_back(key);
    if (auto it = values_.find(key); it != values_.end()) {
      field = it->second.cast<std::vector<double>>();
      values_.erase(it);
    }
  }
  void finish(const std::string& type) const {
    if (values_.empty()) return;
    const std::string key = values_.begin()->first;
    throw InvalidArgument(
        fmt::format("signal '{}': a {} signal has no parameter '{}'{}; it takes "
                    "{}",
                    signal_, type, key, suggestion(key, known_), fmt::join(known_, ", ")));
  }

 private:
  std::string signal_;
  std::map<std::string, py::handle> values_;
  std::vector<std::string> known_;
};

Signal::Shape signal_shape(const std::string& name, const std::string& type,
                           const py::kwargs& kwargs) {
  SignalParameters p(name, kwargs);
  const auto done = [&](auto shape) {
    p.finish(type);
    return Signal::Shape(shape);
  };
  if (type == "constant") {
    ConstantSignal s;
    p.read("value", s.value);
    return done(s);
  }
  if (type == "step") {
    StepSignal s;
    p.read("start", s.start), p.read("initial", s.initial), p.read("final", s.final);
    p.read("rise_time", s.rise_time);
    return done(s);
  }
  if (type == "ramp") {
    RampSignal s;
    p.read("start", s.start), p.read("slope", s.slope), p.read("offset", s.offset);
    p.read("stop", s.stop);
    return done(s);
  }
  if (type == "pulse") {
    PulseSignal s;
    p.read("start", s.start), p.read("width", s.width), p.read("amplitude", s.amplitude);
    p.read("offset", s.offset), p.read("period", s.period);
    return done(s);
  }
  if (type == "sine") {
    SineSignal s;
    p.read("amplitude", s.amplitude), p.read("frequency", s.frequency), p.read("phase", s.phase);
    p.read("offset", s.offset), p.read("start", s.start);
    return done(s);
  }
  if (type == "chirp") {
    ChirpSignal s;
    p.read("amplitude", s.amplitude), p.read("f0", s.f0), p.read("f1", s.f1);
    p.read("start", s.start), p.read("duration", s.duration);
    return done(s);
  }
  if (type == "table") {
    TableSignal s;
    p.read("times", s.times), p.read("values", s.values);
    return done(s);
  }
  const std::vector<std::string> types = {"constant", "step",  "ramp", "pulse",
                                          "sine",     "chirp", "table"};
  throw InvalidArgument(fmt::format("signal '{}': unknown type '{}'{}; known: {}", name, type,
                                    suggestion(type, types), fmt::join(types, ", ")));
}

BodyPoint body_point(const std::string& body, const py::object& point, std::string_view name) {
  return BodyPoint{body, vec3_arg(point, name)};
}

}  // namespace

void bind_model_builder(py::module_& m) {
  py::class_<Builder>(m, "ModelBuilder", R"doc(
Builds a Model in code with the vocabulary of model files (docs/model-format.md): add bodies,
joints, force elements and signals in any order, then build(), which checks everything and
raises InvalidArgument (InvalidInertia for mass properties) naming the item at fault.
Every add_* method returns the builder, so calls chain.)doc")
      .def(py::init([](std::string name) {
             return Builder{{}, std::move(name), {}, {}, {}};
           }),
           py::arg("name") = "model")
      .def(
          "set_gravity",
          [](Builder& b, const py::object& g) -> Builder& {
            b.builder.set_gravity(vec3_arg(g, "gravity"));
            return b;
          },
          py::arg("gravity"), "Gravitational acceleration in W, m/s² (default [0, 0, -9.81]).")
      .def(
          "add_body",
          [](Builder& b, std::string name,
             const inertia::MassProperties& mass_properties) -> Builder& {
            b.builder.add_body(std::move(name), mass_properties);
            return b;
          },
          py::arg("name"), py::arg("mass_properties"),
          "A body with its mass properties in its own frame (momenta.inertia).")
      .def(
          "add_joint",
          [](Builder& b, std::string name, const std::string& type, std::string parent,
             std::string child, const py::object& axis, const py::object& axis2,
             const py::object& in_parent, const py::object& in_child, const py::object& q0,
             const py::object& v0, const py::object& q0_deg, const py::object& v0_deg,
             double damping, double armature, const std::vector<std::string>& prescribed,
             const py::object& limits) -> Builder& {
            Joint j;
            j.name = std::move(name);
            j.type = joint_type_from_name(type);
            j.parent = std::move(parent);
            j.child = std::move(child);
            if (!axis.is_none()) j.axis = vec3_arg(axis, "axis");
            if (!axis2.is_none()) j.axis2 = vec3_arg(axis2, "axis2");
            j.X_PJ = pose_arg(in_parent, "in_parent");
            j.X_CJ = pose_arg(in_child, "in_child");
            const JointTraits& traits = joint_traits(j.type);
            const std::vector<std::string_view> q_units(traits.q_units.begin(),
                                                        traits.q_units.begin() + joint_nq(j.type));
            const std::vector<std::string_view> v_units(traits.v_units.begin(),
                                                        traits.v_units.begin() + joint_nv(j.type));
            j.q0 = initial_coordinates(q0, q0_deg, j.type, "q0", q_units, "rad");
            j.v0 = initial_coordinates(v0, v0_deg, j.type, "v0", v_units, "rad/s");
            j.damping = damping;
            j.armature = armature;
            j.prescribed_signals = prescribed;
            if (!limits.is_none()) j.limits = joint_limits_arg(limits);
            b.builder.add_joint(std::move(j));
            return b;
          },
          py::arg("name"), py::arg("type"), py::kw_only(), py::arg("parent"), py::arg("child"),
          py::arg("axis") = py::none(), py::arg("axis2") = py::none(),
          py::arg("in_parent") = py::none(), py::arg("in_child") = py::none(),
          py::arg("q0") = py::none(), py::arg("v0") = py::none(), py::arg("q0_deg") = py::none(),
          py::arg("v0_deg") = py::none(), py::arg("damping") = 0.0, py::arg("armature") = 0.0,
          py::arg("prescribed") = std::vector<std::string>{}, py::arg("limits") = py::none(),
          R"doc(A joint from `parent` (a body or 'world') to `child`. type: fixed, revolute,
prismatic, cylindrical, universal, spherical, planar, free (or the aliases weld, hinge, slider,
ball, floating). axis (in J, default z) and axis2 (universal, in J'); in_parent / in_child: the
poses of J in the parent and J' in the child, {'position': [x, y, z], 'rotation': R}; q0, v0:
initial coordinates (default neutral, zero; a number for a one-coordinate joint), or q0_deg,
v0_deg in degrees where every coordinate is an angle; damping: viscous c on every coordinate; armature:
a motor's reflected rotor inertia on every coordinate (kg·m² or kg), as MuJoCo's; prescribed: one signal name per velocity coordinate (a ball joint: its rotation vector; a
free joint: rotation vector, then position; model/prescribed_motion.hpp); limits: stops on a revolute
or prismatic joint, {'lower': rad or m, 'upper': ..., 'restitution': e in [0, 1]} (either bound may be
left out; docs/contacts.md).)doc")
      .def(
          "add_spring_damper",
          [](Builder& b, std::string name, const std::string& body_a, const py::object& point_a,
             const std::string& body_b, const py::object& point_b, double stiffness, double damping,
             double free_length) -> Builder& {
            b.builder.add_force_element(LinearSpringDamper{
                std::move(name), body_point(body_a, point_a, "point_a"),
                body_point(body_b, point_b, "point_b"), stiffness, damping, free_length});
            return b;
          },
          py::arg("name"), py::kw_only(), py::arg("body_a"), py::arg("point_a"), py::arg("body_b"),
          py::arg("point_b"), py::arg("stiffness") = 0.0, py::arg("damping") = 0.0,
          py::arg("free_length") = 0.0,
          "A spring (N/m) and damper (N·s/m) between two body points (p_BoP_B, m): tension "
          "T = k (ℓ − free_length) + c ℓ̇.")
      .def(
          "add_torsional_spring",
          [](Builder& b, std::string name, std::string joint, std::string body_a,
             std::string body_b, double stiffness, double damping, double rest_angle) -> Builder& {
            TorsionalSpringDamper s;
            s.name = std::move(name);
            s.joint = std::move(joint);
            s.body_a = std::move(body_a);
            s.body_b = std::move(body_b);
            s.stiffness = stiffness;
            s.damping = damping;
            s.rest_angle = rest_angle;
            b.builder.add_force_element(std::move(s));
            return b;
          },
          py::arg("name"), py::kw_only(), py::arg("joint") = "", py::arg("body_a") = "",
          py::arg("body_b") = "", py::arg("stiffness") = 0.0, py::arg("damping") = 0.0,
          py::arg("rest_angle") = 0.0,
          "On a 1-dof joint, τ = −k (q − rest_angle) − c q̇; or between body_a and body_b, "
          "relaxed at the initial configuration.")
      .def(
          "add_tendon",
          [](Builder& b, std::string name,
             const std::vector<std::pair<std::string, double>>& joints, double stiffness,
             double damping, double rest_length, double offset) -> Builder& {
            FixedTendon t;
            t.name = std::move(name);
            for (const auto& [joint, coefficient] : joints)
              t.terms.push_back({joint, coefficient, -1});
            t.stiffness = stiffness;
            t.damping = damping;
            t.rest_length = rest_length;
            t.offset = offset;
            b.builder.add_force_element(std::move(t));
            return b;
          },
          py::arg("name"), py::kw_only(), py::arg("joints"), py::arg("stiffness") = 0.0,
          py::arg("damping") = 0.0, py::arg("rest_length") = 0.0, py::arg("offset") = 0.0,
          "A fixed tendon over 1-dof joints, joints = [(joint, coefficient), ...]: its length "
          "L = offset + Σ cᵢ qᵢ, its tension T = stiffness (L − rest_length) + damping L̇, and "
          "τᵢ = −cᵢ T on each joint (MuJoCo's fixed tendon).")
      .def(
          "add_joint_friction",
          [](Builder& b, std::string name, std::string joint, double viscous) -> Builder& {
            b.builder.add_force_element(JointFriction{std::move(name), std::move(joint), viscous});
            return b;
          },
          py::arg("name"), py::kw_only(), py::arg("joint"), py::arg("viscous"),
          "Viscous friction τ = −viscous · v on every coordinate of a joint.")
      .def(
          "add_force",
          [](Builder& b, std::string name, const std::string& body, const py::object& point,
             const py::object& vector, const std::string& frame, std::string signal) -> Builder& {
            AppliedForce f;
            f.name = std::move(name);
            f.at = body_point(body, point, "point");
            f.vector = vec3_arg(vector, "vector");
            f.frame = load_frame(frame);
            f.signal = std::move(signal);
            b.builder.add_force_element(std::move(f));
            return b;
          },
          py::arg("name"), py::kw_only(), py::arg("body"),
          py::arg("point") = py::make_tuple(0, 0, 0), py::arg("vector"), py::arg("frame") = "world",
          py::arg("signal") = "",
          "A force (N) at a body point: `vector`, or u(t) · vector with a signal; frame 'world' "
          "or 'body' (a follower load).")
      .def(
          "add_torque",
          [](Builder& b, std::string name, std::string body, const py::object& vector,
             const std::string& frame, std::string signal) -> Builder& {
            AppliedTorque t;
            t.name = std::move(name);
            t.body = std::move(body);
            t.vector = vec3_arg(vector, "vector");
            t.frame = load_frame(frame);
            t.signal = std::move(signal);
            b.builder.add_force_element(std::move(t));
            return b;
          },
          py::arg("name"), py::kw_only(), py::arg("body"), py::arg("vector"),
          py::arg("frame") = "world", py::arg("signal") = "",
          "A pure moment (N·m) on a body, constant or u(t) · vector.")
      .def(
          "add_contact",
          [](Builder& b, std::string name, const std::string& body, const py::object& point,
             double radius, const py::object& normal, const py::object& plane_point,
             std::string other_body, const py::object& other_point, double other_radius,
             double restitution, double friction, const py::object& kinetic_friction,
             bool other_plane, const std::string& shape, const py::object& axis) -> Builder& {
            model::Contact c;
            c.name = std::move(name);
            c.frame.body = body;
            c.frame.X_BF.p = vec3_arg(point, "point");
            if (shape == "disk") {
              c.shape = model::ContactShape::disk;
              const Vec3 a = vec3_arg(axis, "axis");
              if (!(a.norm() > 0.0)) throw py::value_error("add_contact: axis must not be zero");
              c.frame.X_BF.R = plane_frame(a.normalized());
            } else if (shape != "sphere") {
              throw py::value_error(fmt::format(
                  "add_contact: unknown shape '{}'; expected 'sphere' or 'disk'", shape));
            }
            c.radius = radius;
            c.plane_normal = vec3_arg(normal, "normal");
            c.plane_point = vec3_arg(plane_point, "plane_point");
            c.other.body = std::move(other_body);
            c.other.X_BF.p = vec3_arg(other_point, "other_point");
            c.other_radius = other_radius;
            c.other_plane = other_plane;
            c.restitution = restitution;
            c.static_friction = friction;
            c.kinetic_friction =
                kinetic_friction.is_none() ? friction : kinetic_friction.cast<double>();
            b.builder.add_constraint(std::move(c));
            return b;
          },
          py::arg("name"), py::kw_only(), py::arg("body"),
          py::arg("point") = py::make_tuple(0, 0, 0), py::arg("radius") = 0.0,
          py::arg("normal") = py::make_tuple(0, 0, 1),
          py::arg("plane_point") = py::make_tuple(0, 0, 0), py::arg("other_body") = "",
          py::arg("other_point") = py::make_tuple(0, 0, 0), py::arg("other_radius") = 0.0,
          py::arg("restitution") = 0.0, py::arg("friction") = 0.0,
          py::arg("kinetic_friction") = py::none(), py::arg("other_plane") = false,
          py::arg("shape") = "sphere", py::arg("axis") = py::make_tuple(0, 0, 1),
          "A unilateral contact of a body's point (radius 0), sphere (centre `point` in the "
          "body, m) or disk rim (shape='disk': centre `point`, `axis` in the body) with the ground "
          "plane through plane_point with unit `normal` (world), or "
          "with other_body's sphere (centre other_point, radius other_radius) — or its plane "
          "(other_plane=True: normal and plane_point in other_body's frame): impacts with "
          "Newton's restitution e ∈ [0, 1], resting contact while it pushes; "
          "Coulomb friction with the static coefficient `friction` and the kinetic one "
          "`kinetic_friction` (≤ friction; the same when left out): it sticks while the cone "
          "holds, slides against the slip beyond (docs/contacts.md).")
      .def(
          "add_signal",
          [](Builder& b, const std::string& name, const std::string& type,
             const py::kwargs& parameters) -> Builder& {
            b.builder.add_signal(Signal(name, signal_shape(name, type, parameters)));
            b.signals.push_back(name);
            return b;
          },
          py::arg("name"), py::arg("type"),
          R"doc(An input signal u(t) with the model file's parameters: constant(value),
step(final, start, initial, rise_time), ramp(slope, start, offset, stop), pulse(amplitude,
width, start, offset, period), sine(amplitude, frequency [Hz], phase [rad], offset, start),
chirp(amplitude, f0, f1, duration, start), table(times, values).)doc")
      .def(
          "add_controller",
          [](Builder& b, const std::string& name, const std::string& type,
             const py::object& measure, const py::object& drives, const py::object& reference,
             double kp, double ki, double kd, double derivative_filter, const py::object& gain,
             const py::object& state_reference, const py::object& feedforward,
             const py::object& numerator, const py::object& denominator, const py::object& A,
             const py::object& B, const py::object& C, const py::object& D, double sample_time,
             double quantization, double noise, int delay, unsigned seed, double u_min,
             double u_max, double rate_limit) -> Builder& {
            py::dict given;
            given["reference"] = reference;
            given["kp"] = kp;
            given["ki"] = ki;
            given["kd"] = kd;
            given["derivative_filter"] = derivative_filter;
            given["gain"] = gain;
            given["state_reference"] = state_reference;
            given["feedforward"] = feedforward;
            given["numerator"] = numerator;
            given["denominator"] = denominator;
            given["A"] = A;
            given["B"] = B;
            given["C"] = C;
            given["D"] = D;
            given["sample_time"] = sample_time;
            given["quantization"] = quantization;
            given["noise"] = noise;
            given["delay"] = delay;
            given["seed"] = seed;
            given["u_min"] = u_min;
            given["u_max"] = u_max;
            given["rate_limit"] = rate_limit;
            Controller c = controller_arg(name, type, measure, drives, given);
            // The inputs it drives are its own: added here as signals the forces can name.
            for (const std::string& input : c.drives) {
              if (std::find(b.signals.begin(), b.signals.end(), input) != b.signals.end()) {
                throw py::value_error(fmt::format(
                    "add_controller(): '{}' is already a signal; the controller's output takes "
                    "its place (give a disturbance its own force and signal)",
                    input));
              }
              b.builder.add_signal(Signal(input, ConstantSignal{0.0}));
              b.signals.push_back(input);
            }
            b.controllers.push_back(std::move(c));
            return b;
          },
          py::arg("name"), py::arg("type"), py::kw_only(), py::arg("measure"), py::arg("drives"),
          py::arg("reference") = py::none(), py::arg("kp") = 0.0, py::arg("ki") = 0.0,
          py::arg("kd") = 0.0, py::arg("derivative_filter") = 0.0, py::arg("gain") = py::none(),
          py::arg("state_reference") = py::none(), py::arg("feedforward") = py::none(),
          py::arg("numerator") = py::none(), py::arg("denominator") = py::none(),
          py::arg("A") = py::none(), py::arg("B") = py::none(), py::arg("C") = py::none(),
          py::arg("D") = py::none(), py::arg("sample_time") = 0.0, py::arg("quantization") = 0.0,
          py::arg("noise") = 0.0, py::arg("delay") = 0, py::arg("seed") = 1u,
          py::arg("u_min") = -std::numeric_limits<double>::infinity(),
          py::arg("u_max") = std::numeric_limits<double>::infinity(),
          py::arg("rate_limit") = std::numeric_limits<double>::infinity(),
          R"doc(A feedback controller, as the model file's `controllers:` (docs/control.md): type
'pid' (kp, ki, kd, derivative_filter), 'state_feedback' (gain K, state_reference, feedforward),
'transfer_function' (numerator, denominator) or 'state_space' (A, B, C, D). `measure` names
coordinates ("x.position", "tilt.angle_rate"), `drives` the inputs it sets (forces name them as
signals; they are added here), `reference` a number or a signal's name. sample_time > 0 makes it
discrete (zero-order hold); the sensor's quantization, noise (σ), delay (samples) and seed, the
actuator's u_min, u_max and rate_limit (per second) as in the file.)doc")
      .def(
          "add_output",
          [](Builder& b, const std::string& name, const py::kwargs& keys) -> Builder& {
            // The entry as the file writes it, in JSON (a YAML flow map): arrays as lists.
            py::dict entry;
            entry["name"] = name;
            for (const auto& [key, value] : keys) {
              entry[key] = py::hasattr(value, "tolist") ? value.attr("tolist")() : value;
            }
            b.outputs.push_back(
                py::module_::import("json").attr("dumps")(entry).cast<std::string>());
            return b;
          },
          py::arg("name"),
          R"doc(A named quantity to record, with the keys of the model file's `outputs:` entries
(docs/model-format.md): one target — body=, joint=, signal=, spring=, tendon= or constraint= —
and quantity=, point=, component=, frame=, sequence=. add_output('nose', body='cart',
quantity='position', point=[0.5, 0, 0], component='x'). Simulations record it as a column,
linearize takes it as an output, and a controller may measure it (a quantity of the state alone,
one value). Checked when build() runs.)doc")
      .def(
          "build",
          [](const Builder& b) {
            model::Model model = b.builder.build();
            std::vector<OutputSpec> outputs;
            if (!b.outputs.empty()) {
              outputs = io::parse_outputs(fmt::format("[{}]", fmt::join(b.outputs, ", ")),
                                          "ModelBuilder.add_output", model);
            }
            for (const Controller& c : b.controllers)
              model = model.with_controller(with_measured_outputs(c, outputs));
            io::ModelFile file{
                b.name, "", std::move(model), std::move(outputs), {}, "", {}, {}, {}, {}, {},
                {},     {}};
            frontend::accept_model(file);
            return ModelHandle{std::make_shared<const io::ModelFile>(std::move(file))};
          },
          "Checks everything and builds the Model (the builder can be reused).");
}

}  // namespace momenta::python
