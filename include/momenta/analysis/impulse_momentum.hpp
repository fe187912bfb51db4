#pragma once
// The impulse–momentum diagram of one body at an impact (Beer & Johnston §17.8–17.12): its
// momenta just before, the impulses the rest of the system and the blow give it, and its momenta
// just after,
//
//     m v̄₁ + Σ P = m v̄₂,        H_G1 + Σ (r × P + C) = H_G2,     H_G = Ī_G ω,
//
// the impulse–momentum principle for a rigid body over the instant of an impact, where every
// finite force (weight, springs) gives no impulse. The impulses, each a force impulse P (N·s)
// through a point plus an impulsive couple C (N·m·s), in W:
//  - the blow's impulses on the body: an applied impulse at its point, or a collision's
//    (normal, with friction where it has friction) at the contact point;
//  - the joint that carries the body (its impulsive reaction at J' — a pin's impulse on its rod —
//    with a prescribed joint's drive impulse) and, reversed, the joints it carries;
//  - each constraint's impulse (its rows' Λ) on the body, on its line of action.
// The numbers are those of dynamics::impulsive_motion (restitution_impact, frictional_impact):
// the state before, the speeds after, and the joints' and constraints' impulses.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "momenta/analysis/free_body.hpp"
#include "momenta/dynamics/impulse.hpp"
#include "momenta/model/model.hpp"

namespace momenta::analysis {

/// The body's momenta before and after an impact and the impulses between.
struct ImpulseMomentumDiagram : DiagramBody {
  Vec3 v_G_before_W = Vec3::Zero(), v_G_after_W = Vec3::Zero();  ///< v̄₁, v̄₂ (m/s)
  Vec3 w_before_W = Vec3::Zero(), w_after_W = Vec3::Zero();      ///< ω₁, ω₂ (rad/s)
  /// Each impulse: force_W a force impulse (N·s) at p_WoP_W, couple_W an impulsive couple
  /// (N·m·s). Kinds: applied (the blow), reaction (joints, constraints), drive (a prescribed
  /// joint's impulse, reaction included).
  std::vector<Load> impulses;

  Vec3 linear_before() const { return mass * v_G_before_W; }  ///< m v̄₁ (N·s)
  Vec3 linear_after() const { return mass * v_G_after_W; }    ///< m v̄₂
  Vec3 angular_before() const { return I_G_W * w_before_W; }  ///< H_G1 = Ī_G ω₁ (N·m·s)
  Vec3 angular_after() const { return I_G_W * w_after_W; }    ///< H_G2
  Vec3 sum_of_impulses() const;                               ///< Σ P (N·s)
  Vec3 sum_of_moments_about_G() const;                        ///< Σ (p − G) × P + C (N·m·s)
  /// m v̄₁ + Σ P − m v̄₂ and H_G1 + Σ M_G − H_G2: round-off.
  Vec3 linear_residual() const { return linear_before() + sum_of_impulses() - linear_after(); }
  Vec3 angular_residual() const {
    return angular_before() + sum_of_moments_about_G() - angular_after();
  }
};

/// The diagram of body `body` (a name; not the world) for an impact at time t and configuration
/// q: `motion` the mechanism's response (v_before, v_after, joint and constraint impulses) and
/// `blow` the impulses applied at bodies' points (those on `body` are drawn; a collision's pair,
/// P on B and −P on A). Throws InvalidArgument for an unknown body (did-you-mean) or the world.
/// Allocates.
ImpulseMomentumDiagram impulse_momentum_diagram(const model::Model& model, const std::string& body,
                                                double t, VecRef q,
                                                const dynamics::ImpulsiveMotion& motion,
                                                std::span<const dynamics::PointImpulse> blow,
                                                const std::string& blow_name);

}  // namespace momenta::analysis
