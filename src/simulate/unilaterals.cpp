#include "momenta/simulate/unilaterals.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "crossing_time.hpp"
#include "momenta/common/error.hpp"
#include "momenta/dynamics/contact_geometry.hpp"
#include "momenta/dynamics/impulse.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/simultaneous_impact.hpp"
#include "momenta/system/multibody_system.hpp"

namespace momenta::simulate {
namespace {

// Samples of a step where a joint that starts on a stop is looked for off it: a rebound shorter
// than a sixteenth of the step is found at its estimated apex, or not at all (then it is below
// the coordinate's resolution and the stop closes).
constexpr int kSamples = 16;

// How often the unilaterals may act at one instant before the run is stopped as stalled: each
// strikes, closes or lets go there once or twice in a real sequence.
constexpr int kActsAtOneInstant = 64;

// A run whose unilaterals act this often within kCrowdedSpan (s) of the first of them, or within
// ten of the run's steps where that is longer, makes no progress either: a contact that slips and
// stops slipping at once, again and again (its friction agrees with no slip direction near its
// cone's edge), or a rattle between stops a nanometre apart, would crawl on for ever, as would
// a thousand acts in every step (the MuJoCo arm's third link at its cone's edge, sticking and
// slipping every 8 µs at 6 ms steps: an hour to its end). No bouncing sequence comes near it (one
// cut short rests instead); a rattle between stops a micrometre apart acts 100 times in 0.1 ms.
constexpr int kActsInSpan = 10000;
constexpr double kCrowdedSpan = 1e-4;
constexpr double kCrowdedSteps = 10.0;

// A contact's gap below zero by this much (m, times its radius where that is above 1 m) is
// round-off: above the constraint projection's 1e-14, far below any motion a run resolves.
constexpr double kContactSlack = 1e-12;

// A disk contact whose axis comes this close to its plane's normal (rad) while it touches lies
// flat: its face, not a rim point, would touch — not modelled (model::Contact).
constexpr double kFlatDisk = 1e-6;

// A contact or stop reached approaching slower than this (m/s or rad/s) touches without an
// impact: its rate is round-off (the impulse's own measure of it may have the other sign).
constexpr double kGrazingSpeed = 1e-14;

// A contact that closes with its contact point slipping slower than this (m/s) is taken as not
// slipping: it sticks if friction can hold it (projecting that slip away is no visible jump).
constexpr double kSlipAtRest = 1e-10;

// A contact held at the start whose sticking friction is within this fraction of the largest
// constraint force of its cone's edge is at the edge: round-off decides neither way; it sticks.
constexpr double kConeRoundOff = 1e-12;

}  // namespace

std::string_view stop_event_kind_name(StopEventKind kind) {
  switch (kind) {
    case StopEventKind::impact:
      return "impact";
    case StopEventKind::rest:
      return "rest";
    case StopEventKind::release:
      return "release";
    case StopEventKind::stick:
      return "stick";
    case StopEventKind::slip:
      return "slip";
  }
  return "";
}

std::string_view friction_state_name(FrictionState state) {
  switch (state) {
    case FrictionState::none:
      return "";
    case FrictionState::sticking:
      return "sticking";
    case FrictionState::sliding:
      return "sliding";
  }
  return "";
}

Unilaterals::Unilaterals(const model::Model& model, double step)
    : model_(model),
      rest_flight_(1e-6 * step),
      crowded_span_(std::max(kCrowdedSpan, kCrowdedSteps * step)),
      data_(model) {
  for (const model::Joint& j : model.joints()) {
    if (!j.limits) continue;
    const model::JointLimits& l = *j.limits;
    const auto slack = [](double value) {
      return 4.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(value));
    };
    if (std::isfinite(l.lower))
      entries_.push_back(
          {false, j.index, j.q_index, j.v_index, l.lower, 1.0, l.restitution, slack(l.lower)});
    if (std::isfinite(l.upper))
      entries_.push_back(
          {false, j.index, j.q_index, j.v_index, l.upper, -1.0, l.restitution, slack(l.upper)});
  }
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    const auto* c = std::get_if<model::Contact>(&model.constraints()[k]);
    if (c == nullptr) continue;
    entries_.push_back({true, static_cast<int>(k), 0, 0, 0.0, 1.0, c->restitution,
                        kContactSlack * std::max(1.0, c->radius), c->static_friction});
  }
  hold_.assign(entries_.size(), Hold::open);
  slip_reference_.assign(entries_.size(), Vec3::UnitX());
  slip_run_.assign(entries_.size(), 0);
  q_ = VecX::Zero(model.nq());
  v_ = VecX::Zero(model.nv());
}

const model::Contact& Unilaterals::contact_of(const Entry& e) const {
  return std::get<model::Contact>(model_.constraints()[static_cast<std::size_t>(e.index)]);
}

namespace {

// The velocity in W of the point p_B of body b, from data's velocities.
Vec3 point_velocity(const dynamics::Data& data, int b, const Vec3& p_B) {
  const Vec6& V = data.V_WB_B[b];
  return data.X_WB[b].R * (V.tail<3>() + V.head<3>().cross(p_B));
}

}  // namespace

double Unilaterals::gap(const Entry& e, const integrate::State& state) {
  if (!e.contact) return e.outward * (state.q[e.q] - e.value);
  dynamics::forward_kinematics(model_, data_, state.q.head(model_.nq()));
  return dynamics::contact_geometry(contact_of(e), data_).gap;
}

double Unilaterals::rate(const Entry& e, const integrate::State& state) {
  if (!e.contact) return e.outward * state.v[e.v];
  const model::Contact& c = contact_of(e);
  dynamics::forward_kinematics(model_, data_, state.q.head(model_.nq()), state.v.head(model_.nv()));
  const dynamics::ContactGeometry g = dynamics::contact_geometry(c, data_);
  if (c.on_plane() || c.shape == model::ContactShape::disk) {
    // The bodies' material points at the contact, along the normal.
    return g.normal_W.dot(dynamics::contact_point_velocity(c, data_, g.point_W));
  }
  // Two spheres: the rate of the centres' distance.
  const Vec3 relative = point_velocity(data_, c.frame.body_index, c.frame.X_BF.p) -
                        point_velocity(data_, c.other.body_index, c.other.X_BF.p);
  return g.normal_W.dot(relative);
}

