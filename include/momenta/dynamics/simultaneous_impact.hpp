#pragma once
// Contacts struck at one instant — a box landing flat on its four corners, a table on its legs —
// taken as one impact by Poisson's hypothesis (Stronge, Impact Mechanics, 2000, §2.2; Glocker &
// Pfeiffer's generalization to several contacts): compression is plastic, every contact of the
// group held at once (its normal row, and its tangent rows where it has friction: it sticks);
// restitution then applies, at each, e_k times the normal impulse it took in compression, along
// its normal, the tangent rows still holding. With one frictionless contact this is Newton's
// −e v_n⁻ (restitution_impact); with redundant contacts (four coplanar corners) the impulses are
// the least-norm split, as impulsive_motion's.
//
// A contact whose cone cannot hold what sticking needs slides through the impact instead: its
// friction −μk P ŝ with its normal impulse P in each phase, ŝ its slip's direction before the
// impact (where it does not slip, against the friction sticking needed), kept through it — a
// box landing flat while it slides leaves level, μk (1 + e) V slower. Where that friction would
// turn its slip back by the impact's end, the slip stops within restitution: it slides through
// compression and sticks through restitution (its cone there μs e P_c).

#include <optional>
#include <span>
#include <vector>

#include "momenta/dynamics/impulse.hpp"

namespace momenta::dynamics {

/// A contact of the group: where it touches, its first constraint row (the normal; its two
/// tangent rows follow, ConstraintRows), its restitution e ∈ [0, 1] and friction μs, μk.
struct GroupContact {
  PointContact touch;
  int first_row = 0;
  double restitution = 0.0;
  double static_friction = 0.0;
  double kinetic_friction = 0.0;
};

/// How a group contact's friction acts through the impact.
enum class GroupFriction {
  none,                   ///< frictionless
  sticking,               ///< its tangent rows hold in both phases
  sliding,                ///< −μk P ŝ in both phases
  sliding_then_sticking,  ///< −μk P_c ŝ in compression; its tangent rows hold in restitution
};

/// "none", "sticking", "sliding", "sliding, then sticking".
const char* group_friction_name(GroupFriction friction);

/// A group contact's friction through the impact.
struct GroupContactFriction {
  GroupFriction state = GroupFriction::none;
  /// Where it slides: the friction impulse sticking needed, |P_t|, and its cone, μs P_n (N·s),
  /// in the phase (compression, or the whole impact) it was furthest beyond it.
  double needed = 0.0, limit = 0.0;
  double slip_before = 0.0;  ///< m/s: its contact point's slip speed before the impact
};

struct SimultaneousImpact {
  /// Both phases together: v⁻ → v⁺, each row's impulse summed (a group contact's normal row
  /// (1 + e_k) times its compression impulse), the joints' and drives' impulses summed.
  ImpulsiveMotion motion;
  std::vector<double> normal_impulses;         ///< per group contact: (1 + e_k) P_c,k (N·s)
  std::vector<GroupContactFriction> friction;  ///< per group contact
  /// The group contact whose compression impulse pulls most (< 0: it is not struck; leave it out
  /// and solve again), or −1 where none pulls. Then nothing else is checked.
  int pulling = -1;
};

/// The group's impact at (q, v); `enabled_rows` (the rows that hold besides the group's: contacts
/// closed before, without the group's), `held_joints` and `sliding` as impulsive_motion's.
/// Each contact sticks where its cone holds (μs times its normal impulse, in compression and
/// over the whole impact); the one furthest beyond slides and the group is solved again. Returns
/// nullopt where that cannot hold the group: a sliding contact's slip turns back within
/// compression, or one sticking through restitution needs more than μs e P_c there, a contact
/// of the group still approaches after it, or the kinetic energy would grow (beyond 1e-12 of
/// it). The caller then strikes the contacts one after another.
std::optional<SimultaneousImpact> simultaneous_impact(const Model& model, VecRef q, VecRef v,
                                                      std::span<const GroupContact> group,
                                                      std::span<const char> enabled_rows,
                                                      std::span<const char> held_joints = {},
                                                      std::span<const SlidingContact> sliding = {});

}  // namespace momenta::dynamics
