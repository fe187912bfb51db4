#pragma once
// A run's unilateral constraints: joint stops (model::JointLimits on revolute and prismatic
// joints, q ≥ lower and q ≤ upper) and contacts (model::Contact: a body's point or sphere on or
// above a plane — the ground's or another body's — or outside another body's sphere, gap ≥ 0). Each
// is open (the mechanism moves freely), striking (an impact) or closed (it holds the mechanism
// while it pushes).
//
// Open: after every step the gap of each (q − lower, upper − q; a contact's distance above the
// plane) is checked; where it has become negative inside the step, the first time it reaches
// zero is located on the step's dense output (integrate/step_interpolant.hpp) by TOMS 748 to
// 1e-14 relative in time, and the run is taken back to that instant (integrate::RunOptions::
// restarted). There it strikes: a stop by dynamics::stop_impact's generalized impulse on its
// coordinate, the coordinate set on the stop exactly; a contact by dynamics::restitution_impact's
// normal impulse at its point (the contacts already closed take their impulses as constraints,
// and one that would pull is opened and the impact solved again). Either way the whole mechanism
// takes part and the normal rate after is −e times the rate before (Newton's restitution).
// Contacts reached at one instant with it (touching and approaching) strike with it as one impact
// (dynamics::simultaneous_impact: Poisson's law over the group), where that law holds them; else
// one after another.
//
// Closed: a stop holds its joint (MultibodySystem::hold: prescribed at the stop, zero rate), a
// contact holds its body on the plane (MultibodySystem::close_contact: its row switched on, the
// state projected onto it), when the mechanism meets it with nothing to carry it away — after an
// impact whose rebound flight 2 |v⁺| / |a| (a the acceleration into it, free of it) would be
// shorter than the rest threshold, a millionth of the run's step (the Zeno rule below), or at the
// start, on it, at rest or moving into it, and pushed into it (those at rest close together, and
// are then let go or slide one at a time until all push within their cones). It holds while its
// force pushes (a lower stop's along +q, a contact's along the plane's normal); where that force
// would pull, the time it passes zero is located as an impact's is and it is let go there, with no
// impulse.
//
// Zeno. A bouncing sequence with e < 1 has flights shrinking by e each bounce and ends at a finite
// time; the rule above ends it in resting contact after finitely many bounces. The bounces the rule
// cuts short last, under the acceleration of that instant, Σ_k 2|v⁺| eᵏ / |a| = 2|v⁺| / (|a| (1 −
// e)): the time it comes to rest, reported with the hold, is the hold's time plus that tail (a
// constant acceleration's limit; the tail is shorter than a millionth of a step over 1 − e).
//
// A gap that is negative by round-off alone (four ulps of a stop; 1e-12 m for a contact, above
// the projection's 1e-14) is no crossing. Unilaterals that act again and again at one instant
// without the run moving on stop the run with an error naming the stop or contact, the time and
// the state, not a hang.
//
// Friction (a contact with a plane, the ground's or a body's, with μs > 0). A contact that closes
// slipping slides: its normal row holds and the kinetic friction μk N acts against the slip
// (MultibodySystem::hold_contact). It stops slipping where the slip velocity's component along its
// direction at the step's start passes zero (located as above): there it sticks — every row on, the
// state projected onto them — if the friction that needs, |F_t|, is within the cone μs N; else it
// slides on, against that friction. A contact that closes without slip sticks on the same test. A
// sticking contact slides from the instant |F_t| reaches μs N (located as above), against F_t.
// A contact with friction strikes with dynamics::frictional_impact (the impact's course: Routh's
// process, Stronge's energetic restitution); sticking contacts hold through an impact elsewhere,
// their cones not yet checked.
//
// Not yet: stops on a model with constraints (refused by the Simulation), and the cones of
// contacts that stick through another's impact.

#include <limits>
#include <span>
#include <string>
#include <vector>

#include "momenta/dynamics/data.hpp"
#include "momenta/dynamics/impulse.hpp"
#include "momenta/dynamics/simultaneous_impact.hpp"
#include "momenta/integrate/integrator.hpp"
#include "momenta/integrate/step_interpolant.hpp"
#include "momenta/model/model.hpp"

