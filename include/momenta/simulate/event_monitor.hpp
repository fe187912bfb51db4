#pragma once
// Watches a run's events (model/event_spec.hpp) between steps and finds when each happens: the
// quantity is evaluated at every step's end; where its condition turns from false to true inside
// the step, the time is located on the step's dense output (integrate/step_interpolant.hpp: the
// integrator's own, or cubic Hermite) by Alefeld–Potra–Shi's TOMS 748 root finder to a bracket of
// 1e-14 relative in time, each trial state projected onto the constraints and the prescribed
// joints set to their signals.
//
// An event whose quantity equals its value exactly at the start waits until the quantity has
// left the value. A condition that turns true and false again inside one step is not seen: a
// smaller step (--dt, or an adaptive method's largest) finds it.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "momenta/integrate/step_interpolant.hpp"
#include "momenta/model/event_spec.hpp"
#include "momenta/model/model.hpp"
#include "momenta/model/output_spec.hpp"
#include "momenta/system/output_set.hpp"

namespace momenta::system {
class MultibodySystem;
}

namespace momenta::simulate {

/// One time an event happened in a run.
struct EventOccurrence {
  std::string name;       ///< the event's name
  std::string condition;  ///< "tension < 0"
  model::EventAction action = model::EventAction::record;
  double time = 0.0;   ///< s
  double value = 0.0;  ///< the quantity at that time (the value, to the location's accuracy)
};

/// The energy columns of a run's table (J), in order; an event can watch each.
inline constexpr const char* kEnergyColumns[3] = {"energy_kinetic", "energy_potential",
                                                  "energy_total"};

/// The quantities an event can watch on `model` with `outputs`: every configuration coordinate
/// and speed by its column name, energy_kinetic, energy_potential, energy_total and every output
/// column.
std::vector<std::string> event_quantities(const model::Model& model,
                                          const std::vector<model::OutputSpec>& outputs);

/// Throws InvalidArgument when `event` watches no quantity of event_quantities(), naming the
/// event, with a did-you-mean and the quantities there are.
void check_event(const model::Model& model, const std::vector<model::OutputSpec>& outputs,
                 const model::EventSpec& event);

class EventMonitor {
 public:
  /// Resolves every event's quantity (check_event's error for one the run lacks). `model` must
  /// outlive this. The states it is handed may carry `controller_states` more coordinates in q
  /// and in v after the model's (system/closed_loop_system.hpp); the events watch the model's.
  EventMonitor(const model::Model& model, const std::vector<model::OutputSpec>& outputs,
               std::vector<model::EventSpec> events, int controller_states = 0);

  bool empty() const { return events_.empty(); }
  const std::vector<model::EventSpec>& events() const { return events_; }

  /// Evaluates every quantity at the run's first state.
  void start(system::MultibodySystem& system, const integrate::State& state);

  /// The events that happened in the step `integrator` just took from `start` to `end` (the
  /// states the run holds, `end` after projection): at most one per event (its first crossing
  /// in the step), in time order, ending with the first whose action is stop. Allocates only
  /// for the occurrences it returns.
  /// `advanced` is the system the integrator advances: `system` itself, or its closed loop.
  std::span<const EventOccurrence> check(system::MultibodySystem& system,
                                         integrate::SecondOrderSystem& advanced,
                                         const integrate::Integrator& integrator,
                                         const integrate::State& start,
                                         const integrate::State& end);

  /// The state at time t of the step last checked (t an occurrence's time): interpolated,
  /// projected and with the prescribed joints on their signals.
  void state_at(integrate::SecondOrderSystem& advanced, double t, integrate::State& out);

 private:
  struct Watched {
    enum class Kind { coordinate, speed, energy, output };
    Kind kind = Kind::coordinate;
    int index = 0;  // coordinate, speed, energy (kinetic, potential, total), or column of `output`
    std::optional<system::OutputSet> output;  // a set of the output's spec alone
    std::vector<double> values;               // its columns' values (scratch)
  };
  // What `event` watches on `model`; throws check_event's error when the run has no such quantity.
  static Watched resolve(const model::Model& model, const std::vector<model::OutputSpec>& outputs,
                         const model::EventSpec& event);
  // quantity − value of event e at the state (t, q, v) (applies the prescribed motion).
  double offset(system::MultibodySystem& system, int e, const integrate::State& state);
  // The first time in [a, b] where event e's condition holds, found on the step's interpolant:
  // f = sign · (quantity − value) has f(a) = fa ≥ 0 > fb = f(b).
  double locate(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced, int e,
                double sign, double a, double b, double fa, double fb);

  const model::Model& model_;
  std::vector<model::EventSpec> events_;
  std::vector<Watched> watched_;
  std::vector<int> side_;  // sign of quantity − value at the last step's end (0: on it)
  std::vector<EventOccurrence> found_;
  integrate::StepInterpolant interpolant_;
  integrate::State trial_, prescribed_;
};

}  // namespace momenta::simulate