double Unilaterals::push(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
                         const Entry& e, const integrate::State& state) {
  solve_forces(advanced, state);
  return held_force(system, e);
}

void Unilaterals::solve_forces(integrate::SecondOrderSystem& advanced,
                               const integrate::State& state) {
  vdot_.resize(state.v.size());
  advanced.acceleration(state.t, state.q, state.v, vdot_);
}

double Unilaterals::held_force(const system::MultibodySystem& system, const Entry& e) const {
  return e.contact ? system.contact_force(e.index) : e.outward * system.stop_force(e.index);
}

double Unilaterals::acceleration_into(integrate::SecondOrderSystem& advanced, const Entry& e,
                                      const integrate::State& state) {
  vdot_.resize(state.v.size());
  advanced.acceleration(state.t, state.q, state.v, vdot_);
  if (!e.contact) return -e.outward * vdot_[e.v];
  dynamics::forward_kinematics(model_, data_, state.q.head(model_.nq()), state.v.head(model_.nv()),
                               vdot_.head(model_.nv()));
  return -dynamics::contact_gap_acceleration(contact_of(e), data_);
}

void Unilaterals::refuse_flat_disk(const Entry& e, const integrate::State& state) {
  const model::Contact& c = contact_of(e);
  if (c.shape != model::ContactShape::disk) return;
  dynamics::forward_kinematics(model_, data_, state.q.head(model_.nq()));
  if (!dynamics::disk_lies_flat(c, data_, kFlatDisk)) return;
  throw NumericalError(fmt::format(
      "contact '{}' at t = {:.9g} s: the disk lies flat on the plane (its axis within {:g} rad of "
      "the normal) and touches it with its face, which momenta does not model (docs/contacts.md)",
      c.name, state.t, kFlatDisk));
}

StopEvent Unilaterals::event_at(const Entry& e, double t, StopEventKind kind) const {
  StopEvent event;
  event.kind = kind;
  if (e.contact) {
    event.contact = contact_of(e).name;
  } else {
    event.joint = model_.joints()[static_cast<std::size_t>(e.index)].name;
    event.upper = e.outward < 0.0;
  }
  event.time = event.rest_time = t;
  return event;
}

double Unilaterals::first_contact(const Entry& e, integrate::SecondOrderSystem& advanced, double a,
                                  double b, double gap_a, double gap_b) {
  const auto f = [&](double t) {
    interpolant_.evaluate(advanced, t, trial_);
    return gap(e, trial_);
  };
  if (gap_a > 0.0) return detail::crossing_time(f, a, b, gap_a, gap_b);
  // On it at a (it struck or let go there): off it first, then back. The highest point of a
  // short rebound is estimated from the gap's parabola through its rate at a and its value at b;
  // the samples of the step find a longer one.
  const double span = b - a;
  const double rate_a = start_rate_;
  const double curvature = 2.0 * (gap_b - rate_a * span) / (span * span);
  const double apex = curvature < 0.0 && rate_a > 0.0 ? -rate_a / curvature : span;
  double last_off = a, f_off = 0.0;
  bool apex_tried = !(apex < span);
  for (int k = 1; k <= kSamples; ++k) {
    double t = k == kSamples ? b : a + span * k / kSamples;
    if (!apex_tried && t - a > apex) {
      t = a + apex;
      apex_tried = true;
      --k;
    }
    const double g = t == b ? gap_b : f(t);
    if (g > 0.0) {
      last_off = t;
      f_off = g;
    } else if (f_off > 0.0) {
      return detail::crossing_time(f, last_off, t, f_off, g);
    }
  }
  return a;  // it never leaves that the interpolant can see: it meets it again at once
}

void Unilaterals::hold_contact(system::MultibodySystem& system, const Entry& e,
                               integrate::State& at, Hold how, const Vec3& slip_W) {
  set_contact_hold(system, e, at, how, slip_W);
  if (how == Hold::open) return;
  // On the plane with no normal speed (and no slip where it sticks).
  project(system, at);
}

void Unilaterals::set_contact_hold(system::MultibodySystem& system, const Entry& e,
                                   const integrate::State& at, Hold how, const Vec3& slip_W) {
  hold_[slot(e)] = how;
  q_ = at.q.head(model_.nq());
  const system::ContactHold hold = how == Hold::open      ? system::ContactHold::open
                                   : how == Hold::sliding ? system::ContactHold::sliding
                                                          : system::ContactHold::sticking;
  system.hold_contact(e.index, q_, hold, slip_W);
  if (how != Hold::sliding) return;
  slip_reference_[slot(e)] = slip_W;
  slip_run_[slot(e)] = slip_velocity(e, at).norm() > kSlipAtRest;
}

void Unilaterals::project(system::MultibodySystem& system, integrate::State& at) {
  const int nq = model_.nq(), nv = model_.nv();
  q_ = at.q.head(nq);
  v_ = at.v.head(nv);
  if (!system.project(at.t, q_, v_)) return;
  at.q.head(nq) = q_;
  at.v.head(nv) = v_;
}

void Unilaterals::close(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
                        const Entry& e, integrate::State& at) {
  // A contact with friction that does not slip sticks if its cone holds it.
  if (e.contact && e.static_friction > 0.0 && !(slip_velocity(e, at).norm() > kSlipAtRest)) {
    refuse_flat_disk(e, at);
    StopEvent ignored;
    stick_or_slip(system, advanced, e, at, ignored);
    return;
  }
  hold_at_rest(system, e, at);
}

