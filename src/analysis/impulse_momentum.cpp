#include "momenta/analysis/impulse_momentum.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/constraints.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/point_kinematics.hpp"

namespace momenta::analysis {

namespace {

// G's velocity and the body's ω at data's velocities.
void body_motion(const model::Model& model, const dynamics::Data& data, int b, Vec3& v_G, Vec3& w) {
  const Vec3 p_BoG_B = model.body(b).mass_properties.center_of_mass();
  v_G = dynamics::point_kinematics(model, data, b, p_BoG_B).v_WP_W;
  w = data.X_WB[b].R * data.V_WB_B[b].head<3>();
}

// Joint j's impulse on the body (`sign` +1 where the body is its child, −1 its parent: what the
// body feels is the opposite of what it gives its child), at J'.
Load joint_impulse(const model::Model& model, const dynamics::Data& data,
                   const dynamics::ImpulsiveMotion& motion, int j, double sign) {
  const model::Joint& joint = model.joint(j);
  const auto& c = model.joint_constants()[static_cast<std::size_t>(j)];
  const Transform X_WJ = data.X_WB[c.child] * c.X_JC.inverse();
  const dynamics::JointReaction& r = motion.joint_impulses[static_cast<std::size_t>(j)];
  const std::string other = model.body(sign > 0 ? joint.parent_index : joint.child_index).name;
  const std::string side = sign > 0 ? "from " + other : "on " + other + ", reversed";
  const bool drive = joint.is_prescribed();
  return {
      drive ? LoadKind::drive : LoadKind::reaction,
      joint.name,
      fmt::format("{} of joint {} ({})",
                  drive ? "impulse (reaction and drive)" : "impulsive reaction", joint.name, side),
      X_WJ.p,
      sign * r.force,
      sign * r.moment,
      j};
}

}  // namespace

Vec3 ImpulseMomentumDiagram::sum_of_impulses() const { return sum_of_forces(impulses); }

Vec3 ImpulseMomentumDiagram::sum_of_moments_about_G() const {
  return sum_of_moments_about(impulses, p_WoG_W);
}

ImpulseMomentumDiagram impulse_momentum_diagram(const model::Model& model, const std::string& body,
                                                double t, VecRef q,
                                                const dynamics::ImpulsiveMotion& motion,
                                                std::span<const dynamics::PointImpulse> blow,
                                                const std::string& blow_name) {
  const int b = diagram_body_index(model, body, "impulse–momentum diagram",
                                   "it takes every impulse without moving");
  ImpulseMomentumDiagram d;
  dynamics::Data data(model);
  dynamics::forward_kinematics(model, data, q, motion.v_after);
  body_motion(model, data, b, d.v_G_after_W, d.w_after_W);
  dynamics::forward_kinematics(model, data, q, motion.v_before);
  body_motion(model, data, b, d.v_G_before_W, d.w_before_W);
  static_cast<DiagramBody&>(d) = diagram_body(model, data, b, t);
  const Transform& X_WB = data.X_WB[b];

  for (const dynamics::PointImpulse& hit : blow) {
    if (hit.body != b) continue;
    d.impulses.push_back({LoadKind::applied, blow_name, fmt::format("{} on {}", blow_name, body),
                          X_WB.apply(hit.p_BoP_B), hit.impulse_W, Vec3::Zero(), -1});
  }
  d.impulses.push_back(joint_impulse(model, data, motion, model.body(b).joint_index, +1.0));
  for (const model::Joint& j : model.joints()) {
    if (j.parent_index == b)
      d.impulses.push_back(joint_impulse(model, data, motion, j.index, -1.0));
  }
  if (model.has_constraints()) {
    dynamics::ConstraintRows rows(model);
    std::fill(rows.enabled.begin(), rows.enabled.end(), 1);  // Λ is zero on the rows that held
    dynamics::constraint_equations(model, data, q, rows);
    for (int k = 0; k < static_cast<int>(model.constraints().size()); ++k) {
      std::optional<Load> load =
          constraint_load(model, data, rows, motion.constraint_impulses, k, b);
      if (!load || (load->force_W.isZero(0.0) && load->couple_W.isZero(0.0))) continue;
      const model::Constraint& c = model.constraints()[static_cast<std::size_t>(k)];
      load->description = fmt::format("impulse of the {} constraint {}",
                                      model::constraint_type_name(c), model::constraint_name(c));
      d.impulses.push_back(*load);
    }
  }
  std::vector<Vec3> forces{d.linear_before(), d.linear_after()};
  std::vector<Vec3> moments{d.angular_before(), d.angular_after()};
  d.plane_normal = plane_of_loads(model, b, d.R_WB, d.p_WoG_W, d.impulses, forces, moments);
  return d;
}

}  // namespace momenta::analysis
