#pragma once
// A Model as the second-order system the integrators advance: v̇ = a(t, q, v) from the model's
// gravity, force elements (dynamics/force_elements.hpp) and prescribed joints (hybrid dynamics,
// Featherstone 2008 §9.2).
//
// Constraints (model/constraint.hpp). The accelerations are the constrained ones and the
// constraint forces join the force elements' wrenches (external_wrenches(), so joint reactions
// include them); project() puts a stepped state back onto the constraints
// (system/constraint_solver.hpp).
//
// Prescribed joints. Their coordinates stay in q and v (so the state has the model's layout), but
// every evaluation first overwrites them with their signals' values at t, and their acceleration
// is the signals' second derivative: the prescribed motion is exact whatever the integrator's
// error. apply_prescribed_motion() does the same to a state between steps so that what is
// recorded is exact too.
//
// Commanded joints. A controller that drives a signal prescribing a joint's coordinate commands
// that coordinate's acceleration (model/controller.hpp): the coordinate is then the state's own,
// starting at the joint's q0 and v0 (Model::initial_q), its acceleration the driven value
// (plus the signal's acceleration offset; its value and rate offsets move the coordinate and its
// rate).

#include <cassert>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <Eigen/LU>

#include "momenta/dynamics/data.hpp"
#include "momenta/integrate/second_order_system.hpp"
#include "momenta/model/model.hpp"
#include "momenta/system/constraint_solver.hpp"

namespace momenta::system {

/// How a run holds a contact (model::Contact; MultibodySystem::hold_contact).
enum class ContactHold {
  open,      ///< every row off: the bodies move freely
  sliding,   ///< the normal row on; kinetic friction μk N against the slip, applied as a load
  sticking,  ///< every row on (the normal alone where the contact has no friction)
};

/// A slip that starts from rest (hold_contact sliding) runs along its stable direction until it
/// is this fast (m/s), where it has one and the slip is within 90° of it: see
/// MultibodySystem::end_slip_start. At 1e-6 m/s the direction's turning (rate
/// |∂(a × d)/∂θ| / |v_t|, ~1e6–1e7 /s for accelerations of 1–10 m/s²) would settle within a
/// microsecond, and an explicit integrator's steps past it stay above ~1e-7 s (estimates).
inline constexpr double kStartingSlip = 1e-6;

/// Energy of the system at one instant (J).
struct Energy {
  double kinetic = 0.0;            ///< ½ vᵀ M v
  double potential_gravity = 0.0;  ///< −Σ m g · p_cm
  double potential_springs = 0.0;  ///< ½ k (ℓ − ℓ0)² of every spring
  double potential() const { return potential_gravity + potential_springs; }
  double total() const { return kinetic + potential(); }
};

/// What a MultibodySystem asks of its model, checked without building one (a front end accepting
/// a model file it may never run): throws InvalidArgument, naming the joint and coordinate, when
/// the mass matrix of the free coordinates is singular at the initial configuration
/// (dynamics::check_mass_matrix). The constructor checks exactly this.
void check_simulable(const model::Model& model);

class MultibodySystem final : public integrate::SecondOrderSystem {
 public:
  /// Keeps a reference to `model` (it must outlive the system) and sizes every workspace. Throws
  /// what check_simulable throws.
  explicit MultibodySystem(const model::Model& model);

  const model::Model& model() const { return model_; }

  int nq() const override;
  int nv() const override;