void Unilaterals::stick_or_slip(system::MultibodySystem& system,
                                integrate::SecondOrderSystem& advanced, const Entry& e,
                                integrate::State& at, StopEvent& event) {
  hold_contact(system, e, at, Hold::closed);
  event.friction_limit = e.static_friction * push(system, advanced, e, at);
  const Vec3 friction = sticking_friction(system, e, at);
  event.friction_needed = friction.norm();
  if (event.friction_needed <= event.friction_limit + cone_round_off(system)) {
    event.friction = FrictionState::sticking;
    return;
  }
  // It slips the way the friction it needed held it from, or where the mechanism turns a slip
  // from there, its stable direction nearest it (system/slip_direction.hpp).
  event.friction = FrictionState::sliding;
  hold_contact(system, e, at, Hold::sliding, -friction);
  follow_friction(system, advanced, e, at);
}

void Unilaterals::open(system::MultibodySystem& system, const Entry& e,
                       const integrate::State& at) {
  hold_[slot(e)] = Hold::open;
  if (e.contact) {
    system.hold_contact(e.index, at.q.head(model_.nq()), system::ContactHold::open);
  } else {
    system.release(e.index);
  }
}

Vec3 Unilaterals::slip_velocity(const Entry& e, const integrate::State& state) {
  const model::Contact& c = contact_of(e);
  dynamics::forward_kinematics(model_, data_, state.q.head(model_.nq()), state.v.head(model_.nv()));
  const dynamics::ContactGeometry g = dynamics::contact_geometry(c, data_);
  const Vec3 v = dynamics::contact_point_velocity(c, data_, g.point_W);
  return v - g.normal_W * g.normal_W.dot(v);
}

Vec3 Unilaterals::sticking_friction(const system::MultibodySystem& system, const Entry& e,
                                    const integrate::State& state) {
  const model::Contact& c = contact_of(e);
  dynamics::forward_kinematics(model_, data_, state.q.head(model_.nq()));
  const dynamics::ContactGeometry g = dynamics::contact_geometry(c, data_);
  const int first = system.constraints()->rows().first_row[static_cast<std::size_t>(e.index)];
  const VecX& lambda = system.constraints()->multipliers();
  return lambda[first + 1] * g.tangent_1_W + lambda[first + 2] * g.tangent_2_W;
}

double Unilaterals::cone_margin(system::MultibodySystem& system,
                                integrate::SecondOrderSystem& advanced, const Entry& e,
                                const integrate::State& state) {
  return e.static_friction * push(system, advanced, e, state) -
         sticking_friction(system, e, state).norm();
}

double Unilaterals::cone_round_off(const system::MultibodySystem& system) {
  const VecX& lambda = system.constraints()->multipliers();
  return lambda.size() > 0 ? kConeRoundOff * lambda.cwiseAbs().maxCoeff() : 0.0;
}

void Unilaterals::set_slip_references(system::MultibodySystem& system,
                                      integrate::SecondOrderSystem& advanced,
                                      const integrate::State& state) {
  bool evaluated = false;
  for (const Entry& e : entries_) {
    if (hold_[slot(e)] != Hold::sliding) continue;
    const Vec3 slip = slip_velocity(e, state);
    if (slip.norm() > system::kStartingSlip) system.end_slip_start(e.index);
    if (slip.norm() > kSlipAtRest) {
      slip_run_[slot(e)] = 1;
      slip_reference_[slot(e)] = slip;
      system.set_slip_reference(e.index, slip);
      continue;
    }
    if (!evaluated) solve_forces(advanced, state);
    evaluated = true;
    take_friction_as_reference(system, e);
  }
}

void Unilaterals::follow_friction(system::MultibodySystem& system,
                                  integrate::SecondOrderSystem& advanced, const Entry& e,
                                  const integrate::State& state) {
  solve_forces(advanced, state);
  take_friction_as_reference(system, e);
}

void Unilaterals::take_friction_as_reference(system::MultibodySystem& system, const Entry& e) {
  const Vec3 against = -system.contact_friction(e.index);
  if (!(against.norm() > 0.0)) return;  // no friction to say: the last one stands
  slip_reference_[slot(e)] = against;
  system.set_slip_reference(e.index, against);
}

dynamics::PointContact Unilaterals::touch_of(const Entry& e, const integrate::State& at) {
  const model::Contact& c = contact_of(e);
  dynamics::forward_kinematics(model_, data_, at.q.head(model_.nq()));
  // The contact point: the sphere's point nearest the plane, or on the line of centres.
  const dynamics::ContactGeometry geometry = dynamics::contact_geometry(c, data_);
  const Vec3& point = geometry.point_W;
  dynamics::PointContact touch;
  touch.normal_W = geometry.normal_W;
  touch.body_b = c.frame.body_index;
  const auto in_body = [&](int body) {
    const Transform& X = data_.X_WB[body];
    return Vec3(X.R.transpose() * (point - X.p));
  };
  touch.p_BoPb_B = in_body(touch.body_b);
  touch.body_a = c.other.body_index;
  touch.p_AoPa_A = touch.body_a == 0 ? point : in_body(touch.body_a);
  return touch;
}

