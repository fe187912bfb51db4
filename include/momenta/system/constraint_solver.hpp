#pragma once
// Enforces a model's constraints (model/constraint.hpp, rows from dynamics/constraints.hpp) on
// its motion: the constrained accelerations and the multipliers (the constraint forces), the
// projection of a state back onto the constraints after each step, and consistent initial
// states.
//
// Accelerations (Lagrange multipliers on the joint-space equations). With M the mass matrix of
// the free (not prescribed) coordinates, v̇₀ the unconstrained accelerations (ABA or hybrid
// dynamics), G the rows' Jacobian and k their velocity-product term:
//
//     M v̇ = τ − h + Gᵀλ,  G v̇ + k = 0   ⇒   (G M⁻¹ Gᵀ) λ = −k − G v̇₀,   v̇ = v̇₀ + M⁻¹ Gᵀ λ,
//
// inside the forward dynamics' articulated-body algorithm (M never formed; docs/constraints.md):
// without prescribed joints ABA's first two passes, then one leaves-to-root pass of 6-vectors per
// row that exerts a force — L Gᵀ with M⁻¹ = Lᵀ D⁻¹ L, and G v̇₀ by the adjoint of ABA's third
// pass (dynamics/articulated_solve.hpp's articulated_row_factors) — and ABA's third pass once,
// with the row forces Gᵀλ; with prescribed joints hybrid_dynamics, then M⁻¹ Gᵀ by a pair of
// passes per row (articulated_solve). O(n m) either way. G M⁻¹ Gᵀ is factorized by a Cholesky
// factorization in row order that skips rows depending on earlier ones (they carry no force:
// λ = 0; dependent rows are redundant and name themselves, see redundant_rows()). The
// former method — M by CRBA and its dense Cholesky factor, O(n³) — stays selectable
// (AccelerationMethod::dense) as the independent check; the two agree to round-off.
//
// Projection (Hairer, Lubich & Wanner, Geometric Numerical Integration, §IV.4; Ascher et al.
// 1995), after every step: positions by Newton's method on φ(q) = 0 with the step of least
// kinetic metric, q ← q ⊕ −M⁻¹Gᵀ(G M⁻¹ Gᵀ)⁻¹ φ over the holonomic rows, until |φ| stops
// decreasing or is below 1e-14 (m or rad); then velocities onto G v = 0 by the same M-orthogonal
// projection, which removes the kinetic energy of the violation only. M is that of the state the
// projection starts from, kept through the iterations; M⁻¹ Gᵀ by the same method as the
// accelerations (the articulated-body factors of aba at that state, or M's Cholesky factor). The
// residuals stay at round-off; no Baumgarte terms, nothing to tune.

#include <cassert>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/constraints.hpp"
#include "momenta/dynamics/data.hpp"

namespace momenta::system {

namespace detail {
class OrderedCholesky;
}

/// A coordinate that consistent_state() changed.
struct CoordinateChange {
  std::string name;  ///< model::Model::q_name or v_name
  double from = 0.0;
  double to = 0.0;
};

/// What consistent_state() did.
struct ConsistentState {
  std::vector<CoordinateChange> q_changes;  ///< configuration coordinates moved (tangent ones
                                            ///< for quaternions: named by v_name, from 0)
  std::vector<CoordinateChange> v_changes;
  int newton_iterations = 0;
  /// A singular initial configuration (links aligned at a dead point or a bifurcation): the
  /// rows that are dependent on the others there but not at assembled configurations nearby,
  /// and the rank of the rows there and nearby. Empty, 0 and 0 where it is regular.
  std::vector<std::string> singular_rows;
  int rank_at_start = 0;
  int rank_nearby = 0;
};

/// The largest constraint residuals of a state: |φ| over position rows (m or rad) and |G v|
/// over every row (m/s or rad/s).
struct ConstraintResiduals {
  double position = 0.0;
  double velocity = 0.0;
};

/// How correct_accelerations forms M⁻¹ Gᵀ.
enum class AccelerationMethod {
  articulated,  ///< by the articulated-body factors of aba / hybrid_dynamics: O(n m) (default)
  dense,        ///< by CRBA and a dense Cholesky factor of M: O(n³); the check
};

class ConstraintSolver {
 public:
  /// Sizes every workspace for `model` (which must outlive the solver) and finds the rows that
  /// are redundant at its initial configuration.
  explicit ConstraintSolver(const model::Model& model);
  ~ConstraintSolver();
  ConstraintSolver(const ConstraintSolver&) = delete;
  ConstraintSolver& operator=(const ConstraintSolver&) = delete;

  /// The rows of the last evaluation and their multipliers λ (one per row; 0 on a redundant
  /// row): the force along a translation row's axis on body b (N), the moment about a rotation
  /// row's axis (N·m), a coupler's generalized force on joint a.
  const dynamics::ConstraintRows& rows() const { return rows_; }
  const VecX& multipliers() const { return lambda_; }

  /// Names of the rows implied by earlier rows at the reference configuration (the model's
  /// initial one, or the last consistent_state()): redundant, they carry no force.
  const std::vector<std::string>& redundant_rows() const { return redundant_; }

