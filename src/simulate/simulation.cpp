#include "momenta/simulate/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/dynamics/constraints.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/momentum.hpp"
#include "momenta/dynamics/reactions.hpp"
#include "momenta/integrate/integrator.hpp"
#include "momenta/integrate/run.hpp"
#include "momenta/integrate/second_order_system.hpp"
#include "momenta/model/integrators.hpp"
#include "momenta/model/units.hpp"
#include "momenta/system/closed_loop_system.hpp"
#include "momenta/system/integrators.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta/system/rigid_body_integrator.hpp"

namespace momenta::simulate {

using system::Energy;
using system::MultibodySystem;

// --- TableSink -----------------------------------------------------------------------------------

void TableSink::begin(std::span<const std::string> names) {
  columns.assign(names.begin(), names.end());
  rows.clear();
}

void TableSink::row(std::span<const double> values) {
  rows.emplace_back(values.begin(), values.end());
}

int TableSink::column(std::string_view name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it != columns.end()) return static_cast<int>(it - columns.begin());
  const std::vector<std::string_view> names(columns.begin(), columns.end());
  throw InvalidArgument(fmt::format("no column '{}'{}", name, did_you_mean(name, names)));
}

// --- Simulation ----------------------------------------------------------------------------------

namespace {

void check_options(const SimulationOptions& o) {
  if (!(o.duration > 0.0) || !std::isfinite(o.duration)) {
    throw InvalidArgument(
        fmt::format("the duration must be positive and finite, got {} s", o.duration));
  }
  if (!(o.step > 0.0) || !std::isfinite(o.step)) {
    throw InvalidArgument(fmt::format("the step must be positive and finite, got {} s", o.step));
  }
  if (o.every < 1) {
    throw InvalidArgument(fmt::format("every must be at least 1 step, got {}", o.every));
  }
}

// Joints whose coordinates hold a quaternion, and where it starts in q.
std::vector<int> quaternion_offsets(const model::Model& model) {
  std::vector<int> offsets;
  for (const model::Joint& j : model.joints()) {
    if (j.type == model::JointType::spherical) offsets.push_back(j.q_index);
    if (j.type == model::JointType::free) offsets.push_back(j.q_index + 3);
  }
  return offsets;
}

constexpr const char* kReactionSuffixes[6] = {"Fx", "Fy", "Fz", "Mx", "My", "Mz"};

std::string stop_event_line(const StopEvent& e);  // (with the summary's text, below)

// Where a fixed-step method met a point with no acceleration: it may be only a trial point of a
// step, past where the motion turns away from it; an adaptive method retries smaller steps.
std::string fixed_step_note(const NumericalError& e, const integrate::Integrator& integrator) {
  if (dynamic_cast<const integrate::UndefinedAcceleration*>(&e) == nullptr ||
      integrator.adaptive()) {
    return "";
  }
  return fmt::format(
      "{} takes fixed steps, and a point it tries within one may lie past where the motion "
      "turns away (a slip that stops first): ‹integrator=dopri5› or ‹integrator=bdf› retries "
      "smaller steps there and goes on if the motion does",
      integrator.name());
}

}  // namespace

