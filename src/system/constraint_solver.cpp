#include "momenta/system/constraint_solver.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/articulated_solve.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/hybrid_dynamics.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "ordered_cholesky.hpp"

namespace momenta::system {
namespace {

// A row whose remaining pivot in G M⁻¹ Gᵀ is below this fraction of its diagonal is taken as
// dependent on the rows before it: the squared sine of its angle to their span (round-off in
// an exactly redundant row is ~1e-16; a four-bar 1e-5 rad from its dead point is ~1e-10).
constexpr double kDependentRow = 1e-10;
// Newton on φ(q) = 0 stops below this residual (m or rad), or when the residual stops shrinking.
constexpr double kPositionTolerance = 1e-14;
constexpr int kProjectionIterations = 8;
constexpr double kProjectionFailure = 1e-6;

double max_abs_over(const VecX& x, std::span<const char> mask) {
  double m = 0.0;
  for (int i = 0; i < x.size(); ++i)
    if (mask[i]) m = std::max(m, std::abs(x[i]));
  return m;
}

}  // namespace

ConstraintSolver::ConstraintSolver(const model::Model& model)
    : model_(model),
      rows_(model),
      held_(dynamics::prescribed_joint_mask(model)),
      lambda_(VecX::Zero(rows_.count)),
      rhs_(VecX::Zero(rows_.count)),
      delta_(VecX::Zero(model.nv())),
      q_saved_(VecX::Zero(model.nq())),
      lambda_active_(VecX::Zero(rows_.count)),
      cholesky_(std::make_unique<detail::OrderedCholesky>(rows_.count)) {
  gather_free_coordinates();
  const int m = rows_.count;
  A_ = MatX::Zero(m, m);
  Y_ = MatX::Zero(model.nv(), m);
  Dinv_LGt_ = MatX::Zero(model.nv(), m);
  du_ = VecX::Zero(model.nv());
  active_.assign(m, 0);
  zero_ = VecX::Zero(model.nv());
  if (m > 0) iterate_data_ = std::make_unique<dynamics::Data>(model);
  all_rows_.assign(m, 1);
  // The contacts' rows: where they are redundant (a box's four corners on a plane) their forces
  // are the least-norm share (the other rows' redundancy keeps the ordered one: the later of two
  // dependent rows carries no force).
  contact_rows_.assign(m, 0);
  active_contact_rows_.assign(m, 0);
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    if (!model::is_unilateral(model.constraints()[k])) continue;
    has_contacts_ = true;
    const int first = rows_.first_row[k];
    const int count = model::constraint_rows(model.constraints()[k]);
    for (int r = first; r < first + count; ++r) contact_rows_[static_cast<std::size_t>(r)] = 1;
  }
  rows_on_ = static_cast<int>(std::count(rows_.enabled.begin(), rows_.enabled.end(), 1));
  position_rows_.assign(rows_.holonomic.begin(), rows_.holonomic.end());
  if (m > 0) {
    dynamics::Data data(model);
    VecX q = model.initial_q();
    model::normalize(model, q);
    find_redundant_rows(data, q);
  }
}

ConstraintSolver::~ConstraintSolver() = default;

void ConstraintSolver::gather_free_coordinates() {
  free_.clear();
  holding_ = false;
  for (const model::Joint& j : model_.joints()) {
    if (held_[static_cast<std::size_t>(j.index)]) {
      holding_ = true;
      continue;
    }
    for (int k = 0; k < j.nv(); ++k) free_.push_back(j.v_index + k);
  }
  const int nf = static_cast<int>(free_.size());
  const int m = rows_.count;
  M_ff_ = MatX::Zero(nf, nf);
  llt_.compute(MatX::Identity(nf, nf));  // sizes its storage (and its info)
  G_f_ = MatX::Zero(m, nf);
  W_ = MatX::Zero(nf, m);
  dv_ = VecX::Zero(nf);
}