  /// Switches rows [first, first + count) on or off — a unilateral contact's (model::Contact),
  /// which a run closes while the plane holds the body, slides or sticks, and opens where it
  /// lets go — and takes the rank of the rows then on at configuration q as the reference (and
  /// the redundant rows there). Overwrites data. Allocates nothing after the first call; forms M
  /// (an event's cost, not a step's).
  void enable_rows(dynamics::Data& data, VecRef q, int first, int count, bool on);
  /// Holds still the joints marked in `held` (num_joints() entries, 1 where the model prescribes
  /// the joint or a stop holds it: MultibodySystem's hybrid mask) — their coordinates are no
  /// longer free: the accelerations (the forward dynamics is then hybrid_dynamics with this
  /// mask), the projection and the consistent state leave them be — and takes the rank of the
  /// rows at configuration q as the reference again (a hold that locks a loop leaves its rows
  /// dependent: redundant). Overwrites data. Allocates (an event's cost, not a step's).
  void hold_joints(dynamics::Data& data, VecRef q, std::span<const char> held);
  /// The mask the solver holds (the model's prescribed joints until hold_joints).
  std::span<const char> held_joints() const { return held_; }

  /// Sets the multiplier of a row that is off: a force it reports without exerting it — a
  /// sliding contact's kinetic friction along its tangent rows, which MultibodySystem applies as
  /// a load — so that whoever reads multipliers() reads the friction. add_forces() adds nothing
  /// for it (an off row's wrench is zero). No allocation.
  void report_off_row_force(int row, double value) {
    assert(!rows_.enabled[static_cast<std::size_t>(row)]);
    lambda_[row] = value;
  }
  /// How many rows are on: 0 where the only constraints are open contacts, whose motion is then
  /// the free one (MultibodySystem skips the solver; λ is 0).
  int rows_on() const { return rows_on_; }

  /// Chooses how correct_accelerations forms M⁻¹ Gᵀ (AccelerationMethod::articulated unless
  /// set).
  void set_acceleration_method(AccelerationMethod method) { method_ = method; }

  /// Whether correct_accelerations finishes the forward dynamics itself: the articulated method
  /// with no joint prescribed or held (hold_joints), which needs only aba_articulate(q, v, …)
  /// before it (the constraint forces enter aba's one pass 3, dynamics/articulated_solve.hpp's
  /// articulated_row_factors). Otherwise the whole aba, or hybrid_dynamics, comes first.
  bool finishes_forward_dynamics() const {
    return method_ == AccelerationMethod::articulated && !holding_;
  }

  /// Sets vdot (size nv) to the constrained accelerations at (t, q, v), stores λ and returns
  /// true. `data` holds what aba(q, v, …) — or, where joints are prescribed or held,
  /// hybrid_dynamics(q, v, …) with held_joints() — left in it (kinematics, the bodies'
  /// accelerations and the articulated-body factors), and vdot is those accelerations (data.vdot,
  /// or a copy), corrected here with prescribed coordinates kept; except where
  /// finishes_forward_dynamics(), when aba_articulate's state is enough (a whole aba's does too),
  /// vdot is only written and data's accelerations become the constrained ones. The dense
  /// method's crba overwrites its mass matrix. Returns
  /// false, vdot and λ undetermined, at a singular configuration — fewer independent rows than
  /// at the reference (a four-bar at a dead point): the rows there do not fix the accelerations
  /// (MultibodySystem takes their limit along the motion). No allocation.
  bool correct_accelerations(dynamics::Data& data, VecRef q, VecX& vdot);

  /// The error for a singular configuration at time t that cannot be passed (the state at rest
  /// there, so no motion says which way): names the time, the first row that lost
  /// independence, the ranks, and what to do.
  NumericalError singular_configuration_error(double t) const;

  /// Takes `lambda` as the multipliers at configuration q (the rows are evaluated there): the
  /// limit of those of the states nearby, at a singular configuration. No allocation.
  void set_multipliers(dynamics::Data& data, VecRef q, const VecX& lambda);

  /// Adds the forces of the last multipliers to f_ext (body wrenches) and tau (couplers), see
  /// dynamics::add_constraint_forces. `data` must hold the poses of the same instant.
  void add_forces(const dynamics::Data& data, std::span<Vec6> f_ext, VecX& tau) const;

  /// Projects (q, v) onto the constraints (see the header comment); prescribed coordinates are
  /// not moved. Overwrites data (the articulated method leaves aba's, or hybrid_dynamics', results
  /// at (q, v) and zero forces there). Returns true when the state changed. Throws NumericalError
  /// naming the time t and the row with the largest residual when Newton's method does not bring
  /// |φ| below 1e-6 (the step left the constraints too far behind: a limit of the motion, or too
  /// large a step). No allocation.
  bool project(double t, dynamics::Data& data, VecX& q, VecX& v);

  /// The residuals of (q, v). Overwrites data's poses and velocities. No allocation.
  ConstraintResiduals residuals(dynamics::Data& data, VecRef q, VecRef v);