Simulation::Simulation(const model::Model& model, std::vector<model::OutputSpec> outputs,
                       SimulationOptions options)
    : model_(model), options_(std::move(options)), outputs_(model, std::move(outputs)) {
  check_options(options_);
  integrator_ = system::make_integrator(options_.integrator, options_.tolerances);
  if (model.has_constraints() &&
      model::integrator_info(options_.integrator).family == model::IntegratorFamily::rigid_body) {
    throw InvalidArgument(
        fmt::format("integrator '{}' advances one free body's own flow and cannot keep the model's "
                    "constraints (each step must end projected onto them): use rk4, dopri5 or "
                    "symplectic_euler",
                    options_.integrator));
  }
  if (model.has_joint_limits() &&
      model::integrator_info(options_.integrator).family == model::IntegratorFamily::rigid_body) {
    throw InvalidArgument(fmt::format(
        "integrator '{}' advances one free body's own flow and cannot stop a joint at its limits: "
        "use rk4, dopri5, bdf or symplectic_euler",
        options_.integrator));
  }
  // The one system every run() of this simulation advances, closed by the controllers.
  system_ = std::make_unique<MultibodySystem>(model);
  if (model.has_controllers()) closed_loop_ = std::make_unique<system::ClosedLoopSystem>(*system_);
  if (model.has_joint_limits() || model.has_contacts())
    stops_ = std::make_unique<Unilaterals>(model, options_.step);
  events_ =
      std::make_unique<EventMonitor>(model, outputs_.specs(), options_.events,
                                     closed_loop_ ? closed_loop_->num_controller_states() : 0);

  // The columns that do not depend on what the model conserves, each with its unit.
  const auto add = [this](std::string name, std::string unit) {
    columns_.push_back(std::move(name));
    units_.push_back(std::move(unit));
  };
  add("time", "s");
  for (int i = 0; i < model.nq(); ++i) add(model.q_name(i), model::q_unit(model, i));
  for (int i = 0; i < model.nv(); ++i) add(model.v_name(i), model::v_unit(model, i));
  for (const char* name : kEnergyColumns) add(name, "J");
  for (const char* name : {"H_x", "H_y", "H_z"}) add(name, "kg·m²/s");
  for (std::size_t c = 0; c < outputs_.size(); ++c) {
    add(outputs_.column_names()[c], outputs_.column_units()[c]);
  }
  if (closed_loop_) {
    for (std::size_t c = 0; c < closed_loop_->column_names().size(); ++c)
      add(closed_loop_->column_names()[c], closed_loop_->column_units()[c]);
  }
  if (options_.reactions) {
    for (const model::Joint& j : model.joints()) {
      for (int k = 0; k < 6; ++k) {
        add(fmt::format("{}.reaction.{}", j.name, kReactionSuffixes[k]), k < 3 ? "N" : "N·m");
      }
    }
    for (const model::Joint& j : model.joints()) {
      if (j.limits) add(fmt::format("{}.stop_force", j.name), model::effort_unit(model, j.v_index));
    }
    for (std::size_t c = 0; c < model.constraints().size(); ++c) {
      const auto labels = model::constraint_force_labels(model.constraints()[c]);
      for (std::size_t k = 0; k < labels.size(); ++k) {
        add(fmt::format("{}.{}", model::constraint_name(model.constraints()[c]), labels[k]),
            model::output_unit(model, model::OutputQuantity::constraint_force, static_cast<int>(c),
                               static_cast<int>(k)));
      }
    }
  }

  // A run integrate::run would refuse (a step below time's resolution, 1e10 steps) is refused
  // here, before a front end opens any output.
  integrate::RunOptions run_options;
  run_options.t_end = options_.duration;
  run_options.h = options_.step;
  integrate::check_run(advanced(), *integrator_,
                       integrate::State{0.0, model.initial_q(), model.initial_v()}, run_options);
  // The audit columns, where the model should conserve the quantity: energy and momentum
  // drifts are relative (1), the quaternion norm error too, the constraint residuals in the
  // rows' own units (m or rad, m/s or rad/s: "" for the mixture).
  if (system_->conserves_energy()) add("audit.energy_drift", "1");
  if (system_->conserves_angular_momentum()) {
    add("audit.H_norm_drift", "1");
    add("audit.H_drift", "1");
  }
  if (!quaternion_offsets(model).empty()) add("audit.quaternion_norm_error", "1");
  if (model.has_constraints()) {
    add("audit.constraint_position", "");
    add("audit.constraint_velocity", "");
  }

  // A name used twice (an output called "time", a joint "a" with a coordinate column that an
  // output also produces) would make the table ambiguous.
  std::vector<std::string> sorted = columns_;
  std::sort(sorted.begin(), sorted.end());
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice != sorted.end()) {
    throw InvalidArgument(fmt::format(
        "column '{}' would appear twice in the table: rename the output (or joint) that makes it",
        *twice));
  }
}

Simulation::~Simulation() = default;

integrate::SecondOrderSystem& Simulation::advanced() {
  if (closed_loop_) return *closed_loop_;
  return *system_;
}

// Everything one run needs between steps, allocated before the first: the recorded copy of the
// state, the audit and the row, beside the simulation's system. observe() is the step loop's body.
class Simulation::Recorder {
 public:
  Recorder(const Simulation& simulation, MultibodySystem& system,
           system::ClosedLoopSystem* closed_loop, RowSink& sink)
      : sim_(simulation),
        model_(simulation.model_),
        sink_(sink),
        system_(system),
        closed_loop_(closed_loop),
        audit_data_(model_),
        quaternions_(quaternion_offsets(model_)),
        q_(model_.nq()),
        v_(model_.nv()),
        vdot_(model_.nv()),
        row_(simulation.columns_.size()) {}

