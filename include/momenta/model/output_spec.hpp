#pragma once
// What a user asks to record: named model quantities that `momenta simulate` writes as extra CSV
// columns and `momenta linearize` takes as outputs y (the rows of C and D). A description, read
// from model files; system::OutputSet evaluates them on a model.
//
// An output names one quantity of one joint, body, signal or force element. Vector quantities are
// three columns, "<name>.x", "<name>.y", "<name>.z", unless a single component is chosen; joint
// quantities are one column per coordinate, "<name>.<i>", unless one coordinate is chosen. A
// single column is called "<name>".

#include <string>
#include <string_view>

#include "momenta/math/types.hpp"
#include "momenta/model/reaction_frame.hpp"

namespace momenta::model {

enum class OutputQuantity {
  joint_position,         ///< joint coordinates q (nq; quaternions as w, x, y, z)
  joint_velocity,         ///< joint speeds v (nv)
  joint_effort,           ///< generalized force on the joint: element forces + prescribed drive
  body_position,          ///< p_WoP_W of a point P fixed in the body (m); p_FoP_F with a frame
  body_velocity,          ///< v_WP_W (m/s); with a frame F, v_rel: P's velocity seen in F
  body_acceleration,      ///< a_WP_W (m/s²); with a frame F, a_rel: P's acceleration seen in F
  body_angular_velocity,  ///< w_WB_W (rad/s); with a frame F, w_FB_F
  /// α_WB_W (rad/s²); with a frame F, α_FB_F: the rate of w_FB as an observer fixed in F sees
  /// it, (α_WB − α_WF) − w_WF × (w_WB − w_WF), in F's axes.
  body_angular_acceleration,
  /// The body's Euler angles in OutputSpec::sequence (rad): of R_WB, or R_FB with a frame F
  /// (math/rotation.hpp, euler_from_rotation).
  body_euler_angles,
  /// Their rates (rad/s), E(angles)⁻¹ w_FB_F (euler_rate_matrix); undefined at gimbal lock.
  body_euler_rates,
  // Rotating-frame terms of P's motion seen from a frame F (dynamics/relative_kinematics.hpp);
  // they need a frame.
  transport_velocity,        ///< v_Fo + Ω × r (m/s)
  transport_acceleration,    ///< a_Fo + Ω̇ × r + Ω × (Ω × r) (m/s²)
  coriolis_acceleration,     ///< 2 Ω × v_rel (m/s²)
  centripetal_acceleration,  ///< Ω × (Ω × r) (m/s²)
  euler_acceleration,        ///< Ω̇ × r (m/s²)
  reaction_force,            ///< force the joint transmits to its child (N), in `frame`
  reaction_moment,   ///< moment about the child-side joint frame's origin (N·m), in `frame`
  signal,            ///< an input signal's value
  spring_length,     ///< a linear spring-damper's length ℓ (m)
  spring_tension,    ///< its tension k (ℓ − ℓ0) + c ℓ̇ (N)
  constraint_force,  ///< a constraint's forces (dynamics::constraint_force_labels)
};

/// What kind of model item a quantity is of.
enum class OutputTargetKind { joint, body, signal, force_element, constraint };

/// The kind of item `quantity` is of (a reaction is of a joint, a spring length of a force
/// element).
OutputTargetKind output_target_kind(OutputQuantity quantity);

/// True for the rotating-frame terms (transport_velocity ... euler_acceleration), which need a
/// frame to be seen from.
bool is_rotating_frame_term(OutputQuantity quantity);

/// "joint", "body", "signal", "force element", "constraint".
std::string_view output_target_kind_name(OutputTargetKind kind);

/// The name used in model files: "position", "velocity", "effort", "reaction_force", ...
/// (see docs/model-format.md) — joint and body quantities share "position" and "velocity".
std::string_view output_quantity_name(OutputQuantity quantity);

/// One requested output, as written in a model file.
struct OutputSpec {
  std::string name;  ///< column name (stem)
  OutputQuantity quantity = OutputQuantity::body_position;
  std::string target;         ///< the joint, body, signal or force element
  Vec3 point = Vec3::Zero();  ///< body quantities: the point, p_BoP_B (m)
  int component = -1;         ///< 0, 1, 2 for x, y, z (or one coordinate); −1: all
  ReactionFrame frame = ReactionFrame::world;  ///< reactions only
  /// Body quantities: the body whose frame F they are seen from and expressed in (empty: the
  /// world). The position is then p_FoP_F, the velocity and acceleration are relative to F
  /// (v_rel, a_rel) and the angular velocity is w_FB_F; every vector is in F's axes.
  std::string relative_to = {};
  /// Euler angles and rates: the sequence, one of the 12 of rotation_from_euler (upper case
  /// intrinsic). ZXZ by default: precession, nutation, spin — a top's angles.
  std::string sequence = "ZXZ";
};

/// True for the Euler angles and their rates (three values, not a vector).
bool is_euler_quantity(OutputQuantity quantity);

}  // namespace momenta::model