double Unilaterals::contact_impact(system::MultibodySystem& system, const Entry& e,
                                   integrate::State& at) {
  const model::Contact& c = contact_of(e);
  const int nq = model_.nq(), nv = model_.nv();
  const dynamics::PointContact touch = touch_of(e, at);
  // The contacts closed now and the stops holding take their impulses as constraints; one that
  // would pull lets go, one whose cone cannot hold it slides, and the impact is solved again.
  begin_impact(system, at);
  bool all_stuck = false;
  // Contacts sliding through the impact against directions held from before it can jam it
  // (Painlevé) or make energy with it: those contacts stick for the impact instead (constraints
  // with no rebound take energy only), once; a failure then stands.
  const auto stick_them_once = [&] {
    if (all_stuck || sliding_at_impact_.empty()) return false;
    stick_all_sliding(system, at);
    all_stuck = true;
    return true;
  };
  for (;;) {
    if (sliding_at_impact_.empty() && held_by_others(system, e, at)) {
      // What holds now (the others stuck for the impact) holds its points still along the
      // normal: their impulses stop its approach, plastically, and it takes none of its own.
      const dynamics::ImpulsiveMotion held = dynamics::impulsive_motion(
          model_, at.q.head(nq), at.v.head(nv), {}, enabled_rows(system), system.held_joints());
      if (let_go_one_that_pulls(system, held, at) || slide_one_beyond_its_cone(system, held, at)) {
        continue;
      }
      at.v.head(nv) = held.v_after;
      return 0.0;
    }
    // Newton's restitution and Coulomb's law at impact (none without friction).
    dynamics::FrictionalImpact impact;
    try {
      impact = dynamics::frictional_impact(model_, at.q.head(nq), at.v.head(nv), touch,
                                           e.restitution, c.static_friction, c.kinetic_friction,
                                           enabled_rows(system), system.held_joints(),
                                           sliding_at_impact_, dynamics::EnergyGuard::caller);
    } catch (const NumericalError&) {
      if (stick_them_once()) continue;
      throw;
    }
    // One that pulls lets go, one beyond its cone slides, one whose slip the impact turns sticks,
    // and the impact is solved again; only the one kept must take energy or none (one that pulls
    // takes its share of the impulse back with it).
    if (let_go_one_that_pulls(system, impact.motion, at) ||
        slide_one_beyond_its_cone(system, impact.motion, at) ||
        stick_one_whose_slip_turns(system, impact.motion, at)) {
      continue;
    }
    if (dynamics::creates_energy(impact.motion) && stick_them_once()) continue;
    dynamics::check_energy_kept(impact, e.restitution, c.kinetic_friction);
    at.v.head(nv) = impact.motion.v_after;
    return impact.normal_impulse;
  }
}

bool Unilaterals::held_by_others(const system::MultibodySystem& system, const Entry& e,
                                 const integrate::State& at) {
  if (!e.contact) return false;
  return dynamics::held_still(dynamics::normal_mobility(
      model_, at.q.head(model_.nq()), touch_of(e, at), enabled_rows(system), system.held_joints()));
}

std::vector<const Unilaterals::Entry*> Unilaterals::struck_with(const Entry& first,
                                                                const integrate::State& at) {
  std::vector<const Entry*> group{&first};
  if (!first.contact) return group;
  for (const Entry& e : entries_) {
    if (&e == &first || !e.contact || hold_[slot(e)] != Hold::open) continue;
    if (gap(e, at) <= e.slack && rate(e, at) < -kGrazingSpeed) group.push_back(&e);
  }
  return group;
}

bool Unilaterals::strike_together(system::MultibodySystem& system,
                                  integrate::SecondOrderSystem& advanced,
                                  std::vector<const Entry*> group, integrate::State& at,
                                  StopEvent& event) {
  const int nq = model_.nq(), nv = model_.nv();
  const std::vector<int>& first_row = system.constraints()->rows().first_row;
  begin_impact(system, at);
  std::optional<dynamics::SimultaneousImpact> impact;
  std::vector<dynamics::GroupContact> contacts;
  for (;;) {
    contacts.clear();
    for (const Entry* e : group) {
      const model::Contact& c = contact_of(*e);
      contacts.push_back({touch_of(*e, at), first_row[static_cast<std::size_t>(e->index)],
                          c.restitution, c.static_friction, c.kinetic_friction});
    }
    impact = dynamics::simultaneous_impact(model_, at.q.head(nq), at.v.head(nv), contacts,
                                           enabled_rows(system), system.held_joints(),
                                           sliding_at_impact_);
    if (!impact) return false;
    if (impact->pulling >= 0) {  // not struck after all: the others' impact carries it off
      group.erase(group.begin() + impact->pulling);
      if (group.size() < 2) return false;
      continue;
    }
    if (!let_go_one_that_pulls(system, impact->motion, at) &&
        !slide_one_beyond_its_cone(system, impact->motion, at)) {
      break;
    }
  }
  std::vector<StopEvent> struck;
  for (std::size_t k = 0; k < group.size(); ++k) {
    StopEvent s = event_at(*group[k], at.t, StopEventKind::impact);
    s.rate_before = rate(*group[k], at);
    s.impulse = impact->normal_impulses[k];
    struck.push_back(s);
  }
  std::vector<StopEvent> group_slips = slips_in_group_impact(group, *impact, at.t);
  at.v.head(nv) = impact->motion.v_after;
  // The group's energy lost is said once, with the first (the contacts' shares of it are not
  // apart: each one's impulse works against the others' too).
  struck.front().energy_lost = impact->motion.kinetic_before - impact->motion.kinetic_after;
  // Those whose rebound flight the step cannot resolve rest, held together as at the start.
  std::vector<double> rest_tails(group.size(), -1.0);
  for (std::size_t k = 0; k < group.size(); ++k) {
    const double rebound = rate(*group[k], at);
    const double into = acceleration_into(advanced, *group[k], at);
    if (!(into > 0.0 && 2.0 * rebound / into < rest_flight_)) continue;
    const double e = contact_of(*group[k]).restitution;
    rest_tails[k] = rebound > 0.0 && e < 1.0 ? 2.0 * rebound / (into * (1.0 - e)) : 0.0;
  }
  for (std::size_t k = 0; k < group.size(); ++k) {
    if (rest_tails[k] >= 0.0) hold_at_rest(system, *group[k], at);
  }
  settle(system, advanced, at);
  for (std::size_t k = 0; k < group.size(); ++k) {
    const Entry& e = *group[k];
    StopEvent& s = struck[k];
    s.rate_after = rate(e, at);
    if (hold_[slot(e)] == Hold::open) continue;
    s.kind = StopEventKind::rest;
    s.rest_time += std::max(rest_tails[k], 0.0);
    if (e.static_friction > 0.0) {
      s.friction =
          hold_[slot(e)] == Hold::sliding ? FrictionState::sliding : FrictionState::sticking;
    }
  }
  event = struck.front();
  std::vector<StopEvent> slips;
  slips.swap(impact_slips_);
  impact_slips_.assign(struck.begin() + 1, struck.end());
  for (StopEvent& slip : group_slips) impact_slips_.push_back(std::move(slip));
  for (StopEvent& slip : slips) impact_slips_.push_back(std::move(slip));
  return true;
}