  MultibodySystem& system() { return system_; }

  // Sets up the audit from the initial state (prescribed motion already applied).
  void start(const integrate::State& state, SimulationSummary& summary) {
    q_ = state.q.head(model_.nq());
    v_ = state.v.head(model_.nv());
    const Energy e = system_.energy(q_, v_);
    const dynamics::Momentum h = dynamics::momentum(model_, audit_data_, q_, v_);
    summary.energy_audited = system_.conserves_energy();
    summary.momentum_audited = system_.conserves_angular_momentum();
    summary.quaternions_audited = !quaternions_.empty();
    if (summary.energy_audited) {
      // E_scale = T0 + V_springs0 + Σ m_b |g| |p_WoBcm_W| (audit_data_ holds the poses).
      double scale = e.kinetic + std::abs(e.potential_springs);
      for (int b = 1; b < model_.num_bodies(); ++b) {
        const auto& mp = model_.body(b).mass_properties;
        scale += mp.mass() * model_.gravity().norm() *
                 audit_data_.X_WB[b].apply(mp.center_of_mass()).norm();
      }
      energy_ = audit_.add("energy", e.total(), scale);
    }
    if (summary.momentum_audited) {
      double inertia_scale = 0.0;
      for (int b = 1; b < model_.num_bodies(); ++b)
        inertia_scale += model_.body(b).mass_properties.inertia_about_com().trace() / 3.0;
      const double floor = std::sqrt(2.0 * std::max(e.kinetic, 0.0) * inertia_scale);
      h_norm_ = audit_.add("|H|", h.angular_about_com.norm(), floor);
      h_ = audit_.add("H", h.angular_about_com, floor);
    }
    if (summary.quaternions_audited) quaternion_ = audit_.add("quaternion norm", 0.0, 1.0);
    summary.constraints_audited = model_.has_constraints();
    if (summary.constraints_audited) {
      constraint_position_ = audit_.add("constraint position", 0.0, 1.0);
      constraint_velocity_ = audit_.add("constraint velocity", 0.0, 1.0);
    }
    sink_.begin(sim_.columns_);
  }

