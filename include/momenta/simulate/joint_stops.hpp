#pragma once
// A run's joint stops (model::JointLimits on revolute and prismatic joints): the unilateral
// constraints q ≥ lower and q ≤ upper, each either open (the joint moves freely), striking (an
// impact) or closed (the stop holds the joint while it pushes).
//
// Open: after every step the gap to each stop (q − lower, upper − q) is checked; where it has
// become negative inside the step, the first time it reaches zero is located on the step's dense
// output (integrate/step_interpolant.hpp) by TOMS 748 to 1e-14 relative in time, and the run is
// taken back to that instant (integrate::RunOptions::restarted). There the coordinate is set on
// the stop exactly and the stop strikes it: dynamics::stop_impact's generalized impulse, the
// whole mechanism taking part, its rate after −e times its rate before (Newton's restitution).
//
// Closed: a stop holds its joint (MultibodySystem::hold: prescribed at the stop, zero rate) when
// the joint meets it with nothing to carry it away — after an impact whose rebound flight
// 2 |v⁺| / |a| (a the coordinate's acceleration into the stop, free of it) would be shorter than
// the rest threshold, a millionth of the run's step (the Zeno rule below), or at the start, on the
// stop, at rest or moving into it, and pushed into it. It holds while the force it exerts pushes
// the joint off the stop (a lower stop's along +q); where that force would pull, the time it
// passes zero is located as an impact's is and the joint is let go there, with no impulse.
//
// Zeno. A bouncing sequence with e < 1 has flights shrinking by e each bounce and ends at a finite
// time; the rule above ends it in resting contact after finitely many bounces. The bounces the rule
// cuts short last, under the acceleration of that instant, Σ_k 2|v⁺| eᵏ / |a| = 2|v⁺| / (|a| (1 −
// e)): the time the joint comes to rest, reported with the hold, is the hold's time plus that
// tail (a constant acceleration's limit; the tail is shorter than a millionth of a step over 1 −
// e).
//
// A gap that is negative by round-off alone (four ulps of the stop) is no crossing. Stops that act
// again and again at one instant without the run moving on (a joint pushed neither way to within
// round-off) stop the run with an error naming the joint, the time and its state, not a hang.
//
// Not yet: stops on a model with constraints (refused by the Simulation), and two stops struck at
// one instant, which are struck one after another in joint order.

#include <limits>
#include <string>
#include <vector>

#include "momenta/integrate/integrator.hpp"
#include "momenta/integrate/step_interpolant.hpp"
#include "momenta/model/model.hpp"

namespace momenta::system {
class MultibodySystem;
}

namespace momenta::simulate {

/// What a stop did.
enum class StopEventKind {
  impact,   ///< struck the joint; it rebounds
  rest,     ///< struck it (or found it on the stop at the start) and holds it
  release,  ///< let a held joint go: the force it needed would pull
};

/// "impact", "rest" or "release".
std::string_view stop_event_kind_name(StopEventKind kind);

/// One thing a stop did in a run.
struct StopEvent {
  StopEventKind kind = StopEventKind::impact;
  std::string joint;                           ///< the joint's name
  bool upper = false;                          ///< which stop: its upper (true) or lower one
  double time = 0.0;                           ///< s
  double rate_before = 0.0, rate_after = 0.0;  ///< the coordinate's rate (rad/s or m/s)
  double impulse = 0.0;      ///< the stop's generalized impulse on the coordinate (N·m·s or N·s)
  double energy_lost = 0.0;  ///< J: the kinetic energy the impact took (0 at e = 1, a release)
  /// A rest after a bouncing sequence: the time the cut-short bounces end (the Zeno limit,
  /// time + 2|v⁺| / (|a| (1 − e))); the time itself otherwise.
  double rest_time = 0.0;
};

class JointStops {
 public:
  /// The stops of `model`'s joints (model must outlive this); `step` is the run's (fixed, or
  /// largest adaptive) step, which sets the rest threshold (a millionth of it).
  JointStops(const model::Model& model, double step);

  bool empty() const { return stops_.empty(); }

  /// At the run's first state: closes the stops their joints start on, at rest or moving into
  /// them, and pushed into them (those events are returned). `advanced` is what the integrator
  /// advances (`system` itself, or its closed loop); `state` may gain the exact stop value.
  std::vector<StopEvent> start(system::MultibodySystem& system,
                               integrate::SecondOrderSystem& advanced, integrate::State& state);

  /// After the step `integrator` took from `start` to `end`: whether a stop acts inside it — one
  /// its joint reaches, or a held one that would pull. Then `before` is the state at the first
  /// such instant (the coordinate exactly on the stop), and act() does what that stop does.
  /// Allocates nothing.
  bool check(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
             const integrate::Integrator& integrator, const integrate::State& start,
             const integrate::State& end, integrate::State& before);

  /// After check() found a stop acting: `state` (the state check() set `before` to) becomes the
  /// state just after — struck (and perhaps held), or let go — and `event` says what happened.
  /// The caller restarts the integrator from it.
  void act(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
           integrate::State& state, StopEvent& event);

 private:
  struct Stop {
    int joint = 0;
    int q = 0, v = 0;    // the coordinate's indices
    double value = 0.0;  // where it is (rad or m)
    double outward = 1;  // +1 for a lower stop (the joint leaves it along +q), −1 for an upper one
    double restitution = 0.0;
    // A gap this far below zero is round-off, not a crossing: four ulps of the stop (or of 1), so
    // that a joint resting on it with no force either way is not struck over and over.
    double slack = 0.0;
  };
  // The signed gap of a state to stop s (≥ 0 off it).
  double gap(const Stop& s, const integrate::State& state) const {
    return s.outward * (state.q[s.q] - s.value);
  }
  // The force a held stop exerts along its outward direction at `state` (evaluates `advanced`).
  double push(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
              const Stop& s, const integrate::State& state);
  // Every coordinate's acceleration at `state` (evaluates `advanced`).
  const VecX& accelerations(integrate::SecondOrderSystem& advanced, const integrate::State& state);
  // What stop s does at time t, its rates and impulse still to fill.
  StopEvent event_at(const Stop& s, double t, StopEventKind kind) const;
  // The first time in (a, b] the gap of stop s falls below zero on the step's interpolant, given
  // gap(b) < 0; or a itself when it only goes in from there.
  double first_contact(const Stop& s, integrate::SecondOrderSystem& advanced, double a, double b,
                       double gap_a, double gap_b);
  // The time in (a, b] a held stop's push passes zero, push(a) ≥ 0 > push(b).
  double first_pull(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
                    const Stop& s, double a, double b, double push_a, double push_b);
  // Strikes (or closes) stop s at the state `at` (on the stop), filling `event`.
  void strike(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
              const Stop& s, integrate::State& at, StopEvent& event);
  void close(system::MultibodySystem& system, const Stop& s, integrate::State& at);

  const model::Model& model_;
  double rest_flight_;       // s: a rebound flight shorter than this closes the stop
  std::vector<Stop> stops_;  // every finite stop, lower before upper, in joint order
  std::vector<int> held_;    // per stop: 1 where it holds its joint
  int pending_ = -1;         // the stop check() found acting
  double last_act_ = -std::numeric_limits<double>::infinity();  // when act() last acted
  int acts_at_last_ = 0;     // how often it acted then: a run that makes no progress stops
  double start_rate_ = 0.0;  // first_contact: the coordinate's rate at the step's start
  integrate::StepInterpolant interpolant_;
  integrate::State trial_;
  VecX vdot_;
};

}  // namespace momenta::simulate
