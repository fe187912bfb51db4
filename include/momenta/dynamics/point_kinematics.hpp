#pragma once
// Kinematics of points fixed in a body: position, velocity and acceleration with their terms
// separated, and Jacobians.

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// Motion of a point P fixed in body B, all in the world frame W (m, m/s, m/s²).
///
/// The acceleration is given two ways, each summing to a_WP_W:
///  - rigid-body terms of B: a_WBo_W + tangential (α × r) + centripetal (ω × (ω × r)), r = p_BoP;
///  - generalized terms: from_vdot (J v̇) + velocity_product (J̇ v: all Coriolis and centripetal
///    accelerations of the joints, what remains when v̇ = 0).
struct PointKinematics {
  Vec3 p_WoP_W;
  Vec3 v_WP_W;
  Vec3 a_WP_W;
  Vec3 a_WBo_W;           ///< Acceleration of the body origin Bo.
  Vec3 tangential;        ///< α_WB × r.
  Vec3 centripetal;       ///< ω_WB × (ω_WB × r).
  Vec3 from_vdot;         ///< J(q) v̇.
  Vec3 velocity_product;  ///< J̇(q, v) v (Coriolis + centripetal of every joint).
};

/// The kinematics of the point p_BoP_B (m, in B) of body b. Preconditions: data filled by
/// forward_kinematics(model, data, q, v, vdot). Throws InvalidArgument for a bad body index.
PointKinematics point_kinematics(const Model& model, const Data& data, int b, const Vec3& p_BoP_B);

/// Convenience: runs forward_kinematics(q, v, vdot) then point_kinematics.
PointKinematics point_kinematics(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot,
                                 int b, const Vec3& p_BoP_B);

/// The 6 × nv Jacobian of body b at the point P (p_BoP_B), world-aligned: [w_WB_W; v_WP_W] = J v.
/// Rows 3–5 are the point's translational Jacobian. J must be 6 × nv. Preconditions:
/// forward_kinematics(q) has run.
void frame_jacobian(const Model& model, const Data& data, int b, const Vec3& p_BoP_B,
                    Eigen::Ref<MatX> J);

}  // namespace momenta::dynamics