  // Called after every step (and with the initial state): audits, and records a row when asked.
  void observe(const integrate::State& state, bool record) {
    // A stop asked for (SIGINT in the CLI) ends the run on a whole row at this state.
    const bool stopping = sim_.options_.stop != nullptr && sim_.options_.stop->load();
    record = record || stopping;
    if (sim_.options_.progress && (++observed_ & 1023) == 0) sim_.options_.progress(state.t);
    // The recorded copy of the mechanism's state, with the prescribed joints exactly on their
    // signals.
    q_ = state.q.head(model_.nq());
    v_ = state.v.head(model_.nv());
    if (model_.has_prescribed_joints()) system_.apply_prescribed_motion(state.t, q_, v_);

    // Energy and momentum where audited or recorded (each runs the kinematics once).
    Energy e;
    dynamics::Momentum h;
    if (energy_ >= 0 || record) e = system_.energy(q_, v_);
    if (h_ >= 0 || record) h = dynamics::momentum(model_, audit_data_, q_, v_);
    double quaternion_error = 0.0;
    for (int i : quaternions_)
      quaternion_error = std::max(quaternion_error, std::abs(q_.segment<4>(i).norm() - 1.0));
    if (energy_ >= 0) audit_.record(energy_, e.total());
    if (h_ >= 0) {
      audit_.record(h_norm_, h.angular_about_com.norm());
      audit_.record(h_, h.angular_about_com);
    }
    if (quaternion_ >= 0) audit_.record(quaternion_, quaternion_error);
    system::ConstraintResiduals residuals;
    if (constraint_position_ >= 0) {
      residuals = system_.constraints()->residuals(audit_data_, q_, v_);
      audit_.record(constraint_position_, residuals.position);
      audit_.record(constraint_velocity_, residuals.velocity);
    }
    if (!record) return;

    // The row, in column order.
    std::size_t c = 0;
    row_[c++] = state.t;
    for (int i = 0; i < model_.nq(); ++i) row_[c++] = q_[i];
    for (int i = 0; i < model_.nv(); ++i) row_[c++] = v_[i];
    row_[c++] = e.kinetic;
    row_[c++] = e.potential();
    row_[c++] = e.total();
    for (int k = 0; k < 3; ++k) row_[c++] = h.angular_about_com[k];
    // The controllers first: they set the inputs they drive, which the outputs and reactions
    // then see; their columns follow the outputs'.
    const std::size_t n_outputs = sim_.outputs_.size();
    const std::size_t n_controls = closed_loop_ ? closed_loop_->column_names().size() : 0;
    if (closed_loop_) {
      closed_loop_->record(state.t, state.q, state.v,
                           std::span<double>(row_).subspan(c + n_outputs, n_controls));
    }
    // The outputs evaluate the system at (t, q, v), which also serves the reactions below.
    sim_.outputs_.evaluate(system_, state.t, q_, v_, std::span<double>(row_).subspan(c, n_outputs));
    c += n_outputs + n_controls;
    if (sim_.options_.reactions) {
      vdot_ = system_.data().vdot;
      dynamics::joint_reactions(model_, system_.data(), q_, v_, vdot_, system_.external_wrenches());
      for (int j = 0; j < model_.num_joints(); ++j) {
        const dynamics::JointReaction r =
            dynamics::joint_reaction(model_, system_.data(), j, dynamics::ReactionFrame::world);
        for (int k = 0; k < 3; ++k) row_[c++] = r.force[k];
        for (int k = 0; k < 3; ++k) row_[c++] = r.moment[k];
      }
      for (const model::Joint& j : model_.joints()) {
        if (j.limits) row_[c++] = system_.held(j.index) ? system_.stop_force(j.index) : 0.0;
      }
      if (const system::ConstraintSolver* solver = system_.constraints()) {
        for (int k = 0; k < static_cast<int>(model_.constraints().size()); ++k) {
          const int n =
              static_cast<int>(model::constraint_force_labels(model_.constraints()[k]).size());
          dynamics::constraint_forces(model_, system_.data(), solver->rows(), solver->multipliers(),
                                      k, std::span<double>(row_).subspan(c, n));
          c += n;
        }
      }
    }
    if (energy_ >= 0) row_[c++] = audit_.entry(energy_).final_drift;
    if (h_ >= 0) {
      row_[c++] = audit_.entry(h_norm_).final_drift;
      row_[c++] = audit_.entry(h_).final_drift;
    }
    if (quaternion_ >= 0) row_[c++] = quaternion_error;
    if (constraint_position_ >= 0) {
      row_[c++] = residuals.position;
      row_[c++] = residuals.velocity;
    }
    check_row_finite(state.t);
    sink_.row(row_);
    ++rows_;
    if (stopping) {
      throw Interrupted(fmt::format("stopped at t = {:.9g} s on request", state.t));
    }
  }

  // A quantity of the row that overflowed while the state stayed finite (the energy of a spring
  // of absurd stiffness): nothing non-finite is written as a result.
  void check_row_finite(double t) const {
    std::size_t bad = 0;
    while (bad < row_.size() && std::isfinite(row_[bad])) ++bad;
    if (bad == row_.size()) return;
    // The largest coordinate of the state, which the columns after time hold first.
    const std::size_t n_state = static_cast<std::size_t>(model_.nq() + model_.nv());
    std::size_t largest = 1;
    for (std::size_t c = 1; c <= n_state; ++c) {
      if (std::abs(row_[c]) > std::abs(row_[largest])) largest = c;
    }
    throw NumericalError(OptionMessage{fmt::format(
        "the recorded values became non-finite at t = {:.9g} s: {} = {} while the state is "
        "finite (its largest coordinate {} = {:.3g}). The step may be too large for the fastest "
        "motion (try a smaller ‹step›, or ‹integrator=dopri5›; ‹integrator=bdf› for a stiff "
        "model), or a parameter — a stiffness, a mass, a signal's amplitude — is absurd",
        t, sim_.columns_[bad], row_[bad], sim_.columns_[largest], row_[largest])});
  }

  long rows() const { return rows_; }
  const ConservationAudit& audit() const { return audit_; }