  /// v̇ at (t, q, v): force elements at t, then hybrid_dynamics (plain ABA without prescribed
  /// joints). Sizes q nq, v and vdot nv. The integrators' fast path: data() is left partly
  /// updated (world poses only when some element acts on bodies; no body accelerations), so
  /// read quantities after evaluate(). No allocation.
  void acceleration(double t, const VecX& q, const VecX& v, VecX& vdot) override;
  /// The generalized force that accelerations `vdot` leave unbalanced at (t, q, v):
  /// r = ID(q̄, v̄, v̇̄, f_ext) − Q(q̄, v̄), where q̄, v̄ are the state with the prescribed (and held)
  /// coordinates applied, v̇̄ is `vdot` but their prescription's accelerations, and Q, f_ext are
  /// the force elements' loads at t (the signals sampled as acceleration() samples them); zero on
  /// prescribed and held coordinates. The accelerations acceleration() returns leave r = 0, and
  /// on the free rows r = M_ff (vdot − a): a second model's r at the first's accelerations
  /// measures how its accelerations differ for the price of one inverse dynamics (RNEA, no
  /// articulated inertias) — what identify's sensitivities take ∂a/∂p from. Throws
  /// InvalidArgument for a model with constraints. Overwrites data(); no allocation.
  const VecX& residual(double t, const VecX& q, const VecX& v, const VecX& vdot);
  void integrate(const VecX& q, const VecX& dq, VecX& q_out) const override;
  void difference(const VecX& q0, const VecX& q1, VecX& dq) const override;
  void local_coordinate_rate(const VecX& delta, const VecX& v, VecX& delta_rate) const override;
  void configuration_scale(const VecX& q, VecX& scale) const override;
  /// The first breakpoint of any of the model's signals after t (model::Signal::next_breakpoint):
  /// integrate::run ends a step there.
  double next_discontinuity(double t) const override;
  /// Remembers t1: acceleration() at t ≥ t1 samples the signals from the left.
  void begin_step(double t0, double t1) override;
  /// The model's coordinate names ("hinge.q0", "base.v3").
  std::string coordinate_name(int i, bool velocity) const override;

  /// Projects (q, v) onto the model's constraints after a step (prescribed coordinates from
  /// their signals at t first). False, and nothing done, without constraints.
  bool project(double t, VecX& q, VecX& v) override;

  /// The constraint solver, or nullptr for a model without constraints.
  ConstraintSolver* constraints() { return constraints_.get(); }
  const ConstraintSolver* constraints() const { return constraints_.get(); }

  /// Makes the state at t consistent with the constraints, keeping the coordinates of joints
  /// whose q0 / v0 the model gives (and prescribed ones) where the others can take up the
  /// residual (ConstraintSolver::consistent_state). Nothing to do without constraints.
  ConsistentState make_consistent(double t, VecX& q, VecX& v);

  /// Sets the prescribed joints' coordinates of q and v to their signals' value and rate at t
  /// (offsets included); commanded coordinates are left as they are. No allocation.
  void apply_prescribed_motion(double t, VecX& q, VecX& v) const;

  /// Evaluates everything at (t, q, v) and leaves it in data(): kinematics (poses, velocities,
  /// accelerations) of the state with the prescribed coordinates applied, the force elements' tau
  /// and f_ext (element_forces(), external_wrenches()), vdot and data().tau, the total
  /// generalized force on every coordinate: element_forces() on the free ones, and on the
  /// prescribed ones the force their motion needs (rnea(q, v, vdot, f_ext) == data().tau; the
  /// drive's own effort is data().tau − element_forces() there). Returns data().vdot. No
  /// allocation.
  const VecX& evaluate(double t, const VecX& q, const VecX& v);

  /// After evaluate(): the workspace with every quantity of that instant.
  const dynamics::Data& data() const { return data_; }
  dynamics::Data& data() { return data_; }
  /// After evaluate(): the force elements' generalized forces (size nv) and body wrenches (the
  /// wrenches include the constraint forces).
  const VecX& element_forces() const { return tau_elements_; }
  std::span<const Vec6> external_wrenches() const { return f_ext_; }

