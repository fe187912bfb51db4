#pragma once
// A simulation run: a Model integrated from its initial state, one table row recorded every n
// steps (time, coordinates, energies, angular momentum, the model's outputs, optionally every
// joint's reaction, and the conservation audit), handed to a RowSink (csv_writer.hpp writes CSV).
// This is `momenta simulate` without the argument parsing (docs/cli.md).
//
// Columns, in order (column_names()):
//   time                                   s
//   <joint>.<coordinate>   every configuration coordinate, named as Model::q_name names it
//                  (pivot.angle, slide.position, ball.qw ... ball.qz; model/joint.hpp)
//   <joint>.<speed>        every velocity coordinate, as Model::v_name (pivot.angle_rate)
//   energy_kinetic, energy_potential, energy_total     J (potential: gravity and springs)
//   H_x, H_y, H_z  angular momentum about the system centre of mass, in W (kg·m²/s)
//   the model's outputs (OutputSet::column_names())
//   with controllers (model/controller.hpp), each one's outputs, reference, error and states
//                  (system::ClosedLoopSystem::column_names(): cruise.throttle, cruise.reference,
//                  cruise.error, cruise.integral, ...)
//   with options.reactions: <joint>.reaction.Fx .Fy .Fz .Mx .My .Mz for every joint: the
//                  wrench it transmits to its child, in W, the moment about the child-side joint
//                  frame's origin J'o (dynamics/reactions.hpp)
//                  and every constraint's forces, <constraint>.<label>
//                  (dynamics::constraint_force_labels: reaction.Fx ... of a loop, tension,
//                  normal/longitudinal/lateral of a rolling contact, ...)
//   the audit, where audited (see below): audit.energy_drift, audit.H_norm_drift, audit.H_drift,
//                  audit.quaternion_norm_error, audit.constraint_position,
//                  audit.constraint_velocity
//
// Conservation audit. Evaluated after every step (not only at recorded rows), without
// allocation: the relative drift of the total energy where MultibodySystem::conserves_energy(),
// of |H| and of the vector H where conserves_angular_momentum(), and the largest | |q| − 1 | of
// the quaternions of spherical and free joints where the model has any. Energy drift is
// (E − E0) / max(|E0|, E_scale) with E_scale = T0 + V_springs0 + Σ_b m_b |g| |p_WoBcm_W| (the
// energy the motion could exchange, so that a model starting at E0 = 0 is not divided by zero);
// |H| and H drift are (|H| − |H0|) / S and |H − H0| / S with S = max(|H0|, sqrt(2 T0 Σ_b
// tr I_Bcm / 3)). The quaternion norm error is absolute, and so are the constraint residuals of
// a constrained model: the largest |φ| of its position rows (m or rad) and |G v| of all rows
// (m/s or rad/s), after the step's projection.
//
// Constraints. The run starts from the model's initial state made consistent with them
// (MultibodySystem::make_consistent: what changed is in the summary), and every step ends with
// the projection onto them. The rigid-body integrators (splitting, exact, lie_group) advance a
// free body's own flow and cannot honour constraints: they are refused.
//
// Joint stops (model::JointLimits): the run is taken back to each instant a joint reaches a stop,
// which strikes it (Newton's restitution through the whole mechanism) or holds it, and lets it go
// where holding it would pull (simulate/unilaterals.hpp); contacts (model::Contact) likewise
// strike, hold and let go of their bodies. Each is a row just before and one just after, and an
// entry of the summary's stop_events. With options.reactions each limited joint has
// a column <joint>.stop_force (N·m or N: the force its stop exerts on the coordinate, 0 when open).
//
// Prescribed joints. After every step the recorded copy of the state gets the prescribed
// coordinates' exact values (MultibodySystem::apply_prescribed_motion); the integrator's own
// state is left as it returned it.

#include <atomic>
#include <complex>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "momenta/integrate/integrator.hpp"
#include "momenta/integrate/stiffness.hpp"
#include "momenta/model/model.hpp"
#include "momenta/simulate/conservation_audit.hpp"
#include "momenta/simulate/event_monitor.hpp"
#include "momenta/simulate/unilaterals.hpp"
#include "momenta/system/constraint_solver.hpp"
#include "momenta/system/output_set.hpp"