void ConstraintSolver::hold_joints(dynamics::Data& data, VecRef q, std::span<const char> held) {
  assert(static_cast<int>(held.size()) == model_.num_joints());
  if (std::equal(held.begin(), held.end(), held_.begin())) return;
  held_.assign(held.begin(), held.end());
  gather_free_coordinates();
  if (rows_.count > 0) find_redundant_rows(data, q);
}

void ConstraintSolver::gather_free_columns() {
  const int nf = static_cast<int>(free_.size());
  for (int c = 0; c < nf; ++c) G_f_.col(c) = rows_.G.col(free_[c]);
}

void ConstraintSolver::factor_mass_matrix(dynamics::Data& data, VecRef q) {
  const MatX& M = dynamics::crba(model_, data, q);
  const int nf = static_cast<int>(free_.size());
  if (nf == model_.nv()) {
    M_ff_ = M;  // nothing prescribed: a straight copy into the sized workspace
  } else {
    for (int c = 0; c < nf; ++c)
      for (int r = 0; r < nf; ++r) M_ff_(r, c) = M(free_[r], free_[c]);
  }
  llt_.compute(M_ff_);
  if (llt_.info() != Eigen::Success) {
    throw NumericalError(
        "the constraint solver found the mass matrix of the free coordinates not positive "
        "definite: a massless body carries degrees of freedom");
  }
}

void ConstraintSolver::factor_rows(std::span<const char> mask) {
  // With M = L Lᵀ: W = L⁻¹ G_fᵀ over the rows in mask, A = G_f M⁻¹ G_fᵀ = Wᵀ W (one triangular
  // solve with the rows instead of two).
  W_ = G_f_.transpose();
  for (int i = 0; i < rows_.count; ++i)
    if (!mask[i]) W_.col(i).setZero();
  llt_.matrixL().solveInPlace(W_);
  A_.setZero();
  A_.selfadjointView<Eigen::Lower>().rankUpdate(W_.transpose());
  A_.triangularView<Eigen::StrictlyUpper>() = A_.transpose();
  for (int i = 0; i < rows_.count; ++i) {
    if (mask[i]) continue;
    A_.row(i).setZero();
    A_.col(i).setZero();
  }
  cholesky_->factorize(A_, kDependentRow);
}

void ConstraintSolver::apply_row_forces(const VecX& lambda) {
  // dv = M⁻¹ G_fᵀ λ = L⁻ᵀ (W λ).
  dv_.noalias() = W_ * lambda;
  llt_.matrixU().solveInPlace(dv_);
}

void ConstraintSolver::find_redundant_rows(dynamics::Data& data, VecRef q) {
  dynamics::forward_kinematics(model_, data, q);
  dynamics::constraint_equations(model_, data, q, rows_);
  gather_free_columns();
  factor_mass_matrix(data, q);
  factor_rows(all_rows_);
  // No more rows are independent than there are free coordinates: where nearly parallel rows
  // (two sticking corners of a box turned a little about the normal) leave round-off above the
  // factorization's tolerance, the count would say more, and every configuration near it would
  // look singular.
  reference_rank_ = std::min(cholesky_->rank(), static_cast<int>(free_.size()));
  redundant_.clear();
  for (int i = 0; i < rows_.count; ++i)
    if (cholesky_->dependent(i) && rows_.enabled[i]) redundant_.push_back(rows_.names[i]);
}

void ConstraintSolver::enable_rows(dynamics::Data& data, VecRef q, int first, int count, bool on) {
  bool changed = false;
  for (int row = first; row < first + count; ++row) {
    lambda_[row] = 0.0;
    if (rows_.enabled[row] == static_cast<char>(on)) continue;
    rows_.enabled[row] = on ? 1 : 0;
    rows_on_ += on ? 1 : -1;
    changed = true;
  }
  if (changed) find_redundant_rows(data, q);
}