 private:
  const Simulation& sim_;
  const model::Model& model_;
  RowSink& sink_;
  MultibodySystem& system_;
  system::ClosedLoopSystem* closed_loop_;  // null without controllers
  dynamics::Data audit_data_;  // for the momentum, so system_'s evaluation stays as it was
  std::vector<int> quaternions_;
  VecX q_, v_, vdot_;
  std::vector<double> row_;
  ConservationAudit audit_;
  // Audit entries, −1 if not audited.
  int energy_ = -1, h_norm_ = -1, h_ = -1, quaternion_ = -1;
  int constraint_position_ = -1, constraint_velocity_ = -1;
  long rows_ = 0;
  long observed_ = 0;
};

void Simulation::check_stiffness(integrate::SecondOrderSystem& system,
                                 const integrate::State& state, SimulationSummary& summary) const {
  const std::string_view name = integrator_->name();
  if (std::isnan(integrate::amplification(name, {0.0, 0.0}))) return;
  if (model_.nv() == 0 || model_.nv() > kStiffnessCheckLimit) return;
  const Eigen::VectorXcd eigenvalues = integrate::linearization_eigenvalues(system, state);
  if (eigenvalues.size() == 0) return;
  summary.stiffness_checked = true;
  for (const std::complex<double>& lambda : eigenvalues) {
    if (std::abs(lambda) > std::abs(summary.fastest_eigenvalue))
      summary.fastest_eigenvalue = lambda;
  }
  summary.step_stability = integrate::check_step_stability(name, eigenvalues, options_.step);
}

SimulationSummary Simulation::run(RowSink& sink) {
  Recorder recorder(*this, *system_, closed_loop_.get(), sink);
  SimulationSummary summary;
  summary.integrator = std::string(integrator_->name());
  summary.order = integrator_->order();
  summary.adaptive = integrator_->adaptive();
  summary.step = options_.step;

  // The initial state: the model's, with unit quaternions and exact prescribed coordinates.
  integrate::State state{0.0, model_.initial_q(), model_.initial_v()};
  model::normalize(model_, state.q);
  if (model_.has_prescribed_joints())
    recorder.system().apply_prescribed_motion(0.0, state.q, state.v);
  if (stops_) stops_->open_all(recorder.system(), state);  // nothing held from an earlier run
  summary.initial_state = recorder.system().make_consistent(0.0, state.q, state.v);
  if (const system::ConstraintSolver* solver = recorder.system().constraints())
    summary.redundant_constraint_rows = solver->redundant_rows();
  // With controllers: their states joined to the mechanism's, their first samples taken.
  if (closed_loop_) state = closed_loop_->start(0.0, state.q, state.v);
  if (stops_) {
    for (StopEvent& e : stops_->start(recorder.system(), advanced(), state)) {
      summary.stop_events.push_back(std::move(e));
    }
  }
  recorder.start(state, summary);
  check_stiffness(advanced(), state, summary);

  // integrate::run reports every step (so the audit sees each); rows are kept every n-th, and
  // the last.
  integrate::RunOptions run_options;
  run_options.t_end = options_.duration;
  run_options.h = options_.step;
  run_options.every = 1;
  long step = -1;
  // Events: the state at the last step's end (the next step's start), and at an event.
  // Stops: the state just before a stop acts (the step is taken back to it, `state` becoming
  // the state just after).
  integrate::State previous = state, at_event = state, before_stop = state;
  bool finished = false, restarted = false;
  run_options.finished = &finished;
  if (stops_) run_options.restarted = &restarted;
  StopEvent stop_event;
  const auto observe = [&](const integrate::State& s) {
    ++step;
    // A stop that acts inside the step ends it there: the events up to then, a row just before
    // and one just after, and the integrator restarts from the latter.
    const bool stopped =
        stops_ && step > 0 &&
        stops_->check(recorder.system(), advanced(), *integrator_, previous, s, before_stop);
    const integrate::State& end = stopped ? before_stop : s;
    if (!events_->empty()) {
      if (step == 0) events_->start(recorder.system(), s);
      for (const EventOccurrence& o :
           step == 0 ? std::span<const EventOccurrence>()
                     : events_->check(recorder.system(), advanced(), *integrator_, previous, end)) {
        events_->state_at(advanced(), o.time, at_event);
        recorder.observe(at_event, true);
        summary.events.push_back(o);
        finished = o.action == model::EventAction::stop;
      }
      if (finished) return;
    }
    if (stopped) {
      recorder.observe(before_stop, true);
      state = before_stop;  // the run's own state, which `s` refers to
      stops_->act(recorder.system(), advanced(), state, stop_event);
      summary.stop_events.push_back(stop_event);
      for (StopEvent& slip : stops_->take_impact_slips()) {
        summary.stop_events.push_back(std::move(slip));
      }
      restarted = true;
      --step;
    }
    if (!events_->empty() || stops_) {
      previous.t = s.t;
      previous.q = s.q;
      previous.v = s.v;
    }
    recorder.observe(s, stopped || step % options_.every == 0 || s.t >= options_.duration);
  };
  try {
    const integrate::RunSummary run_summary =
        integrate::run(advanced(), *integrator_, state, run_options, observe);
    summary.statistics = run_summary.statistics;
    summary.wall_seconds = run_summary.wall_seconds;
  } catch (const NumericalError& e) {
    // Keep what was recorded, and say how far it goes.
    sink.flush();
    // What the stops and contacts did last, where they act: the run stopped where they do, often.
    const std::string last_stop =
        summary.stop_events.empty()
            ? ""
            : fmt::format("; the last of its stops' and contacts' events: {}",
                          stop_event_line(summary.stop_events.back()));
    std::string note = stiffness_note(summary);
    if (const std::string fixed = fixed_step_note(e, *integrator_); !fixed.empty()) {
      note += (note.empty() ? "" : ". ") + fixed;
    }
    throw NumericalError(OptionMessage{
        fmt::format("{} ({} row{} up to the failure were written{}){}{}",
                    e.spelled(keep_option_marks), recorder.rows(), recorder.rows() == 1 ? "" : "s",
                    last_stop, note.empty() ? "" : ". ", note)});
  } catch (const Interrupted& e) {
    sink.flush();
    throw Interrupted(fmt::format("{}; {} whole row{} written", e.what(), recorder.rows(),
                                  recorder.rows() == 1 ? "" : "s"));
  } catch (...) {
    sink.flush();
    throw;
  }
  sink.flush();
  summary.t_end = finished ? at_event.t : state.t;
  summary.rows = recorder.rows();
  summary.audit = recorder.audit().entries();
  return summary;
}