namespace momenta::system {
class MultibodySystem;
class ClosedLoopSystem;
}  // namespace momenta::system

namespace momenta::simulate {

/// How a run is integrated and what it records. The defaults are `momenta simulate`'s.
struct SimulationOptions {
  double duration = 10.0;  ///< s, > 0: the run goes from t = 0 to t = duration
  double step = 1e-3;      ///< s, > 0: the fixed step, or the largest step of an adaptive method
  std::string integrator = "rk4";    ///< a name of model::integrators()
  integrate::Tolerances tolerances;  ///< adaptive methods (dopri5, bdf) only
  long every = 1;          ///< record every n-th step (≥ 1); the first and last states always
  bool reactions = false;  ///< add every joint's reaction wrench to each row
  /// Conditions watched between steps (model/event_spec.hpp, simulate/event_monitor.hpp): each
  /// time one turns true the run writes a row at that time, and a `stop` event ends the run there.
  std::vector<model::EventSpec> events;
  /// When set and it becomes true (a signal handler's flag), the run records the state it has
  /// reached as a last whole row, flushes the sink and throws Interrupted.
  const std::atomic<bool>* stop = nullptr;
  /// Called with the time reached about every 1024 steps (a progress line); none when empty.
  std::function<void(double t)> progress;
};

/// Receives the table a run produces, row by row.
class RowSink {
 public:
  virtual ~RowSink() = default;
  /// Called once, before any row, with every column's name.
  virtual void begin(std::span<const std::string> columns) = 0;
  /// One row, values in column order. Called from the step loop.
  virtual void row(std::span<const double> values) = 0;
  /// Pushes buffered rows out: called at the end of a run and before a failed run throws.
  virtual void flush() {}
};

/// Keeps the table in memory (allocates per row: for tests and short runs).
class TableSink final : public RowSink {
 public:
  void begin(std::span<const std::string> columns) override;
  void row(std::span<const double> values) override;

  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  /// Index of the column with that name; throws InvalidArgument (with a did-you-mean) if none.
  int column(std::string_view name) const;
};

/// What a run did.
struct SimulationSummary {
  std::string integrator;  ///< its name
  int order = 0;           ///< its order (model::kExactOrder: exact)
  bool adaptive = false;
  double step = 0.0;   ///< s: the fixed step, or the adaptive method's largest
  double t_end = 0.0;  ///< s: the time reached
  integrate::IntegratorStatistics statistics;
  double wall_seconds = 0.0;
  long rows = 0;  ///< rows handed to the sink
  bool energy_audited = false;
  bool momentum_audited = false;
  bool quaternions_audited = false;
  bool constraints_audited = false;
  /// The audited quantities, in this order where audited: "energy", "|H|", "H", "quaternion
  /// norm", "constraint position", "constraint velocity". final_drift is at t_end, max_drift the
  /// largest over every step.
  std::vector<AuditEntry> audit;
  /// Constrained models: the rows implied by the others (they carry no force), and what making
  /// the initial state consistent changed.
  std::vector<std::string> redundant_constraint_rows;
  system::ConsistentState initial_state;
  /// Explicit Runge–Kutta methods (rk4, dopri5) on models of at most kStiffnessCheckLimit
  /// velocities: the linearization at the initial state (integrate/stiffness.hpp), its
  /// eigenvalue of largest magnitude, and the step against the method's stability region (for
  /// dopri5, its largest step). dopri5's estimate during the run is in `statistics`.
  bool stiffness_checked = false;
  std::complex<double> fastest_eigenvalue{0.0, 0.0};  ///< 1/s
  integrate::StepStability step_stability;
  /// Every event that happened, in time order (each also a row of the table); the last one's
  /// action is stop when an event ended the run (t_end is then its time).
  std::vector<EventOccurrence> events;
  /// Every impact, rest and release of the stops and contacts (simulate/unilaterals.hpp), in time
  /// order; each impact is two rows of the table at its time, just before and just after.
  std::vector<StopEvent> stop_events;
};

/// The most velocity coordinates for which a run examines the linearization's eigenvalues (a
/// dense eigenproblem of size 2 nv).
inline constexpr int kStiffnessCheckLimit = 200;

/// What the summary says about stiffness, a sentence, or "" when there is nothing to say: a fixed
/// step outside the explicit method's stability region for some mode (with the eigenvalue and the
/// largest stable step), or dopri5 held by stability (Hairer's test: 15 stability-limited steps in
/// a row), each suggesting bdf. The options it names are marked (common/error.hpp,
/// OptionMessage): a front end spells them with spell_options.
std::string stiffness_note(const SimulationSummary& summary);

/// What the summary says about a singular initial configuration (ConsistentState::
/// singular_rows: the rows that lost independence there, the ranks), or "" for a regular one.
std::string singular_start_note(const system::ConsistentState& state);

class Simulation {
 public:
  /// Checks the options, resolves the outputs against `model` (which must outlive this) and
  /// makes the integrator. Throws InvalidArgument naming the option and its value (duration or
  /// step not positive and finite, every < 1, an unknown integrator), the output at fault, or
  /// an event that watches no quantity of the run (check_event).
  Simulation(const model::Model& model, std::vector<model::OutputSpec> outputs,
             SimulationOptions options);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  const SimulationOptions& options() const { return options_; }
  /// Every column of a row, in order (see the file comment).
  const std::vector<std::string>& column_names() const { return columns_; }
  /// Each column's unit (model/units.hpp): "s", "rad", "m/s", "J", "N·m", "1" for the relative
  /// drifts, "" for a constraint residual that mixes lengths and angles.
  const std::vector<std::string>& column_units() const { return units_; }
  const system::OutputSet& outputs() const { return outputs_; }

