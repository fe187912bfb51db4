#include "momenta/dynamics/momentum.hpp"

#include <fmt/format.h>

#include "momenta/common/error.hpp"
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

BodyMomentum body_momentum(const Model& model, const Data& data, int b) {
  if (b < 1 || b >= model.num_bodies()) {
    throw InvalidArgument(
        fmt::format("body_momentum: body index {} outside [1, {})", b, model.num_bodies()));
  }
  const inertia::MassProperties& mp = model.body(b).mass_properties;
  const Mat3& R = data.X_WB[b].R;
  const Vec3 w_WB_B = data.V_WB_B[b].head<3>();
  BodyMomentum m;
  m.mass = mp.mass();
  m.p_WoBcm_W = data.X_WB[b].apply(mp.center_of_mass());
  m.v_WBcm_W = R * (data.V_WB_B[b].tail<3>() + w_WB_B.cross(mp.center_of_mass()));
  m.linear = m.mass * m.v_WBcm_W;
  const Vec3 H_B = mp.inertia_about_com() * w_WB_B;
  m.angular_about_com = R * H_B;
  m.kinetic_translation = 0.5 * m.mass * m.v_WBcm_W.squaredNorm();
  m.kinetic_rotation = 0.5 * w_WB_B.dot(H_B);
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
