#include "momenta/system/multibody_system.hpp"

#include <algorithm>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/contact_geometry.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/energy.hpp"
#include "momenta/dynamics/force_elements.hpp"
#include "momenta/dynamics/hybrid_dynamics.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta/model/prescribed_motion.hpp"
#include "slip_direction.hpp"

namespace momenta::system {

namespace {

// A signal's sample plus its offsets (the linearization's perturbation; zero in a simulation).
model::SignalSample offset_sample(const model::Signal& signal, const model::SignalSample& offset,
                                  double t, model::Limit limit = model::Limit::right) {
  const model::SignalSample s = signal.sample(t, limit);
  return {s.value + offset.value, s.rate + offset.rate, s.acceleration + offset.acceleration};
}

// Writes every prescribed joint's coordinates of q and v (and of vdot, when not null) from the
// samples of every signal.
void write_prescribed(const model::Model& model, std::span<const model::SignalSample> samples,
                      VecX& q, VecX& v, VecX* vdot) {
  for (const model::Joint& j : model.joints()) {
    if (!j.is_prescribed()) continue;
    model::prescribed_joint_motion(j, samples, q.data() + j.q_index, v.data() + j.v_index,
                                   vdot != nullptr ? vdot->data() + j.v_index : nullptr);
  }
}

}  // namespace

void check_simulable(const model::Model& model) {
  // Forward dynamics needs an invertible mass matrix: say which coordinate has no inertia now,
  // rather than return NaN accelerations later. (The constraint solver factors the same matrix's
  // free block, which is positive definite when this passes.)
  dynamics::check_mass_matrix(model, model.initial_q());
}

MultibodySystem::MultibodySystem(const model::Model& model)
    : model_(model),
      data_(model),
      q_(model.initial_q()),
      v_(model.initial_v()),
      tau_elements_(VecX::Zero(model.nv())),
      constraint_tau_(VecX::Zero(model.nv())),
      vdot_prescribed_(VecX::Zero(model.nv())),
      residual_(VecX::Zero(model.nv())),
      f_ext_(model.num_bodies(), Vec6::Zero()),
      samples_(model.signals().size(), model::SignalSample{0.0, 0.0, 0.0}),
      signal_values_(model.signals().size(), 0.0),
      offsets_(model.signals().size(), model::SignalSample{0.0, 0.0, 0.0}),
      driven_(model.signals().size(), 0),
      driven_values_(model.signals().size(), 0.0),
      commanded_q_(model.signals().size(), -1),
      commanded_v_(model.signals().size(), -1),
      applied_samples_(model.signals().size(), model::SignalSample{0.0, 0.0, 0.0}),
      singular_q_(VecX::Zero(model.nq())),
      singular_v_(VecX::Zero(model.nv())),
      probe_q_(VecX::Zero(model.nq())),
      probe_v_(VecX::Zero(model.nv())),
      vdot_mean_(VecX::Zero(model.nv())),
      lambda_mean_(VecX::Zero(0)),
      held_(model.num_joints(), 0),
      held_value_(model.num_joints(), 0.0),
      hybrid_mask_(dynamics::prescribed_joint_mask(model)) {
  check_simulable(model);
  for (std::size_t s = 0; s < driven_.size(); ++s) {
    driven_[s] = model.is_driven(static_cast<int>(s));
    const auto coordinate = model.prescribed_coordinate(static_cast<int>(s));
    if (!driven_[s] || !coordinate) continue;
    commanded_q_[s] = coordinate->q;
    commanded_v_[s] = coordinate->v;
  }
  // A stop with e < 1 takes energy at each impact (one that holds its joint does no work).
  bool inelastic_stops = false;
  for (const model::Joint& j : model.joints()) {
    if (j.limits && j.limits->restitution < 1.0) inelastic_stops = true;
  }
  for (const model::Constraint& c : model.constraints()) {
    const auto* contact = std::get_if<model::Contact>(&c);
    if (contact && (contact->restitution < 1.0 || contact->kinetic_friction > 0.0))
      inelastic_stops = true;
  }
  conserves_energy_ = !model.has_prescribed_joints() && !inelastic_stops &&
                      dynamics::force_elements_conservative(model);
  // Angular momentum about the centre of mass: besides conserving energy, no body may be held
  // by the world — every joint on the world free, no spring attached to the world. Uniform
  // gravity acts at the centre of mass and exerts no moment about it.
  bool floating = true;
  for (const model::Joint& j : model.joints()) {
    if (j.parent_index == 0 && j.type != model::JointType::free) floating = false;
  }
  for (const model::ForceElement& element : model.force_elements()) {
    if (const auto* s = std::get_if<model::LinearSpringDamper>(&element)) {
      if (s->a.body_index == 0 || s->b.body_index == 0) floating = false;
    } else if (const auto* t = std::get_if<model::TorsionalSpringDamper>(&element)) {
      if (t->joint_index < 0 && (t->body_a_index == 0 || t->body_b_index == 0)) floating = false;
    }
  }
  // Ideal constraints do no work; those on the world (rolling, knife edges, loops to the
  // ground) exert external moments.
  for (const model::Constraint& c : model.constraints()) {
    if (std::holds_alternative<model::RollingContact>(c) ||
        std::holds_alternative<model::KnifeEdge>(c) || std::holds_alternative<model::Contact>(c)) {
      floating = false;
    } else if (const auto* loop = std::get_if<model::LoopClosure>(&c)) {
      if (loop->a.body_index == 0 || loop->b.body_index == 0) floating = false;
    } else if (const auto* link = std::get_if<model::DistanceLink>(&c)) {
      if (link->a.body_index == 0 || link->b.body_index == 0) floating = false;
    }
  }
  // A rotor's reflected inertia (armature) adds to its coordinate's inertia with no angular
  // momentum of its own in the bodies' H: H is not what is conserved then.
  bool armature = false;
  for (const model::Joint& j : model.joints()) armature = armature || j.armature != 0.0;
  conserves_angular_momentum_ = conserves_energy_ && floating && !armature;
  if (model.has_constraints()) {
    constraints_ = std::make_unique<ConstraintSolver>(model);
    lambda_mean_ = VecX::Zero(constraints_->multipliers().size());
  }
  for (const model::ForceElement& element : model.force_elements()) {
    const auto* t = std::get_if<model::TorsionalSpringDamper>(&element);
    const bool on_joint = std::holds_alternative<model::JointFriction>(element) ||
                          std::holds_alternative<model::FixedTendon>(element) ||
                          (t != nullptr && t->joint_index >= 0);
    if (!on_joint) body_loads_ = true;
  }
}

int MultibodySystem::nq() const { return model_.nq(); }
int MultibodySystem::nv() const { return model_.nv(); }

namespace {

// A slip slower than this (m/s) gives no direction of its own: the friction keeps its reference.
constexpr double kSlipDirectionSpeed = 1e-12;

// Below this 1 − ∂N/∂N through friction (det of I − R), sliding has no single normal force.
constexpr double kPainleve = 1e-9;

}  // namespace

const VecX& MultibodySystem::compute(double t, const VecX& q, const VecX& v, model::Limit limit) {
  if (sliding_.empty()) return solve(t, q, v, limit);
  // N = N₀ + R N (R_ij: contact i's normal force per newton of contact j's normal force, through
  // j's friction), so (I − R) N = N₀: a solve without friction gives N₀, more solves R, and the
  // last solve applies the friction at N.
  const int m = static_cast<int>(sliding_.size());
  for (SlidingContact& s : sliding_) {
    s.normal = 0.0;
    s.directed = false;
  }
  solve(t, q, v, limit);
  for (int i = 0; i < m; ++i)
    sliding_base_[i] = constraints_->multipliers()[sliding_[i].normal_row];
  if (const int j = lone_starting_slip(); j >= 0) {
    respond_with_starting_slip(j, t, q, v, limit);
  } else {
    respond_to_unit_normals(t, q, v, limit);
  }
  sliding_lu_.compute(sliding_response_);
  const double determinant = sliding_lu_.determinant();
  if (!(determinant > kPainleve)) {
    const auto& c = std::get<model::Contact>(model_.constraints()[sliding_[0].constraint]);
    throw integrate::UndefinedAcceleration(fmt::format(
        "contact '{}' at t = {:.12g} s: sliding with kinetic friction μk = {} has no single "
        "normal force (Painlevé's paradox: the friction presses the body into the plane as fast "
        "as the normal force lifts it, det(I − ∂N/∂N) = {:.3g}); momenta does not resolve it. "
        "Lower the friction coefficient",
        c.name, t, sliding_[0].mu, determinant));
  }
  // N, into the trial workspace (free again here): solved in place over N₀, the LU's row
  // permutation would be applied in place, which allocates a mask.
  trial_normals_ = sliding_lu_.solve(sliding_base_);
  for (int i = 0; i < m; ++i) sliding_[i].normal = trial_normals_[i];
  solve(t, q, v, limit);
  // The friction reported by the tangent rows, which are off (data_ holds the poses).
  for (const SlidingContact& s : sliding_) {
    const Vec3 friction = -s.mu * s.normal * s.slip_W;
    constraints_->report_off_row_force(s.normal_row + 1, friction.dot(s.tangent_1_W));
    constraints_->report_off_row_force(s.normal_row + 2, friction.dot(s.tangent_2_W));
  }
  return data_.vdot;
}

void MultibodySystem::respond_to_unit_normals(double t, const VecX& q, const VecX& v,
                                              model::Limit limit) {
  const int m = static_cast<int>(sliding_.size());
  for (int j = 0; j < m; ++j) {
    sliding_[j].normal = 1.0;
    solve(t, q, v, limit);
    sliding_[j].normal = 0.0;
    for (int i = 0; i < m; ++i) {
      const double response =
          constraints_->multipliers()[sliding_[i].normal_row] - sliding_base_[i];
      sliding_response_(i, j) = (i == j ? 1.0 : 0.0) - response;
    }
  }
}

int MultibodySystem::lone_starting_slip() const {
  int starting = -1;
  for (int j = 0; j < static_cast<int>(sliding_.size()); ++j) {
    if (sliding_[j].slip_velocity_W.norm() > kStartingSlip) continue;
    if (starting >= 0 || !sliding_[j].starting) return -1;  // several slow, or one stopping
    starting = j;
  }
  return starting;
}

void MultibodySystem::respond_with_starting_slip(int starting, double t, const VecX& q,
                                                 const VecX& v, model::Limit limit) {
  const int m = static_cast<int>(sliding_.size());
  // The slips' accelerations without friction, and each contact's direction as it slides now
  // (against its slip, or its reference), in its tangent basis.
  slip_accelerations(slip_rate_base_);
  for (int j = 0; j < m; ++j) {
    const SlidingContact& s = sliding_[j];
    slip_directions_.segment<2>(2 * j) << s.slip_W.dot(s.tangent_1_W), s.slip_W.dot(s.tangent_2_W);
  }
  // A unit force along each tangent of each contact in turn: the normal forces' and the slips'
  // accelerations' responses, linear in the forces (every sliding contact's N held at 0).
  for (int j = 0; j < m; ++j) {
    SlidingContact& s = sliding_[j];
    const Vec3 slip_W = s.slip_W;
    for (int axis = 0; axis < 2; ++axis) {
      s.directed = true;
      s.slip_W = -(axis == 0 ? s.tangent_1_W : s.tangent_2_W);  // −μk N ŝ = the tangent
      s.normal = 1.0 / s.mu;
      solve(t, q, v, limit);
      const int column = 2 * j + axis;
      for (int i = 0; i < m; ++i) {
        slip_normals_(i, column) =
            constraints_->multipliers()[sliding_[i].normal_row] - sliding_base_[i];
      }
      slip_accelerations(slip_rate_trial_);
      slip_rates_.col(column) = slip_rate_trial_ - slip_rate_base_;
    }
    s.normal = 0.0;
    s.directed = false;
    s.slip_W = slip_W;
  }
  // The starting slip takes its stable direction, the others' held.
  SlidingContact& s = sliding_[starting];
  const auto acceleration_of = [&](const Vec2& d) -> std::optional<Vec2> {
    slip_directions_.segment<2>(2 * starting) = d;
    response_for(slip_directions_, trial_response_);
    trial_lu_.compute(trial_response_);
    if (!(trial_lu_.determinant() > kPainleve)) return std::nullopt;
    trial_normals_ = trial_lu_.solve(sliding_base_);
    Vec2 a = slip_rate_base_.segment<2>(2 * starting);
    for (int k = 0; k < m; ++k) {
      const Vec2 force = -sliding_[k].mu * trial_normals_[k] * slip_directions_.segment<2>(2 * k);
      a += slip_rates_.block<2, 2>(2 * starting, 2 * k) * force;
    }
    return a;
  };
  const Vec2 current = slip_directions_.segment<2>(2 * starting);
  const Vec2 projected(s.reference_W.dot(s.tangent_1_W), s.reference_W.dot(s.tangent_2_W));
  const Vec2 reference = projected.norm() > 0.5 ? Vec2(projected.normalized()) : current;
  const std::optional<Vec2> stable = detail::stable_slip_direction(reference, acceleration_of);
  const Vec3 along =
      stable ? Vec3(stable->x() * s.tangent_1_W + stable->y() * s.tangent_2_W) : Vec3::Zero();
  // Taken where the slip has no direction of its own or runs within 90° of it.
  const double speed = s.slip_velocity_W.norm();
  if (stable && (!(speed > kSlipDirectionSpeed) || s.slip_velocity_W.dot(along) > 0.0)) {
    slip_directions_.segment<2>(2 * starting) = *stable;
    s.slip_W = along;
    s.directed = true;
  } else {
    slip_directions_.segment<2>(2 * starting) = current;
  }
  response_for(slip_directions_, sliding_response_);
}

void MultibodySystem::slip_accelerations(VecX& rates) {
  dynamics::forward_kinematics(model_, data_, q_, v_, data_.vdot);
  for (std::size_t j = 0; j < sliding_.size(); ++j) {
    const auto& c = std::get<model::Contact>(model_.constraints()[sliding_[j].constraint]);
    rates.segment<2>(2 * static_cast<int>(j)) = dynamics::contact_slip_acceleration(c, data_);
  }
}

void MultibodySystem::response_for(const VecX& directions, MatX& response) const {
  // Column k: −∂N/∂N_k = −(∂N/∂f_k)(−μk d_k), f_k = −μk N_k d_k contact k's friction.
  const int m = static_cast<int>(sliding_.size());
  for (int k = 0; k < m; ++k) {
    const Vec2 scaled = sliding_[k].mu * directions.segment<2>(2 * k);
    response.col(k).noalias() = slip_normals_.middleCols<2>(2 * k) * scaled;
    response(k, k) += 1.0;
  }
}

const VecX& MultibodySystem::solve(double t, const VecX& q, const VecX& v, model::Limit limit) {
  // Every row off (a model whose only constraints are open contacts): the free dynamics.
  const bool constrained = constraints_ && constraints_->rows_on() > 0;
  free_dynamics(t, q, v, limit, constrained && constraints_->finishes_forward_dynamics());
  if (constrained) {
    if (!constraints_->correct_accelerations(data_, q_, data_.vdot)) {
      accelerations_at_singular_configuration(t, limit);
    }
    constraint_tau_.setZero();
    constraints_->add_forces(data_, f_ext_, constraint_tau_);
    // The drives of prescribed joints, and the stops that hold joints, also carry the constraint
    // forces: the whole generalized force the motion needs (couplers' included).
    if (model_.has_prescribed_joints() || holding_ > 0) {
      dynamics::rnea(model_, data_, q_, v_, data_.vdot, f_ext_);
    } else {
      data_.tau += constraint_tau_;
    }
  }
  return data_.vdot;
}

std::span<const Vec6> MultibodySystem::apply_loads(double t, const VecX& q, const VecX& v,
                                                   model::Limit limit) {
  // Every signal once at t (offsets added), from the side `limit` says at a breakpoint.
  const auto& signals = model_.signals();
  for (std::size_t i = 0; i < signals.size(); ++i) {
    if (commanded_q_[i] >= 0) {
      samples_[i] = {q[commanded_q_[i]] + offsets_[i].value, v[commanded_v_[i]] + offsets_[i].rate,
                     driven_values_[i] + offsets_[i].acceleration};
    } else if (driven_[i]) {
      samples_[i] = {driven_values_[i] + offsets_[i].value, 0.0, 0.0};
    } else {
      samples_[i] = offset_sample(signals[i], offsets_[i], t, limit);
    }
    signal_values_[i] = samples_[i].value;
  }

  // The state with the prescribed coordinates taken from their signals; their accelerations too.
  q_ = q;
  v_ = v;
  if (model_.has_prescribed_joints()) {
    write_prescribed(model_, samples_, q_, v_, &vdot_prescribed_);
  }
  if (holding_ > 0) {
    for (const model::Joint& j : model_.joints()) {
      if (!held_[j.index]) continue;
      q_[j.q_index] = held_value_[j.index];
      v_[j.v_index] = 0.0;
      vdot_prescribed_[j.v_index] = 0.0;
    }
  }

  // The force elements. Those on bodies read the poses and velocities of forward kinematics;
  // without any, only joint-space elements remain (they read q and v alone), kinematics is left
  // to the dynamics algorithm, and the zero wrenches are not passed on.
  const bool loads = body_loads_ || !sliding_.empty();
  if (loads) dynamics::forward_kinematics(model_, data_, q_, v_);
  dynamics::force_element_forces(model_, data_, signal_values_, q_, v_, tau_elements_, f_ext_);
  add_sliding_friction();
  return loads ? std::span<const Vec6>(f_ext_) : std::span<const Vec6>();
}

void MultibodySystem::free_dynamics(double t, const VecX& q, const VecX& v, model::Limit limit,
                                    bool factors_only) {
  const std::span<const Vec6> f_ext = apply_loads(t, q, v, limit);
  const bool prescribed = model_.has_prescribed_joints() || holding_ > 0;

  // Forward dynamics; hybrid where joints are prescribed (it also fills data_.tau with the
  // generalized forces the prescription needs).
  if (prescribed) {
    dynamics::hybrid_dynamics(model_, data_, hybrid_mask_, q_, v_, vdot_prescribed_, tau_elements_,
                              f_ext);
  } else {
    dynamics::aba_articulate(model_, data_, q_, v_, tau_elements_, f_ext);
    if (!factors_only) dynamics::aba_accelerate(model_, data_);
    data_.tau = tau_elements_;
  }
}

void MultibodySystem::add_sliding_friction() {
  for (SlidingContact& s : sliding_) {
    const auto& c = std::get<model::Contact>(model_.constraints()[s.constraint]);
    const dynamics::ContactGeometry g = dynamics::contact_geometry(c, data_);
    Vec3 slip = dynamics::contact_point_velocity(c, data_, g.point_W);
    slip -= g.normal_W * g.normal_W.dot(slip);
    s.slip_velocity_W = slip;
    s.tangent_1_W = g.tangent_1_W;
    s.tangent_2_W = g.tangent_2_W;
    const double speed = slip.norm();
    if (!s.directed) {
      s.slip_W = speed > kSlipDirectionSpeed && slip.dot(s.reference_W) > 0.0 ? Vec3(slip / speed)
                                                                              : s.reference_W;
    }
    const Vec3 force = -s.mu * s.normal * s.slip_W;
    Vec6 wrench;  // in W about Wo
    wrench << g.point_W.cross(force), force;
    f_ext_[c.frame.body_index] += data_.X_WB[c.frame.body_index].act_force_inverse(wrench);
    if (c.other.body_index != 0)
      f_ext_[c.other.body_index] -= data_.X_WB[c.other.body_index].act_force_inverse(wrench);
  }
}

void MultibodySystem::accelerations_at_singular_configuration(double t, model::Limit limit) {
  const double speed = v_.cwiseAbs().maxCoeff();
  // A probe's state singular again names the singular state's time, not the probe's.
  if (probing_) throw constraints_->singular_configuration_error(singular_t_);
  if (!(speed > 0.0)) throw constraints_->singular_configuration_error(t);
  singular_t_ = t;
  singular_q_ = q_;
  singular_v_ = v_;
  vdot_mean_.setZero();
  lambda_mean_.setZero();
  const double tau = 1e-4 / speed;
  // Probing, a state that is singular again cannot be passed (the flag is cleared however the
  // probes end).
  struct Probing {
    bool& flag;
    explicit Probing(bool& f) : flag(f) { flag = true; }
    ~Probing() { flag = false; }
  } probing(probing_);
  for (const double side : {1.0, -1.0}) {
    model::integrate(model_, singular_q_, singular_v_, side * tau, probe_q_);
    probe_v_ = singular_v_;
    constraints_->project(t + side * tau, data_, probe_q_, probe_v_);
    compute(t + side * tau, probe_q_, probe_v_, limit);
    vdot_mean_ += 0.5 * data_.vdot;
    lambda_mean_ += 0.5 * constraints_->multipliers();
  }
  // Back at the singular state: its free dynamics, the mean accelerations and multipliers.
  free_dynamics(t, singular_q_, singular_v_, limit);
  data_.vdot = vdot_mean_;
  constraints_->set_multipliers(data_, q_, lambda_mean_);
}

bool MultibodySystem::project(double t, VecX& q, VecX& v) {
  if (!constraints_ || constraints_->rows_on() == 0) return false;
  apply_prescribed_motion(t, q, v);
  return constraints_->project(t, data_, q, v);
}

ConsistentState MultibodySystem::make_consistent(double t, VecX& q, VecX& v) {
  if (!constraints_) return {};
  apply_prescribed_motion(t, q, v);
  std::vector<char> q_given(model_.num_joints()), v_given(model_.num_joints());
  for (const model::Joint& j : model_.joints()) {
    q_given[j.index] = j.q0.size() > 0 || j.is_prescribed();
    v_given[j.index] = j.v0.size() > 0 || j.is_prescribed();
  }
  return constraints_->consistent_state(data_, q, v, q_given, v_given);
}

const VecX& MultibodySystem::evaluate(double t, const VecX& q, const VecX& v) {
  compute(t, q, v, model::Limit::right);
  dynamics::forward_kinematics(model_, data_, q_, v_, data_.vdot);
  return data_.vdot;
}

const VecX& MultibodySystem::residual(double t, const VecX& q, const VecX& v, const VecX& vdot) {
  if (constraints_) {
    throw InvalidArgument(
        "the unbalanced generalized force of a model with constraints: their forces are not "
        "known without its accelerations");
  }
  const std::span<const Vec6> f_ext = apply_loads(t, q, v, limit_at(t));
  residual_ = vdot;
  for (int i = 0; i < model_.nv(); ++i) {
    if (hybrid_mask_[static_cast<std::size_t>(model_.joint_of_v(i))]) {
      residual_[i] = vdot_prescribed_[i];
    }
  }
  residual_ = dynamics::rnea(model_, data_, q_, v_, residual_, f_ext);
  residual_ -= tau_elements_;
  for (int i = 0; i < model_.nv(); ++i) {
    if (hybrid_mask_[static_cast<std::size_t>(model_.joint_of_v(i))]) residual_[i] = 0.0;
  }
  return residual_;
}

void MultibodySystem::acceleration(double t, const VecX& q, const VecX& v, VecX& vdot) {
  // At the end of the announced step the inputs are taken from the left: the step integrated
  // them over the interval that ends there (see begin_step).
  vdot = compute(t, q, v, limit_at(t));
}

double MultibodySystem::next_discontinuity(double t) const {
  double next = std::numeric_limits<double>::infinity();
  for (std::size_t s = 0; s < driven_.size(); ++s) {
    if (!driven_[s]) next = std::min(next, model_.signals()[s].next_breakpoint(t));
  }
  return next;
}

void MultibodySystem::begin_step(double t0, double t1) {
  (void)t0;
  step_end_ = t1;
}

void MultibodySystem::integrate(const VecX& q, const VecX& dq, VecX& q_out) const {
  model::integrate(model_, q, dq, 1.0, q_out);
}

void MultibodySystem::difference(const VecX& q0, const VecX& q1, VecX& dq) const {
  model::difference(model_, q0, q1, dq);
}

void MultibodySystem::local_coordinate_rate(const VecX& delta, const VecX& v,
                                            VecX& delta_rate) const {
  model::local_coordinate_rate(model_, delta, v, delta_rate);
}

void MultibodySystem::configuration_scale(const VecX& q, VecX& scale) const {
  // |q_i| on vector-space coordinates; 1 rad on the rotation coordinates of ball and free joints
  // (their tangent coordinates have no configuration value of their own).
  scale.resize(model_.nv());
  for (const model::Joint& j : model_.joints()) {
    switch (j.type) {
      case model::JointType::spherical:
        scale.segment<3>(j.v_index).setOnes();
        break;
      case model::JointType::free:
        scale.segment<3>(j.v_index).setOnes();
        scale.segment<3>(j.v_index + 3) = q.segment<3>(j.q_index).cwiseAbs();
        break;
      case model::JointType::fixed:
      case model::JointType::revolute:
      case model::JointType::prismatic:
      case model::JointType::cylindrical:
      case model::JointType::universal:
      case model::JointType::planar:
        scale.segment(j.v_index, j.nv()) = q.segment(j.q_index, j.nq()).cwiseAbs();
        break;
    }
  }
}

std::string MultibodySystem::coordinate_name(int i, bool velocity) const {
  return velocity ? model_.v_name(i) : model_.q_name(i);
}

void MultibodySystem::apply_prescribed_motion(double t, VecX& q, VecX& v) const {
  if (!model_.has_prescribed_joints()) return;
  const auto& signals = model_.signals();
  for (std::size_t i = 0; i < signals.size(); ++i) {
    applied_samples_[i] = commanded_q_[i] >= 0
                              ? model::SignalSample{q[commanded_q_[i]], v[commanded_v_[i]], 0.0}
                              : offset_sample(signals[i], offsets_[i], t);
  }
  write_prescribed(model_, applied_samples_, q, v, nullptr);
}

void MultibodySystem::hold(int j, double value) {
  const model::Joint& joint = model_.joints()[static_cast<std::size_t>(j)];
  assert(joint.nv() == 1 && !joint.is_prescribed());
  if (!held_[j]) ++holding_;
  held_[j] = 1;
  held_value_[j] = value;
  hybrid_mask_[j] = 1;
  if (constraints_) {
    q_[joint.q_index] = value;
    constraints_->hold_joints(data_, q_, hybrid_mask_);
  }
}

void MultibodySystem::release(int j) {
  if (held_[j]) --holding_;
  held_[j] = 0;
  hybrid_mask_[j] = model_.joints()[static_cast<std::size_t>(j)].is_prescribed() ? 1 : 0;
  if (constraints_) constraints_->hold_joints(data_, q_, hybrid_mask_);
}

void MultibodySystem::hold_contact(int k, VecRef q, ContactHold how, const Vec3& slip_W) {
  const auto& c = std::get<model::Contact>(model_.constraints()[static_cast<std::size_t>(k)]);
  const int first = constraints_->rows().first_row[static_cast<std::size_t>(k)];
  const int tangents = model::constraint_rows(c) - 1;
  std::erase_if(sliding_, [k](const SlidingContact& s) { return s.constraint == k; });
  if (how == ContactHold::sliding && c.kinetic_friction > 0.0) {
    SlidingContact s;
    s.constraint = k;
    s.normal_row = first;
    s.mu = c.kinetic_friction;
    sliding_.push_back(s);
    set_slip_reference(k, slip_W);
  }
  const int m = static_cast<int>(sliding_.size());
  sliding_base_.resize(m);
  sliding_response_.resize(m, m);
  sliding_lu_ = Eigen::PartialPivLU<MatX>(m);
  slip_normals_.resize(m, 2 * m);
  slip_rates_.resize(2 * m, 2 * m);
  slip_rate_base_.resize(2 * m);
  slip_rate_trial_.resize(2 * m);
  slip_directions_.resize(2 * m);
  trial_response_.resize(m, m);
  trial_lu_ = Eigen::PartialPivLU<MatX>(m);
  trial_normals_.resize(m);
  constraints_->enable_rows(data_, q, first, 1, how != ContactHold::open);
  if (tangents > 0)
    constraints_->enable_rows(data_, q, first + 1, tangents, how == ContactHold::sticking);
}

void MultibodySystem::end_slip_start(int k) {
  for (SlidingContact& s : sliding_) {
    if (s.constraint == k) s.starting = false;
  }
}

void MultibodySystem::set_slip_reference(int k, const Vec3& slip_W) {
  const double length = slip_W.norm();
  if (!(length > 0.0)) return;  // no direction: the last one stands
  for (SlidingContact& s : sliding_) {
    if (s.constraint == k) s.reference_W = slip_W / length;
  }
}

double MultibodySystem::contact_force(int k) const {
  return constraints_->multipliers()[constraints_->rows().first_row[static_cast<std::size_t>(k)]];
}

Vec3 MultibodySystem::contact_friction(int k) const {
  for (const SlidingContact& s : sliding_) {
    if (s.constraint == k) return -s.mu * s.normal * s.slip_W;
  }
  return Vec3::Zero();
}

double MultibodySystem::stop_force(int j) const {
  const int v = model_.joints()[static_cast<std::size_t>(j)].v_index;
  return data_.tau[v] - tau_elements_[v] - constraint_tau_[v];
}

void MultibodySystem::drive_signal(int s) {
  if (s < 0 || s >= static_cast<int>(driven_.size()))
    throw InvalidArgument(fmt::format("no signal #{}; the model has {}", s, driven_.size()));
  if (const auto j = model_.joint_prescribed_by(s)) {
    throw InvalidArgument(fmt::format(
        "input '{}' prescribes joint '{}': its motion is the signal's, with rates; it cannot be "
        "set as a value",
        model_.signals()[static_cast<std::size_t>(s)].name(),
        model_.joints()[static_cast<std::size_t>(*j)].name));
  }
  driven_[static_cast<std::size_t>(s)] = 1;
}

void MultibodySystem::set_signal_offsets(std::span<const double> value,
                                         std::span<const double> rate,
                                         std::span<const double> acceleration) {
  const std::size_t n = model_.signals().size();
  if (value.size() != n || rate.size() != n || acceleration.size() != n) {
    throw InvalidArgument(fmt::format(
        "set_signal_offsets: {} value, {} rate and {} acceleration offsets; the model has {} "
        "signals (one of each per signal)",
        value.size(), rate.size(), acceleration.size(), n));
  }
  for (std::size_t i = 0; i < n; ++i) offsets_[i] = {value[i], rate[i], acceleration[i]};
}

Energy MultibodySystem::energy(const VecX& q, const VecX& v) {
  dynamics::forward_kinematics(model_, data_, q, v);
  Energy e;
  e.kinetic = dynamics::kinetic_energy(model_, static_cast<const dynamics::Data&>(data_), v);
  e.potential_gravity =
      dynamics::potential_energy(model_, static_cast<const dynamics::Data&>(data_));
  e.potential_springs = dynamics::spring_potential_energy(model_, data_, q);
  return e;
}

}  // namespace momenta::system