  /// Perturbations added to the signals: value, rate and acceleration offsets, one each per
  /// model signal (model.signals()), zero by default. Linearization perturbs inputs through
  /// these; a simulation leaves them at zero. Throws InvalidArgument on a size mismatch.
  void set_signal_offsets(std::span<const double> value, std::span<const double> rate,
                          std::span<const double> acceleration);
  /// Sets the value of signal s, one a controller drives (Model::is_driven): evaluations use it
  /// (plus the offset) in place of the signal of time, with zero rate and acceleration, until
  /// it is set again. Zero at first. system/closed_loop_system.hpp sets them before each
  /// evaluation. No allocation; s must be driven (checked in debug builds).
  void set_driven_value(int s, double value) {
    assert(driven_[static_cast<std::size_t>(s)]);
    driven_values_[static_cast<std::size_t>(s)] = value;
  }
  /// Makes signal s driven from now on, as a controller's (its value set by set_driven_value,
  /// zero until then): Python's Model.dynamics(t, x, u) sets every input so. Throws
  /// InvalidArgument for a signal that prescribes a joint (its motion needs rates).
  void drive_signal(int s);
  /// The value set_driven_value last gave signal s.
  double driven_value(int s) const { return driven_values_[static_cast<std::size_t>(s)]; }
  /// After evaluate(): the state it evaluated, q and v with the prescribed coordinates applied.
  const VecX& evaluated_q() const { return q_; }
  const VecX& evaluated_v() const { return v_; }
  /// The signals' samples (with offsets) at the last evaluated instant.
  std::span<const model::SignalSample> signal_samples() const { return samples_; }

  /// Holds joint j's coordinate (a revolute or prismatic joint's) at `value` with zero rate and
  /// acceleration, as a stop holds it (simulate/unilaterals.hpp): evaluations then treat it as
  /// prescribed (hybrid dynamics), and stop_force(j) is the force the hold needs. The caller sets
  /// the state's coordinate and rate to match. No allocation without constraints; with them the
  /// constraint solver frees the joint's coordinate no more (ConstraintSolver::hold_joints: an
  /// event's cost), and the stop's force carries the constraints' share.
  void hold(int j, double value);
  /// Lets joint j move by forces again.
  void release(int j);
  bool held(int j) const { return held_[static_cast<std::size_t>(j)] != 0; }
  /// Per joint, 1 where a stop holds it (the model's prescribed joints not marked): the mask
  /// dynamics::stop_impact and the impacts take as `held_joints`.
  std::span<const char> held_joints() const { return held_; }
  /// After an evaluation (acceleration() or evaluate()): the generalized force the hold of joint j
  /// exerts on its coordinate (N·m or N): what the joint's motion needs less the force elements'.
  double stop_force(int j) const;

  /// Holds contact k — constraint k, a model::Contact — as `how` from configuration q
  /// (ConstraintSolver::enable_rows): its rows on while it holds (the normal alone while it
  /// slides), off while open. Sliding with kinetic friction μk > 0, evaluations apply the force
  /// −μk N ŝ at the contact point, ŝ the direction of the contact point's slip velocity v_t —
  /// while v_t · ŝ_ref > 0 and |v_t| > 1e-12 m/s, else ŝ_ref (see set_slip_reference), which
  /// `slip_W` (along the plane, not zero) sets first; but a slip held so starts from rest, and
  /// while it is slower than kStartingSlip (the only sliding contact that slow) its ŝ is its
  /// stable direction nearest ŝ_ref (see end_slip_start). The normal force N depends on the
  /// friction and the friction on N: both are affine in the loads, so N comes exactly from the
  /// solves with each sliding contact's friction at unit N and none (Painlevé's paradox — no N ≥ 0
  /// or many — is a NumericalError). The caller puts the state on the plane with no normal speed
  /// (and no slip where it sticks) first. Overwrites data(). Allocates only when the set of sliding
  /// contacts changes.
  void hold_contact(int k, VecRef q, ContactHold how, const Vec3& slip_W = Vec3::Zero());
  /// Sets sliding contact k's reference direction ŝ_ref (along the plane; normalized here, and
  /// ignored where zero): the friction keeps acting against it, not turning round, where the slip
  /// speed passes zero inside a step (the run locates that instant; simulate/unilaterals.hpp sets
  /// the reference from the slip at each step's start). No allocation.
  void set_slip_reference(int k, const Vec3& slip_W);
  /// Sliding contact k's slip, which started from rest (hold_contact), has run faster than
  /// kStartingSlip: from now on its friction acts against the slip alone. Until then, while it
  /// is slower than that, the friction acts against the direction in which the slip's
  /// acceleration is along the slip (λ ≥ 0), the stable one nearest its reference
  /// (src/system/slip_direction.hpp; docs/contacts.md, "Coulomb friction"). No allocation.
  void end_slip_start(int k);
  /// The contacts that slide, in the order they began to.
  int sliding_contacts() const { return static_cast<int>(sliding_.size()); }
  /// After an evaluation: the normal force (N) closed contact k exerts on its body, > 0 pushing
  /// it off the plane; 0 while open.
  double contact_force(int k) const;
  /// After an evaluation: the kinetic friction −μk N ŝ (N, world axes) sliding contact k exerts
  /// on its body at the contact point; zero where it sticks (its rows carry the friction) or is
  /// open.
  Vec3 contact_friction(int k) const;