  /// Integrates from t = 0 and the model's initial state (quaternions normalized, prescribed
  /// coordinates set from their signals) to options().duration, handing sink.begin() the
  /// columns and sink.row() every recorded row, then flushes the sink. The step loop does not
  /// allocate (the sink aside). May be called again; each call starts afresh from the same state
  /// and writes the same table (the one MultibodySystem the constructor built is reused).
  /// Each event that happens adds a row at its time (simulate/event_monitor.hpp); one whose
  /// action is stop makes that row the last.
  ///
  /// Throws NumericalError when the state stops being finite, naming the time, the coordinate
  /// and a hint (integrate::run), or when a recorded quantity overflows (naming the column), with
  /// how many rows were written — after flushing the sink so the rows up to then are kept;
  /// Interrupted when options().stop is raised, after a last whole row; and what the integrator
  /// throws (a rigid-body method on a model it does not apply to).
  SimulationSummary run(RowSink& sink);

 private:
  class Recorder;
  // Fills the summary's stiffness fields for an explicit Runge–Kutta method.
  void check_stiffness(integrate::SecondOrderSystem& system, const integrate::State& state,
                       SimulationSummary& summary) const;
  // What the integrator advances: the closed loop where the model has controllers, else the
  // mechanism.
  integrate::SecondOrderSystem& advanced();

  const model::Model& model_;
  SimulationOptions options_;
  system::OutputSet outputs_;
  // Built once, here, and advanced by every run() (each starts it afresh from the initial state).
  std::unique_ptr<system::MultibodySystem> system_;
  std::unique_ptr<system::ClosedLoopSystem> closed_loop_;  // null without controllers
  std::unique_ptr<integrate::Integrator> integrator_;
  std::unique_ptr<EventMonitor> events_;
  std::unique_ptr<Unilaterals> stops_;  // null without joint limits or contacts
  std::vector<std::string> columns_;
  std::vector<std::string> units_;
};

/// The summary as `momenta simulate` prints it on stderr: steps (accepted, rejected),
/// evaluations, wall time, rows, and the audit (end and maximum drift, or why a quantity is not
/// audited). Several lines, each ending in '\n'. The options a note names are written by `spell`
/// (the command line's --integrator, Python's integrator=).
std::string format_summary(const SimulationSummary& summary, OptionSpelling spell = plain_spelling);

/// What a run that stopped early (a NumericalError from Simulation::run) did, as far as its
/// recorded rows tell: the integrator and step of `options`, `rows` rows, up to `t_end` (the last
/// row's time). Counts and audit stay empty.
SimulationSummary summary_of_stopped_run(const SimulationOptions& options, long rows, double t_end);

}  // namespace momenta::simulate
