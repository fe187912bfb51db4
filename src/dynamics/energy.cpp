#include "momenta/dynamics/energy.hpp"

#include "momenta/dynamics/kinematics.hpp"

namespace momenta::dynamics {

double kinetic_energy(const Model& model, const Data& data, VecRef v) {
  double T = 0.0;
  for (int b = 1; b < model.num_bodies(); ++b) {
    T += model.spatial_inertia(b).kinetic_energy(data.V_WB_B[b]);
  }
  for (const model::JointConstants& c : model.joint_constants()) {  // the rotors (armature)
    for (int k = 0; k < c.nv && c.armature != 0.0; ++k)
      T += 0.5 * c.armature * v[c.v_index + k] * v[c.v_index + k];
  }
  return T;
}

double potential_energy(const Model& model, const Data& data) {
  // V = −Σ m g · p_WoBcm_W; m p_WoBcm_W = m p_WoBo_W + R_WB h_B.
  double V = 0.0;
  for (int b = 1; b < model.num_bodies(); ++b) {
    const SpatialInertia& I = model.spatial_inertia(b);
    const Transform& X = data.X_WB[b];
    V -= model.gravity().dot(I.mass * X.p + X.R * I.h);
  }
  return V;
}

double kinetic_energy(const Model& model, Data& data, VecRef q, VecRef v) {
  forward_kinematics(model, data, q, v);
  return kinetic_energy(model, static_cast<const Data&>(data), v);
}

double potential_energy(const Model& model, Data& data, VecRef q) {
  forward_kinematics(model, data, q);
  return potential_energy(model, static_cast<const Data&>(data));
}

}  // namespace momenta::dynamics