  /// Energy at (q, v) (prescribed coordinates as given). Overwrites data()'s poses and
  /// velocities with those of (q, v). No allocation.
  Energy energy(const VecX& q, const VecX& v);

  /// True when total energy should be conserved: no prescribed joints, no dampers, friction or
  /// applied loads.
  bool conserves_energy() const { return conserves_energy_; }
  /// True when the angular momentum about the system centre of mass (world frame) should be
  /// conserved: additionally every joint on the world is free and no spring attaches to the world.
  bool conserves_angular_momentum() const { return conserves_angular_momentum_; }

 private:
  // evaluate() without the bodies' accelerations: signals (from the side `limit` at a
  // breakpoint), prescribed state, kinematics, force elements, forward dynamics; with sliding
  // contacts, the normal forces their friction needs (see hold_contact).
  const VecX& compute(double t, const VecX& q, const VecX& v, model::Limit limit);
  // compute() with each sliding contact's friction at the normal force it is given.
  const VecX& solve(double t, const VecX& q, const VecX& v, model::Limit limit);
  // Adds each sliding contact's friction −μk N ŝ to f_ext_ (needs data_'s poses and velocities).
  void add_sliding_friction();
  // sliding_response_ (I − ∂N_i/∂N_j through friction) from one solve per sliding contact at
  // unit N, after the solve without friction.
  void respond_to_unit_normals(double t, const VecX& q, const VecX& v, model::Limit limit);
  // The sliding contact whose slip started from rest (hold_contact) and is slower than
  // kStartingSlip, where it is the only one slower than that; −1 where there is none, or where
  // several are that slow (a group sliding to rest together: each keeps its direction).
  int lone_starting_slip() const;
  // respond_to_unit_normals() where sliding contact `starting` is such a slip: two solves per
  // sliding contact, a unit force along each tangent, give the normal forces and the slips'
  // accelerations for any directions, and that slip takes its stable direction
  // (src/system/slip_direction.hpp), the others theirs.
  void respond_with_starting_slip(int starting, double t, const VecX& q, const VecX& v,
                                  model::Limit limit);
  // After a solve: each sliding contact's slip acceleration along its tangents into `rates`
  // (two entries a contact).
  void slip_accelerations(VecX& rates);
  // I + ∂N/∂f · (μ d) for the sliding contacts' unit directions `directions` (two entries a
  // contact, in its tangent basis) into `response`, from slip_normals_.
  void response_for(const VecX& directions, MatX& response) const;
  // The side of a breakpoint the signals are sampled from at t: the left at the end of the
  // announced step (see begin_step), else the right.
  model::Limit limit_at(double t) const {
    return t >= step_end_ ? model::Limit::left : model::Limit::right;
  }
  // Samples the signals at t, applies the prescribed and held coordinates to q_, v_ (their
  // accelerations to vdot_prescribed_) and evaluates the force elements into tau_elements_ and
  // f_ext_. Returns the wrenches the dynamics should take: none when no element acts on bodies.
  std::span<const Vec6> apply_loads(double t, const VecX& q, const VecX& v, model::Limit limit);
  // compute() up to the constraints: apply_loads, then the unconstrained forward dynamics into
  // data_ — only aba_articulate's passes where `factors_only` (the constraint solver finishes aba
  // with the constraint forces).
  void free_dynamics(double t, const VecX& q, const VecX& v, model::Limit limit,
                     bool factors_only = false);
  // At a singular configuration (the constraint rows lose rank: a dead point or a bifurcation
  // passed exactly, or the start there) the rows do not fix the accelerations; along the motion
  // they are continuous. Takes the mean of the accelerations and multipliers at the assembled
  // states a small time ±τ along the motion (q ⊕ ±τ v projected; 1e-4 on the fastest
  // coordinate): O(τ²) = 1e-8 off the limit. At rest there: the solver's error.
  void accelerations_at_singular_configuration(double t, model::Limit limit);