std::vector<StopEvent> Unilaterals::slips_in_group_impact(
    const std::vector<const Entry*>& group, const dynamics::SimultaneousImpact& impact,
    double t) const {
  std::vector<StopEvent> events;
  for (std::size_t k = 0; k < group.size(); ++k) {
    const dynamics::GroupContactFriction& f = impact.friction[k];
    if (f.state != dynamics::GroupFriction::sliding &&
        f.state != dynamics::GroupFriction::sliding_then_sticking) {
      continue;
    }
    StopEvent slip = event_at(*group[k], t, StopEventKind::slip);
    slip.in_impact = true;
    slip.friction = FrictionState::sliding;
    slip.friction_needed = f.needed;
    slip.friction_limit = f.limit;
    events.push_back(slip);
    if (f.state != dynamics::GroupFriction::sliding_then_sticking) continue;
    StopEvent stick = event_at(*group[k], t, StopEventKind::stick);
    stick.in_impact = true;
    stick.friction = FrictionState::sticking;
    stick.rate_before = f.slip_before;
    events.push_back(stick);
  }
  return events;
}

double Unilaterals::stop_strike(system::MultibodySystem& system, const Entry& e,
                                integrate::State& at) {
  const int nq = model_.nq(), nv = model_.nv();
  begin_impact(system, at);
  for (;;) {  // as contact_impact: what holds takes its impulse, unless it pulls or slides
    const dynamics::StopImpact impact =
        dynamics::stop_impact(model_, at.q.head(nq), at.v.head(nv), e.v, e.restitution,
                              enabled_rows(system), system.held_joints(), sliding_at_impact_);
    if (!let_go_one_that_pulls(system, impact.motion, at) &&
        !slide_one_beyond_its_cone(system, impact.motion, at) &&
        !stick_one_whose_slip_turns(system, impact.motion, at)) {
      at.v.head(nv) = impact.motion.v_after;
      return impact.impulse;
    }
  }
}

std::span<const char> Unilaterals::enabled_rows(const system::MultibodySystem& system) const {
  if (system.constraints() == nullptr) return {};
  return system.constraints()->rows().enabled;
}

bool Unilaterals::let_go_one_that_pulls(system::MultibodySystem& system,
                                        const dynamics::ImpulsiveMotion& motion,
                                        const integrate::State& at) {
  // The most negative impulse: a contact's normal impulse, a holding stop's along its outward
  // direction (N·s or N·m·s; round-off of a zero impulse lets nothing go).
  const Entry* pulling = nullptr;
  double least = 0.0;
  for (const Entry& e : entries_) {
    if (hold_[slot(e)] == Hold::open) continue;
    const double P =
        e.contact ? motion.constraint_impulses[system.constraints()->rows().first_row[e.index]]
                  : e.outward * motion.drive_impulses[e.v];
    if (P < least) {
      least = P;
      pulling = &e;
    }
  }
  if (pulling == nullptr) return false;
  open(system, *pulling, at);
  return true;
}

bool Unilaterals::slide_one_beyond_its_cone(system::MultibodySystem& system,
                                            const dynamics::ImpulsiveMotion& motion,
                                            integrate::State& at) {
  if (system.constraints() == nullptr) return false;
  const VecX& impulses = motion.constraint_impulses;
  const std::vector<int>& first_row = system.constraints()->rows().first_row;
  // The friction impulse its tangent rows carry (W, on body b) and μs times its normal impulse;
  // round-off of a zero friction impulse slides nothing.
  const Entry* beyond = nullptr;
  double most = impulses.size() > 0 ? 1e-12 * impulses.cwiseAbs().maxCoeff() : 0.0;
  Vec3 needed = Vec3::Zero();
  dynamics::forward_kinematics(model_, data_, at.q.head(model_.nq()));
  for (const Entry& e : entries_) {
    if (!e.contact || hold_[slot(e)] != Hold::closed || !(e.static_friction > 0.0)) continue;
    const int first = first_row[static_cast<std::size_t>(e.index)];
    const dynamics::ContactGeometry g = dynamics::contact_geometry(contact_of(e), data_);
    const Vec3 friction = impulses[first + 1] * g.tangent_1_W + impulses[first + 2] * g.tangent_2_W;
    const double excess = friction.norm() - e.static_friction * impulses[first];
    if (excess > most) {
      most = excess;
      beyond = &e;
      needed = friction;
    }
  }
  if (beyond == nullptr) return false;
  const int first = first_row[static_cast<std::size_t>(beyond->index)];
  StopEvent slip = event_at(*beyond, at.t, StopEventKind::slip);
  slip.in_impact = true;
  slip.friction = FrictionState::sliding;
  slip.friction_needed = needed.norm();
  slip.friction_limit = beyond->static_friction * impulses[first];
  impact_slips_.push_back(slip);
  // It slides the way the friction sticking needed held it from, through the impact and after.
  hold_contact(system, *beyond, at, Hold::sliding, -needed);
  sliding_at_impact_.push_back({first, touch_of(*beyond, at), Vec3(needed / needed.norm()),
                                contact_of(*beyond).kinetic_friction});
  return true;
}

