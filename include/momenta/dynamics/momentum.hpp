#pragma once
// System centre of mass and momentum.

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// Mass, centre of mass and momentum of the whole system S, in the world frame.
struct Momentum {
  double mass = 0.0;       ///< kg.
  Vec3 p_WoScm_W;          ///< Centre of mass (m).
  Vec3 v_WScm_W;           ///< Velocity of the centre of mass (m/s).
  Vec3 linear;             ///< Linear momentum L = m v_Scm (kg·m/s).
  Vec3 angular_about_com;  ///< Angular momentum about Scm, H_Scm (kg·m²/s).

  /// Angular momentum about the world-fixed point Q at p_WoQ_W: H_Q = H_Scm + (p_Scm − p_Q) × L.
  Vec3 angular_about(const Vec3& p_WoQ_W) const {
    return angular_about_com + (p_WoScm_W - p_WoQ_W).cross(linear);
  }
};

/// Momentum and kinetic energy of one body B with centre of mass G, in the world frame (Beer &
/// Johnston §18.1, §17.2): L = m v̄, H_G = Ī ω, T = ½ m v̄² + ½ ωᵀ Ī ω.
struct BodyMomentum {
  double mass = 0.0;                 ///< kg.
  Vec3 p_WoBcm_W;                    ///< G (m).
  Vec3 v_WBcm_W;                     ///< v̄ (m/s).
  Vec3 linear;                       ///< L = m v̄ (kg·m/s).
  Vec3 angular_about_com;            ///< H_G = Ī ω (kg·m²/s).
  double kinetic_translation = 0.0;  ///< ½ m v̄² (J).
  double kinetic_rotation = 0.0;     ///< ½ ωᵀ Ī ω (J).

  double kinetic_energy() const { return kinetic_translation + kinetic_rotation; }
  /// Angular momentum about any point A at p_WoA_W (moving or not; the momentum is the body's
  /// absolute one): H_A = H_G + (p_G − p_A) × L.
  Vec3 angular_about(const Vec3& p_WoA_W) const {
    return angular_about_com + (p_WoBcm_W - p_WoA_W).cross(linear);
  }
};

/// Body b's momentum from data filled by forward_kinematics(q, v). Throws InvalidArgument for a
/// body index out of [1, num_bodies).
BodyMomentum body_momentum(const Model& model, const Data& data, int b);

/// Centre of mass of the system (m, in W) at configuration q. Runs forward_kinematics(q).
Vec3 center_of_mass(const Model& model, Data& data, VecRef q);

/// Momentum of the system at (q, v). Runs forward_kinematics(q, v).
Momentum momentum(const Model& model, Data& data, VecRef q, VecRef v);

/// From data already filled by forward_kinematics(q, v).
Momentum momentum(const Model& model, const Data& data);

}  // namespace momenta::dynamics