bool ConstraintSolver::correct_accelerations(dynamics::Data& data, VecRef q, VecX& vdot) {
  if (finishes_forward_dynamics()) return accelerations_with_row_forces(data, q, vdot);
  // λ from (G M⁻¹ Gᵀ) λ = −(G v̇₀ + k) (the full G: prescribed accelerations enter too). The
  // articulated method reads G v̇₀ + k off the bodies' accelerations of the free dynamics just
  // computed (vdot is data.vdot there); the dense one, the check, forms k and G v̇₀ apart.
  if (method_ == AccelerationMethod::articulated) {
    dynamics::constraint_equations(model_, data, q, rows_,
                                   dynamics::RowTerms::with_acceleration_residual);
    factor_rows_articulated(data, all_rows_);
    rhs_.noalias() = -rows_.bias;
    rows_.bias.noalias() -= rows_.G.lazyProduct(vdot);  // k, for whoever reads the rows
  } else {
    dynamics::constraint_equations(model_, data, q, rows_,
                                   dynamics::RowTerms::with_velocity_products);
    gather_free_columns();
    factor_mass_matrix(data, q);
    factor_rows(all_rows_);
    rhs_.noalias() = -rows_.bias;
    rhs_.noalias() -= rows_.G * vdot;
  }
  if (cholesky_->rank() < reference_rank_) return false;
  cholesky_->solve_in_place(rhs_);
  if (has_contacts_) cholesky_->least_norm_in_place(rhs_, contact_rows_);
  lambda_ = rhs_;
  if (method_ == AccelerationMethod::articulated) {
    vdot.noalias() += Y_ * lambda_;
    return true;
  }
  apply_row_forces(lambda_);
  for (int c = 0; c < static_cast<int>(free_.size()); ++c) vdot[free_[c]] += dv_[c];
  return true;
}

bool ConstraintSolver::accelerations_with_row_forces(dynamics::Data& data, VecRef q, VecX& vdot) {
  // (G M⁻¹ Gᵀ) λ = −(G v̇₀ + k) with M⁻¹ = Lᵀ D⁻¹ L: G M⁻¹ Gᵀ = (L Gᵀ)ᵀ D⁻¹ (L Gᵀ), and G v̇₀ + k
  // as the rows' accelerations at v̇₀ (the adjoint of aba's pass 3) plus ẇ·(V_b − V_a); then
  // v̇ = v̇₀ + Lᵀ D⁻¹ (L Gᵀ λ) is pass 3 run once, with the row forces. A row that exerts no force
  // here (a zero row of G) has a zero row and column, which the ordered factorization would
  // skip: the system is formed over the others alone (`active` of them, in row order), λ = 0 on it.
  dynamics::constraint_equations(model_, data, q, rows_, dynamics::RowTerms::with_wrench_rates);
  // Only the active rows' columns of Y_ and Dinv_LGt_ are written.
  const int active =
      dynamics::articulated_row_factors(model_, data, rows_, Y_, Dinv_LGt_, rhs_, active_);
  rhs_ += rows_.bias;                         // G v̇₀ + k
  auto A = A_.topLeftCorner(active, active);  // lower triangle, over the active rows
  auto b = lambda_active_.head(active);
  for (int i = 0; i < active; ++i) {
    const int c = active_[i];
    for (int k = i; k < active; ++k) A(k, i) = Y_.col(active_[k]).dot(Dinv_LGt_.col(c));
    b[i] = rhs_[c];
  }
  cholesky_->factorize(A, kDependentRow, std::span<const int>(active_).first(active));
  if (cholesky_->rank() < reference_rank_) return false;
  rows_.bias = rhs_;
  cholesky_->solve_in_place(b);
  if (has_contacts_) {
    for (int i = 0; i < active; ++i) active_contact_rows_[i] = contact_rows_[active_[i]];
    cholesky_->least_norm_in_place(b, std::span<const char>(active_contact_rows_).first(active));
  }
  lambda_.setZero();
  du_.setZero();
  for (int i = 0; i < active; ++i) {
    b[i] = -b[i];
    lambda_[active_[i]] = b[i];
    du_.noalias() += Y_.col(active_[i]) * b[i];
  }
  const VecX& constrained = dynamics::aba_accelerate(model_, data, du_);
  if (&vdot != &constrained) vdot = constrained;
  // k, for whoever reads the rows: (G v̇₀ + k) − G v̇₀, with G v̇₀ = G v̇ − (G M⁻¹ Gᵀ) λ (0 on a
  // row that exerts no force).
  for (int i = 0; i < active; ++i) {
    double G_vdot0 = rows_.G.row(active_[i]).dot(constrained);
    for (int k = 0; k < active; ++k) G_vdot0 -= (k <= i ? A(i, k) : A(k, i)) * b[k];
    rows_.bias[active_[i]] -= G_vdot0;
  }
  return true;
}