  /// Makes (q, v) satisfy the constraints, keeping the coordinates marked `given` (per joint,
  /// 1 where the user set q0 or v0; prescribed joints always) where the others can absorb the
  /// residual, moving every free coordinate least otherwise. Resets the reference rank to the
  /// consistent state's — or, where that state is singular (fewer independent rows than at an
  /// assembled configuration a small move along v away: ConsistentState::singular_rows), to
  /// the rank nearby, so that evaluations at the singular state are recognized as such. Throws
  /// InvalidArgument naming the row with the largest residual when no consistent state is near
  /// (Newton's method fails to converge in 50 iterations), or when rows conflict (a residual
  /// remains along dependent rows). Allocates.
  ConsistentState consistent_state(dynamics::Data& data, VecX& q, VecX& v,
                                   std::span<const char> q_given, std::span<const char> v_given);

 private:
  // free_ from held_ (and holding_), and the workspaces sized to them.
  void gather_free_coordinates();
  // Mass matrix of the free coordinates at data's configuration, factorized; G_f too.
  void factor_mass_matrix(dynamics::Data& data, VecRef q);
  void gather_free_columns();
  // (G_f M⁻¹ G_fᵀ) over the rows in `mask` (others zeroed), factorized in row order.
  void factor_rows(std::span<const char> mask);
  void find_redundant_rows(dynamics::Data& data, VecRef q);
  // A singular consistent state: compares the rank at (q, v) with that at an assembled
  // configuration a small move along v (or along every free coordinate, at rest) away, and
  // where it is higher there takes it (and the rows redundant there) as the reference.
  void check_singular_start(dynamics::Data& data, const VecX& q, const VecX& v,
                            ConsistentState& report);
  // dv_ = M⁻¹ G_fᵀ λ (the free coordinates' accelerations of row forces λ).
  void apply_row_forces(const VecX& lambda);
  // Y = M⁻¹ Gᵀ over the rows in `mask` (other columns zero) by articulated_solve on data's
  // factors, and A = G Y factorized in row order.
  void factor_rows_articulated(dynamics::Data& data, std::span<const char> mask);
  // correct_accelerations where finishes_forward_dynamics(): L Gᵀ, G M⁻¹ Gᵀ = (L Gᵀ)ᵀ D⁻¹ L Gᵀ
  // and G v̇₀ from the articulated-body factors, λ, then aba's pass 3 with the row forces.
  bool accelerations_with_row_forces(dynamics::Data& data, VecRef q, VecX& vdot);
  // The projection's metric M at (q, v) by the chosen method: its articulated-body factors in
  // `data` (aba, or hybrid_dynamics with the model's prescribed joints held, at zero forces), or
  // its Cholesky factor of the free coordinates.
  void factor_metric(dynamics::Data& data, VecRef q, VecRef v);
  // G M⁻¹ Gᵀ over the rows in `mask`, factorized, for the current rows and that metric.
  void factor_metric_rows(dynamics::Data& data, std::span<const char> mask);
  // dx ← M⁻¹ Gᵀ λ on the free coordinates, 0 on the prescribed ones.
  void metric_step(const VecX& lambda, VecX& dx);

  const model::Model& model_;
  dynamics::ConstraintRows rows_;
  std::vector<int> free_;   // velocity indices not held (see hold_joints)
  std::vector<char> held_;  // per joint: prescribed, or held by a stop
  bool holding_ = false;    // some joint is held
  std::vector<char> all_rows_, position_rows_;
  // The unilateral contacts' rows (their redundant forces shared by least norm), and the same
  // flags over the active rows of accelerations_with_row_forces.
  std::vector<char> contact_rows_, active_contact_rows_;
  bool has_contacts_ = false;
  MatX M_ff_, G_f_, W_, A_;  // W = L⁻¹ G_fᵀ with M_ff = L Lᵀ; A = Wᵀ W
  MatX Y_;                   // nv × rows: M⁻¹ Gᵀ (articulated; 0 on prescribed coordinates),
                             // or L Gᵀ where finishes_forward_dynamics()
  MatX Dinv_LGt_;            // nv × rows: D⁻¹ L Gᵀ, where finishes_forward_dynamics()
  std::vector<int> active_;  // there: the rows that exert a force (nonzero rows of G)
  AccelerationMethod method_ = AccelerationMethod::articulated;
  Eigen::LLT<MatX> llt_;
  VecX lambda_, rhs_, dv_, delta_, q_saved_, zero_, du_;
  VecX lambda_active_;  // accelerations_with_row_forces: λ over the active rows, in their order
  // The projection's iterates' kinematics and rows (articulated method), apart from the metric's
  // factors in the caller's Data.
  std::unique_ptr<dynamics::Data> iterate_data_;
  std::unique_ptr<detail::OrderedCholesky> cholesky_;
  int reference_rank_ = 0;
  int rows_on_ = 0;  // rows_.enabled's ones
  std::vector<std::string> redundant_;
};

}  // namespace momenta::system
