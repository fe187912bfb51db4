#include "momenta/simulate/event_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <fmt/format.h>

#include "crossing_time.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/system/multibody_system.hpp"

namespace momenta::simulate {
namespace {

using model::EventDirection;
using system::MultibodySystem;

// The side of the value a quantity is on: −1 below, +1 above, 0 on it; kUnknown before the
// quantity has left a value it started on.
constexpr int kUnknown = 2;

int side_of(double offset) { return offset < 0.0 ? -1 : offset > 0.0 ? 1 : 0; }

// Whether moving from side `before` to side `after` makes the condition true, and which way:
// −1 into "below", +1 into "above", 0 no.
int crossing(EventDirection direction, int before, int after) {
  if (before == kUnknown || after == 0) return 0;
  const bool falls = after == -1 && before != -1;
  const bool rises = after == 1 && before != 1;
  switch (direction) {
    case EventDirection::falling:
      return falls ? -1 : 0;
    case EventDirection::rising:
      return rises ? 1 : 0;
    case EventDirection::either:
      return falls ? -1 : rises ? 1 : 0;
  }
  return 0;
}

}  // namespace

std::vector<std::string> event_quantities(const model::Model& model,
                                          const std::vector<model::OutputSpec>& outputs) {
  std::vector<std::string> names;
  for (int i = 0; i < model.nq(); ++i) names.push_back(model.q_name(i));
  for (int i = 0; i < model.nv(); ++i) names.push_back(model.v_name(i));
  for (const char* energy : kEnergyColumns) names.emplace_back(energy);
  const system::OutputSet set(model, outputs);
  for (const std::string& column : set.column_names()) names.push_back(column);
  return names;
}

namespace {
// The error for an event whose quantity the run does not have: the names it has, and the closest.
InvalidArgument unknown_quantity(const model::Model& model,
                                 const std::vector<model::OutputSpec>& outputs,
                                 const model::EventSpec& event) {
  const std::vector<std::string> names = event_quantities(model, outputs);
  const std::vector<std::string_view> candidates(names.begin(), names.end());
  return InvalidArgument(fmt::format(
      "event '{}': no quantity '{}'{} to watch; an event watches a coordinate, a speed, an energy "
      "or an output of the model: {}",
      event.name, event.quantity, did_you_mean(event.quantity, candidates),
      fmt::join(names, ", ")));
}
}  // namespace

void check_event(const model::Model& model, const std::vector<model::OutputSpec>& outputs,
                 const model::EventSpec& event) {
  const std::vector<std::string> names = event_quantities(model, outputs);
  if (std::find(names.begin(), names.end(), event.quantity) == names.end())
    throw unknown_quantity(model, outputs, event);
}

EventMonitor::Watched EventMonitor::resolve(const model::Model& model,
                                            const std::vector<model::OutputSpec>& outputs,
                                            const model::EventSpec& event) {
  for (int i = 0; i < model.nq(); ++i) {
    if (model.q_name(i) == event.quantity) return {Watched::Kind::coordinate, i, {}, {}};
  }
  for (int i = 0; i < model.nv(); ++i) {
    if (model.v_name(i) == event.quantity) return {Watched::Kind::speed, i, {}, {}};
  }
  for (int k = 0; k < 3; ++k) {
    if (event.quantity == kEnergyColumns[k]) return {Watched::Kind::energy, k, {}, {}};
  }
  // The output that makes the column, alone in a set of its own.
  for (const model::OutputSpec& spec : outputs) {
    system::OutputSet set(model, {spec});
    const auto& columns = set.column_names();
    const auto it = std::find(columns.begin(), columns.end(), event.quantity);
    if (it == columns.end()) continue;
    const auto column = static_cast<int>(it - columns.begin());
    std::vector<double> values(columns.size(), 0.0);
    return {Watched::Kind::output, column, std::move(set), std::move(values)};
  }
  throw unknown_quantity(model, outputs, event);
}

EventMonitor::EventMonitor(const model::Model& model, const std::vector<model::OutputSpec>& outputs,
                           std::vector<model::EventSpec> events, int controller_states)
    : model_(model), events_(std::move(events)) {
  for (const model::EventSpec& event : events_) watched_.push_back(resolve(model, outputs, event));
  side_.assign(events_.size(), 0);
  found_.reserve(events_.size());
  interpolant_.resize(model.nq() + controller_states, model.nv() + controller_states);
  trial_ = integrate::State{0.0, VecX::Zero(model.nq() + controller_states),
                            VecX::Zero(model.nv() + controller_states)};
  prescribed_ = integrate::State{0.0, VecX::Zero(model.nq()), VecX::Zero(model.nv())};
}

double EventMonitor::offset(MultibodySystem& system, int e, const integrate::State& state) {
  // The model's part of the state as the table records it: the prescribed joints on their
  // signals.
  const bool prescribed = model_.has_prescribed_joints();
  const bool copy = prescribed || state.q.size() != model_.nq();
  if (copy) {
    prescribed_.q = state.q.head(model_.nq());
    prescribed_.v = state.v.head(model_.nv());
  }
  if (prescribed) system.apply_prescribed_motion(state.t, prescribed_.q, prescribed_.v);
  const VecX& q = copy ? prescribed_.q : state.q;
  const VecX& v = copy ? prescribed_.v : state.v;
  Watched& w = watched_[static_cast<std::size_t>(e)];
  double quantity = 0.0;
  switch (w.kind) {
    case Watched::Kind::coordinate:
      quantity = q[w.index];
      break;
    case Watched::Kind::speed:
      quantity = v[w.index];
      break;
    case Watched::Kind::energy: {
      const system::Energy energy = system.energy(q, v);
      const double energies[] = {energy.kinetic, energy.potential(), energy.total()};
      quantity = energies[w.index];
      break;
    }
    case Watched::Kind::output:
      w.output->evaluate(system, state.t, q, v, w.values);
      quantity = w.values[static_cast<std::size_t>(w.index)];
      break;
  }
  return quantity - events_[static_cast<std::size_t>(e)].value;
}

void EventMonitor::start(MultibodySystem& system, const integrate::State& state) {
  for (std::size_t e = 0; e < events_.size(); ++e) {
    const int side = side_of(offset(system, static_cast<int>(e), state));
    side_[e] = side == 0 ? kUnknown : side;
  }
}

std::span<const EventOccurrence> EventMonitor::check(MultibodySystem& system,
                                                     integrate::SecondOrderSystem& advanced,
                                                     const integrate::Integrator& integrator,
                                                     const integrate::State& start,
                                                     const integrate::State& end) {
  found_.clear();
  bool interpolant_set = false;
  for (std::size_t e = 0; e < events_.size(); ++e) {
    const double at_end = offset(system, static_cast<int>(e), end);
    if (std::isnan(at_end)) continue;  // the run's own checks name a non-finite state
    const int after = side_of(at_end);
    const int before = side_[e];
    side_[e] = before == kUnknown && after == 0 ? kUnknown : after;
    const int way = crossing(events_[e].direction, before, after);
    if (way == 0) continue;
    if (!interpolant_set) {
      interpolant_.set(advanced, integrator, start, end);
      interpolant_set = true;
    }
    // f = offset signed so that the condition holds where f < 0: f(start) ≥ 0 > f(end).
    const double sign = way < 0 ? 1.0 : -1.0;
    const double at_start = offset(system, static_cast<int>(e), start);
    const double t = locate(system, advanced, static_cast<int>(e), sign, start.t, end.t,
                            sign * at_start, sign * at_end);
    state_at(advanced, t, trial_);
    EventOccurrence o;
    o.name = events_[e].name;
    o.condition = model::event_condition_text(events_[e]);
    o.action = events_[e].action;
    o.time = t;
    o.value = offset(system, static_cast<int>(e), trial_) + events_[e].value;
    found_.push_back(std::move(o));
  }
  // In time order (a stable insertion sort: few events, no buffer to allocate), up to the first
  // that stops the run.
  for (std::size_t i = 1; i < found_.size(); ++i) {
    for (std::size_t k = i; k > 0 && found_[k].time < found_[k - 1].time; --k)
      std::swap(found_[k], found_[k - 1]);
  }
  const auto stop = std::find_if(found_.begin(), found_.end(), [](const EventOccurrence& o) {
    return o.action == model::EventAction::stop;
  });
  if (stop != found_.end()) found_.erase(stop + 1, found_.end());
  return found_;
}

double EventMonitor::locate(MultibodySystem& system, integrate::SecondOrderSystem& advanced, int e,
                            double sign, double a, double b, double fa, double fb) {
  // On the value at the step's start (past it after): a itself.
  const auto f = [&](double t) {
    state_at(advanced, t, trial_);
    return sign * offset(system, e, trial_);
  };
  return detail::crossing_time(f, a, b, fa, fb);
}

void EventMonitor::state_at(integrate::SecondOrderSystem& advanced, double t,
                            integrate::State& out) {
  interpolant_.evaluate(advanced, t, out);
  advanced.project(t, out.q, out.v);  // the ends are on the constraints already: no change there
}

}  // namespace momenta::simulate
