#pragma once
// What an impulse does to a mechanism in one instant (impulse and momentum: Beer & Johnston,
// Vector Mechanics, ch. 17; Featherstone 2008, §11.3). During the impact the configuration does
// not move and every finite force — gravity, springs, dampers, finite drives — gives no impulse;
// the speeds jump by Δv so that the generalized momentum balances the impulses:
//
//   M(q) Δv = Σ J_Pᵀ P + Gᵀ Λ,     G (v⁻ + Δv) = 0,     Δv = 0 on prescribed joints,
//
// P an impulse (N·s) applied at a point of a body, J_P that point's Jacobian, G the constraints'
// velocity rows (dynamics/constraints.hpp) and Λ their impulses (the rows' multipliers
// integrated over the instant: N·s on a translation row, N·m·s on a rotation row). The joints
// carry impulsive reactions too — a pin's impulse on its rod — found by the Newton–Euler
// recursion with Δv in place of v̇ and no velocity or gravity terms. A prescribed joint keeps its
// speed: its drive gives the impulse that takes.
//
// Kelvin's theorem checks the result: the kinetic energy changes by the work of the applied
// impulses at the mean of the points' velocities before and after, Σ ½ P · (v_P⁻ + v_P⁺), plus
// the drives' impulses at their joints' (unchanged) speeds; the constraints' impulses do none on
// a state that satisfies them.

#include <algorithm>
#include <span>
#include <vector>

#include "momenta/dynamics/data.hpp"
#include "momenta/dynamics/reactions.hpp"

