// The dynamics algorithms called directly from C++, for tests/python/test_dynamics.py to compare
// the Python bindings with (bit for bit: both run the same compiled code on the same doubles).
//
//   dynamics_reference MODEL < {"q": [...], "v": [...], "tau": [...], "vdot": [...],
//                               "body": B, "point": [x, y, z]}
//
// prints one JSON object of every result (doubles written to round-trip exactly).

#include <iostream>
#include <nlohmann/json.hpp>
#include <vector>

#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/aba_derivatives.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/data.hpp"
#include "momenta/dynamics/energy.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/momentum.hpp"
#include "momenta/dynamics/point_kinematics.hpp"
#include "momenta/dynamics/reactions.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta/dynamics/rnea_derivatives.hpp"
#include "momenta/frontend/model_loading.hpp"

namespace {

using json = nlohmann::json;
using namespace momenta;

VecX vector_from(const json& j) {
  const auto x = j.get<std::vector<double>>();
  return Eigen::Map<const VecX>(x.data(), static_cast<Eigen::Index>(x.size()));
}

template <class Derived>
json to_json(const Eigen::MatrixBase<Derived>& x) {
  if constexpr (Derived::ColsAtCompileTime == 1) {
    return std::vector<double>(x.derived().data(), x.derived().data() + x.size());
  } else {
    json rows = json::array();
    for (Eigen::Index r = 0; r < x.rows(); ++r) rows.push_back(to_json(VecX(x.row(r).transpose())));
    return rows;
  }
}

json reactions(const model::Model& model, const dynamics::Data& data) {
  json by_frame;
  const std::pair<const char*, model::ReactionFrame> frames[] = {
      {"world", model::ReactionFrame::world},
      {"joint", model::ReactionFrame::joint},
      {"child", model::ReactionFrame::child},
      {"parent", model::ReactionFrame::parent}};
  for (const auto& [name, frame] : frames) {
    json forces = json::array(), moments = json::array();
    for (int j = 0; j < model.num_joints(); ++j) {
      const dynamics::JointReaction r = dynamics::joint_reaction(model, data, j, frame);
      forces.push_back(to_json(r.force));
      moments.push_back(to_json(r.moment));
    }
    by_frame[name] = {{"forces", forces}, {"moments", moments}};
  }
  return by_frame;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: dynamics_reference MODEL < state.json\n";
    return 2;
  }
  const io::ModelFile file = frontend::load_model(argv[1]);
  const model::Model& model = file.model;
  dynamics::Data data(model);
  const json in = json::parse(std::cin);
  const VecX q = vector_from(in["q"]), v = vector_from(in["v"]);
  const VecX tau = vector_from(in["tau"]), vdot = vector_from(in["vdot"]);
  const int body = in["body"].get<int>();
  const auto point = vector_from(in["point"]);
  const Vec3 p_BoP_B = point;

  json out;
  out["aba"] = to_json(VecX(dynamics::aba(model, data, q, v, tau)));
  out["rnea"] = to_json(VecX(dynamics::rnea(model, data, q, v, vdot)));
  out["crba"] = to_json(MatX(dynamics::crba(model, data, q)));
  out["nonlinear_effects"] = to_json(VecX(dynamics::nonlinear_effects(model, data, q, v)));
  out["generalized_gravity"] = to_json(VecX(dynamics::generalized_gravity(model, data, q)));
  dynamics::rnea_derivatives(model, data, q, v, vdot);
  out["rnea_derivatives"] = {to_json(data.dtau_dq), to_json(data.dtau_dv), to_json(data.M)};
  dynamics::aba_derivatives(model, data, q, v, tau);
  out["aba_derivatives"] = {to_json(data.dvdot_dq), to_json(data.dvdot_dv), to_json(data.Minv)};
  dynamics::joint_reactions(model, data, q, v, vdot);
  out["joint_reactions"] = reactions(model, data);

  dynamics::forward_kinematics(model, data, q, v, vdot);
  json poses = json::array(), velocities = json::array(), accelerations = json::array();
  for (int b = 0; b < model.num_bodies(); ++b) {
    poses.push_back({to_json(data.X_WB[b].R), to_json(data.X_WB[b].p)});
    velocities.push_back(to_json(dynamics::body_velocity_in_world(data, b)));
    accelerations.push_back(to_json(dynamics::body_acceleration_in_world(data, b)));
  }
  out["body_poses"] = poses;
  out["body_velocities"] = velocities;
  out["body_accelerations"] = accelerations;

  const dynamics::PointKinematics k =
      dynamics::point_kinematics(model, data, q, v, vdot, body, p_BoP_B);
  out["point_kinematics"] = {
      {"position", to_json(k.p_WoP_W)},      {"velocity", to_json(k.v_WP_W)},
      {"acceleration", to_json(k.a_WP_W)},   {"origin_acceleration", to_json(k.a_WBo_W)},
      {"tangential", to_json(k.tangential)}, {"centripetal", to_json(k.centripetal)},
      {"from_vdot", to_json(k.from_vdot)},   {"velocity_product", to_json(k.velocity_product)}};
  dynamics::forward_kinematics(model, data, q);
  MatX J(6, model.nv());
  dynamics::frame_jacobian(model, data, body, p_BoP_B, J);
  out["frame_jacobian"] = to_json(J);

  out["kinetic_energy"] = dynamics::kinetic_energy(model, data, q, v);
  out["potential_energy"] = dynamics::potential_energy(model, data, q);
  out["center_of_mass"] = to_json(dynamics::center_of_mass(model, data, q));
  const dynamics::Momentum p = dynamics::momentum(model, data, q, v);
  out["momentum"] = {{"mass", p.mass},
                     {"center_of_mass", to_json(p.p_WoScm_W)},
                     {"center_of_mass_velocity", to_json(p.v_WScm_W)},
                     {"linear", to_json(p.linear)},
                     {"angular_about_com", to_json(p.angular_about_com)}};
  std::cout << out.dump() << '\n';
}
