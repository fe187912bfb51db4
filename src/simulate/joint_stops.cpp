#include "momenta/simulate/joint_stops.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <fmt/format.h>

#include "crossing_time.hpp"
#include "momenta/common/error.hpp"
#include "momenta/dynamics/impulse.hpp"
#include "momenta/system/multibody_system.hpp"

namespace momenta::simulate {
namespace {

// Samples of a step where a joint that starts on a stop is looked for off it: a rebound shorter
// than a sixteenth of the step is found at its estimated apex, or not at all (then it is below
// the coordinate's resolution and the stop closes).
constexpr int kSamples = 16;

// How often the stops may act at one instant before the run is stopped as stalled: each stop
// strikes, closes or lets go there once or twice in a real sequence.
constexpr int kActsAtOneInstant = 64;

}  // namespace

std::string_view stop_event_kind_name(StopEventKind kind) {
  switch (kind) {
    case StopEventKind::impact:
      return "impact";
    case StopEventKind::rest:
      return "rest";
    case StopEventKind::release:
      return "release";
  }
  return "";
}

JointStops::JointStops(const model::Model& model, double step)
    : model_(model), rest_flight_(1e-6 * step) {
  for (const model::Joint& j : model.joints()) {
    if (!j.limits) continue;
    const model::JointLimits& l = *j.limits;
    const auto slack = [](double value) {
      return 4.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(value));
    };
    if (std::isfinite(l.lower))
      stops_.push_back(
          {j.index, j.q_index, j.v_index, l.lower, 1.0, l.restitution, slack(l.lower)});
    if (std::isfinite(l.upper))
      stops_.push_back(
          {j.index, j.q_index, j.v_index, l.upper, -1.0, l.restitution, slack(l.upper)});
  }
  held_.assign(stops_.size(), 0);
}

const VecX& JointStops::accelerations(integrate::SecondOrderSystem& advanced,
                                      const integrate::State& state) {
  vdot_.resize(state.v.size());
  advanced.acceleration(state.t, state.q, state.v, vdot_);
  return vdot_;
}

double JointStops::push(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
                        const Stop& s, const integrate::State& state) {
  accelerations(advanced, state);
  return s.outward * system.stop_force(s.joint);
}

StopEvent JointStops::event_at(const Stop& s, double t, StopEventKind kind) const {
  StopEvent event;
  event.kind = kind;
  event.joint = model_.joints()[static_cast<std::size_t>(s.joint)].name;
  event.upper = s.outward < 0.0;
  event.time = event.rest_time = t;
  return event;
}

double JointStops::first_contact(const Stop& s, integrate::SecondOrderSystem& advanced, double a,
                                 double b, double gap_a, double gap_b) {
  const auto f = [&](double t) {
    interpolant_.evaluate(advanced, t, trial_);
    return gap(s, trial_);
  };
  if (gap_a > 0.0) return detail::crossing_time(f, a, b, gap_a, gap_b);
  // On the stop at a (it struck or let go there): off it first, then back. The highest point of
  // a short rebound is estimated from the gap's parabola through its rate at a and its value at
  // b; the samples of the step find a longer one.
  const double span = b - a;
  const double rate_a = s.outward * start_rate_;
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
  return a;  // it never leaves the stop that the interpolant can see: it meets it again at once
}

double JointStops::first_pull(system::MultibodySystem& system,
                              integrate::SecondOrderSystem& advanced, const Stop& s, double a,
                              double b, double push_a, double push_b) {
  if (!(push_a > 0.0)) return a;
  const auto f = [&](double t) {
    interpolant_.evaluate(advanced, t, trial_);
    return push(system, advanced, s, trial_);
  };
  return detail::crossing_time(f, a, b, push_a, push_b);
}

void JointStops::close(system::MultibodySystem& system, const Stop& s, integrate::State& at) {
  at.q[s.q] = s.value;
  at.v[s.v] = 0.0;
  system.hold(s.joint, s.value);
  held_[static_cast<std::size_t>(&s - stops_.data())] = 1;
}

