// Several contacts struck at one instant, by Poisson's hypothesis (simultaneous_impact.hpp).

#include "momenta/dynamics/simultaneous_impact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "momenta/dynamics/constraints.hpp"
#include "momenta/dynamics/contact_geometry.hpp"
#include "momenta/dynamics/kinematics.hpp"

#include "contact_impulse.hpp"

namespace momenta::dynamics {
namespace {

// The kinetic energy may grow by this fraction of itself in round-off, no more.
constexpr double kEnergyRoundOff = 1e-12;

// Impulses within this fraction of the largest one, and speeds within this fraction of the
// group's fastest approach, are round-off: a cone exceeded by less holds, a slip turned by less
// has not turned, a slip slower than that has no direction of its own.
constexpr double kRoundOff = 1e-12;

// The two phases of the group's impact, each contact's friction as `friction` says.
struct Phases {
  ImpulsiveMotion compression, restitution;
};

// A contact's friction impulse in one phase's solve (W): what its two tangent rows carry.
Vec3 friction_impulse(const ImpulsiveMotion& phase, const GroupContact& c,
                      const ContactGeometry& g) {
  return phase.constraint_impulses[c.first_row + 1] * g.tangent_1_W +
         phase.constraint_impulses[c.first_row + 2] * g.tangent_2_W;
}

// The contact point's slip, b's relative to a's along the plane, at velocities v.
Vec3 slip_at(const Model& model, Data& data, VecRef q, VecRef v, const GroupContact& c) {
  const Vec3 relative = detail::relative_velocity(model, data, q, v, c.touch);
  return relative - c.touch.normal_W * c.touch.normal_W.dot(relative);
}

Phases poisson_phases(const Model& model, VecRef q, VecRef v, std::span<const GroupContact> group,
                      std::span<const GroupContactFriction> friction,
                      std::span<const Vec3> friction_W, std::span<const char> enabled_rows,
                      std::span<const char> held_joints,
                      std::span<const SlidingContact> sliding_before) {
  std::vector<char> rows(enabled_rows.begin(), enabled_rows.end());
  std::vector<SlidingContact> sliding(sliding_before.begin(), sliding_before.end());
  const auto hold_tangents = [&](const GroupContact& c, bool on) {
    rows[static_cast<std::size_t>(c.first_row + 1)] = on;
    rows[static_cast<std::size_t>(c.first_row + 2)] = on;
  };
  // Compression, plastic: the group held with what holds already; a sliding contact's friction
  // rides on its normal impulse.
  for (std::size_t k = 0; k < group.size(); ++k) {
    const GroupContact& c = group[k];
    rows[static_cast<std::size_t>(c.first_row)] = 1;
    const GroupFriction state = friction[k].state;
    if (state == GroupFriction::none) continue;
    hold_tangents(c, state == GroupFriction::sticking);
    if (state != GroupFriction::sticking) {
      sliding.push_back({c.first_row, c.touch, friction_W[k], c.kinetic_friction});
    }
  }
  Phases phases;
  phases.compression = impulsive_motion(model, q, v, {}, rows, held_joints, sliding);
  // Restitution: e_k P_c,k along each normal (with μk times it against the slip where the
  // contact slides on), the normal rows let go, the sticking contacts' tangent rows holding.
  std::vector<PointImpulse> impulses;
  for (std::size_t k = 0; k < group.size(); ++k) {
    const GroupContact& c = group[k];
    rows[static_cast<std::size_t>(c.first_row)] = 0;
    const GroupFriction state = friction[k].state;
    if (state != GroupFriction::none) hold_tangents(c, state != GroupFriction::sliding);
    Vec3 along = c.touch.normal_W;
    if (state == GroupFriction::sliding) along += c.kinetic_friction * friction_W[k];
    const double P = c.restitution * phases.compression.constraint_impulses[c.first_row];
    for (const PointImpulse& p : detail::impulse_pair(c.touch, P * along)) impulses.push_back(p);
  }
  phases.restitution =
      impulsive_motion(model, q, phases.compression.v_after, impulses, rows, held_joints, sliding);
  return phases;
}

// Both phases as one impulse: v⁻ → v⁺, each row's impulses summed, a group contact's normal
// row (1 + e_k) times its compression impulse.
ImpulsiveMotion whole_impact(const Phases& phases, std::span<const GroupContact> group) {
  const ImpulsiveMotion& compression = phases.compression;
  ImpulsiveMotion motion = phases.restitution;
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
  for (const GroupContact& c : group) {
    motion.constraint_impulses[c.first_row] =
        (1.0 + c.restitution) * compression.constraint_impulses[c.first_row];
  }
  return motion;
}

// How far a contact's friction is beyond its cone in the phases (N·s; ≤ 0 within it), and the
// friction impulse sticking needed where it is furthest: a sticking contact's in compression and
// over the whole impact, one sticking through restitution there.
struct ConeExcess {
  double excess = -std::numeric_limits<double>::infinity();
  Vec3 needed = Vec3::Zero();
  double limit = 0.0;
};

ConeExcess cone_excess(const Phases& phases, const ImpulsiveMotion& whole, const GroupContact& c,
                       GroupFriction state, const ContactGeometry& g) {
  ConeExcess worst;
  const auto weigh = [&](const Vec3& needed, double normal) {
    const double limit = c.static_friction * normal;
    if (needed.norm() - limit > worst.excess) worst = {needed.norm() - limit, needed, limit};
  };
  const double P_c = phases.compression.constraint_impulses[c.first_row];
  if (state == GroupFriction::sticking) {
    weigh(friction_impulse(phases.compression, c, g), P_c);
    weigh(friction_impulse(whole, c, g), whole.constraint_impulses[c.first_row]);
  } else if (state == GroupFriction::sliding_then_sticking) {
    weigh(friction_impulse(phases.restitution, c, g), c.restitution * P_c);
  }
  return worst;
}

// The contact's geometry at q (its tangent rows' directions), found by its first row.
ContactGeometry geometry_of(const Model& model, const Data& data, const ConstraintRows& layout,
                            const GroupContact& c) {
  const auto index =
      static_cast<std::size_t>(layout.constraint[static_cast<std::size_t>(c.first_row)]);
  return contact_geometry(std::get<model::Contact>(model.constraints()[index]), data);
}

}  // namespace

const char* group_friction_name(GroupFriction friction) {
  switch (friction) {
    case GroupFriction::none:
      return "none";
    case GroupFriction::sticking:
      return "sticking";
    case GroupFriction::sliding:
      return "sliding";
    case GroupFriction::sliding_then_sticking:
      return "sliding, then sticking";
  }
  return "none";
}

std::optional<SimultaneousImpact> simultaneous_impact(const Model& model, VecRef q, VecRef v,
                                                      std::span<const GroupContact> group,
                                                      std::span<const char> enabled_rows,
                                                      std::span<const char> held_joints,
                                                      std::span<const SlidingContact> sliding) {
  // Each contact's slip before, and its geometry (the tangent rows' directions).
  Data data(model);
  const ConstraintRows layout(model);
  std::vector<Vec3> slip_before;
  double fastest = 0.0;
  for (const GroupContact& c : group) {
    slip_before.push_back(slip_at(model, data, q, v, c));
    fastest = std::max(fastest, std::abs(detail::normal_speed(model, data, q, v, c.touch)));
  }
  forward_kinematics(model, data, q);
  std::vector<ContactGeometry> geometry;
  SimultaneousImpact result;
  for (std::size_t k = 0; k < group.size(); ++k) {
    const GroupContact& c = group[k];
    geometry.push_back(geometry_of(model, data, layout, c));
    GroupContactFriction f;
    f.state = c.static_friction > 0.0 ? GroupFriction::sticking : GroupFriction::none;
    f.slip_before = slip_before[k].norm();
    result.friction.push_back(f);
  }
  std::vector<Vec3> friction_W(group.size(), Vec3::Zero());

  // Each contact sticks where its cone holds; the one furthest beyond slides, the way its slip
  // ran (or against the friction sticking needed), and the sliding ones whose slip their
  // friction would turn back by the end stick through restitution. Each contact moves on at most
  // twice.
  for (;;) {
    const Phases phases = poisson_phases(model, q, v, group, result.friction, friction_W,
                                         enabled_rows, held_joints, sliding);
    const ImpulsiveMotion whole = whole_impact(phases, group);
    double least = 0.0;
    for (std::size_t k = 0; k < group.size(); ++k) {
      const double P = phases.compression.constraint_impulses[group[k].first_row];
      if (P < least) {
        least = P;
        result.pulling = static_cast<int>(k);
      }
    }
    if (result.pulling >= 0) return result;

    int beyond = -1;
    ConeExcess most;
    most.excess = kRoundOff * whole.constraint_impulses.cwiseAbs().maxCoeff();
    for (std::size_t k = 0; k < group.size(); ++k) {
      const ConeExcess x =
          cone_excess(phases, whole, group[k], result.friction[k].state, geometry[k]);
      if (x.excess > most.excess) {
        most = x;
        beyond = static_cast<int>(k);
      }
    }
    if (beyond >= 0) {
      GroupContactFriction& f = result.friction[static_cast<std::size_t>(beyond)];
      if (f.state != GroupFriction::sticking) return std::nullopt;  // beyond in restitution
      f.state = GroupFriction::sliding;
      f.needed = most.needed.norm();
      f.limit = most.limit;
      const Vec3& slip = slip_before[static_cast<std::size_t>(beyond)];
      friction_W[static_cast<std::size_t>(beyond)] =
          slip.norm() > kRoundOff * fastest ? Vec3(-slip.normalized()) : most.needed.normalized();
      continue;
    }

    // Those whose slip their friction would turn back by the end stick through restitution, all
    // at once (on one body, each one's stopping stops the others').
    bool turned = false;
    for (std::size_t k = 0; k < group.size(); ++k) {
      if (result.friction[k].state != GroupFriction::sliding) continue;
      // The slip along its own direction, −friction_W: below zero it runs with its friction.
      const auto along = [&](const VecX& v_at) {
        return -friction_W[k].dot(slip_at(model, data, q, v_at, group[k]));
      };
      if (!(along(whole.v_after) < -kRoundOff * fastest)) continue;
      if (along(phases.compression.v_after) < -kRoundOff * fastest) return std::nullopt;
      result.friction[k].state = GroupFriction::sliding_then_sticking;
      turned = true;
    }
    if (turned) continue;
    result.motion = whole;
    break;
  }

  for (std::size_t k = 0; k < group.size(); ++k) {
    const GroupContact& c = group[k];
    result.normal_impulses.push_back(result.motion.constraint_impulses[c.first_row]);
    // Each separates or stays (the restitution impulses of the others may not drive it back in).
    const double after = detail::normal_speed(model, data, q, result.motion.v_after, c.touch);
    const double before = detail::normal_speed(model, data, q, v, c.touch);
    if (after < kEnergyRoundOff * before) return std::nullopt;
  }
  if (result.motion.kinetic_after > result.motion.kinetic_before * (1.0 + kEnergyRoundOff)) {
    return std::nullopt;
  }
  return result;
}

}  // namespace momenta::dynamics