// --- Summary -------------------------------------------------------------------------------------

SimulationSummary summary_of_stopped_run(const SimulationOptions& options, long rows,
                                         double t_end) {
  SimulationSummary summary;
  summary.integrator = options.integrator;
  summary.step = options.step;
  summary.rows = rows;
  summary.t_end = t_end;
  return summary;
}

namespace {
// "−8117 1/s", "−3.2 ± 41.5i 1/s" (`unit` empty: a plain number).
std::string complex_text(std::complex<double> z, std::string_view unit) {
  const std::string space = unit.empty() ? "" : " ";
  if (std::abs(z.imag()) <= 1e-9 * std::abs(z))
    return fmt::format("{:.4g}{}{}", z.real(), space, unit);
  return fmt::format("{:.4g} ± {:.4g}i{}{}", z.real(), std::abs(z.imag()), space, unit);
}
}  // namespace

std::string singular_start_note(const system::ConsistentState& state) {
  if (state.singular_rows.empty()) return "";
  return fmt::format(
      "the initial configuration is singular: row{} {} depend{} on the others there but not at "
      "assembled configurations nearby ({} independent rows there, {} nearby) — links aligned at "
      "a dead point or a bifurcation; the accelerations there are their limit along the motion",
      state.singular_rows.size() == 1 ? "" : "s", fmt::join(state.singular_rows, ", "),
      state.singular_rows.size() == 1 ? "s" : "", state.rank_at_start, state.rank_nearby);
}

