// The 3-D scene of a simulation report: what each body looks like, where its joints and springs
// attach, and how it moves (poses at the kept rows, float64, so the page reproduces positions
// exactly at those times).

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <variant>

#include "momenta/analysis/free_body.hpp"
#include "momenta/analysis/linearize.hpp"
#include "momenta/dynamics/contact_geometry.hpp"
#include "momenta/dynamics/data.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/system/multibody_system.hpp"
#include "sections.hpp"

namespace momenta::report::detail {
namespace {

json body_json(const io::ModelFile& file, int b) {
  const model::Body& body = file.model.bodies()[b];
  const inertia::MassProperties& mp = body.mass_properties;
  json parts = json::array();
  for (const io::PartSummary& part : file.parts_of(b)) parts.push_back(part_json(part));
  json j = {{"name", body.name},
            {"parent", file.model.bodies()[body.parent_index].name},
            {"mass", mp.mass()},
            {"com", vec_json(mp.center_of_mass())},
            {"inertia", mat_json(mp.inertia_about_com())},
            {"parts", parts}};
  // Drawn as its equivalent ellipsoid when nothing else says what it looks like.
  if (parts.empty()) j["equivalent"] = equivalent_ellipsoid_json(mp);
  return j;
}

json joint_json(const model::Joint& joint) {
  json j = {{"name", joint.name},
            {"type", std::string(model::joint_type_name(joint.type))},
            {"parent", joint.parent},
            {"child", joint.child},
            // J' in the child: where the joint is drawn, moving with the child.
            {"origin", vec_json(joint.X_CJ.p)},
            {"R", mat_json(joint.X_CJ.R)}};
  const bool has_axis = model::joint_traits(joint.type).axes >= 1;
  // The axis is fixed in J; J' coincides with J at q = 0 and turns about the axis, so the axis
  // reads the same in J'.
  j["axis"] = has_axis ? vec_json(joint.X_CJ.R * joint.axis) : json(nullptr);
  return j;
}

json force_element_json(const model::Model& model, const model::ForceElement& element) {
  const auto body_name = [&](int index) { return model.bodies()[index].name; };
  return std::visit(
      [&](const auto& e) -> json {
        using T = std::decay_t<decltype(e)>;
        if constexpr (std::is_same_v<T, model::LinearSpringDamper>) {
          return {{"name", e.name},
                  {"type", "spring"},
                  {"stiffness", e.stiffness},
                  {"damping", e.damping},
                  {"a", body_name(e.a.body_index)},
                  {"pa", vec_json(e.a.p_BoP_B)},
                  {"b", body_name(e.b.body_index)},
                  {"pb", vec_json(e.b.p_BoP_B)}};
        } else if constexpr (std::is_same_v<T, model::AppliedForce>) {
          return {{"name", e.name},
                  {"type", "force"},
                  {"body", body_name(e.at.body_index)},
                  {"point", vec_json(e.at.p_BoP_B)}};
        } else {
          return {{"name", e.name}, {"type", "other"}};
        }
      },
      element);
}

}  // namespace

json scene_json(const io::ModelFile& file) {
  const model::Model& model = file.model;
  json bodies = json::array(), joints = json::array(), elements = json::array();
  for (int b = 1; b < model.num_bodies(); ++b) bodies.push_back(body_json(file, b));
  for (const model::Joint& joint : model.joints()) joints.push_back(joint_json(joint));
  for (const model::ForceElement& e : model.force_elements()) {
    elements.push_back(force_element_json(model, e));
  }
  // The ground planes contacts touch (a ramp, a floor): drawn so that a body resting on one is
  // seen on it.
  json planes = json::array();
  for (const model::Constraint& c : model.constraints()) {
    const auto* contact = std::get_if<model::Contact>(&c);
    if (contact == nullptr || !contact->on_ground()) continue;
    planes.push_back({{"name", contact->name},
                      {"point", vec_json(contact->plane_point)},
                      {"normal", vec_json(contact->plane_normal)}});
  }
  return {{"gravity", vec_json(model.gravity())},
          {"length", analysis::characteristic_length(model)},
          {"bodies", bodies},
          {"joints", joints},
          {"elements", elements},
          {"planes", planes}};
}

void append_poses(const model::Model& model, const dynamics::Data& data,
                  std::vector<double>& positions, std::vector<double>& quaternions) {
  for (int b = 1; b < model.num_bodies(); ++b) {
    const Vec3& p = data.X_WB[b].p;
    const Eigen::Quaterniond r(data.X_WB[b].R);
    positions.insert(positions.end(), {p.x(), p.y(), p.z()});
    quaternions.insert(quaternions.end(), {r.x(), r.y(), r.z(), r.w()});
  }
}

json frames_json(const SimulationRun& run) {
  const model::Model& model = run.file->model;
  const int bodies = model.num_bodies() - 1;
  const int rows = static_cast<int>(run.rows.size());
  const int stride = std::max(1, (rows * bodies + kMaxBodyPoses - 1) / kMaxBodyPoses);
  std::vector<int> kept;
  for (int r = 0; r < rows; r += stride) kept.push_back(r);
  if (rows > 0 && kept.back() != rows - 1) kept.push_back(rows - 1);  // the last state, always

  // Applied loads and reactions drawn as arrows: which columns and elements.
  std::vector<const model::AppliedForce*> loads;
  for (const model::ForceElement& e : model.force_elements()) {
    if (const auto* f = std::get_if<model::AppliedForce>(&e)) loads.push_back(f);
  }
  std::vector<int> reaction_columns;  // Fx of each joint, when recorded
  for (const model::Joint& joint : model.joints()) {
    const auto it = std::find(run.columns.begin(), run.columns.end(), joint.name + ".reaction.Fx");
    if (it != run.columns.end())
      reaction_columns.push_back(static_cast<int>(it - run.columns.begin()));
  }
  const bool reactions =
      reaction_columns.size() == model.joints().size() && !model.joints().empty();
  // With reactions, each constraint's force on its body (the first of a loop's or link's that
  // moves; a coupler's acts in joint space and has none): from the constrained dynamics of the
  // row's state, as its free-body diagram draws it (analysis::constraint_load).
  std::vector<std::pair<int, int>> constraint_bodies;  // (constraint, body)
  // A contact's force is open in the dynamics of a row's state alone: its recorded columns
  // `<contact>.normal` (and with friction .tangent_1, .tangent_2, which follow it) say it,
  // N n + F₁ t₁ + F₂ t₂ at its point (−1: not a contact).
  std::vector<int> contact_columns;
  std::optional<system::MultibodySystem> constrained;
  if (reactions && !model.constraints().empty()) {
    constrained.emplace(model);
    const dynamics::ConstraintRows& constraint_rows = constrained->constraints()->rows();
    for (int k = 0; k < static_cast<int>(model.constraints().size()); ++k) {
      const auto first =
          static_cast<std::size_t>(constraint_rows.first_row[static_cast<std::size_t>(k)]);
      const int body = constraint_rows.body_b[first] != 0 ? constraint_rows.body_b[first]
                                                          : constraint_rows.body_a[first];
      if (body == 0) continue;
      constraint_bodies.emplace_back(k, body);
      const model::Constraint& c = model.constraints()[static_cast<std::size_t>(k)];
      const auto it =
          std::find(run.columns.begin(), run.columns.end(), model::constraint_name(c) + ".normal");
      contact_columns.push_back(model::is_unilateral(c) && it != run.columns.end()
                                    ? static_cast<int>(it - run.columns.begin())
                                    : -1);
    }
  }

  dynamics::Data data(model);
  std::vector<double> time, positions, quaternions, omegas, load_vectors, reaction_forces,
      reaction_moments, reaction_points;
  for (const int r : kept) {
    const std::vector<double>& row = run.rows[r];
    const VecX q = Eigen::Map<const VecX>(row.data() + 1, model.nq());
    const VecX v = Eigen::Map<const VecX>(row.data() + 1 + model.nq(), model.nv());
    time.push_back(row[0]);
    dynamics::forward_kinematics(model, data, q, v);
    append_poses(model, data, positions, quaternions);
    for (int b = 1; b <= bodies; ++b) {
      const Vec3 w = dynamics::body_velocity_in_world(data, b).head<3>();
      omegas.insert(omegas.end(), {w.x(), w.y(), w.z()});
    }
    for (const model::AppliedForce* f : loads) {
      const double scale =
          f->signal_index >= 0 ? model.signals()[f->signal_index].value(row[0]) : 1.0;
      const Vec3 F = scale * (f->frame == model::LoadFrame::world
                                  ? f->vector
                                  : Vec3(data.X_WB[f->at.body_index].R * f->vector));
      load_vectors.insert(load_vectors.end(), {F.x(), F.y(), F.z()});
    }
    if (reactions) {
      for (std::size_t j = 0; j < model.joints().size(); ++j) {
        const int c = reaction_columns[j];
        reaction_forces.insert(reaction_forces.end(), {row[c], row[c + 1], row[c + 2]});
        reaction_moments.insert(reaction_moments.end(), {row[c + 3], row[c + 4], row[c + 5]});
        const model::Joint& joint = model.joints()[j];
        const Transform& X = data.X_WB[joint.child_index];
        const Vec3 at = X.p + X.R * joint.X_CJ.p;
        reaction_points.insert(reaction_points.end(), {at.x(), at.y(), at.z()});
      }
    }
    if (!constraint_bodies.empty()) {
      constrained->evaluate(row[0], q, v);
      for (std::size_t i = 0; i < constraint_bodies.size(); ++i) {
        const auto [k, body] = constraint_bodies[i];
        std::optional<analysis::Load> load;
        if (contact_columns[i] >= 0) {  // on body b: N n + friction at the contact point
          const auto& contact = std::get<model::Contact>(model.constraints()[std::size_t(k)]);
          const dynamics::ContactGeometry g = dynamics::contact_geometry(contact, data);
          const auto column = static_cast<std::size_t>(contact_columns[i]);
          load = analysis::Load{};
          load->force_W = row[column] * g.normal_W;
          if (contact.has_friction()) {
            load->force_W += row[column + 1] * g.tangent_1_W + row[column + 2] * g.tangent_2_W;
          }
          load->couple_W.setZero();
          load->p_WoP_W = g.point_W;
        } else {
          load = analysis::constraint_load(*constrained, k, body);
        }
        const Vec3 F = load ? load->force_W : Vec3::Zero(),
                   M = load ? load->couple_W : Vec3::Zero();
        const Vec3 at = load ? load->p_WoP_W : data.X_WB[body].p;
        reaction_forces.insert(reaction_forces.end(), {F.x(), F.y(), F.z()});
        reaction_moments.insert(reaction_moments.end(), {M.x(), M.y(), M.z()});
        reaction_points.insert(reaction_points.end(), {at.x(), at.y(), at.z()});
      }
    }
  }
  json frames = {{"count", kept.size()},
                 {"stride", stride},
                 {"rows", rows},
                 {"time", encode_f64(time)},
                 {"position", encode_f64(positions)},
                 {"quaternion", encode_f64(quaternions)},
                 {"omega", encode_f32(omegas)}};
  if (!loads.empty()) {
    json names = json::array();
    for (const auto* f : loads) names.push_back(f->name);
    frames["loads"] = {{"names", names}, {"vector", encode_f32(load_vectors)}};
  }
  if (reactions) {
    json names = json::array();
    for (const model::Joint& joint : model.joints()) names.push_back(joint.name);
    for (const auto& [k, body] : constraint_bodies)
      names.push_back(model::constraint_name(model.constraints()[static_cast<std::size_t>(k)]));
    frames["reactions"] = {{"names", names},
                           {"force", encode_f32(reaction_forces)},
                           {"moment", encode_f32(reaction_moments)},
                           {"point", encode_f32(reaction_points)}};
  }
  return frames;
}

}  // namespace momenta::report::detail
