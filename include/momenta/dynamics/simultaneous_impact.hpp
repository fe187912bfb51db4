#pragma once
// Contacts struck at one instant — a box landing flat on its four corners, a table on its legs —
// taken as one impact by Poisson's hypothesis (Stronge, Impact Mechanics, 2000, §2.2; Glocker &
// Pfeiffer's generalization to several contacts): compression is plastic, every contact of the
// group held at once (its normal row, and its tangent rows where it has friction: it sticks);
// restitution then applies, at each, e_k times the normal impulse it took in compression, along
// its normal, the tangent rows still holding. With one frictionless contact this is Newton's
// −e v_n⁻ (restitution_impact); with redundant contacts (four coplanar corners) the impulses are
// the least-norm split, as impulsive_motion's.

#include <optional>
#include <span>
#include <vector>

#include "momenta/dynamics/impulse.hpp"

namespace momenta::dynamics {

/// A contact of the group: where it touches, its first constraint row (the normal; its two
/// tangent rows follow, ConstraintRows), its restitution e ∈ [0, 1] and static friction μs.
struct GroupContact {
  PointContact touch;
  int first_row = 0;
  double restitution = 0.0;
  double static_friction = 0.0;
};

struct SimultaneousImpact {
  /// Both phases together: v⁻ → v⁺, each row's impulse summed (a group contact's normal row
  /// (1 + e_k) times its compression impulse), the joints' and drives' impulses summed.
  ImpulsiveMotion motion;
  std::vector<double> normal_impulses;  ///< per group contact: (1 + e_k) P_c,k (N·s)
  /// The group contact whose compression impulse pulls most (< 0: it is not struck; leave it out
  /// and solve again), or −1 where none pulls. Then nothing else is checked.
  int pulling = -1;
};

/// The group's impact at (q, v); `enabled_rows` (the rows that hold besides the group's: contacts
/// closed before, without the group's), `held_joints` and `sliding` as impulsive_motion's.
/// Returns nullopt where Poisson's law with sticking friction cannot hold the group: a contact
/// needs more friction than μs times its normal impulse (in compression, or over the whole
/// impact), a contact of the group still approaches after it, or the kinetic energy would grow
/// (beyond 1e-12 of it). The caller then strikes the contacts one after another.
std::optional<SimultaneousImpact> simultaneous_impact(const Model& model, VecRef q, VecRef v,
                                                      std::span<const GroupContact> group,
                                                      std::span<const char> enabled_rows,
                                                      std::span<const char> held_joints = {},
                                                      std::span<const SlidingContact> sliding = {});

}  // namespace momenta::dynamics