std::string stiffness_note(const SimulationSummary& s) {
  if (s.stiffness_checked && !s.step_stability.stable && !s.adaptive) {
    const std::complex<double> lambda = s.step_stability.eigenvalue;
    return fmt::format(
        "{} at h = {:.3g} s is unstable here: the linearization at t = 0 has "
        "λ = {}, and h·λ = {} lies outside {}'s stability region (stable for h ≤ {:.3g} s). "
        "Use ‹integrator=bdf› or ‹integrator=sdirk3› (stable at any step), or a smaller ‹step›",
        s.integrator, s.step, complex_text(lambda, "1/s"), complex_text(s.step * lambda, ""),
        s.integrator, s.step_stability.largest_stable_step);
  }
  if (!std::isnan(s.statistics.stiff_from)) {
    return fmt::format(
        "{} was held by stability, not accuracy: {} of {} steps had h·|λ| ≥ 3.25 "
        "(|λ| up to {:.4g} 1/s, from t = {:.6g} s){}. ‹integrator=bdf› takes far fewer steps "
        "(docs/integrators.md)",
        s.integrator, s.statistics.stability_limited_steps, s.statistics.steps,
        s.statistics.stiff_eigenvalue, s.statistics.stiff_from,
        s.stiffness_checked ? fmt::format("; the linearization at t = 0 has λ = {}",
                                          complex_text(s.fastest_eigenvalue, "1/s"))
                            : "");
  }
  return "";
}

namespace {
// The events that happened: each on a line, or the first few of many and how many there were.
std::string format_events(const std::vector<EventOccurrence>& events) {
  constexpr std::size_t kListed = 8;
  std::string out;
  const std::size_t listed = events.size() <= kListed ? events.size() : kListed - 2;
  for (std::size_t i = 0; i < listed; ++i) {
    const EventOccurrence& e = events[i];
    const std::string label =
        e.name == e.condition ? e.name : fmt::format("{} ({})", e.name, e.condition);
    out += fmt::format("{:<13}{} at t = {:.12g} s{}\n", i == 0 ? "events" : "", label, e.time,
                       e.action == model::EventAction::stop ? ": the run stops there" : "");
  }
  if (listed < events.size()) {
    const EventOccurrence& last = events.back();
    out += fmt::format(
        "{:<13}... {} events in all, the last {} at t = {:.12g} s{} (each is a row of the table)\n",
        "", events.size(), last.name, last.time,
        last.action == model::EventAction::stop ? ", which stops the run" : "");
  }
  return out;
}

// One line of the summary for a stop or contact event.
std::string stop_event_line(const StopEvent& e) {
  const bool contact = !e.contact.empty();
  const std::string stop = contact
                               ? fmt::format("contact {}", e.contact)
                               : fmt::format("{} {} stop", e.joint, e.upper ? "upper" : "lower");
  const char* const held = contact ? "the body" : "the joint";
  const char* const rate = contact ? "normal speed" : "rate";
  switch (e.kind) {
    case StopEventKind::impact:
      return fmt::format(
          "{} impact at t = {:.12g} s: {} {:.6g} -> {:.6g}, impulse {:.6g}, "
          "{:.6g} J lost",
          stop, e.time, rate, e.rate_before, e.rate_after, e.impulse, e.energy_lost);
    case StopEventKind::rest: {
      // Bounces that end later than the time says (a rebound's round-off tail says nothing).
      const std::string rest_time = fmt::format("{:.12g}", e.rest_time);
      return fmt::format(
          "{} holds {} from t = {:.12g} s{}{} ({} {:.6g} -> 0, {:.6g} J lost)", stop, held, e.time,
          e.rest_time > e.time && rest_time != fmt::format("{:.12g}", e.time)
              ? fmt::format(" (its bounces end at t = {} s)", rest_time)
              : "",
          e.friction == FrictionState::none ? ""
                                            : fmt::format(", {}", friction_state_name(e.friction)),
          rate, e.rate_before + 0.0, e.energy_lost);  // −0 (n · 0) as 0
    }
    case StopEventKind::release:
      return fmt::format("{} lets {} go at t = {:.12g} s (it would pull)", stop, held, e.time);
    case StopEventKind::stick:
      if (e.in_impact) {
        return fmt::format(
            "{} sticks at t = {:.12g} s, in the impact (its slip of {:.3g} m/s would have "
            "turned to run with its friction)",
            stop, e.time, e.rate_before);
      }
      return fmt::format(
          "{} sticks at t = {:.12g} s (slip speed {:.3g} -> 0; friction {:.6g} N within "
          "μs N = {:.6g} N)",
          stop, e.time, e.rate_before, e.friction_needed, e.friction_limit);
    case StopEventKind::slip:
      if (e.in_impact) {
        return fmt::format(
            "{} slips at t = {:.12g} s, in the impact (sticking would need a friction impulse "
            "of {:.6g} N·s, beyond μs P_n = {:.6g} N·s)",
            stop, e.time, e.friction_needed, e.friction_limit);
      }
      // Where the friction sticking needs reached the cone (located there), or was beyond it
      // where a slip stopped (it slides on the other way).
      if (e.friction_needed <= e.friction_limit * (1.0 + 1e-9)) {
        return fmt::format("{} slips at t = {:.12g} s (its friction reached μs N = {:.6g} N)", stop,
                           e.time, e.friction_limit);
      }
      return fmt::format(
          "{} slips at t = {:.12g} s (sticking would need {:.6g} N of friction, beyond "
          "μs N = {:.6g} N)",
          stop, e.time, e.friction_needed, e.friction_limit);
  }
  return std::string();
}

// The stops' impacts, rests and releases: the first few and the last, with their count.
std::string format_stop_events(const std::vector<StopEvent>& events) {
  if (events.empty()) return "";
  constexpr std::size_t kListed = 6;
  std::string out;
  const std::size_t listed = events.size() <= kListed ? events.size() : kListed - 2;
  for (std::size_t i = 0; i < listed; ++i) {
    out += fmt::format("{:<13}{}\n", i == 0 ? "stops" : "", stop_event_line(events[i]));
  }
  if (listed < events.size()) {
    long impacts = 0;
    double lost = 0.0;
    for (const StopEvent& e : events) {
      impacts +=
          e.kind == StopEventKind::impact || (e.kind == StopEventKind::rest && e.impulse != 0.0);
      lost += e.energy_lost;
    }
    out += fmt::format("{:<13}... {} in all ({} impacts, {:.6g} J lost), the last: {}\n", "",
                       events.size(), impacts, lost, stop_event_line(events.back()));
  }
  return out;
}

}  // namespace