namespace momenta::system {
class MultibodySystem;
}

namespace momenta::simulate {

/// What a stop or contact did.
enum class StopEventKind {
  impact,   ///< struck; the mechanism rebounds
  rest,     ///< struck (or found closed at the start) and holds
  release,  ///< let go: the force it needed would pull
  stick,    ///< a sliding contact's slip reached zero and friction holds it there
  slip,     ///< a contact's friction cannot hold it (the cone is left): it slides
};

/// "impact", "rest", "release", "stick" or "slip".
std::string_view stop_event_kind_name(StopEventKind kind);

/// How a closed contact's friction holds after an event: not at all (a stop, a frictionless or
/// open contact), sticking, or sliding.
enum class FrictionState { none, sticking, sliding };

/// "", "sticking" or "sliding".
std::string_view friction_state_name(FrictionState state);

/// One thing a stop or a contact did in a run.
struct StopEvent {
  StopEventKind kind = StopEventKind::impact;
  std::string joint;    ///< a stop's joint (empty for a contact)
  std::string contact;  ///< a contact's name (empty for a stop)
  bool upper = false;   ///< a stop's: its upper (true) or lower one
  double time = 0.0;    ///< s
  /// A stop's coordinate rate (rad/s or m/s); a contact's normal speed (m/s, > 0 leaving); at a
  /// stick or slip, the contact point's slip speed (m/s; 0 after a stick).
  double rate_before = 0.0, rate_after = 0.0;
  /// A stop's generalized impulse on its coordinate (N·m·s or N·s); a contact's normal impulse
  /// (N·s).
  double impulse = 0.0;
  double energy_lost = 0.0;  ///< J: the kinetic energy the impact took (0 at e = 1, a release)
  /// A rest after a bouncing sequence: the time the cut-short bounces end (the Zeno limit,
  /// time + 2|v⁺| / (|a| (1 − e))); the time itself otherwise.
  double rest_time = 0.0;
  /// A contact with friction, after a rest, stick or slip: whether it sticks or slides.
  FrictionState friction = FrictionState::none;
  /// A stick or slip: the friction force sticking needs there, |F_t|, and what the cone gives,
  /// μs N (N); for a slip within an impact (in_impact) the impulses, |P_t| and μs P_n (N·s).
  double friction_needed = 0.0, friction_limit = 0.0;
  /// A slip within another's impact: a sticking contact whose cone could not hold the friction
  /// impulse sticking needed there; it slides through the impact and after it. A stick within
  /// one: a sliding contact whose slip the impulses would turn to run with its friction (the
  /// slip passed zero within the impact); it sticks through the impact (rate_before its slip
  /// speed before it).
  bool in_impact = false;
};

/// The stops and contacts a run starting at `state` holds (Unilaterals::start, `system` advancing
/// itself, a 1 ms step setting the rest threshold): those the mechanism touches, at rest or moving
/// into them (struck first: `state` becomes the state after), and pushed into them — so that an
/// evaluation at one instant (a free-body diagram) feels their forces. None on a model with both
/// joint limits and constraints (a run refuses it). Returns the events start() says.
std::vector<StopEvent> hold_what_touches(system::MultibodySystem& system, integrate::State& state);

class Unilaterals {
 public:
  /// The stops of `model`'s joints and its contacts (model must outlive this); `step` is the
  /// run's (fixed, or largest adaptive) step, which sets the rest threshold (a millionth of it).
  Unilaterals(const model::Model& model, double step);

  bool empty() const { return entries_.empty(); }

  /// Opens every one on `system` (a stop lets its joint go, a contact's rows go off): what an
  /// earlier run left held is held no more. A run does so before it makes its initial state
  /// consistent, where a held joint would not move.
  void open_all(system::MultibodySystem& system, const integrate::State& state);

  /// At the run's first state: opens every one (open_all), then closes those the mechanism
  /// starts on, at rest or moving into them, and pushed into them (those events are returned).
  /// `advanced` is what the integrator advances (`system` itself, or its closed loop); `state` may
  /// gain the exact stop value.
  std::vector<StopEvent> start(system::MultibodySystem& system,
                               integrate::SecondOrderSystem& advanced, integrate::State& state);