bool Unilaterals::stick_one_whose_slip_turns(system::MultibodySystem& system,
                                             const dynamics::ImpulsiveMotion& motion,
                                             const integrate::State& at) {
  if (sliding_at_impact_.empty()) return false;
  trial_ = at;
  trial_.v.head(model_.nv()) = motion.v_after;
  for (std::size_t k = 0; k < sliding_at_impact_.size(); ++k) {
    const Entry& e = sliding_entry(system, sliding_at_impact_[k]);
    // The slip after, along the friction: positive where the friction would push it on. One
    // stuck once in this impact and slid again (its cone could not hold it) slides on.
    if (!(slip_velocity(e, trial_).dot(sliding_at_impact_[k].friction_W) > kSlipAtRest)) continue;
    if (std::find(stuck_in_impact_.begin(), stuck_in_impact_.end(), &e) != stuck_in_impact_.end()) {
      continue;
    }
    sliding_at_impact_.erase(sliding_at_impact_.begin() + static_cast<std::ptrdiff_t>(k));
    stick_for_impact(system, e, at);
    return true;
  }
  return false;
}

void Unilaterals::stick_all_sliding(system::MultibodySystem& system, const integrate::State& at) {
  std::vector<dynamics::SlidingContact> sliding;
  sliding.swap(sliding_at_impact_);
  for (const dynamics::SlidingContact& s : sliding) {
    stick_for_impact(system, sliding_entry(system, s), at);
  }
}

const Unilaterals::Entry& Unilaterals::sliding_entry(const system::MultibodySystem& system,
                                                     const dynamics::SlidingContact& s) const {
  const std::vector<int>& first_row = system.constraints()->rows().first_row;
  return *std::find_if(entries_.begin(), entries_.end(), [&](const Entry& x) {
    return x.contact && first_row[static_cast<std::size_t>(x.index)] == s.normal_row;
  });
}

void Unilaterals::stick_for_impact(system::MultibodySystem& system, const Entry& e,
                                   const integrate::State& at) {
  // Its tangent rows on, the state as it is: the impact's impulses stop its slip (projecting
  // the state first would stop it outside the impact's law and its energy count).
  StopEvent stick = event_at(e, at.t, StopEventKind::stick);
  stick.in_impact = true;
  stick.friction = FrictionState::sticking;
  stick.rate_before = slip_velocity(e, at).norm();
  impact_slips_.push_back(stick);
  stuck_in_impact_.push_back(&e);
  set_contact_hold(system, e, at, Hold::closed);
}

void Unilaterals::begin_impact(const system::MultibodySystem& system, const integrate::State& at) {
  sliding_at_impact_.clear();
  stuck_in_impact_.clear();
  if (system.constraints() == nullptr) return;
  const std::vector<int>& first_row = system.constraints()->rows().first_row;
  for (const Entry& e : entries_) {
    if (!e.contact || hold_[slot(e)] != Hold::sliding) continue;
    const model::Contact& c = contact_of(e);
    if (!(c.kinetic_friction > 0.0)) continue;
    // Against its slip (its reference direction where it is too slow to say).
    const Vec3 slip = slip_velocity(e, at);
    const Vec3 along = slip.norm() > kSlipAtRest ? slip : slip_reference_[slot(e)];
    sliding_at_impact_.push_back({first_row[static_cast<std::size_t>(e.index)], touch_of(e, at),
                                  Vec3(-along / along.norm()), c.kinetic_friction});
  }
}

std::vector<StopEvent> Unilaterals::take_impact_slips() {
  std::vector<StopEvent> slips;
  slips.swap(impact_slips_);
  return slips;
}

void Unilaterals::strike(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
                         const Entry& e, integrate::State& at, StopEvent& event) {
  const int nq = model_.nq(), nv = model_.nv();
  if (!e.contact) at.q[e.q] = e.value;
  event = event_at(e, at.t, StopEventKind::impact);
  // A stop reports its coordinate's rate as it is; a contact its normal speed.
  const auto reported_rate = [&] { return e.contact ? rate(e, at) : at.v[e.v]; };
  event.rate_before = reported_rate();
  const double approach = rate(e, at);
  const double kinetic_before = system.energy(at.q.head(nq), at.v.head(nv)).kinetic;
  // Approaching, it strikes — unless what holds already holds it still along its normal (a
  // foot's fourth corner where three are held): then its approach is their round-off.
  if (approach < -kGrazingSpeed && !held_by_others(system, e, at)) {
    if (e.contact) {
      event.impulse = contact_impact(system, e, at);
    } else {
      event.impulse = stop_strike(system, e, at);
    }
  }
  // Carried away, or held: the rebound's flight under the acceleration into it; one found back
  // on it at once, leaving it (a flight the step cannot resolve), is held too.
  const bool leaving = approach > 0.0;
  const double rebound = rate(e, at);
  const double into = acceleration_into(advanced, e, at);
  if (into > 0.0 && (leaving || 2.0 * rebound / into < rest_flight_)) {
    close(system, advanced, e, at);
    // Closed, it must push: where its force does not (pushed neither way to within round-off),
    // it stays open.
    if (push(system, advanced, e, at) > 0.0) {
      event.kind = StopEventKind::rest;
      if (e.static_friction > 0.0) {
        event.friction =
            hold_[slot(e)] == Hold::sliding ? FrictionState::sliding : FrictionState::sticking;
      }
      if (rebound > 0.0 && e.restitution < 1.0) {
        event.rest_time += 2.0 * rebound / (into * (1.0 - e.restitution));
      }
    } else {
      open(system, e, at);
    }
  }
  event.rate_after = reported_rate();
  event.energy_lost = kinetic_before - system.energy(at.q.head(nq), at.v.head(nv)).kinetic;
}

std::vector<StopEvent> hold_what_touches(system::MultibodySystem& system, integrate::State& state) {
  const model::Model& model = system.model();
  if (!model.has_joint_limits() && !model.has_contacts()) return {};
  Unilaterals unilaterals(model, 1e-3);
  return unilaterals.start(system, system, state);
}

void Unilaterals::open_all(system::MultibodySystem& system, const integrate::State& state) {
  for (const Entry& e : entries_) open(system, e, state);
  std::fill(slip_reference_.begin(), slip_reference_.end(), Vec3::UnitX());
}