std::string format_summary(const SimulationSummary& s, OptionSpelling spell) {
  std::string out;
  const std::string order =
      s.order == model::kExactOrder ? std::string("exact") : fmt::format("order {}", s.order);
  out += fmt::format("integrator   {} ({}{}), {} {:.6g} s, to t = {:.6g} s\n", s.integrator, order,
                     s.adaptive ? ", adaptive" : "", s.adaptive ? "largest step" : "step", s.step,
                     s.t_end);
  out += fmt::format("steps        {} accepted, {} rejected; {} evaluations\n", s.statistics.steps,
                     s.statistics.rejected_steps, s.statistics.evaluations);
  const double rate = s.wall_seconds > 0.0 ? s.statistics.steps / s.wall_seconds : 0.0;
  out += fmt::format("wall time    {:.3g} s ({:.3g} steps/s); {} rows\n", s.wall_seconds, rate,
                     s.rows);
  for (const system::CoordinateChange& c : s.initial_state.q_changes)
    out += fmt::format("initial q    {} {:.9g} -> {:.12g} (made consistent with the constraints)\n",
                       c.name, c.from, c.to);
  for (const system::CoordinateChange& c : s.initial_state.v_changes)
    out += fmt::format("initial v    {} {:.9g} -> {:.12g} (made consistent with the constraints)\n",
                       c.name, c.from, c.to);
  if (const std::string note = singular_start_note(s.initial_state); !note.empty()) {
    out += fmt::format("constraints  {}\n", note);
  }
  if (!s.redundant_constraint_rows.empty()) {
    out += fmt::format(
        "constraints  redundant rows (implied by the others; they carry no force): {}\n",
        fmt::join(s.redundant_constraint_rows, ", "));
  }
  out += format_events(s.events);
  out += format_stop_events(s.stop_events);
  if (const std::string note = stiffness_note(s); !note.empty()) {
    out += fmt::format("stiffness    {}\n", spell_options(note, spell));
  }
  out += "conservation audit (relative drift: at the end, largest over every step)\n";
  for (const AuditEntry& e : s.audit) {
    out += fmt::format("  {:<16} {:>10.2e}  {:>10.2e}\n", e.name, e.final_drift, e.max_drift);
  }
  if (!s.energy_audited)
    out +=
        "  energy           not audited: damping, friction, applied loads, prescribed motion or "
        "inelastic stops\n";
  if (!s.momentum_audited)
    out +=
        "  H                not audited: external torques act (a joint or spring to the world, "
        "applied loads)\n";
  return out;
}

}  // namespace momenta::simulate