  /// After the step `integrator` took from `start` to `end`: whether one acts inside it — one
  /// the mechanism reaches, or a closed one that would pull. Then `before` is the state at the
  /// first such instant (a stop's coordinate exactly on it), projected onto the constraints that
  /// hold (a reached stop's coordinate kept), and act() does what it does. Allocates nothing
  /// where none acts (a stop reached on a constrained model is held for the projection: an
  /// event's cost, ConstraintSolver::hold_joints).
  bool check(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
             const integrate::Integrator& integrator, const integrate::State& start,
             const integrate::State& end, integrate::State& before);

  /// After check() found one acting: `state` (the state check() set `before` to) becomes the
  /// state just after — struck (and perhaps held), or let go — and `event` says what happened.
  /// The caller restarts the integrator from it.
  void act(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
           integrate::State& state, StopEvent& event);

  /// The events of the last act() after its own, taken (the list is empty after): the sticking
  /// contacts that slid or stuck through its impact (StopEvent::in_impact, in the order they began
  /// to), and the other contacts of a simultaneous impact (their impacts, then their rests).
  std::vector<StopEvent> take_impact_slips();

 private:
  // How an entry holds: open; closed (a stop holds its joint, a contact's rows are on — it
  // sticks where it has friction); or sliding (a contact's normal row on, kinetic friction).
  enum class Hold : char { open, closed, sliding };
  // What check() found one about to do.
  enum class Pending { reach, release, slip, stop_slipping };
  struct Entry {
    bool contact = false;  // a contact (constraint `index`), or a stop (on joint `index`)
    int index = 0;
    int q = 0, v = 0;    // a stop's coordinate indices
    double value = 0.0;  // a stop's position (rad or m)
    double outward = 1;  // a stop's: +1 for a lower stop (left along +q), −1 for an upper one
    double restitution = 0.0;
    // A gap this far below zero is round-off, not a crossing, so that a mechanism resting on it
    // with no force either way is not struck over and over.
    double slack = 0.0;
    double static_friction = 0.0;  // a contact's μs (0: frictionless)
  };
  const model::Contact& contact_of(const Entry& e) const;
  // The signed gap of a state (≥ 0 off it; m or rad).
  double gap(const Entry& e, const integrate::State& state);
  // Its rate, > 0 leaving (m/s or rad/s).
  double rate(const Entry& e, const integrate::State& state);
  // The force a closed one exerts along its outward direction at `state` (evaluates `advanced`).
  double push(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
              const Entry& e, const integrate::State& state);
  // push() in two parts: the forces of every closed one solved at `state`, then one's read.
  void solve_forces(integrate::SecondOrderSystem& advanced, const integrate::State& state);
  double held_force(const system::MultibodySystem& system, const Entry& e) const;
  // Its acceleration into the constraint (> 0 towards it) at `state`, free of it (evaluates
  // `advanced`).
  double acceleration_into(integrate::SecondOrderSystem& advanced, const Entry& e,
                           const integrate::State& state);
  // Throws NumericalError, naming the time, where e is a disk contact lying flat at `state`.
  void refuse_flat_disk(const Entry& e, const integrate::State& state);
  // What e does at time t, its rates and impulse still to fill.
  StopEvent event_at(const Entry& e, double t, StopEventKind kind) const;
  // The first time in (a, b] the gap of e falls below zero on the step's interpolant, given
  // gap(b) < 0; or a itself when it only goes in from there.
  double first_contact(const Entry& e, integrate::SecondOrderSystem& advanced, double a, double b,
                       double gap_a, double gap_b);
  // Strikes (or closes) e at the state `at` (on it), filling `event`.
  void strike(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
              const Entry& e, integrate::State& at, StopEvent& event);
  // The open contacts the mechanism meets at `at` together with `first` (touching, to their
  // slack, and approaching), `first` leading.
  std::vector<const Entry*> struck_with(const Entry& first, const integrate::State& at);
  // Strikes the group as one impact (dynamics::simultaneous_impact) and holds those whose
  // rebound the step cannot resolve, filling `event` for the first and the impact slips' list
  // for the others; false, having changed nothing of theirs, where that law cannot hold them.
  bool strike_together(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
                       std::vector<const Entry*> group, integrate::State& at, StopEvent& event);
  // The slip events of a group's impact at t: each contact that slid through it, and a stick
  // after the slip for each that stuck through restitution.
  std::vector<StopEvent> slips_in_group_impact(const std::vector<const Entry*>& group,
                                               const dynamics::SimultaneousImpact& impact,
                                               double t) const;
  // Whether the contacts held and the joints held keep contact e's points still along its normal
  // (it has no impact of its own).
  bool held_by_others(const system::MultibodySystem& system, const Entry& e,
                      const integrate::State& at);
  // A contact's impact: the state just after, its normal impulse returned; closed contacts that
  // would pull are opened.
  double contact_impact(system::MultibodySystem& system, const Entry& e, integrate::State& at);
  // A stop's impact: the state just after, its impulse returned; as contact_impact, the closed
  // contacts and the holding stops take their impulses, and one that would pull lets go.
  double stop_strike(system::MultibodySystem& system, const Entry& e, integrate::State& at);
  // The rows the system's closed contacts have on (empty without constraints), for the impulse
  // solves.
  std::span<const char> enabled_rows(const system::MultibodySystem& system) const;
  // After an impact's impulses `motion`: lets go the closed contact or holding stop whose impulse
  // pulls most, if one does, and says whether one did.
  bool let_go_one_that_pulls(system::MultibodySystem& system,
                             const dynamics::ImpulsiveMotion& motion, const integrate::State& at);
  // After an impact's impulses `motion` that no closed contact pulls in: the sticking contact
  // whose friction impulse leaves its cone most (|P_t| > μs P_n) slides through the impact —
  // sliding_at_impact_ gains it, its tangent rows go off — if one does; says whether one did.
  bool slide_one_beyond_its_cone(system::MultibodySystem& system,
                                 const dynamics::ImpulsiveMotion& motion, integrate::State& at);
  // After an impact's impulses `motion` that no closed contact pulls in and whose cones hold: the
  // contact sliding through the impact whose slip the impulses would turn to run with its
  // friction (the slip passed zero within the impact: held against its old direction, the
  // friction would push) sticks for the impact instead — it leaves sliding_at_impact_, its
  // tangent rows go on — if one does; says whether one did.
  bool stick_one_whose_slip_turns(system::MultibodySystem& system,
                                  const dynamics::ImpulsiveMotion& motion,
                                  const integrate::State& at);
  // Every contact sliding through the impact sticks for it instead (its tangent rows go on).
  void stick_all_sliding(system::MultibodySystem& system, const integrate::State& at);
  // A contact sliding through the impact sticks for it: its tangent rows on, `at` as it is (the
  // impulses stop its slip); a stick event in the impact (in_impact) for take_impact_slips().
  void stick_for_impact(system::MultibodySystem& system, const Entry& e,
                        const integrate::State& at);
  // The entry of a contact sliding through the impact.
  const Entry& sliding_entry(const system::MultibodySystem& system,
                             const dynamics::SlidingContact& s) const;
  // Before an impact's solves: the contacts sliding now slide through it (sliding_at_impact_),
  // their friction impulse μk P_n against their slip (Coulomb's law at impact).
  void begin_impact(const system::MultibodySystem& system, const integrate::State& at);
  // A contact's points at `at`: b's and a's at the contact point, and its normal.
  dynamics::PointContact touch_of(const Entry& e, const integrate::State& at);
  // Closes e at `at`: a stop holds; a contact holds its body on the plane, sliding where its
  // contact point slips (faster than kSlipAtRest) or friction cannot hold it, sticking otherwise.
  void close(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
             const Entry& e, integrate::State& at);
  void open(system::MultibodySystem& system, const Entry& e, const integrate::State& at);
  // A contact with friction at `at`: sticks if the cone holds it there, else slides against the
  // friction sticking would need (the state projected onto its rows; `event` gets the state and
  // the forces).
  void stick_or_slip(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
                     const Entry& e, integrate::State& at, StopEvent& event);
  void hold_contact(system::MultibodySystem& system, const Entry& e, integrate::State& at, Hold how,
                    const Vec3& slip_W = Vec3::Zero());
  // hold_contact() without putting `at` onto the rows (an impact's impulses do that).
  void set_contact_hold(system::MultibodySystem& system, const Entry& e, const integrate::State& at,
                        Hold how, const Vec3& slip_W = Vec3::Zero());
  // Projects `at` onto the constraints that hold now (MultibodySystem::project; a held joint's
  // coordinate stays).
  void project(system::MultibodySystem& system, integrate::State& at);
  // A contact's slip velocity at `state` (W, along the plane).
  Vec3 slip_velocity(const Entry& e, const integrate::State& state);
  // After an evaluation of a sticking contact at `state`: the friction its tangent rows exert
  // (W, N).
  Vec3 sticking_friction(const system::MultibodySystem& system, const Entry& e,
                         const integrate::State& state);
  // μs N − |F_t| of a sticking contact at `state` (evaluates `advanced`): < 0 outside the cone.
  // Round-off in a cone's margin: kConeRoundOff times the largest constraint force just solved.
  static double cone_round_off(const system::MultibodySystem& system);
  // Holds one touching, its friction undecided: a stop on its value, a contact sliding where it
  // slips, else held on all its rows (close() then decides; start() and a group's rest settle).
  void hold_at_rest(system::MultibodySystem& system, const Entry& e, integrate::State& at);
  // Lets go of or slides those held, one at a time, until every one pushes and sticks within its
  // cone.
  void settle(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
              integrate::State& at);
  double cone_margin(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
                     const Entry& e, const integrate::State& state);
  // Sets each sliding contact's reference slip direction from `state` (see
  // MultibodySystem::set_slip_reference): its slip's, or where that is too slow to say, the way
  // the system's friction takes it there (a slow slip's stable direction: evaluates `advanced`).
  void set_slip_references(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
                           const integrate::State& state);
  // A sliding contact's reference: the way its friction acts against at `state` (evaluates
  // `advanced`) — where a slip starts, its stable direction (system/slip_direction.hpp).
  void follow_friction(system::MultibodySystem& system, integrate::SecondOrderSystem& advanced,
                       const Entry& e, const integrate::State& state);
  // After an evaluation: sliding contact e's reference is the way its friction acts against.
  void take_friction_as_reference(system::MultibodySystem& system, const Entry& e);
  std::size_t slot(const Entry& e) const { return static_cast<std::size_t>(&e - entries_.data()); }