void ConstraintSolver::factor_rows_articulated(dynamics::Data& data, std::span<const char> mask) {
  Y_ = rows_.G.transpose();
  for (int i = 0; i < rows_.count; ++i)
    if (!mask[i]) Y_.col(i).setZero();
  // Held where the forward dynamics was hybrid (prescribed joints, and those stops hold).
  const std::span<const char> prescribed =
      holding_ ? std::span<const char>(held_) : std::span<const char>();
  dynamics::articulated_solve(model_, data, prescribed, Y_);
  // A = G Y, symmetric: its lower triangle (what the factorization reads), zero outside the
  // mask, and nothing to form for a row that exerts no force here (its column of Y is zero: a
  // planar loop's out-of-plane rows).
  const int m = rows_.count;
  for (int c = 0; c < m; ++c) {
    if (Y_.col(c).isZero(0.0)) {
      A_.col(c).setZero();
      continue;
    }
    for (int r = c; r < m; ++r) A_(r, c) = mask[r] ? rows_.G.row(r).dot(Y_.col(c)) : 0.0;
  }
  cholesky_->factorize(A_, kDependentRow);
}

NumericalError ConstraintSolver::singular_configuration_error(double t) const {
  // The first dependent row that is independent at the reference.
  int row = 0;
  while (row < rows_.count &&
         !(cholesky_->dependent(row) &&
           std::find(redundant_.begin(), redundant_.end(), rows_.names[row]) == redundant_.end()))
    ++row;
  if (row == rows_.count) row = 0;
  return NumericalError(fmt::format(
      "singular configuration at t = {:.9g} s, at rest: constraint row '{}' became dependent on "
      "the others ({} independent rows, {} at assembled configurations nearby) — the mechanism "
      "is at a dead point or a bifurcation with no motion to say which way it goes on, and the "
      "constraint forces are not determined there. Give a velocity along the branch it should "
      "follow, or start it off that configuration",
      t, rows_.names[row], cholesky_->rank(), reference_rank_));
}

void ConstraintSolver::set_multipliers(dynamics::Data& data, VecRef q, const VecX& lambda) {
  dynamics::constraint_equations(model_, data, q, rows_,
                                 dynamics::RowTerms::with_velocity_products);
  lambda_ = lambda;
}

void ConstraintSolver::add_forces(const dynamics::Data& data, std::span<Vec6> f_ext,
                                  VecX& tau) const {
  dynamics::add_constraint_forces(model_, data, rows_, lambda_, f_ext, tau);
}

void ConstraintSolver::factor_metric(dynamics::Data& data, VecRef q, VecRef v) {
  if (method_ == AccelerationMethod::dense) {
    dynamics::forward_kinematics(model_, data, q);
    factor_mass_matrix(data, q);
  } else if (holding_) {
    dynamics::hybrid_dynamics(model_, data, held_, q, v, zero_, zero_);
  } else {
    dynamics::aba(model_, data, q, v, zero_);
  }
}

