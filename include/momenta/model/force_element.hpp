#pragma once
// Force elements: springs, dampers, friction and applied loads, as data.
//
// These structs describe the elements; ModelBuilder::build() checks their parameters and fills
// the resolved indices; the simulator evaluates them into generalized forces (and the springs'
// potential energy). Bodies are named, "world" for the ground; points are fixed in their body and
// given in its frame. Signals are named and live in the Model.

#include <string>
#include <variant>
#include <vector>

#include "momenta/math/types.hpp"

namespace momenta::model {

/// A point P fixed in body B: the body's name and p_BoP_B (m).
struct BodyPoint {
  std::string body;
  Vec3 p_BoP_B = Vec3::Zero();
  int body_index = -1;  ///< Set by ModelBuilder::build().
};

/// Frame in which an applied load's vector is given.
enum class LoadFrame { world, body };

/// Spring and damper along the line between point a and point b (either may be on the world):
/// tension T = stiffness · (ℓ − free_length) + damping · ℓ̇, ℓ = |p_b − p_a|, pulling the points
/// together when T > 0. Potential energy ½ stiffness (ℓ − free_length)².
struct LinearSpringDamper {
  std::string name;
  BodyPoint a;
  BodyPoint b;
  double stiffness = 0.0;    ///< N/m, ≥ 0.
  double damping = 0.0;      ///< N·s/m, ≥ 0.
  double free_length = 0.0;  ///< m, ≥ 0.
};

/// Torsional spring and damper. On a 1-dof joint (`joint` set; revolute, or prismatic where it
/// acts as a linear spring): τ = −stiffness (q − rest_angle) − damping q̇. Between two bodies
/// (`joint` empty, `body_a` and `body_b` set; either may be the world): the moment on b is
/// −stiffness · θ − damping · (ω_B − ω_A), and the opposite moment acts on a. θ = log(R_AB_restᵀ
/// R_AB) is the rotation vector (|θ| ≤ π) of b relative to a measured from their rest relative
/// orientation R_AB_rest, which is their relative orientation at the model's initial
/// configuration (Model::initial_q(), the joints' q0): the spring is relaxed there. Potential
/// energy ½ stiffness |θ|² (½ stiffness (q − rest_angle)² in the joint form).
struct TorsionalSpringDamper {
  std::string name;
  std::string joint;
  std::string body_a;
  std::string body_b;
  double stiffness = 0.0;   ///< N·m/rad, ≥ 0.
  double damping = 0.0;     ///< N·m·s/rad, ≥ 0.
  double rest_angle = 0.0;  ///< rad (m on a prismatic joint); joint form only.
  int joint_index = -1;     ///< Set by ModelBuilder::build(); −1 in the two-body form.
  int body_a_index = -1;    ///< Set by ModelBuilder::build() in the two-body form.
  int body_b_index = -1;    ///< Set by ModelBuilder::build() in the two-body form.
  /// Set by ModelBuilder::build() in the two-body form: R_AB (b's orientation in a) at the
  /// model's initial configuration, where the spring is relaxed. Identity in the joint form.
  Mat3 R_AB_rest = Mat3::Identity();
};

/// Viscous friction on every velocity coordinate of a joint: τ = −viscous · v.
struct JointFriction {
  std::string name;
  std::string joint;
  double viscous = 0.0;  ///< N·m·s/rad or N·s/m, ≥ 0.
  int joint_index = -1;  ///< Set by ModelBuilder::build().
};

/// A force applied at a point of a body: F = vector, or F = u(t) · vector when `signal` names a
/// signal. `vector` is expressed in the world (a fixed direction) or in the body (a follower
/// load), per `frame`.
struct AppliedForce {
  std::string name;
  BodyPoint at;
  LoadFrame frame = LoadFrame::world;
  Vec3 vector = Vec3::Zero();  ///< N (or a direction scaled by the signal).
  std::string signal;          ///< Empty for a constant load.
  int signal_index = -1;       ///< Set by ModelBuilder::build(); −1 without a signal.
};

/// A pure moment applied to a body: M = vector, or M = u(t) · vector with a signal.
struct AppliedTorque {
  std::string name;
  std::string body;
  LoadFrame frame = LoadFrame::world;
  Vec3 vector = Vec3::Zero();  ///< N·m (or a direction scaled by the signal).
  std::string signal;
  int body_index = -1;    ///< Set by ModelBuilder::build().
  int signal_index = -1;  ///< Set by ModelBuilder::build(); −1 without a signal.
};

/// One joint of a fixed tendon and its coefficient.
struct TendonTerm {
  std::string joint;
  double coefficient = 1.0;  ///< the tendon's length unit per unit of the joint's coordinate
  int joint_index = -1;      ///< Set by ModelBuilder::build().
};

/// A fixed tendon (MuJoCo's `<tendon><fixed>`): a length that is a fixed linear combination of
/// 1-dof joints' coordinates, L = offset + Σ cᵢ qᵢ, with a spring-damper along it of tension
/// T = stiffness (L − rest_length) + damping L̇; each of its joints feels τᵢ = −cᵢ T. Potential
/// energy ½ stiffness (L − rest_length)². With neither stiffness nor damping it only measures
/// (the outputs `spring_length` L and `spring_tension` T). L is in its first joint's unit (rad
/// or m); a coefficient of a joint of the other kind carries the conversion (m/rad or rad/m).
struct FixedTendon {
  std::string name;
  std::vector<TendonTerm> terms;  ///< at least one, each joint once
  double offset = 0.0;            ///< L at q = 0
  double stiffness = 0.0;         ///< N·m/rad or N/m (the length's unit), ≥ 0.
  double damping = 0.0;           ///< N·m·s/rad or N·s/m, ≥ 0.
  double rest_length = 0.0;       ///< L where the spring is relaxed
};

using ForceElement = std::variant<LinearSpringDamper, TorsionalSpringDamper, JointFriction,
                                  AppliedForce, AppliedTorque, FixedTendon>;

/// The name of any force element.
const std::string& force_element_name(const ForceElement& element);

}  // namespace momenta::model
