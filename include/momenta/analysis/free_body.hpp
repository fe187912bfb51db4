#pragma once
// Free-body and kinetic diagrams (Beer & Johnston §16.1, §18.1): one body isolated from a model
// at one instant, with every force and moment the rest of the system and the world put on it,
// beside the kinetic terms they must equal,
//
//     ΣF = m a_G,      ΣM_G = Ḣ_G = Ī_G α + ω × (Ī_G ω).
//
// What acts on the body, each as a force through a point plus a couple:
//  - gravity, m g at G;
//  - the joint that carries it: the constraint reaction at the joint centre J' (the transmitted
//    wrench less its part along the joint's free motions) and, along those motions, each joint
//    element (torsional spring, friction, the joint's own damping) and, on a prescribed joint,
//    the drive's effort;
//  - the joints it carries: the same items of each child joint, with the opposite sign;
//  - springs and dampers at their attachment points, applied forces and moments;
//  - constraint forces (loops, wires, rolling contacts), each drawn on its line of action.
// The split of a joint's wrench into "along the free motions" and "reaction" uses the joint's
// motion subspace S in J' about J'o: w_motion = S (SᵀS)⁻¹ Sᵀ w (a moment about a hinge's axis,
// a force along a slider's), so the reaction does no work on any motion the joint allows.
//
// The numbers are those of the simulation: system::MultibodySystem::evaluate at the state, and
// the joint reactions of dynamics::joint_reactions. All vectors are in the world frame W (SI).

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "momenta/dynamics/constraints.hpp"
#include "momenta/math/types.hpp"
#include "momenta/system/multibody_system.hpp"

namespace momenta::analysis {

/// What puts a load on the body, for its colour and legend.
enum class LoadKind {
  gravity,   ///< the body's weight
  reaction,  ///< a joint's or a constraint's reaction (does no work on the allowed motion)
  element,   ///< a spring, damper or friction element (a joint's own damping included)
  applied,   ///< an applied force or moment (model loads)
  drive,     ///< a prescribed joint's effort
};

/// The name of a load kind: "gravity", "reaction", ...
const char* load_kind_name(LoadKind kind);

/// One force through a point plus one couple, acting on the body.
struct Load {
  LoadKind kind = LoadKind::gravity;
  std::string name;         ///< the joint, element or constraint ("gravity" for the weight)
  std::string description;  ///< what it is, for a legend: "reaction of joint hinge (from world)"
  Vec3 p_WoP_W = Vec3::Zero();   ///< where the force acts (m)
  Vec3 force_W = Vec3::Zero();   ///< N
  Vec3 couple_W = Vec3::Zero();  ///< N·m: a couple (free vector), zero for a plain force
  /// The joint it acts through (its reaction, its elements, its drive), −1 for none: the loads of
  /// one joint sum to the wrench dynamics::joint_reaction gives (reversed on the parent).
  int joint_index = -1;
};

/// The sum of the loads' forces (N; or impulses, N·s).
Vec3 sum_of_forces(std::span<const Load> loads);
/// The sum of the loads' moments about the point p_WoO_W: Σ (p − O) × F + couples (N·m).
Vec3 sum_of_moments_about(std::span<const Load> loads, const Vec3& p_WoO_W);

/// The body a diagram isolates (free-body, kinetic or impulse–momentum), at its instant.
struct DiagramBody {
  std::string body;
  double t = 0.0;
  double mass = 0.0;             ///< kg
  Vec3 p_WoG_W = Vec3::Zero();   ///< centre of mass G (m)
  Vec3 p_WoBo_W = Vec3::Zero();  ///< body frame origin (m)
  Mat3 R_WB = Mat3::Identity();  ///< body axes
  Mat3 I_G_W = Mat3::Zero();     ///< Ī_G in W (kg·m²)
  /// The unit normal of the plane of motion when the diagram is planar (plane_of_loads): every
  /// force and momentum or m a_G in the plane, every couple and moment normal to it. Empty
  /// otherwise (a 3-D view).
  std::optional<Vec3> plane_normal;
};

/// The index of body `name` for a diagram: throws InvalidArgument for an unknown body (with a
/// did-you-mean) or the world — "the world has no <diagram>: <why>".
int diagram_body_index(const model::Model& model, const std::string& name, std::string_view diagram,
                       std::string_view why);

/// Body b's name, mass, pose and central inertia at data's poses, at time t.
DiagramBody diagram_body(const model::Model& model, const dynamics::Data& data, int b, double t);

/// The body's diagrams at one instant.
struct FreeBodyDiagram : DiagramBody {
  Vec3 w_WB_W = Vec3::Zero();      ///< ω (rad/s)
  Vec3 alpha_WB_W = Vec3::Zero();  ///< α (rad/s²)
  Vec3 a_WG_W = Vec3::Zero();      ///< a_G (m/s²)
  std::vector<Load> loads;

