// `momenta impact MODEL (--at BODY:x,y,z --impulse Px,Py,Pz | --between A:x,y,z B:x,y,z --normal n
// --restitution e [--friction μs[,μk]]) [--time T | --state FILE] [--json]`: impulse and momentum
// (Beer & Johnston ch. 17) — the speeds just after an impulse at a point of a body, or after two
// bodies' points collide with restitution e (and Coulomb friction); the impulses every joint and
// constraint carries (a pin's impulsive reaction), the drive impulses of prescribed joints, and
// the kinetic energy gained or lost, checked by Kelvin's theorem. Calls dynamics::
// impulsive_motion, restitution_impact and frictional_impact;
// documented in docs/cli.md and docs/contacts.md.

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "impact_blow.hpp"
#include "model_argument.hpp"
#include "momenta/common/number_text.hpp"
#include "momenta/dynamics/constraints.hpp"
#include "momenta/dynamics/impulse.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "momenta/model/units.hpp"
#include "output_format.hpp"
#include "state_file.hpp"

namespace momenta::cli {
namespace {

using json = nlohmann::ordered_json;

struct ImpactOptions {
  ModelArgument model;
  BlowOptions blow;
  InstantOptions instant;
  bool json = false;
};

// A vector as text shows it (common/number_text.hpp: round-off of `scale` as 0).
Vec3 shown(const Vec3& v, double scale) {
  return Vec3(shown_value(v.x(), scale), shown_value(v.y(), scale), shown_value(v.z(), scale));
}

// Every labelled constraint impulse: "<constraint>.<label>" and its value (N·s or N·m·s).
std::vector<std::pair<std::string, double>> constraint_impulses(const model::Model& model, VecRef q,
                                                                const VecX& impulses) {
  std::vector<std::pair<std::string, double>> out;
  if (!model.has_constraints()) return out;
  dynamics::Data data(model);
  dynamics::forward_kinematics(model, data, q);
  dynamics::ConstraintRows rows(model);
  dynamics::constraint_equations(model, data, q, rows);
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    const auto labels = model::constraint_force_labels(model.constraints()[k]);
    std::vector<double> values(labels.size());
    dynamics::constraint_forces(model, data, rows, impulses, static_cast<int>(k), values);
    for (std::size_t i = 0; i < labels.size(); ++i) {
      out.emplace_back(
          fmt::format("{}.{}", model::constraint_name(model.constraints()[k]), labels[i]),
          values[i]);
    }
  }
  return out;
}

// The unit of an impulse along velocity coordinate i: its effort's unit times s.
std::string impulse_unit(const model::Model& model, int i) {
  return model::effort_unit(model, i) + "·s";
}

void print_text(const io::ModelFile& file, double t, const Blow& blow,
                const dynamics::ImpulsiveMotion& r,
                const std::vector<std::pair<std::string, double>>& constraints) {
  const model::Model& model = file.model;
  if (const auto& c = blow.contact) {
    fmt::print("{} at t = {:.6g} s: {} + {} m strikes {} + {} m along n = {}, e = {:.6g}\n",
               file.name, t, model.body(c->body_a).name, vec_text(c->p_AoPa_A),
               model.body(c->body_b).name, vec_text(c->p_BoPb_B), vec_text(c->normal_W),
               blow.restitution);
    fmt::print(
        "normal speed {:.6g} m/s (approach) → {:.6g} m/s (separation); normal impulse "
        "{:.6g} N·s\n",
        blow.impact->approach_speed, blow.impact->separation_speed, blow.impact->normal_impulse);
    if (const auto& f = blow.rough) {
      const Vec3 friction = f->impulse_W - f->normal_impulse * c->normal_W;
      // Slips shown against the contact's relative speed: round-off of it reads as zero.
      const double scale = std::max(
          {f->slip_before_W.norm(), f->slip_after_W.norm(), std::abs(blow.impact->approach_speed)});
      fmt::print(
          "friction (μs {:.6g}, μk {:.6g}): {}, friction impulse {} N·s; slip {} → {} m/s "
          "(compression ends at a normal impulse of {:.6g} N·s)\n",
          blow.static_friction, blow.kinetic_friction, friction_outcome(*f),
          vec_text(shown(friction, f->impulse_W.norm())), vec_text(shown(f->slip_before_W, scale)),
          vec_text(shown(f->slip_after_W, scale)), f->compression_impulse);
    }
  } else {
    const dynamics::PointImpulse& hit = blow.impulses.front();
    fmt::print("{} at t = {:.6g} s: an impulse P = {} N·s (world axes) at {} + {} m\n", file.name,
               t, vec_text(hit.impulse_W), model.body(hit.body).name, vec_text(hit.p_BoP_B));
  }
  const Vec3 P = blow.impulses.front().impulse_W;
  const double v_scale =
      std::max(r.v_before.cwiseAbs().maxCoeff(), r.v_after.cwiseAbs().maxCoeff());
  fmt::print("speeds, just before → just after\n");
  for (int i = 0; i < model.nv(); ++i) {
    fmt::print("  {}  {:.6g} → {:.6g} {}\n", model.v_name(i), shown_value(r.v_before[i], v_scale),
               shown_value(r.v_after[i], v_scale), model::v_unit(model, i));
  }
  double j_scale = P.norm();
  for (const auto& j : r.joint_impulses) {
    j_scale = std::max({j_scale, j.force.norm(), j.moment.norm()});
  }
  fmt::print("impulses the joints carry to their child bodies (world axes, moments about J'o)\n");
  for (int j = 0; j < model.num_joints(); ++j) {
    const dynamics::JointReaction& J = r.joint_impulses[static_cast<std::size_t>(j)];
    fmt::print("  {}  force {} N·s, moment {} N·m·s\n", model.joint(j).name,
               vec_text(shown(J.force, j_scale)), vec_text(shown(J.moment, j_scale)));
  }
  if (!constraints.empty()) {
    fmt::print("constraint impulses{}\n",
               r.redundant_rows > 0
                   ? fmt::format(" ({} redundant row{}: their split is the least-norm one)",
                                 r.redundant_rows, r.redundant_rows == 1 ? "" : "s")
                   : "");
    for (const auto& [name, value] : constraints) {
      fmt::print("  {}  {:.6g}\n", name, shown_value(value, j_scale));
    }
  }
  for (const model::Joint& joint : model.joints()) {
    if (!joint.is_prescribed()) continue;
    for (int k = 0; k < joint.nv(); ++k) {
      const int i = joint.v_index + k;
      fmt::print("drive impulse of prescribed {}  {:.6g} {}\n", model.v_name(i),
                 shown_value(r.drive_impulses[i], j_scale), impulse_unit(model, i));
    }
  }
  const double e_scale = std::max(r.kinetic_before, r.kinetic_after);
  const double change = shown_value(r.kinetic_after - r.kinetic_before, e_scale);
  fmt::print("kinetic energy  {:.6g} J → {:.6g} J: {} {:.6g} J\n", r.kinetic_before,
             r.kinetic_after, change >= 0 ? "gained" : "lost", std::abs(change));
  fmt::print("  Kelvin's theorem: the impulses' work ½ P·(v_P⁻ + v_P⁺){} = {:.6g} J\n",
             model.has_prescribed_joints() ? " + the drives'" : "",
             shown_value(r.impulse_work, e_scale));
}

json result_json(const io::ModelFile& file, double t, const Blow& blow,
                 const dynamics::ImpulsiveMotion& r,
                 const std::vector<std::pair<std::string, double>>& constraints) {
  const model::Model& model = file.model;
  json before = json::object(), after = json::object();
  for (int i = 0; i < model.nv(); ++i) {
    before[model.v_name(i)] = r.v_before[i];
    after[model.v_name(i)] = r.v_after[i];
  }
  json joints = json::object();
  for (int j = 0; j < model.num_joints(); ++j) {
    const dynamics::JointReaction& J = r.joint_impulses[static_cast<std::size_t>(j)];
    joints[model.joint(j).name] = {{"force", vec_json(J.force)}, {"moment", vec_json(J.moment)}};
  }
  json constraint_json = json::object();
  for (const auto& [name, value] : constraints) constraint_json[name] = value;
  json drives = json::object();
  for (const model::Joint& joint : model.joints()) {
    if (!joint.is_prescribed()) continue;
    for (int k = 0; k < joint.nv(); ++k) {
      drives[model.v_name(joint.v_index + k)] = r.drive_impulses[joint.v_index + k];
    }
  }
  json blow_json;
  if (const auto& c = blow.contact) {
    blow_json = {{"contact",
                  {{"body_a", model.body(c->body_a).name},
                   {"point_a", vec_json(c->p_AoPa_A)},
                   {"body_b", model.body(c->body_b).name},
                   {"point_b", vec_json(c->p_BoPb_B)},
                   {"normal", vec_json(c->normal_W)},
                   {"restitution", blow.restitution}}},
                 {"approach_speed", blow.impact->approach_speed},
                 {"separation_speed", blow.impact->separation_speed},
                 {"normal_impulse", blow.impact->normal_impulse}};
    if (const auto& f = blow.rough) {
      blow_json["friction"] = {
          {"static", blow.static_friction},
          {"kinetic", blow.kinetic_friction},
          {"outcome", friction_outcome(*f)},
          {"compression_impulse", f->compression_impulse},
          {"impulse", vec_json(Vec3(f->impulse_W - f->normal_impulse * c->normal_W))},
          {"slip_before", vec_json(f->slip_before_W)},
          {"slip_after", vec_json(f->slip_after_W)}};
    }
  } else {
    const dynamics::PointImpulse& hit = blow.impulses.front();
    blow_json = {{"body", model.body(hit.body).name},
                 {"point", vec_json(hit.p_BoP_B)},
                 {"impulse", vec_json(hit.impulse_W)}};
  }
  json out = {{"model", file.name}, {"t", t}};
  out.update(blow_json);
  json rest = {{"v_before", before},
               {"v_after", after},
               {"joint_impulses", joints},
               {"constraint_impulses", constraint_json},
               {"redundant_rows", r.redundant_rows},
               {"drive_impulses", drives},
               {"kinetic_energy",
                {{"before", r.kinetic_before},
                 {"after", r.kinetic_after},
                 {"change", r.kinetic_after - r.kinetic_before}}},
               {"impulse_work", r.impulse_work}};
  out.update(rest);
  return out;
}

void run(const ImpactOptions& o) {
  const io::ModelFile file = load_model(o.model);
  const model::Model& model = file.model;
  const integrate::State state = instant_of(file, o.instant);
  const Blow blow = blow_of(model, o.blow, state);
  const dynamics::ImpulsiveMotion& r = blow.motion;
  const auto constraints = constraint_impulses(model, state.q, r.constraint_impulses);
  if (o.json) {
    fmt::print("{}\n",
               json_text(result_json(file, state.t, blow, r, constraints), ListSpacing::spaced));
  } else {
    print_text(file, state.t, blow, r, constraints);
  }
}

}  // namespace

void add_impact_command(CLI::App& app) {
  auto options = std::make_shared<ImpactOptions>();
  CLI::App* command = app.add_subcommand(
      "impact",
      "Impulse and momentum: the speeds just after an impulse at a body's point, the impulses "
      "the joints and constraints carry, the kinetic energy gained or lost");
  add_model_argument(command, options->model);
  add_blow_options(command, options->blow);
  add_instant_options(command, options->instant);
  command->add_flag("--json", options->json, "Print JSON instead of text");
  command->footer(
      "Examples (a rod struck at its centre of percussion: no impulse at the pin; a sphere "
      "striking a rod):\n"
      "  momenta impact examples/struck_rod.yaml --at rod:0,0,-0.8 --impulse 4,0,0\n"
      "  momenta impact examples/eccentric_impact.yaml --between sphere rod:0,0,-1.1 --normal "
      "1,0,0 --restitution 0.6\n"
      "Laws and tests: docs/contacts.md.");
  command->callback([options] { run(*options); });
}

}  // namespace momenta::cli