void ConstraintSolver::factor_metric_rows(dynamics::Data& data, std::span<const char> mask) {
  if (method_ == AccelerationMethod::dense) {
    gather_free_columns();
    factor_rows(mask);
  } else {
    factor_rows_articulated(data, mask);
  }
}

void ConstraintSolver::metric_step(const VecX& lambda, VecX& dx) {
  if (method_ == AccelerationMethod::dense) {
    apply_row_forces(lambda);
    dx.setZero();
    for (int c = 0; c < static_cast<int>(free_.size()); ++c) dx[free_[c]] = dv_[c];
  } else {
    dx.noalias() = Y_ * lambda;  // zero on prescribed coordinates
  }
}

bool ConstraintSolver::project(double t, dynamics::Data& data, VecX& q, VecX& v) {
  if (rows_.count == 0) return false;
  bool changed = false;
  // Positions: Newton with the mass metric (M at the step's end state, kept through the
  // iterations), until round-off. The articulated method keeps M's factors in `data` and forms
  // the iterates' rows in a Data of its own; the dense one keeps M's Cholesky factor.
  factor_metric(data, q, v);
  dynamics::Data& iterate = method_ == AccelerationMethod::articulated ? *iterate_data_ : data;
  dynamics::constraint_equations(model_, data, q, rows_);
  double residual = max_abs_over(rows_.position, position_rows_);
  for (int it = 0; it < kProjectionIterations && residual > kPositionTolerance; ++it) {
    factor_metric_rows(data, position_rows_);
    rhs_ = -rows_.position;
    cholesky_->solve_in_place(rhs_);
    metric_step(rhs_, delta_);
    q_saved_ = q;
    model::integrate(model_, q_saved_, delta_, 1.0, q);
    dynamics::forward_kinematics(model_, iterate, q);
    dynamics::constraint_equations(model_, iterate, q, rows_);
    const double next = max_abs_over(rows_.position, position_rows_);
    if (!(next < residual)) {  // round-off reached: keep the better state
      if (!(next <= residual)) {
        q = q_saved_;
        dynamics::forward_kinematics(model_, iterate, q);
        dynamics::constraint_equations(model_, iterate, q, rows_);
      }
      break;
    }
    residual = next;
    changed = true;
  }
  if (!(residual <= kProjectionFailure)) {
    int worst = 0;
    for (int r = 0; r < rows_.count; ++r) {
      if (position_rows_[r] && !(std::abs(rows_.position[r]) <= std::abs(rows_.position[worst])))
        worst = r;
    }
    throw NumericalError(fmt::format(
        "at t = {:.9g} s the state left constraint row '{}' too far to project back: residual "
        "{:.3g} (m or rad) after Newton's method; the mechanism has reached a limit of its motion "
        "(a dead point, or a driven link past where the loop can close), or the step is too "
        "large — take a smaller step",
        t, rows_.names[static_cast<std::size_t>(worst)], residual));
  }
  // Velocities: v ← v − M⁻¹Gᵀ (G M⁻¹ Gᵀ)⁻¹ G v over every row.
  factor_metric_rows(data, all_rows_);
  rhs_.noalias() = -rows_.G * v;
  if (rhs_.cwiseAbs().maxCoeff() > 0.0) {
    cholesky_->solve_in_place(rhs_);
    metric_step(rhs_, delta_);
    v += delta_;
    changed = true;
  }
  return changed;
}

ConstraintResiduals ConstraintSolver::residuals(dynamics::Data& data, VecRef q, VecRef v) {
  ConstraintResiduals r;
  if (rows_.count == 0) return r;
  dynamics::forward_kinematics(model_, data, q);
  dynamics::constraint_equations(model_, data, q, rows_);
  r.position = max_abs_over(rows_.position, position_rows_);
  rhs_.noalias() = rows_.G * v;
  r.velocity = rhs_.cwiseAbs().maxCoeff();
  return r;
}