  const model::Model& model_;
  double rest_flight_;                // s: a rebound flight shorter than this closes it
  double crowded_span_;               // s: kActsInSpan acts within it stop the run
  std::vector<Entry> entries_;        // every finite stop, lower before upper, in joint order; then
                                      // the contacts in constraint order
  std::vector<Hold> hold_;            // per entry
  std::vector<Vec3> slip_reference_;  // per entry: a sliding contact's reference slip direction
  // Per entry: a sliding contact whose slip has run faster than kSlipAtRest since it was held
  // sliding (one held from rest has not, until it does).
  std::vector<char> slip_run_;
  int pending_ = -1;  // the one check() found acting
  Pending pending_action_ = Pending::reach;
  double last_act_ = -std::numeric_limits<double>::infinity();  // when act() last acted
  int acts_at_last_ = 0;  // how often it acted then: a run that makes no progress stops
  double span_start_ = -std::numeric_limits<double>::infinity();  // the first act of a span
  int acts_in_span_ = 0;     // acts within crowded_span_ of span_start_
  double start_rate_ = 0.0;  // first_contact: the rate at the step's start
  integrate::StepInterpolant interpolant_;
  integrate::State trial_;
  VecX vdot_, q_, v_;
  dynamics::Data data_;  // a contact's kinematics
  // The contacts sliding through the impact being solved, those stuck for it (each once), and
  // the slips and sticks they began.
  std::vector<dynamics::SlidingContact> sliding_at_impact_;
  std::vector<const Entry*> stuck_in_impact_;
  std::vector<StopEvent> impact_slips_;
};

}  // namespace momenta::simulate