namespace momenta::dynamics {

/// An impulse applied at a point P fixed in body b: p_BoP_B (m, in B), impulse (N·s, in W).
struct PointImpulse {
  int body = 0;
  Vec3 p_BoP_B = Vec3::Zero();
  Vec3 impulse_W = Vec3::Zero();
};

/// Two bodies meeting at a point: A's point p_AoPa_A and B's point p_BoPb_B, which touch, and the
/// contact normal n (unit, in W) along which B is pushed away from A. A may be the world (0).
struct PointContact {
  int body_a = 0;
  Vec3 p_AoPa_A = Vec3::Zero();
  int body_b = 0;
  Vec3 p_BoPb_B = Vec3::Zero();
  Vec3 normal_W = Vec3::UnitZ();
};

/// A contact that slides through an impact: a closed contact with friction whose cone cannot
/// hold the friction impulse sticking would need in the impact (its tangent rows then off). Its
/// normal row keeps the points from approaching, and its impulse Λ_n there brings the friction
/// impulse μk Λ_n along `friction_W` (unit, on body b at its point; the opposite on a) — Coulomb's
/// law at impact with the slip's direction taken as the one sticking held it from: the impulse
/// the row carries acts along n + μk friction_W (docs/contacts.md, "A sticking contact in
/// another's impact").
struct SlidingContact {
  int normal_row = 0;  ///< its normal row (the layout of ConstraintRows)
  PointContact contact;
  Vec3 friction_W = Vec3::UnitX();
  double kinetic_friction = 0.0;  ///< μk
};

/// The state just after the impulses, and every impulse the mechanism carries.
struct ImpulsiveMotion {
  VecX v_before, v_after;  ///< v⁻, v⁺
  /// Per constraint row (the layout of ConstraintRows): its impulse Λ (N·s or N·m·s). Where rows
  /// are redundant (a parallelogram's) the split among them is the least-norm one; their sum on
  /// the bodies is unique.
  VecX constraint_impulses;
  int redundant_rows = 0;
  /// Per joint: the impulse it transmits to its child, force (N·s) and moment (N·m·s) about J''s
  /// origin, in W — the part along its motion is a prescribed joint's drive impulse.
  std::vector<JointReaction> joint_impulses;
  /// Per velocity coordinate: the drive impulse a prescribed joint gives to keep its speed, or
  /// the stop's impulse on a held joint (`held_joints`) (N·s or N·m·s; 0 on free coordinates).
  VecX drive_impulses;
  double kinetic_before = 0.0, kinetic_after = 0.0;  ///< J (armature included)
  /// The impulses' work (J): Σ ½ P · (v_P⁻ + v_P⁺) over the applied impulses, plus each drive
  /// impulse times its joint's unchanged speed. Equals kinetic_after − kinetic_before.
  double impulse_work = 0.0;
};

/// The response of the model at (q, v) to the impulses. `q` must satisfy the constraints (v need
/// not: the rows' G v⁻ is removed, as a constrained impact does). Throws InvalidArgument for a
/// body index out of range, a non-finite impulse or state, or wrong sizes; NumericalError where
/// the free coordinates' mass matrix is singular. `enabled_rows` (one flag per constraint row,
/// ConstraintRows::enabled) says which rows hold; empty, the model's own (its contacts open):
/// a run passes the contacts it has closed, which then take their impulses too. `held_joints`
/// (one flag per joint; empty, none) marks the joints a stop holds: they keep their speed like a
/// prescribed joint's, and the stop's impulse is their entry of drive_impulses. `sliding`: the
/// closed contacts that slide through the impact (SlidingContact; their normal rows enabled,
/// their tangent rows not): each one's friction impulse is μk times its normal row's impulse
/// (constraint_impulses), counted in the joints' impulses and in impulse_work.
ImpulsiveMotion impulsive_motion(const Model& model, VecRef q, VecRef v,
                                 std::span<const PointImpulse> impulses,
                                 std::span<const char> enabled_rows = {},
                                 std::span<const char> held_joints = {},
                                 std::span<const SlidingContact> sliding = {});

/// A frictionless impact at a contact by Newton's law of restitution (Beer & Johnston ch. 17,
/// eccentric impact; Stronge, Impact Mechanics, ch. 2): the normal impulse P n on B (−P n on A)
/// that turns the approach speed v_n⁻ = n · (v_Pb − v_Pa) < 0 into the separation speed
/// v_n⁺ = −e v_n⁻, the whole mechanism taking part (its joints' and constraints' impulses).
struct Impact {
  double normal_impulse = 0.0;    ///< P (N·s), ≥ 0
  double approach_speed = 0.0;    ///< v_n⁻ (m/s), < 0
  double separation_speed = 0.0;  ///< v_n⁺ = −e v_n⁻ (m/s)
  ImpulsiveMotion motion;         ///< the mechanism's response to the pair ±P n
};

/// The separation speed a unit normal pair ±n at `contact`'s points gives them from rest, w (m/s
/// per N·s; restitution_impact's), the rows in `enabled_rows` and the joints in `held_joints`
/// holding and the `sliding` contacts sliding. Round-off (≤ 1e-12 of max(1, w)) where the joints
/// and rows hold the points still along the normal — a box's fourth corner where three are held:
/// such a contact has no impact of its own.
double normal_mobility(const Model& model, VecRef q, const PointContact& contact,
                       std::span<const char> enabled_rows = {},
                       std::span<const char> held_joints = {},
                       std::span<const SlidingContact> sliding = {});

/// Whether a normal_mobility w is round-off: the points are held still along the normal.
inline bool held_still(double w) { return !(w > 1e-12 * std::max(1.0, w)); }

/// The impact at `contact` with restitution e ∈ [0, 1] at (q, v). The separation speed is linear
/// in P: v_n(P) = v_n⁻ + P w, w = n · (J_Pb − J_Pa) M⁻¹ (J_Pb − J_Pa)ᵀ n > 0 found by a unit pair,
/// so P = −(1 + e) v_n⁻ / w. Throws InvalidArgument where the points do not approach (v_n⁻ ≥ 0:
/// no impact), e is outside [0, 1], the normal is not a unit vector, both points are on one body,
/// or the mechanism cannot move them apart (w = 0: a contact the constraints hold still).
/// `enabled_rows`, `held_joints` and `sliding` as impulsive_motion's; where contacts slide
/// through the impact and w ≤ 0 (their friction, taken with their normal impulses, turns the
/// pair's push back on itself: Painlevé's paradox at impact), NumericalError instead — the caller
/// may stick them and solve again.
Impact restitution_impact(const Model& model, VecRef q, VecRef v, const PointContact& contact,
                          double restitution, std::span<const char> enabled_rows = {},
                          std::span<const char> held_joints = {},
                          std::span<const SlidingContact> sliding = {});

/// What the slip at a contact did within an impact with friction.
enum class SlipCourse {
  sticks,        ///< no slip before, and the friction cone holds it: none after
  slides,        ///< it slides throughout (its direction may turn)
  stops,         ///< the slip comes to rest within the impact and the cone holds it there
  slides_again,  ///< it comes to rest (or starts at rest) where the cone cannot hold it, and slides
                 ///< again along ŝ with W_tn − μk W_tt ŝ = λ ŝ, λ > 0 (reversed, in a plane)
};

/// The course's name as `momenta impact` prints it: "sticking", "sliding", "sliding, then
/// sticking", "sliding again" (from rest, or reversed).
const char* slip_course_name(SlipCourse course);

/// An impact with restitution and Coulomb friction (a contact with friction, model::Contact;
/// docs/contacts.md), its course followed (Routh's process; Stronge, Impact Mechanics, 2000,
/// ch. 4–5): the normal impulse p grows from zero and the contact's relative velocity follows
/// du/dp = W (n + f), W the mechanism's inverse inertia at the contact (from three unit impulse
/// solves) and f the friction impulse per unit normal impulse — μk against the slip while it
/// slides (its direction may turn), and while it sticks the fixed f* = −W_tt⁺ W_tn that keeps it
/// stuck, held while |f*| ≤ μs; where the cone cannot hold a stopped slip, it slides again.
/// Compression ends where u_n reaches zero at p_c; the impact ends where the normal impulse has
/// given back e² of the work it took in compression (Stronge's energetic coefficient of
/// restitution, which cannot create energy). Where W n has no tangential part (a ball, a point
/// mass, a body struck on the line of its centre's response), u_n is linear in p and this is
/// Newton's −e v_n⁻ with μk P_n against the slip or the impulse that stops it; where the mechanism
/// couples the normal and the slip (a rod striking by one end) the separation speed differs from
/// −e v_n⁻. Refused with NumericalError where the impact would not end (friction jamming it:
/// Painlevé) or the result would create kinetic energy (a guard: the law above cannot).
struct FrictionalImpact {
  Vec3 impulse_W = Vec3::Zero();     ///< P on B (N·s, W): P_n n + the friction impulse
  double normal_impulse = 0.0;       ///< P_n (N·s), ≥ 0
  double compression_impulse = 0.0;  ///< p_c (N·s): the normal impulse at the end of compression
  double approach_speed = 0.0;       ///< v_n⁻ (m/s), < 0
  double separation_speed = 0.0;     ///< v_n⁺ (m/s), ≥ 0
  Vec3 slip_before_W = Vec3::Zero(), slip_after_W = Vec3::Zero();  ///< tangential u (m/s)
  bool sticking = false;  ///< the impulse leaves no slip (sticks or stops)
  SlipCourse course = SlipCourse::slides;
  ImpulsiveMotion motion;
};

/// Who refuses an impact that creates kinetic energy. The course cannot, but the other contacts'
/// impulses taken with it can: a held one in `enabled_rows` that pulls, or one in `sliding`
/// whose friction acts against a direction held from before the impact while its normal
/// impulse pulls. A caller that lets such a contact go, or sticks it, and solves again
/// (simulate::Unilaterals) judges only the impact it keeps (check_energy_kept).
enum class EnergyGuard {
  refuse,  ///< frictional_impact throws NumericalError (check_energy_kept)
  caller,  ///< frictional_impact returns it; the caller checks what it keeps
};

/// The impact at `contact` with restitution e, static and kinetic friction μs ≥ μk ≥ 0 at
/// (q, v); arguments checked as restitution_impact's. `enabled_rows`, `held_joints` and
/// `sliding` as impulsive_motion's. With μs = 0 it is restitution_impact's (its slips left zero,
/// not computed, its course `slides`).
FrictionalImpact frictional_impact(const Model& model, VecRef q, VecRef v,
                                   const PointContact& contact, double restitution,
                                   double static_friction, double kinetic_friction,
                                   std::span<const char> enabled_rows = {},
                                   std::span<const char> held_joints = {},
                                   std::span<const SlidingContact> sliding = {},
                                   EnergyGuard guard = EnergyGuard::refuse);

/// Whether `motion` leaves more kinetic energy than it found, by more than 1e-12 of it (of 1 J
/// below 1 J: round-off).
bool creates_energy(const ImpulsiveMotion& motion);

/// Throws NumericalError, naming e and μk and the energies, where `impact` creates energy
/// (creates_energy).
void check_energy_kept(const FrictionalImpact& impact, double restitution, double kinetic_friction);

/// A stop striking a joint's coordinate (a revolute or prismatic joint at its limit,
/// model::JointLimits): the generalized impulse P on coordinate i alone, M Δv = e_i P (+ the
/// constraints' impulses), that turns its rate v_i⁻ into v_i⁺ = −e v_i⁻ (Newton's restitution on
/// the coordinate). The rate is linear in P, v_i(P) = v_i⁻ + P (M⁻¹)_ii, so P = −(1 + e) v_i⁻ /
/// (M⁻¹)_ii. The joint's entry of motion.joint_impulses includes the stop's impulse (its part
/// along the joint's axis is P).
struct StopImpact {
  double impulse = 0.0;      ///< P (N·s or N·m·s), along the coordinate
  double rate_before = 0.0;  ///< v_i⁻ (m/s or rad/s)
  double rate_after = 0.0;   ///< v_i⁺ = −e v_i⁻
  ImpulsiveMotion motion;    ///< the mechanism's response (impulse_work: ½ P (v_i⁻ + v_i⁺))
};

/// The stop's impact on velocity coordinate `coordinate` with restitution e ∈ [0, 1] at (q, v).
/// Whatever the sign of v_i⁻ (the caller knows which stop it meets). Throws InvalidArgument for a
/// coordinate out of range, prescribed or held, e outside [0, 1], or one the constraints hold
/// still. `enabled_rows`, `held_joints` and `sliding` as impulsive_motion's.
StopImpact stop_impact(const Model& model, VecRef q, VecRef v, int coordinate, double restitution,
                       std::span<const char> enabled_rows = {},
                       std::span<const char> held_joints = {},
                       std::span<const SlidingContact> sliding = {});

}  // namespace momenta::dynamics