  const model::Model& model_;
  dynamics::Data data_;
  VecX q_, v_;            // the state with prescribed coordinates applied
  VecX tau_elements_;     // force elements on the joints
  VecX constraint_tau_;   // couplers' forces on the joints (the last evaluation's)
  VecX vdot_prescribed_;  // signals' accelerations at the prescribed coordinates
  VecX residual_;         // residual()'s
  std::vector<Vec6> f_ext_;
  std::vector<model::SignalSample> samples_;  // every signal at the current instant
  std::vector<double> signal_values_;         // samples_[i].value, for force_element_forces
  std::vector<model::SignalSample> offsets_;  // see set_signal_offsets
  std::vector<char> driven_;                  // whether a controller drives signal i
  std::vector<double> driven_values_;         // see set_driven_value
  // Per signal, the coordinate (q and v index) whose acceleration it commands; −1 for none.
  std::vector<int> commanded_q_, commanded_v_;
  mutable std::vector<model::SignalSample> applied_samples_;   // apply_prescribed_motion's
  double step_end_ = std::numeric_limits<double>::infinity();  // see begin_step
  std::unique_ptr<ConstraintSolver> constraints_;              // null without constraints
  // accelerations_at_singular_configuration's workspace, and whether it is running.
  double singular_t_ = 0.0;  // the singular state's time, while it is probed
  VecX singular_q_, singular_v_, probe_q_, probe_v_, vdot_mean_, lambda_mean_;
  bool probing_ = false;
  // Joints a stop holds (see hold()): per joint, whether held and at what value; the hybrid
  // dynamics' mask (prescribed or held joints); and how many are held.
  std::vector<char> held_;
  std::vector<double> held_value_;
  std::vector<char> hybrid_mask_;
  int holding_ = 0;
  // The contacts that slide (hold_contact): constraint index, its normal row, μk, the reference
  // slip direction, the normal force their friction is taken at, and the direction it acts
  // against at the last evaluation.
  // `directed`: slip_W set by compute() (a slow slip's stable direction, or a unit force along
  // a tangent), not from the slip velocity; the slip velocity and the tangents at the last
  // evaluation.
  struct SlidingContact {
    int constraint = 0;
    int normal_row = 0;
    double mu = 0.0;
    Vec3 reference_W = Vec3::UnitX();
    double normal = 0.0;
    Vec3 slip_W = Vec3::UnitX();
    bool directed = false;
    bool starting = true;  // from rest, until end_slip_start
    Vec3 slip_velocity_W = Vec3::Zero();
    Vec3 tangent_1_W = Vec3::UnitX(), tangent_2_W = Vec3::UnitY();
  };
  std::vector<SlidingContact> sliding_;
  VecX sliding_base_;      // their normal forces with no friction
  MatX sliding_response_;  // I − ∂N_i/∂N_j through friction
  Eigen::PartialPivLU<MatX> sliding_lu_;
  // respond_with_starting_slip's workspace: per unit force along each contact's tangents (columns
  // 2j, 2j + 1), the normal forces' response (m × 2m) and the slips' accelerations' (2m × 2m);
  // the slips' accelerations with no friction; the directions (two entries a contact); a trial
  // response, its factors and normal forces (compute()'s final normal forces are solved there).
  MatX slip_normals_, slip_rates_;
  VecX slip_rate_base_, slip_rate_trial_, slip_directions_;
  MatX trial_response_;
  Eigen::PartialPivLU<MatX> trial_lu_;
  VecX trial_normals_;
  bool body_loads_ = false;  // some element acts on bodies (needs poses; f_ext is not zero)
  bool conserves_energy_ = false;
  bool conserves_angular_momentum_ = false;
};

}  // namespace momenta::system
