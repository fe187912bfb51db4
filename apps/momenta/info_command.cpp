// `momenta info MODEL`: what a model file describes — degrees of freedom, bodies with their mass
// properties, joints and their coordinates, force elements, signals, outputs and simulation
// settings — as text or JSON. Reads the file with momenta::io and prints what the Model holds.
// Documented in docs/cli.md.

#include <cmath>
#include <memory>
#include <string>
#include <variant>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "model_argument.hpp"
#include "momenta/common/error.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/model/units.hpp"
#include "momenta/system/freedoms.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta/system/output_set.hpp"
#include "option_spelling.hpp"
#include "output_format.hpp"

namespace momenta::cli {
namespace {

// Ordered: keys print in the order written.
using json = nlohmann::ordered_json;

// The file's notes with the options they name as the command line spells them (--link-density).
std::vector<std::string> spelled_notes(const io::ModelFile& file) {
  std::vector<std::string> notes;
  for (const std::string& note : file.notes)
    notes.push_back(spell_options(note, command_line_spelling));
  return notes;
}

struct InfoOptions {
  ModelArgument model;
  bool json = false;
};

std::string body_point_text(const model::BodyPoint& p) {
  return fmt::format("{} {}", p.body, vec_text(p.p_BoP_B));
}

const char* frame_name(model::LoadFrame frame) {
  return frame == model::LoadFrame::world ? "world" : "body";
}

// A constraint's kind and rows; a contact's shapes and restitution besides.
json constraint_json(const model::Constraint& constraint) {
  json j = {{"name", model::constraint_name(constraint)},
            {"type", model::constraint_type_name(constraint)},
            {"rows", model::constraint_rows(constraint)}};
  if (const auto* c = std::get_if<model::Contact>(&constraint)) {
    j["body"] = c->frame.body;
    j["point"] = vec_json(c->frame.X_BF.p);
    j["radius"] = c->radius;
    j["shape"] = c->shape == model::ContactShape::disk ? "disk" : "sphere";
    if (c->shape == model::ContactShape::disk) j["axis"] = vec_json(c->frame.X_BF.R.col(2));
    if (c->on_plane()) {
      j["plane"] = {{"normal", vec_json(c->plane_normal)}, {"point", vec_json(c->plane_point)}};
      // A body's plane: its normal and point in that body's frame.
      if (c->other_plane) j["plane"]["body"] = c->other.body;
    } else {
      j["other_body"] = c->other.body;
      j["other_point"] = vec_json(c->other.X_BF.p);
      j["other_radius"] = c->other_radius;
    }
    j["restitution"] = c->restitution;
    j["static_friction"] = c->static_friction;
    j["kinetic_friction"] = c->kinetic_friction;
  }
  return j;
}

// A constraint's line: its kind and rows, or what a contact touches.
std::string constraint_text(const model::Constraint& constraint) {
  const auto* c = std::get_if<model::Contact>(&constraint);
  if (c == nullptr) {
    const int rows = model::constraint_rows(constraint);
    return fmt::format("{} ({} row{})", model::constraint_type_name(constraint), rows,
                       rows == 1 ? "" : "s");
  }
  const auto shape = [](const std::string& body, const Vec3& p, double r) {
    return r > 0.0 ? fmt::format("{}'s sphere (radius {:.6g} m, centre {} m)", body, r, vec_text(p))
                   : fmt::format("{}'s point {} m", body, vec_text(p));
  };
  const std::string other =
      c->on_ground() ? fmt::format("the ground plane (normal {}, through {} m)",
                                   vec_text(c->plane_normal), vec_text(c->plane_point))
      : c->other_plane
          ? fmt::format("{}'s plane (normal {}, through {} m, in {}'s frame)", c->other.body,
                        vec_text(c->plane_normal), vec_text(c->plane_point), c->other.body)
          : shape(c->other.body, c->other.X_BF.p, c->other_radius);
  const std::string friction =
      c->has_friction()
          ? fmt::format("friction μs {:.6g}, μk {:.6g}", c->static_friction, c->kinetic_friction)
          : std::string("frictionless");
  // On a plane a disk touches by its rim; a sphere may meet its face or its rim.
  const std::string body =
      c->shape == model::ContactShape::disk
          ? fmt::format("{}'s disk {}(radius {:.6g} m, centre {} m, axis {})", c->frame.body,
                        c->on_plane() ? "rim " : "", c->radius, vec_text(c->frame.X_BF.p),
                        vec_text(c->frame.X_BF.R.col(2)))
          : shape(c->frame.body, c->frame.X_BF.p, c->radius);
  return fmt::format("contact, {} on {}, restitution {:.6g}, {}", body, other, c->restitution,
                     friction);
}

// A force element's kind and parameters.
json element_json(const model::ForceElement& element) {
  return std::visit(
      [](const auto& e) -> json {
        using T = std::decay_t<decltype(e)>;
        json j;
        j["name"] = e.name;
        if constexpr (std::is_same_v<T, model::LinearSpringDamper>) {
          j["kind"] = "linear_spring_damper";
          j["a"] = {{"body", e.a.body}, {"point", vec_json(e.a.p_BoP_B)}};
          j["b"] = {{"body", e.b.body}, {"point", vec_json(e.b.p_BoP_B)}};
          j["stiffness"] = e.stiffness;
          j["damping"] = e.damping;
          j["free_length"] = e.free_length;
        } else if constexpr (std::is_same_v<T, model::TorsionalSpringDamper>) {
          j["kind"] = "torsional_spring_damper";
          if (!e.joint.empty()) {
            j["joint"] = e.joint;
          } else {
            j["body_a"] = e.body_a;
            j["body_b"] = e.body_b;
          }
          j["stiffness"] = e.stiffness;
          j["damping"] = e.damping;
          if (!e.joint.empty()) j["rest_angle"] = e.rest_angle;
        } else if constexpr (std::is_same_v<T, model::JointFriction>) {
          j["kind"] = "joint_friction";
          j["joint"] = e.joint;
          j["viscous"] = e.viscous;
        } else if constexpr (std::is_same_v<T, model::FixedTendon>) {
          j["kind"] = "fixed_tendon";
          j["joints"] = json::array();
          for (const model::TendonTerm& term : e.terms) {
            j["joints"].push_back({{"joint", term.joint}, {"coefficient", term.coefficient}});
          }
          j["offset"] = e.offset;
          j["stiffness"] = e.stiffness;
          j["damping"] = e.damping;
          j["rest_length"] = e.rest_length;
        } else if constexpr (std::is_same_v<T, model::AppliedForce>) {
          j["kind"] = "applied_force";
          j["body"] = e.at.body;
          j["point"] = vec_json(e.at.p_BoP_B);
          j["frame"] = frame_name(e.frame);
          j["vector"] = vec_json(e.vector);
          j["signal"] = e.signal.empty() ? json(nullptr) : json(e.signal);
        } else {
          j["kind"] = "applied_torque";
          j["body"] = e.body;
          j["frame"] = frame_name(e.frame);
          j["vector"] = vec_json(e.vector);
          j["signal"] = e.signal.empty() ? json(nullptr) : json(e.signal);
        }
        return j;
      },
      element);
}

std::string element_text(const model::Model& model, const model::ForceElement& element) {
  return std::visit(
      [&model](const auto& e) -> std::string {
        using T = std::decay_t<decltype(e)>;
        if constexpr (std::is_same_v<T, model::LinearSpringDamper>) {
          return fmt::format(
              "linear spring-damper  {} — {}: k {:.6g} N/m, c {:.6g} N·s/m, free length {:.6g} m",
              body_point_text(e.a), body_point_text(e.b), e.stiffness, e.damping, e.free_length);
        } else if constexpr (std::is_same_v<T, model::TorsionalSpringDamper>) {
          if (!e.joint.empty()) {
            return fmt::format(
                "torsional spring-damper on joint {}: k {:.6g}, c {:.6g}, rest {:.6g}", e.joint,
                e.stiffness, e.damping, e.rest_angle);
          }
          return fmt::format(
              "torsional spring-damper {} — {}: k {:.6g} N·m/rad, c {:.6g} N·m·s/rad", e.body_a,
              e.body_b, e.stiffness, e.damping);
        } else if constexpr (std::is_same_v<T, model::JointFriction>) {
          return fmt::format("joint friction on {}: viscous {:.6g}", e.joint, e.viscous);
        } else if constexpr (std::is_same_v<T, model::FixedTendon>) {
          // "fixed tendon L = 0.5 hip − 0.5 knee (rad): k 3 N·m/rad, c 0 N·m·s/rad, rest 0 rad"
          const model::TendonUnits units = model::tendon_units(model, e);
          std::string sum = e.offset != 0.0 ? fmt::format("{:.6g}", e.offset) : "";
          for (const model::TendonTerm& term : e.terms) {
            const bool first = sum.empty(), minus = term.coefficient < 0;
            const char* sign = first ? (minus ? "−" : "") : (minus ? " − " : " + ");
            sum += fmt::format("{}{:.6g} {}", sign, std::abs(term.coefficient), term.joint);
          }
          return fmt::format("fixed tendon L = {} ({}): k {:.6g} {}, c {:.6g} {}, rest {:.6g} {}",
                             sum, units.length, e.stiffness, units.stiffness, e.damping,
                             units.damping, e.rest_length, units.length);
        } else if constexpr (std::is_same_v<T, model::AppliedForce>) {
          return fmt::format("applied force at {}: {} N in {}{}", body_point_text(e.at),
                             vec_text(e.vector), frame_name(e.frame),
                             e.signal.empty() ? "" : " × signal " + e.signal);
        } else {
          return fmt::format("applied torque on {}: {} N·m in {}{}", e.body, vec_text(e.vector),
                             frame_name(e.frame), e.signal.empty() ? "" : " × signal " + e.signal);
        }
      },
      element);
}

// A signal's shape and parameters.
json signal_json(const model::Signal& signal) {
  json j;
  j["name"] = signal.name();
  std::visit(
      [&j](const auto& s) {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, model::ConstantSignal>) {
          j["kind"] = "constant";
          j["value"] = s.value;
        } else if constexpr (std::is_same_v<T, model::StepSignal>) {
          j["kind"] = "step";
          j["start"] = s.start;
          j["initial"] = s.initial;
          j["final"] = s.final;
          j["rise_time"] = s.rise_time;
        } else if constexpr (std::is_same_v<T, model::RampSignal>) {
          j["kind"] = "ramp";
          j["start"] = s.start;
          j["slope"] = s.slope;
          j["offset"] = s.offset;
          j["stop"] = std::isfinite(s.stop) ? json(s.stop) : json(nullptr);
        } else if constexpr (std::is_same_v<T, model::PulseSignal>) {
          j["kind"] = "pulse";
          j["start"] = s.start;
          j["width"] = s.width;
          j["amplitude"] = s.amplitude;
          j["offset"] = s.offset;
          j["period"] = s.period;
        } else if constexpr (std::is_same_v<T, model::SineSignal>) {
          j["kind"] = "sine";
          j["amplitude"] = s.amplitude;
          j["frequency"] = s.frequency;
          j["phase"] = s.phase;
          j["offset"] = s.offset;
          j["start"] = s.start;
        } else if constexpr (std::is_same_v<T, model::ChirpSignal>) {
          j["kind"] = "chirp";
          j["amplitude"] = s.amplitude;
          j["f0"] = s.f0;
          j["f1"] = s.f1;
          j["start"] = s.start;
          j["duration"] = s.duration;
        } else {
          j["kind"] = "table";
          j["times"] = s.times;
          j["values"] = s.values;
        }
      },
      signal.shape());
  return j;
}

std::string signal_text(const json& j) {
  std::string text = j["kind"].get<std::string>();
  if (j["kind"] == "table") {
    const auto& times = j["times"];
    return fmt::format("table of {} points, t from {:.6g} to {:.6g} s", times.size(),
                       times.front().get<double>(), times.back().get<double>());
  }
  const char* separator = " ";
  for (const auto& [key, value] : j.items()) {
    if (key == "name" || key == "kind") continue;
    text += fmt::format("{}{} {}", separator, key,
                        value.is_null() ? std::string("none") : value.dump());
    separator = ", ";
  }
  return text;
}

// "1 (3 joint speeds, 1 prescribed, 2 independent constraint rows of 3)", or "2" alone when
// nothing takes any.
std::string freedoms_text(const json& f) {
  const int speeds = f["speeds"], prescribed = f["prescribed"];
  const int rows = f["constraint_rows"], independent = f["independent_constraint_rows"];
  std::string text = std::to_string(f["free"].get<int>());
  if (prescribed == 0 && rows == 0) return text;
  text += fmt::format(" ({} joint speed{}", speeds, speeds == 1 ? "" : "s");
  if (prescribed > 0) text += fmt::format(", {} prescribed", prescribed);
  if (rows > 0) {
    text +=
        fmt::format(", {} independent constraint row{}", independent, independent == 1 ? "" : "s");
    if (independent < rows) text += fmt::format(" of {}", rows);
  }
  return text + ")";
}

// Everything `info` reports, as JSON; the text form prints from it.
json describe(const InfoOptions& o, const io::ModelFile& file) {
  const model::Model& m = file.model;
  const system::MultibodySystem system(m);
  json j;
  j["file"] = o.model.file;
  j["name"] = file.name;
  j["description"] = file.description;
  j["gravity"] = vec_json(m.gravity());
  j["nq"] = m.nq();
  const system::Freedoms freedoms = system::count_freedoms(m);
  j["degrees_of_freedom"] = {{"free", freedoms.free()},
                             {"speeds", freedoms.speeds},
                             {"prescribed", freedoms.prescribed},
                             {"constraint_rows", freedoms.constraint_rows},
                             {"independent_constraint_rows", freedoms.independent_rows}};
  j["nv"] = m.nv();
  j["total_mass"] = m.total_mass();
  j["conserves_energy"] = system.conserves_energy();
  j["conserves_angular_momentum"] = system.conserves_angular_momentum();

  json bodies = json::array();
  for (int b = 1; b < m.num_bodies(); ++b) {
    const model::Body& body = m.body(b);
    const inertia::MassProperties& mp = body.mass_properties;
    bodies.push_back({{"name", body.name},
                      {"joint", m.joint(body.joint_index).name},
                      {"mass", mp.mass()},
                      {"com", vec_json(mp.center_of_mass())},
                      {"inertia_com", matrix_json(mp.inertia_about_com())},
                      {"principal_moments", vec_json(mp.principal_axes().moments)}});
  }
  j["bodies"] = std::move(bodies);

  json joints = json::array();
  for (const model::Joint& joint : m.joints()) {
    json q = json::array(), v = json::array();
    for (int i = 0; i < joint.nq(); ++i)
      q.push_back(
          {{"name", m.q_name(joint.q_index + i)}, {"unit", model::q_unit(m, joint.q_index + i)}});
    for (int i = 0; i < joint.nv(); ++i)
      v.push_back(
          {{"name", m.v_name(joint.v_index + i)}, {"unit", model::v_unit(m, joint.v_index + i)}});
    json entry = {{"name", joint.name},          {"type", model::joint_type_name(joint.type)},
                  {"parent", joint.parent},      {"child", joint.child},
                  {"q_index", joint.q_index},    {"v_index", joint.v_index},
                  {"coordinates", std::move(q)}, {"speeds", std::move(v)},
                  {"damping", joint.damping},    {"armature", joint.armature}};
    entry["prescribed_by"] = joint.prescribed_signals;
    if (joint.limits) {
      // JSON has no infinity: an absent stop is null.
      const auto bound = [](double x) { return std::isfinite(x) ? json(x) : json(nullptr); };
      entry["limits"] = {{"lower", bound(joint.limits->lower)},
                         {"upper", bound(joint.limits->upper)},
                         {"restitution", joint.limits->restitution}};
    }
    joints.push_back(std::move(entry));
  }
  j["joints"] = std::move(joints);

  json constraints = json::array();
  for (const model::Constraint& c : m.constraints()) constraints.push_back(constraint_json(c));
  j["constraints"] = std::move(constraints);

  json elements = json::array();
  for (const model::ForceElement& e : m.force_elements()) elements.push_back(element_json(e));
  j["force_elements"] = std::move(elements);

  json signals = json::array();
  for (const model::Signal& s : m.signals()) signals.push_back(signal_json(s));
  j["signals"] = std::move(signals);

  // Controllers: kind, what each measures and drives, its sample time (0: continuous).
  json controllers = json::array();
  for (const model::ResolvedController& c : m.controllers()) {
    controllers.push_back({{"name", c.spec.name},
                           {"type", model::controller_kind_name(c.spec.kind)},
                           {"measures", c.spec.measured},
                           {"drives", c.spec.drives},
                           {"sample_time", c.spec.sample_time}});
  }
  j["controllers"] = std::move(controllers);

  // Outputs with the columns each gives, resolved as `simulate` resolves them.
  json out = json::array();
  for (const model::OutputSpec& spec : file.outputs) {
    const system::OutputSet one(m, {spec});
    out.push_back({{"name", spec.name},
                   {"quantity", model::output_quantity_name(spec.quantity)},
                   {"target", spec.target},
                   {"columns", one.column_names()}});
  }
  j["outputs"] = std::move(out);

  const model::SimulationSettings& s = file.simulation;
  json settings = json::object();
  if (s.duration) settings["duration"] = *s.duration;
  if (s.step) settings["step"] = *s.step;
  if (s.integrator) settings["integrator"] = *s.integrator;
  if (s.relative_tolerance) settings["rtol"] = *s.relative_tolerance;
  if (s.absolute_tolerance) settings["atol"] = *s.absolute_tolerance;
  if (s.every) settings["every"] = *s.every;
  j["simulation"] = std::move(settings);
  j["not_used"] = spelled_notes(file);  // what a URDF says that momenta does not use, with its line
  json keyframes = json::array();       // an MJCF file's named states, in momenta's q and v
  for (const io::Keyframe& key : file.keyframes) {
    keyframes.push_back({{"name", key.name},
                         {"time", key.time},
                         {"q", std::vector<double>(key.q.data(), key.q.data() + key.q.size())},
                         {"v", std::vector<double>(key.v.data(), key.v.data() + key.v.size())}});
  }
  j["keyframes"] = std::move(keyframes);
  return j;
}

void print_text(const json& j, const io::ModelFile& file) {
  const model::Model& m = file.model;
  fmt::print("{} ({})\n", j["name"].get<std::string>(), j["file"].get<std::string>());
  if (!file.description.empty()) fmt::print("{}\n", file.description);
  fmt::print("\ndegrees of freedom  {}\n", freedoms_text(j["degrees_of_freedom"]));
  fmt::print("coordinates         nq {}, nv {}\n", m.nq(), m.nv());
  fmt::print("gravity             {} m/s²\n", vec_text(m.gravity()));
  fmt::print("total mass          {:.9g} kg\n", m.total_mass());
  fmt::print("conserves           energy: {}; angular momentum about the centre of mass: {}\n",
             j["conserves_energy"].get<bool>() ? "yes" : "no",
             j["conserves_angular_momentum"].get<bool>() ? "yes" : "no");

  fmt::print("\nbodies ({})\n", m.num_bodies() - 1);
  for (int b = 1; b < m.num_bodies(); ++b) {
    const model::Body& body = m.body(b);
    const inertia::MassProperties& mp = body.mass_properties;
    fmt::print("  {}  (on joint {})\n", body.name, m.joint(body.joint_index).name);
    fmt::print("    mass               {:.9g} kg\n", mp.mass());
    fmt::print("    centre of mass     {} m (in {})\n",
               vec_text(shown(mp.center_of_mass(), length_scale(mp))), body.name);
    fmt::print("    inertia about com  ");
    const Mat3 I = shown(mp.inertia_about_com());
    for (int r = 0; r < 3; ++r) {
      fmt::print("{}[{:>13.6e} {:>13.6e} {:>13.6e} ]\n", r == 0 ? "" : "                       ",
                 I(r, 0), I(r, 1), I(r, 2));
    }
    const Vec3 moments = mp.principal_axes().moments;
    fmt::print("    principal moments  {} kg·m²\n", vec_text(shown(moments, moments.maxCoeff())));
  }

  fmt::print("\njoints ({})\n", m.num_joints());
  for (const model::Joint& joint : m.joints()) {
    fmt::print("  {}  {}, {} → {}", joint.name, model::joint_type_name(joint.type), joint.parent,
               joint.child);
    if (joint.damping > 0.0) fmt::print(", damping {:.6g}", joint.damping);
    if (joint.armature > 0.0) {
      const std::string unit = model::joint_armature_unit(m, joint);
      fmt::print(", armature {:.6g} {}", joint.armature, unit.empty() ? "(kg·m² or kg)" : unit);
    }
    if (joint.limits) {
      const std::string unit = model::q_unit(m, joint.q_index);
      const auto bound = [&](double x) {
        return std::isfinite(x) ? fmt::format("{:.6g} {}", x, unit) : std::string("none");
      };
      fmt::print(", stops: lower {}, upper {}, restitution {:.6g}", bound(joint.limits->lower),
                 bound(joint.limits->upper), joint.limits->restitution);
    }
    fmt::print("\n");
    for (int i = 0; i < joint.nq(); ++i) {
      fmt::print("    {}  {}", m.q_name(joint.q_index + i), model::q_unit(m, joint.q_index + i));
      if (joint.is_prescribed() && joint.nq() == joint.nv())
        fmt::print("  prescribed by signal {}", joint.prescribed_signals[i]);
      fmt::print("\n");
    }
    for (int i = 0; i < joint.nv(); ++i)
      fmt::print("    {}  {}\n", m.v_name(joint.v_index + i), model::v_unit(m, joint.v_index + i));
    if (joint.is_prescribed() && joint.nq() != joint.nv()) {
      fmt::print("    prescribed by signals {} ({})\n", fmt::join(joint.prescribed_signals, ", "),
                 joint.type == model::JointType::free ? "rotation vector, then position"
                                                      : "rotation vector");
    }
  }

  if (m.has_constraints()) {
    fmt::print("\nconstraints ({})\n", m.constraints().size());
    for (const model::Constraint& c : m.constraints())
      fmt::print("  {}  {}\n", model::constraint_name(c), constraint_text(c));
  }

  fmt::print("\nforce elements ({})\n", m.force_elements().size());
  for (const model::ForceElement& e : m.force_elements())
    fmt::print("  {}  {}\n", model::force_element_name(e), element_text(m, e));

  fmt::print("\nsignals ({})\n", m.signals().size());
  for (std::size_t i = 0; i < m.signals().size(); ++i) {
    const json& s = j["signals"][i];
    fmt::print(
        "  {}  {}\n", s["name"].get<std::string>(),
        m.is_driven(static_cast<int>(i)) ? std::string("driven by a controller") : signal_text(s));
  }
  if (m.has_controllers()) {
    fmt::print("\ncontrollers ({})\n", m.controllers().size());
    for (const model::ResolvedController& c : m.controllers()) {
      fmt::print("  {}  {} measuring {}, driving {}, {}\n", c.spec.name,
                 model::controller_kind_name(c.spec.kind), fmt::join(c.spec.measured, ", "),
                 fmt::join(c.spec.drives, ", "),
                 c.spec.discrete() ? fmt::format("sampled every {} s", c.spec.sample_time)
                                   : std::string("continuous"));
    }
  }

  fmt::print("\noutputs ({})\n", j["outputs"].size());
  for (const json& out : j["outputs"]) {
    std::string columns;
    for (const json& c : out["columns"])
      columns += (columns.empty() ? "" : ", ") + c.get<std::string>();
    // A tendon's length and tension, in the words its file gives them.
    const std::string target = out["target"].get<std::string>();
    std::string quantity = out["quantity"].get<std::string>() + " of";
    const auto& elements = file.model.force_elements();
    if (std::any_of(elements.begin(), elements.end(), [&](const model::ForceElement& e) {
          return std::holds_alternative<model::FixedTendon>(e) &&
                 model::force_element_name(e) == target;
        })) {
      quantity = out["quantity"] == "spring_length" ? "length of tendon" : "tension of tendon";
    }
    fmt::print("  {}  {} {}: {}\n", out["name"].get<std::string>(), quantity, target, columns);
  }

  if (!file.keyframes.empty()) {
    fmt::print("\nkeyframes ({}): the state of one is the initial state with --keyframe NAME\n",
               file.keyframes.size());
    for (const io::Keyframe& key : file.keyframes) {
      const bool moving = key.v.size() > 0 && key.v.cwiseAbs().maxCoeff() > 0.0;
      fmt::print("  {}  (line {}){}{}\n", key.name, key.line,
                 key.time != 0.0 ? fmt::format(", t = {} s", key.time) : "",
                 moving ? ", moving" : ", at rest");
    }
  }

  if (!file.notes.empty()) {
    fmt::print("\nnot used by momenta ({})\n", file.notes.size());
    for (const std::string& note : spelled_notes(file)) fmt::print("  {}\n", note);
  }

  if (!j["simulation"].empty()) {
    std::string settings;
    for (const auto& [key, value] : j["simulation"].items())
      settings += fmt::format("{}{} {}", settings.empty() ? "" : ", ", key,
                              value.is_string() ? value.get<std::string>() : value.dump());
    fmt::print("\nsimulation          {}\n", settings);
  }
}

void run(const InfoOptions& o) {
  const io::ModelFile file = load_model(o.model);
  const json j = describe(o, file);
  if (o.json) {
    fmt::print("{}\n", j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
  } else {
    print_text(j, file);
  }
}

}  // namespace

void add_info_command(CLI::App& app) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App* command = app.add_subcommand(
      "info",
      "Describe a model file: degrees of freedom, bodies and mass properties, joints and their "
      "coordinates, force elements, signals, outputs");
  add_model_argument(command, options->model);
  command->add_flag("--json", options->json, "Print JSON (SI units) instead of text");
  command->footer(
      "Examples:\n"
      "  momenta info examples/double_pendulum.yaml\n"
      "  momenta info examples/double_pendulum.yaml --json\n"
      "Coordinates are listed in the state's order (the file's, depth first, as MuJoCo's qpos) by "
      "their CSV column names (pivot.angle, pivot.angle_rate) and units.");
  command->callback([options] { run(*options); });
}

}  // namespace momenta::cli