  // --- the kinetic diagram ------------------------------------------------------------------
  Vec3 m_a_G() const { return mass * a_WG_W; }
  Vec3 I_alpha() const { return I_G_W * alpha_WB_W; }              ///< Ī_G α
  Vec3 w_cross_H() const { return w_WB_W.cross(I_G_W * w_WB_W); }  ///< ω × H_G
  Vec3 H_G_dot() const { return I_alpha() + w_cross_H(); }

  // --- the balance ---------------------------------------------------------------------------
  Vec3 sum_of_forces() const;           ///< ΣF (N)
  Vec3 sum_of_moments_about_G() const;  ///< ΣM_G: Σ (p − G) × F + couples (N·m)
  Vec3 force_residual() const { return sum_of_forces() - m_a_G(); }              ///< ΣF − m a_G
  Vec3 moment_residual() const { return sum_of_moments_about_G() - H_G_dot(); }  ///< ΣM_G − Ḣ_G
};

/// The diagrams of body `body` (a name; not the world) at time t and state (q, v) of `system`'s
/// model (prescribed coordinates are set from their signals). Throws InvalidArgument for an
/// unknown body (with a did-you-mean) or the world, and what evaluate() throws. Allocates.
FreeBodyDiagram free_body_diagram(system::MultibodySystem& system, const std::string& body,
                                  double t, const VecX& q, const VecX& v);

/// Constraint `constraint`'s load on body `body` (an index) at the instant `system` last
/// evaluated, as a diagram draws it: its rows' forces summed into one wrench, given as a force on
/// its line of action at the point nearest the body's centre of mass plus the couple that
/// remains. Empty when the constraint acts on other bodies only or in joint space only (a
/// coupler), or the model has no constraints.
std::optional<Load> constraint_load(const system::MultibodySystem& system, int constraint,
                                    int body);

/// The same from constraint rows written at data's poses (dynamics::constraint_equations) and
/// their multipliers — forces, or the impulses Λ of an impact (dynamics::ImpulsiveMotion).
std::optional<Load> constraint_load(const model::Model& model, const dynamics::Data& data,
                                    const dynamics::ConstraintRows& rows, const VecX& multipliers,
                                    int constraint, int body);

/// The unit normal of the plane of motion of body `body` (an index; R_WB its axes, G at p_WoG_W)
/// under `loads` with the kinetic vectors `forces` (m a_G, or momenta) and `moments` (Ḣ_G, or
/// H_G): every force in the plane, every moment about G normal to it, to 1e-9 of the largest.
/// Tried in turn: the world's z, y and x axes, the body's joint axis (a revolute or
/// cylindrical joint), the largest moment, the normal of the two largest forces. Empty where
/// none is (a 3-D view).
std::optional<Vec3> plane_of_loads(const model::Model& model, int body, const Mat3& R_WB,
                                   const Vec3& p_WoG_W, std::span<const Load> loads,
                                   std::span<const Vec3> forces, std::span<const Vec3> moments);

}  // namespace momenta::analysis
