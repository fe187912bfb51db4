#include "momenta/dynamics/momentum.hpp"

#include "momenta/dynamics/kinematics.hpp"

namespace momenta::dynamics {

Momentum momentum(const Model& model, const Data& data) {
  // Spatial momentum about Wo in W: h = Σ ᵂX_B* (I_B V_B) = [H_Wo; L].
  Vec6 h = Vec6::Zero();
  Vec3 first_moment = Vec3::Zero();
  for (int b = 1; b < model.num_bodies(); ++b) {
    const SpatialInertia& I = model.spatial_inertia(b);
    const Transform& X = data.X_WB[b];
    h += X.act_force(I * data.V_WB_B[b]);
    first_moment += I.mass * X.p + X.R * I.h;
  }
  Momentum m;
  m.mass = model.total_mass();
  m.p_WoScm_W = m.mass > 0 ? Vec3(first_moment / m.mass) : Vec3::Zero();
  m.linear = h.tail<3>();
  m.v_WScm_W = m.mass > 0 ? Vec3(m.linear / m.mass) : Vec3::Zero();
  // H_Scm = H_Wo − p_Scm × L.
  m.angular_about_com = h.head<3>() - m.p_WoScm_W.cross(m.linear);
  return m;
}

Momentum momentum(const Model& model, Data& data, VecRef q, VecRef v) {
  forward_kinematics(model, data, q, v);
  return momentum(model, static_cast<const Data&>(data));
}

Vec3 center_of_mass(const Model& model, Data& data, VecRef q) {
  forward_kinematics(model, data, q);
  Vec3 first_moment = Vec3::Zero();
  for (int b = 1; b < model.num_bodies(); ++b) {
    const SpatialInertia& I = model.spatial_inertia(b);
    first_moment += I.mass * data.X_WB[b].p + data.X_WB[b].R * I.h;
  }
  return model.total_mass() > 0 ? Vec3(first_moment / model.total_mass()) : Vec3::Zero();
}

}  // namespace momenta::dynamics