namespace {

// Least-change corrections over a set of columns: Δx_S = −G_Sᵀ (G_S G_Sᵀ)⁻¹ r over the rows in
// `rows` (dependent rows skipped), zero elsewhere. Also returns the rank G_S has there.
int least_change(const MatX& G, std::span<const char> rows, const std::vector<int>& columns,
                 const VecX& residual, VecX& correction) {
  const int m = static_cast<int>(G.rows());
  MatX G_S = MatX::Zero(m, static_cast<int>(columns.size()));
  for (int c = 0; c < static_cast<int>(columns.size()); ++c) G_S.col(c) = G.col(columns[c]);
  for (int i = 0; i < m; ++i)
    if (!rows[i]) G_S.row(i).setZero();
  detail::OrderedCholesky cholesky(m);
  cholesky.factorize(G_S * G_S.transpose(), kDependentRow);
  VecX y = -residual;
  for (int i = 0; i < m; ++i)
    if (!rows[i]) y[i] = 0.0;
  cholesky.solve_in_place(y);
  const VecX dx = G_S.transpose() * y;
  correction.setZero();
  for (int c = 0; c < static_cast<int>(columns.size()); ++c) correction[columns[c]] = dx[c];
  return cholesky.rank();
}

// The free velocity coordinates of the joints not marked in `given`, where their least change
// takes up the whole residual of the rows; otherwise every free one. (Whether they can is a
// question about the residual, not about ranks: coordinates that cannot move every row may still
// be able to move the rows that are off — a rolling disk's given speed and spin kept, its unset
// heading rate taking up the rest.)
std::vector<int> columns_to_move(const model::Model& model, const MatX& G,
                                 std::span<const char> rows, const std::vector<int>& free,
                                 std::span<const char> given, const VecX& residual) {
  std::vector<int> preferred;
  for (int c : free)
    if (!given[model.joint_of_v(c)]) preferred.push_back(c);
  if (preferred.empty() || preferred.size() == free.size()) return free;
  VecX change(G.cols());
  least_change(G, rows, preferred, residual, change);
  const VecX left = G * change + residual;
  double largest_left = 0.0, largest = 0.0;
  for (Eigen::Index i = 0; i < residual.size(); ++i) {
    if (!rows[static_cast<std::size_t>(i)]) continue;
    largest_left = std::max(largest_left, std::abs(left[i]));
    largest = std::max(largest, std::abs(residual[i]));
  }
  // Round-off of the least-squares solve: far below the residual it removes.
  return largest_left <= 1e-9 * largest ? preferred : free;
}

}  // namespace

