// Several contacts struck at one instant, by Poisson's hypothesis (simultaneous_impact.hpp).

#include "momenta/dynamics/simultaneous_impact.hpp"

#include <algorithm>
#include <cmath>

#include "contact_impulse.hpp"

namespace momenta::dynamics {
namespace {

// The kinetic energy may grow by this fraction of itself in round-off, no more.
constexpr double kEnergyRoundOff = 1e-12;

// The friction impulse a contact's two tangent rows carry, as a magnitude.
double tangent_impulse(const VecX& impulses, const GroupContact& c) {
  return std::hypot(impulses[c.first_row + 1], impulses[c.first_row + 2]);
}

}  // namespace

std::optional<SimultaneousImpact> simultaneous_impact(const Model& model, VecRef q, VecRef v,
                                                      std::span<const GroupContact> group,
                                                      std::span<const char> enabled_rows,
                                                      std::span<const char> held_joints,
                                                      std::span<const SlidingContact> sliding) {
  // Compression, plastic: the group held with what holds already, sticking where it has friction.
  std::vector<char> rows(enabled_rows.begin(), enabled_rows.end());
  for (const GroupContact& c : group) {
    rows[static_cast<std::size_t>(c.first_row)] = 1;
    if (c.static_friction > 0.0) {
      rows[static_cast<std::size_t>(c.first_row + 1)] = 1;
      rows[static_cast<std::size_t>(c.first_row + 2)] = 1;
    }
  }
  const ImpulsiveMotion compression = impulsive_motion(model, q, v, {}, rows, held_joints, sliding);
  SimultaneousImpact result;
  double least = 0.0;
  for (std::size_t k = 0; k < group.size(); ++k) {
    const double P = compression.constraint_impulses[group[k].first_row];
    if (P < least) {
      least = P;
      result.pulling = static_cast<int>(k);
    }
  }
  if (result.pulling >= 0) return result;

  // Restitution: e_k P_c,k along each normal, the normal rows let go, the tangent rows holding.
  std::vector<PointImpulse> restitution_impulses;
  for (const GroupContact& c : group) {
    rows[static_cast<std::size_t>(c.first_row)] = 0;
    const double P = compression.constraint_impulses[c.first_row];
    for (const PointImpulse& p :
         detail::impulse_pair(c.touch, c.restitution * P * c.touch.normal_W)) {
      restitution_impulses.push_back(p);
    }
  }
  const ImpulsiveMotion restitution = impulsive_motion(
      model, q, compression.v_after, restitution_impulses, rows, held_joints, sliding);

  // Both phases as one impulse.
  ImpulsiveMotion& motion = result.motion;
  motion = restitution;
  motion.v_before = compression.v_before;
  motion.kinetic_before = compression.kinetic_before;
  motion.constraint_impulses += compression.constraint_impulses;
  motion.drive_impulses += compression.drive_impulses;
  motion.impulse_work += compression.impulse_work;
  motion.redundant_rows = std::max(motion.redundant_rows, compression.redundant_rows);
  for (std::size_t j = 0; j < motion.joint_impulses.size(); ++j) {
    motion.joint_impulses[j].force += compression.joint_impulses[j].force;
    motion.joint_impulses[j].moment += compression.joint_impulses[j].moment;
  }
  Data data(model);
  for (const GroupContact& c : group) {
    const double P_c = compression.constraint_impulses[c.first_row];
    const double P = (1.0 + c.restitution) * P_c;
    motion.constraint_impulses[c.first_row] = P;
    result.normal_impulses.push_back(P);
    // Coulomb's cone over compression and over the whole impact.
    if (tangent_impulse(compression.constraint_impulses, c) > c.static_friction * P_c ||
        tangent_impulse(motion.constraint_impulses, c) > c.static_friction * P) {
      return std::nullopt;
    }
    // Each separates or stays (the restitution impulses of the others may not drive it back in).
    const double after = detail::normal_speed(model, data, q, motion.v_after, c.touch);
    const double before = detail::normal_speed(model, data, q, v, c.touch);
    if (after < kEnergyRoundOff * before) return std::nullopt;
  }
  if (motion.kinetic_after > motion.kinetic_before * (1.0 + kEnergyRoundOff)) return std::nullopt;
  return result;
}

}  // namespace momenta::dynamics