std::vector<StopEvent> Unilaterals::start(system::MultibodySystem& system,
                                          integrate::SecondOrderSystem& advanced,
                                          integrate::State& state) {
  interpolant_.resize(static_cast<int>(state.q.size()), static_cast<int>(state.v.size()));
  trial_ = state;
  open_all(system, state);
  // Those touching at rest close together, and then those that pull or need more friction than
  // their cones hold are let go or slide: closed one at a time, each would decide as if the
  // others were open (a box's first corner alone would tip it over). Then those approaching
  // strike, against the others held.
  std::vector<const Entry*> approaching, resting;
  for (const Entry& e : entries_) {
    if (gap(e, state) > e.slack) continue;
    const double rate_now = rate(e, state);
    if (rate_now < -kGrazingSpeed) {
      approaching.push_back(&e);
      continue;
    }
    // Touching and leaving it so slowly that the flight is below what a step resolves (the
    // round-off of a state given as resting on it: a rolling coin's rim point) is resting on it,
    // as strike() holds such a rebound.
    if (rate_now > 0.0 &&
        !(2.0 * rate_now < rest_flight_ * acceleration_into(advanced, e, state))) {
      continue;
    }
    // Pressed onto it, as all are free (a ball hung touching another is not).
    if (acceleration_into(advanced, e, state) > 0.0) resting.push_back(&e);
  }
  for (const Entry* e : resting) hold_at_rest(system, *e, state);
  settle(system, advanced, state);
  std::vector<StopEvent> events;
  for (const Entry& e : entries_) {
    if (hold_[slot(e)] == Hold::open) continue;
    StopEvent event = event_at(e, state.t, StopEventKind::rest);
    event.rate_before = event.rate_after = e.contact ? rate(e, state) : state.v[e.v];
    if (e.contact && e.static_friction > 0.0) {
      event.friction =
          hold_[slot(e)] == Hold::sliding ? FrictionState::sliding : FrictionState::sticking;
    }
    events.push_back(event);
  }
  for (const Entry* e : approaching) {
    StopEvent event;
    strike(system, advanced, *e, state, event);
    if (event.kind == StopEventKind::rest || event.impulse != 0.0) events.push_back(event);
    for (StopEvent& slip : take_impact_slips()) events.push_back(std::move(slip));
  }
  return events;
}

void Unilaterals::hold_at_rest(system::MultibodySystem& system, const Entry& e,
                               integrate::State& at) {
  if (!e.contact) {
    hold_[slot(e)] = Hold::closed;
    at.q[e.q] = e.value;
    at.v[e.v] = 0.0;
    system.hold(e.index, e.value);
    // On a constrained model the other rates follow the held one's zero (a rebound too short to
    // resolve leaves them the constraints' share of its small rate).
    project(system, at);
    return;
  }
  refuse_flat_disk(e, at);
  const Vec3 slip = slip_velocity(e, at);
  if (e.static_friction > 0.0 && slip.norm() > kSlipAtRest) {
    hold_contact(system, e, at, Hold::sliding, slip);
  } else {
    hold_contact(system, e, at, Hold::closed);
  }
}

void Unilaterals::settle(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
                         integrate::State& at) {
  // Each pass lets one go (the one that pulls most; one that pushes neither way is not resting on
  // it either) or makes one slide (the one furthest beyond its cone), so it ends: a held one
  // slides or opens, a sliding one opens, none closes again.
  for (;;) {
    const Entry* pulling = nullptr;
    const Entry* beyond = nullptr;
    double least = 0.0, most = 0.0;
    solve_forces(advanced, at);  // every held one's force, and the multipliers, at once
    for (const Entry& e : entries_) {
      if (hold_[slot(e)] == Hold::open) continue;
      const double force = held_force(system, e);
      if (force < least || (pulling == nullptr && !(force > 0.0))) {
        least = force;
        pulling = &e;
      }
      if (e.contact && hold_[slot(e)] == Hold::closed && e.static_friction > 0.0) {
        const double excess = sticking_friction(system, e, at).norm() - e.static_friction * force -
                              cone_round_off(system);
        if (excess > most) {
          most = excess;
          beyond = &e;
        }
      }
    }
    if (pulling != nullptr) {
      open(system, *pulling, at);
    } else if (beyond != nullptr) {
      hold_contact(system, *beyond, at, Hold::sliding, -sticking_friction(system, *beyond, at));
      follow_friction(system, advanced, *beyond, at);
    } else {
      return;
    }
  }
}

