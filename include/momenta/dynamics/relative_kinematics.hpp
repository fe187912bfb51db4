#pragma once
// Rotating-frame kinematics: the motion of a point seen from a frame that moves, split into the
// terms of (Q̇)_OXYZ = (Q̇)_Oxyz + Ω × Q (Beer & Johnston, Vector Mechanics: Dynamics, §15.10–15.14).
//
// Frame F is the frame of a body f of the model (the world included) with origin Fo; Ω = w_WF and
// Ω̇ = α_WF its angular velocity and acceleration. For a point P with r = p_FoP:
//   v_P = v_Fo + Ω × r + v_rel                                     (transport + relative)
//   a_P = a_Fo + Ω̇ × r + Ω × (Ω × r) + 2 Ω × v_rel + a_rel
//         └──────── transport ───────┘   Coriolis      relative
// where v_rel and a_rel are the first and second rates of r as an observer fixed in F sees them
// (the time derivatives of r's components in F's axes).

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// The motion of a point P relative to frame F. Every vector in F's axes; SI units (m, m/s, m/s²,
/// rad/s, rad/s²).
struct RelativeKinematics {
  Vec3 p_FoP_F;        ///< r, the point's position from Fo.
  Vec3 w_WF_F;         ///< Ω, F's angular velocity.
  Vec3 alpha_WF_F;     ///< Ω̇, F's angular acceleration.
  Vec3 v_WFo_F;        ///< Velocity of Fo.
  Vec3 a_WFo_F;        ///< Acceleration of Fo.
  Vec3 v_relative;     ///< v_rel: the rate of r seen in F.
  Vec3 v_rotation;     ///< Ω × r.
  Vec3 v_WP_F;         ///< The absolute velocity v_Fo + Ω × r + v_rel.
  Vec3 a_relative;     ///< a_rel: the second rate of r seen in F.
  Vec3 a_euler;        ///< Ω̇ × r (the tangential or Euler term).
  Vec3 a_centripetal;  ///< Ω × (Ω × r).
  Vec3 a_coriolis;     ///< 2 Ω × v_rel.
  Vec3 a_WP_F;         ///< The absolute acceleration, the sum of the five terms.

  /// The velocity P would have if fixed in F: v_Fo + Ω × r.
  Vec3 v_transport() const { return v_WFo_F + v_rotation; }
  /// The acceleration P would have if fixed in F: a_Fo + Ω̇ × r + Ω × (Ω × r).
  Vec3 a_transport() const { return a_WFo_F + a_euler + a_centripetal; }
};

/// The motion of the point p_BoP_B (m, in B) of body `body` seen from the frame of body `frame`
/// (0: the world, where Ω = 0 and the terms reduce to the absolute motion). Preconditions: data
/// filled by forward_kinematics(model, data, q, v, vdot). Throws InvalidArgument for a body index
/// out of range.
RelativeKinematics relative_kinematics(const Model& model, const Data& data, int body,
                                       const Vec3& p_BoP_B, int frame);

/// The rotation of a body B seen from the frame of body F, in F's axes (rad/s, rad/s²).
struct RelativeRotation {
  Vec3 w_FB_F;      ///< w_WB − w_WF.
  Vec3 alpha_FB_F;  ///< The rate of w_FB seen in F: (α_WB − α_WF) − w_WF × (w_WB − w_WF).
};

/// The rotation of body `body` seen from the frame of body `frame` (0: the world). Preconditions
/// and errors as relative_kinematics().
RelativeRotation relative_rotation(const Model& model, const Data& data, int body, int frame);

}  // namespace momenta::dynamics