void JointStops::strike(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
                        const Stop& s, integrate::State& at, StopEvent& event) {
  const int nq = model_.nq(), nv = model_.nv();
  at.q[s.q] = s.value;
  event = event_at(s, at.t, StopEventKind::impact);
  event.rate_before = at.v[s.v];
  const double kinetic_before = system.energy(at.q.head(nq), at.v.head(nv)).kinetic;
  if (s.outward * at.v[s.v] < 0.0) {  // approaching: the stop strikes
    const dynamics::StopImpact impact =
        dynamics::stop_impact(model_, at.q.head(nq), at.v.head(nv), s.v, s.restitution);
    at.v.head(nv) = impact.motion.v_after;
    event.impulse = impact.impulse;
  }
  // Carried away, or held: the rebound's flight under the acceleration into the stop; one found
  // back on the stop at once, leaving it (a flight the step cannot resolve), is held too.
  const bool leaving = s.outward * event.rate_before > 0.0;
  const double rebound = s.outward * at.v[s.v];
  const double into = -s.outward * accelerations(advanced, at)[s.v];
  if (into > 0.0 && (leaving || 2.0 * rebound / into < rest_flight_)) {
    close(system, s, at);
    // Held, the stop must push: where its force does not (the joint pushed neither way to within
    // round-off), the joint stays free.
    if (push(system, advanced, s, at) > 0.0) {
      event.kind = StopEventKind::rest;
      if (rebound > 0.0 && s.restitution < 1.0) {
        event.rest_time += 2.0 * rebound / (into * (1.0 - s.restitution));
      }
    } else {
      system.release(s.joint);
      held_[static_cast<std::size_t>(&s - stops_.data())] = 0;
    }
  }
  event.rate_after = at.v[s.v];
  event.energy_lost = kinetic_before - system.energy(at.q.head(nq), at.v.head(nv)).kinetic;
}

std::vector<StopEvent> JointStops::start(system::MultibodySystem& system,
                                         integrate::SecondOrderSystem& advanced,
                                         integrate::State& state) {
  interpolant_.resize(static_cast<int>(state.q.size()), static_cast<int>(state.v.size()));
  trial_ = state;
  std::vector<StopEvent> events;
  for (const Stop& s : stops_) {
    if (gap(s, state) > 0.0 || s.outward * state.v[s.v] > 0.0) continue;
    StopEvent event;
    strike(system, advanced, s, state, event);
    if (event.kind == StopEventKind::rest || event.impulse != 0.0) events.push_back(event);
  }
  return events;
}

bool JointStops::check(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
                       const integrate::Integrator& integrator, const integrate::State& start,
                       const integrate::State& end, integrate::State& before) {
  // The first stop to act in the step: one that closes on its joint, or a held one that would
  // pull.
  double first = std::numeric_limits<double>::infinity();
  const Stop* acting = nullptr;
  bool interpolant_set = false;
  const auto set_interpolant = [&] {
    if (interpolant_set) return;
    interpolant_.set(advanced, integrator, start, end);
    interpolant_set = true;
  };
  for (std::size_t k = 0; k < stops_.size(); ++k) {
    const Stop& s = stops_[k];
    double t = first;
    if (held_[k]) {
      const double push_end = push(system, advanced, s, end);
      if (!(push_end < 0.0)) continue;
      const double push_start = push(system, advanced, s, start);
      set_interpolant();
      t = first_pull(system, advanced, s, start.t, end.t, push_start, push_end);
    } else {
      if (system.held(s.joint)) continue;  // its other stop holds it
      const double gap_end = gap(s, end);
      if (!(gap_end < -s.slack)) continue;
      set_interpolant();
      start_rate_ = start.v[s.v];
      t = first_contact(s, advanced, start.t, end.t, gap(s, start), gap_end);
    }
    if (t < first) {
      first = t;
      acting = &s;
    }
  }
  if (acting == nullptr) return false;
  interpolant_.evaluate(advanced, first, before);
  before.q[acting->q] = acting->value;
  pending_ = static_cast<int>(acting - stops_.data());
  return true;
}

void JointStops::act(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
                     integrate::State& state, StopEvent& event) {
  const std::size_t k = static_cast<std::size_t>(pending_);
  const Stop& s = stops_[k];
  pending_ = -1;
  acts_at_last_ = state.t == last_act_ ? acts_at_last_ + 1 : 1;
  last_act_ = state.t;
  if (acts_at_last_ > kActsAtOneInstant) {
    throw NumericalError(fmt::format(
        "the stops make no progress at t = {:.12g} s: joint '{}''s {} stop has acted {} times "
        "there (its coordinate {:.17g}, rate {:.3g}) without the run moving on — the joint is "
        "pushed neither onto the stop nor off it to within round-off. Widen the limits, or give "
        "the joint a little damping or load",
        state.t, model_.joints()[static_cast<std::size_t>(s.joint)].name,
        s.outward > 0.0 ? "lower" : "upper", kActsAtOneInstant, state.q[s.q], state.v[s.v]));
  }
  if (!held_[k]) {
    strike(system, advanced, s, state, event);
    return;
  }
  system.release(s.joint);
  held_[k] = 0;
  state.q[s.q] = s.value;
  state.v[s.v] = 0.0;
  event = event_at(s, state.t, StopEventKind::release);
}

}  // namespace momenta::simulate