ConsistentState ConstraintSolver::consistent_state(dynamics::Data& data, VecX& q, VecX& v,
                                                   std::span<const char> q_given,
                                                   std::span<const char> v_given) {
  ConsistentState report;
  if (rows_.count == 0) return report;
  constexpr int kMaxIterations = 50;
  constexpr double kConsistent = 1e-12;  // m or rad, m/s or rad/s
  const VecX q_start = q, v_start = v;

  // Positions: Newton on φ(q) = 0 over the coordinates to move.
  dynamics::forward_kinematics(model_, data, q);
  dynamics::constraint_equations(model_, data, q, rows_);
  const std::vector<int> q_columns =
      columns_to_move(model_, rows_.G, position_rows_, free_, q_given, rows_.position);
  VecX correction(model_.nv());
  double residual = max_abs_over(rows_.position, position_rows_);
  int it = 0;
  for (; it < kMaxIterations && residual > kPositionTolerance; ++it) {
    least_change(rows_.G, position_rows_, q_columns, rows_.position, correction);
    q = model::integrate(model_, q, correction, 1.0);
    dynamics::forward_kinematics(model_, data, q);
    dynamics::constraint_equations(model_, data, q, rows_);
    const double next = max_abs_over(rows_.position, position_rows_);
    if (!(next < residual) && next <= kConsistent) break;
    residual = next;
  }
  report.newton_iterations = it;
  residual = max_abs_over(rows_.position, position_rows_);
  if (!(residual <= kConsistent)) {
    int worst = 0;
    for (int i = 0; i < rows_.count; ++i)
      if (position_rows_[i] && std::abs(rows_.position[i]) > std::abs(rows_.position[worst]))
        worst = i;
    if (!position_rows_[worst]) worst = 0;
    q = q_start;
    throw InvalidArgument(fmt::format(
        "no consistent initial state near the given one: constraint row '{}' keeps a residual "
        "of {:.3g} (m or rad) after {} Newton steps. The constraints conflict, or the initial "
        "configuration is far from any assembled one: give q0 closer to it",
        rows_.names[worst], rows_.position[worst], it));
  }

  // Velocities: the least change onto G v = 0.
  dynamics::forward_kinematics(model_, data, q);
  dynamics::constraint_equations(model_, data, q, rows_);
  VecX velocity_residual = rows_.G * v;
  const std::vector<int> v_columns =
      columns_to_move(model_, rows_.G, all_rows_, free_, v_given, velocity_residual);
  least_change(rows_.G, all_rows_, v_columns, velocity_residual, correction);
  v += correction;
  velocity_residual = rows_.G * v;
  const double scale = std::max(1.0, v.cwiseAbs().maxCoeff());
  int worst = 0;
  velocity_residual.cwiseAbs().maxCoeff(&worst);
  if (!(std::abs(velocity_residual[worst]) <= kConsistent * scale)) {
    v = v_start;
    throw InvalidArgument(fmt::format(
        "the initial velocities cannot satisfy the constraints: row '{}' keeps a velocity "
        "residual of {:.3g} (m/s or rad/s) — the constraints conflict",
        rows_.names[worst], velocity_residual[worst]));
  }

  // What changed, coordinate by coordinate.
  for (int i = 0; i < model_.nq(); ++i) {
    if (q[i] != q_start[i] && std::abs(q[i] - q_start[i]) > 1e-15 * (1 + std::abs(q_start[i])))
      report.q_changes.push_back({model_.q_name(i), q_start[i], q[i]});
  }
  for (int i = 0; i < model_.nv(); ++i) {
    if (std::abs(v[i] - v_start[i]) > 1e-15 * (1 + std::abs(v_start[i])))
      report.v_changes.push_back({model_.v_name(i), v_start[i], v[i]});
  }
  find_redundant_rows(data, q);
  check_singular_start(data, q, v, report);
  return report;
}

void ConstraintSolver::check_singular_start(dynamics::Data& data, const VecX& q, const VecX& v,
                                            ConsistentState& report) {
  if (rows_.count == 0 || free_.empty()) return;
  // A move of 1e-3 (rad or m) on the fastest free coordinate along the motion, or on every free
  // coordinate at rest; then back onto the constraints. A regular state has the same rank there.
  VecX direction = VecX::Zero(model_.nv());
  for (int c : free_) direction[c] = v[c];
  const double speed = direction.cwiseAbs().maxCoeff();
  if (speed > 0.0) {
    direction /= speed;
  } else {
    for (int c : free_) direction[c] = 1.0;
  }
  VecX q_near(model_.nq()), v_near = v;
  model::integrate(model_, q, direction, 1e-3, q_near);
  try {
    project(0.0, data, q_near, v_near);
  } catch (const NumericalError&) {
    return;  // no assembled configuration that near: nothing to compare with
  }
  const int rank_here = reference_rank_;
  std::vector<std::string> redundant_here = redundant_;
  find_redundant_rows(data, q_near);
  if (reference_rank_ <= rank_here) {  // regular: the reference stays the state's own
    reference_rank_ = rank_here;
    redundant_ = std::move(redundant_here);
    return;
  }
  report.rank_at_start = rank_here;
  report.rank_nearby = reference_rank_;
  for (const std::string& name : redundant_here) {
    if (std::find(redundant_.begin(), redundant_.end(), name) == redundant_.end())
      report.singular_rows.push_back(name);
  }
}

}  // namespace momenta::system
