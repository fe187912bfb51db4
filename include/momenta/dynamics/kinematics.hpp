#pragma once
// Forward kinematics: pose, velocity and acceleration of every body (Featherstone 2008, §4.4).

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// Poses: sets data.X_PB, data.X_WB and data.S for configuration q (size nq).
void forward_kinematics(const Model& model, Data& data, VecRef q);

/// Poses and velocities: also data.V_WB_B and data.c_B for velocity v (size nv).
void forward_kinematics(const Model& model, Data& data, VecRef q, VecRef v);

/// Poses, velocities and accelerations: also data.A_WB_B and data.A_bias_B for vdot (size nv).
void forward_kinematics(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot);

/// Velocity of body b in the world, expressed in W about Bo: [w_WB_W; v_WBo_W] (after
/// forward_kinematics with v).
inline Vec6 body_velocity_in_world(const Data& data, int b) {
  const Mat3& R = data.X_WB[b].R;
  return spatial(R * data.V_WB_B[b].head<3>(), R * data.V_WB_B[b].tail<3>());
}

/// Classical acceleration of body b in the world, expressed in W: [alpha_WB_W; a_WBo_W], the
/// second time derivative of Bo's position (after forward_kinematics with vdot).
inline Vec6 body_acceleration_in_world(const Data& data, int b) {
  const Mat3& R = data.X_WB[b].R;
  const Vec6& V = data.V_WB_B[b];
  const Vec6& A = data.A_WB_B[b];
  return spatial(R * A.head<3>(), R * (A.tail<3>() + V.head<3>().cross(V.tail<3>())));
}

/// The wrench on body b (in B about Bo, the f_ext convention) of a force f_W (N, in W) acting at
/// the point p_WoP_W (m), after forward_kinematics(q).
inline Vec6 body_wrench_from_world_force(const Data& data, int b, const Vec3& f_W,
                                         const Vec3& p_WoP_W) {
  const Transform& X = data.X_WB[b];
  const Vec3 f_B = X.R.transpose() * f_W;
  const Vec3 p_BoP_B = X.R.transpose() * (p_WoP_W - X.p);
  return spatial(p_BoP_B.cross(f_B), f_B);
}

}  // namespace momenta::dynamics