bool Unilaterals::check(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
                        const integrate::Integrator& integrator, const integrate::State& start,
                        const integrate::State& end, integrate::State& before) {
  // The first to act in the step: one that closes on the mechanism, a closed one that would
  // pull, a sticking contact whose friction leaves the cone, or a sliding one whose slip passes
  // zero. At one instant, letting go comes first.
  double first = std::numeric_limits<double>::infinity();
  const Entry* acting = nullptr;
  bool interpolant_set = false;
  const auto set_interpolant = [&] {
    if (interpolant_set) return;
    interpolant_.set(advanced, integrator, start, end);
    interpolant_set = true;
  };
  const auto consider = [&](const Entry& e, double t, Pending what) {
    if (!(t < first)) return;
    first = t;
    acting = &e;
    pending_action_ = what;
  };
  // The first time in [start, end] a function of the state, ≥ 0 at the start and < 0 at the
  // end, reaches zero on the step's dense output (the start where it is not above zero there).
  const auto zero_of = [&](auto&& of_state, double at_end) {
    const double at_start = of_state(start);
    if (!(at_start > 0.0)) return start.t;
    set_interpolant();
    const auto f = [&](double t) {
      interpolant_.evaluate(advanced, t, trial_);
      return of_state(trial_);
    };
    return detail::crossing_time(f, start.t, end.t, at_start, at_end);
  };
  for (std::size_t k = 0; k < entries_.size(); ++k) {
    const Entry& e = entries_[k];
    if (hold_[k] == Hold::open) {
      if (!e.contact && system.held(e.index)) continue;  // its other stop holds the joint
      const double gap_end = gap(e, end);
      if (!(gap_end < -e.slack)) continue;
      set_interpolant();
      start_rate_ = rate(e, start);
      consider(e, first_contact(e, advanced, start.t, end.t, gap(e, start), gap_end),
               Pending::reach);
      continue;
    }
    if (e.contact) refuse_flat_disk(e, end);
    const double push_end = push(system, advanced, e, end);
    if (push_end < 0.0) {
      const auto pushes = [&](const integrate::State& x) { return push(system, advanced, e, x); };
      consider(e, zero_of(pushes, push_end), Pending::release);
    }
    if (hold_[k] == Hold::closed && e.static_friction > 0.0) {
      // Sticking, from the evaluation push() just made at the end; beyond its cone by more than
      // the forces' round-off (one carrying round-off alone would slip and stick at every step).
      const double margin_end =
          e.static_friction * push_end - sticking_friction(system, e, end).norm();
      if (!(margin_end < -cone_round_off(system))) continue;
      const auto margin = [&](const integrate::State& x) {
        return cone_margin(system, advanced, e, x);
      };
      consider(e, zero_of(margin, margin_end), Pending::slip);
    } else if (hold_[k] == Hold::sliding) {
      // A slip held from rest that has not yet run (at its cone's edge its acceleration starts
      // from zero) is round-off along its reference at first, either sign: it stops where it
      // runs back faster than kSlipAtRest, not at once.
      const Vec3 reference = slip_reference_[k].normalized();
      const double allowance = slip_run_[k] ? 0.0 : kSlipAtRest;
      const auto along = [&](const integrate::State& x) {
        return slip_velocity(e, x).dot(reference) + allowance;
      };
      const double along_end = along(end);
      if (along_end < 0.0) consider(e, zero_of(along, along_end), Pending::stop_slipping);
    }
  }
  if (acting == nullptr) {
    set_slip_references(system, advanced, end);
    return false;
  }
  if (first == start.t) {
    before = start;  // one that acts at once (found without the dense output)
  } else {
    interpolant_.evaluate(advanced, first, before);
  }
  // The dense output between two projected states leaves the constraints by its interpolation
  // error (1e-9 in a rate at dopri5's 10 ms steps): the state it acts on is put back on them — a
  // stop's coordinate exactly on the stop, held there while the others take up the residual.
  if (acting->contact || system.held(acting->index)) {
    project(system, before);
  } else {
    before.q[acting->q] = acting->value;
    if (system.constraints() != nullptr) {
      system.hold(acting->index, acting->value);
      project(system, before);
      system.release(acting->index);
    }
  }
  pending_ = static_cast<int>(acting - entries_.data());
  return true;
}

void Unilaterals::act(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
                      integrate::State& state, StopEvent& event) {
  const std::size_t k = static_cast<std::size_t>(pending_);
  const Entry& e = entries_[k];
  pending_ = -1;
  acts_at_last_ = state.t == last_act_ ? acts_at_last_ + 1 : 1;
  last_act_ = state.t;
  if (!(state.t - span_start_ < crowded_span_)) {
    span_start_ = state.t;
    acts_in_span_ = 0;
  }
  const auto what = [&] {
    return e.contact ? fmt::format("contact '{}'", contact_of(e).name)
                     : fmt::format("joint '{}''s {} stop",
                                   model_.joints()[static_cast<std::size_t>(e.index)].name,
                                   e.outward > 0.0 ? "lower" : "upper");
  };
  if (acts_at_last_ > kActsAtOneInstant) {
    throw NumericalError(fmt::format(
        "the unilaterals make no progress at t = {:.12g} s: {} has acted {} times there (its gap "
        "{:.17g}, rate {:.3g}) without the run moving on — it is pushed neither onto its "
        "constraint nor off it to within round-off. Move the limit or the plane, or give the "
        "mechanism a little damping or load",
        state.t, what(), kActsAtOneInstant, gap(e, state), rate(e, state)));
  }
  if (++acts_in_span_ > kActsInSpan) {
    throw NumericalError(fmt::format(
        "the unilaterals make no progress at t = {:.12g} s: they acted {} times since t = {:.12g} "
        "s, the last {} — faster than a run can follow them: a rattle between stops or contacts "
        "nearer than the motion resolves, or a contact whose friction agrees with no slip "
        "direction at its cone's edge, slipping and sticking again at once (docs/contacts.md). "
        "Widen the clearance, or give a smaller friction (or μs above μk) or a little damping",
        state.t, kActsInSpan, span_start_, what()));
  }
  switch (pending_action_) {
    case Pending::reach: {
      std::vector<const Entry*> group = struck_with(e, state);
      if (group.size() > 1 && strike_together(system, advanced, std::move(group), state, event)) {
        return;
      }
      strike(system, advanced, e, state, event);
      return;
    }
    case Pending::release:
      open(system, e, state);
      if (!e.contact) {
        state.q[e.q] = e.value;
        state.v[e.v] = 0.0;
      }
      event = event_at(e, state.t, StopEventKind::release);
      return;
    case Pending::slip: {
      // It slides the way the friction sticking needs held it from.
      event = event_at(e, state.t, StopEventKind::slip);
      event.friction_limit = e.static_friction * push(system, advanced, e, state);
      const Vec3 friction = sticking_friction(system, e, state);
      event.friction_needed = friction.norm();
      event.friction = FrictionState::sliding;
      hold_contact(system, e, state, Hold::sliding, -friction);
      follow_friction(system, advanced, e, state);
      return;
    }
    case Pending::stop_slipping:
      event = event_at(e, state.t, StopEventKind::stick);
      event.rate_before = slip_velocity(e, state).norm();
      stick_or_slip(system, advanced, e, state, event);
      if (event.friction == FrictionState::sliding) event.kind = StopEventKind::slip;
      return;
  }
}

}  // namespace momenta::simulate
