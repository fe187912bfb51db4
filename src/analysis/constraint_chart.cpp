#include "constraint_chart.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>

#include <fmt/format.h>
#include <Eigen/LU>

#include "linearize_parts.hpp"
#include "momenta/analysis/linearize.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/dynamics/kinematics.hpp"

namespace momenta::analysis::detail {
namespace {

// A row (or column) counts as independent of those already chosen when what is left of it after
// removing their span is above this fraction of its norm: well conditioned first, then any that
// is not round-off.
constexpr double kWellConditioned = 1e-3;
constexpr double kIndependent = 1e-9;
// Newton on φ: stop below this (m or rad, times the characteristic length for lengths), fail
// above the second.
constexpr double kConverged = 1e-15;
constexpr double kFailed = 1e-9;
constexpr int kMaxNewton = 50;

// Greedy Gram–Schmidt: the vectors of `candidates` (columns of V, in order) independent of the
// basis and of each other; appends them to `basis` (orthonormal columns) and returns them, at
// most `limit`.
std::vector<int> independent_columns(const MatX& V, const std::vector<int>& candidates,
                                     double threshold, int limit, std::vector<VecX>& basis,
                                     const std::vector<int>& exclude = {}) {
  std::vector<int> chosen;
  for (int c : candidates) {
    if (static_cast<int>(chosen.size()) >= limit) break;
    if (std::find(exclude.begin(), exclude.end(), c) != exclude.end()) continue;
    VecX r = V.col(c);
    const double norm = r.norm();
    if (norm == 0.0) continue;
    for (int pass = 0; pass < 2; ++pass)  // twice is enough (Giraud et al. 2005)
      for (const VecX& b : basis) r -= b.dot(r) * b;
    if (r.norm() <= threshold * norm) continue;
    basis.push_back(r / r.norm());
    chosen.push_back(c);
  }
  return chosen;
}

// Columns of G_rows (rows chosen) to add to `dependent` until their rank reaches the rows':
// well-conditioned ones first.
void choose_dependent(const MatX& G_rows, const std::vector<int>& candidates,
                      std::vector<int>& dependent) {
  const int target = static_cast<int>(G_rows.rows());
  std::vector<VecX> basis;
  independent_columns(G_rows, dependent, kIndependent, target, basis);
  for (double threshold : {kWellConditioned, kIndependent}) {
    const int missing = target - static_cast<int>(basis.size());
    if (missing <= 0) break;
    const std::vector<int> more =
        independent_columns(G_rows, candidates, threshold, missing, basis, dependent);
    dependent.insert(dependent.end(), more.begin(), more.end());
  }
}

std::vector<int> without(const std::vector<int>& all, const std::vector<int>& removed) {
  std::vector<int> left;
  for (int i : all)
    if (std::find(removed.begin(), removed.end(), i) == removed.end()) left.push_back(i);
  return left;
}

MatX rows_of(const MatX& G, const std::vector<int>& rows) {
  MatX out(static_cast<Eigen::Index>(rows.size()), G.cols());
  for (std::size_t r = 0; r < rows.size(); ++r)
    out.row(static_cast<Eigen::Index>(r)) = G.row(rows[r]);
  return out;
}

MatX block_of(const MatX& G, const std::vector<int>& rows, const std::vector<int>& columns) {
  MatX out(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(columns.size()));
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::size_t c = 0; c < columns.size(); ++c)
      out(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = G(rows[r], columns[c]);
  return out;
}

// The velocity index a coordinate name stands for (q_name of a one-coordinate-per-velocity
// joint, or a tangent name), or throws with a "did you mean".
int coordinate_named(const model::Model& model, const std::vector<int>& free,
                     const std::string& name) {
  std::vector<std::string> names;
  for (int i : free) {
    const std::string tangent = tangent_name(model, i);
    if (tangent == name || model.v_name(i) == name) return i;
    names.push_back(tangent);
  }
  const std::vector<std::string_view> views(names.begin(), names.end());
  throw InvalidArgument(
      fmt::format("linearize: independent coordinate '{}' is not a free coordinate of the model{}",
                  name, did_you_mean(name, views)));
}

}  // namespace

ConstraintChart::ConstraintChart(const model::Model& model, const std::vector<int>& free,
                                 const VecX& q0, const VecX& v0,
                                 const std::vector<std::string>& preferred)
    : model_(model),
      data_(model),
      rows_(model),
      q0_(q0),
      v0_(v0),
      length_(characteristic_length(model)),
      free_(free) {
  for (int i = 0; i < model.nv(); ++i)
    if (std::find(free.begin(), free.end(), i) == free.end()) prescribed_.push_back(i);
  evaluate_rows(q0);

  // Independent rows: holonomic first (they fix the configuration), then the velocity-only ones.
  const MatX Gt = rows_.G.transpose();  // columns = rows of G
  std::vector<int> holonomic, nonholonomic;
  for (int r = 0; r < rows_.count; ++r)
    (rows_.holonomic[r] ? holonomic : nonholonomic).push_back(r);
  std::vector<VecX> row_basis;
  const int nf = static_cast<int>(free.size());
  MatX Gt_free(nf, rows_.count);
  for (int k = 0; k < nf; ++k) Gt_free.row(k) = Gt.row(free[static_cast<std::size_t>(k)]);
  holonomic_rows_ = independent_columns(Gt_free, holonomic, kIndependent, nf, row_basis);
  velocity_rows_ = holonomic_rows_;
  const std::vector<int> more =
      independent_columns(Gt_free, nonholonomic, kIndependent,
                          nf - static_cast<int>(holonomic_rows_.size()), row_basis);
  velocity_rows_.insert(velocity_rows_.end(), more.begin(), more.end());

  // Candidates for dependent coordinates: the last joints first, the preferred ones last.
  std::vector<int> kept;
  for (const std::string& name : preferred) kept.push_back(coordinate_named(model, free, name));
  std::vector<int> candidates = without(std::vector<int>(free.rbegin(), free.rend()), kept);
  candidates.insert(candidates.end(), kept.rbegin(), kept.rend());

  choose_dependent(rows_of(rows_.G, holonomic_rows_), candidates, position_dependent_);
  velocity_dependent_ = position_dependent_;
  choose_dependent(rows_of(rows_.G, velocity_rows_), candidates, velocity_dependent_);
  position_independent_ = without(free, position_dependent_);
  velocity_independent_ = without(free, velocity_dependent_);
  if (velocity_independent_.empty()) {
    throw InvalidArgument(fmt::format(
        "linearize: the constraints leave the model no freedom: {} independent constraint rows "
        "on {} free coordinates",
        velocity_rows_.size(), nf));
  }
}

void ConstraintChart::evaluate_rows(const VecX& q) {
  dynamics::forward_kinematics(model_, data_, q);
  dynamics::constraint_equations(model_, data_, q, rows_);
}

void ConstraintChart::configuration(const VecX& xi, VecX& q, VecX& delta) {
  delta = VecX::Zero(model_.nv());
  for (std::size_t k = 0; k < position_independent_.size(); ++k)
    delta[position_independent_[k]] = xi[static_cast<Eigen::Index>(k)];
  const auto residual = [&] {
    double largest = 0.0;
    for (int r : holonomic_rows_) largest = std::max(largest, std::abs(rows_.position[r]));
    return largest;
  };
  VecX best_delta = delta, phi(static_cast<Eigen::Index>(holonomic_rows_.size()));
  double best = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration <= kMaxNewton && !holonomic_rows_.empty(); ++iteration) {
    model::integrate(model_, q0_, delta, 1.0, q);
    evaluate_rows(q);
    const double norm = residual();
    if (!(norm < best)) break;  // no progress (or NaN): keep the best
    best = norm;
    best_delta = delta;
    if (norm <= kConverged * std::max(1.0, length_)) break;
    for (std::size_t r = 0; r < holonomic_rows_.size(); ++r)
      phi[static_cast<Eigen::Index>(r)] = rows_.position[holonomic_rows_[r]];
    const VecX step =
        block_of(rows_.G, holonomic_rows_, position_dependent_).partialPivLu().solve(-phi);
    for (std::size_t k = 0; k < position_dependent_.size(); ++k)
      delta[position_dependent_[k]] += step[static_cast<Eigen::Index>(k)];
  }
  delta = best_delta;
  model::integrate(model_, q0_, delta, 1.0, q);
  if (!holonomic_rows_.empty() && !(best <= kFailed * std::max(1.0, length_))) {
    throw NumericalError(fmt::format(
        "linearize: the constraints cannot be closed {} from the operating point (residual "
        "{:.3g}): the step reaches past where the dependent coordinates follow; try a smaller "
        "angle_step or length_step",
        xi.cwiseAbs().maxCoeff(), best));
  }
}

void ConstraintChart::velocity(const VecX& q, const VecX& zeta, VecX& v) {
  evaluate_rows(q);
  v = v0_;
  for (int i : velocity_dependent_) v[i] = 0.0;
  for (std::size_t k = 0; k < velocity_independent_.size(); ++k)
    v[velocity_independent_[k]] = zeta[static_cast<Eigen::Index>(k)];
  if (velocity_rows_.empty()) return;
  const VecX rhs = -rows_of(rows_.G, velocity_rows_) * v;
  const VecX dependent =
      block_of(rows_.G, velocity_rows_, velocity_dependent_).partialPivLu().solve(rhs);
  for (std::size_t k = 0; k < velocity_dependent_.size(); ++k)
    v[velocity_dependent_[k]] = dependent[static_cast<Eigen::Index>(k)];
}

MatX ConstraintChart::velocity_map(const VecX& q) {
  const auto nz = static_cast<Eigen::Index>(velocity_independent_.size());
  const auto nf = static_cast<Eigen::Index>(free_.size());
  MatX T(nf, nz);
  VecX v_zero, v_unit, unit;
  velocity(q, VecX::Zero(nz), v_zero);
  for (Eigen::Index k = 0; k < nz; ++k) {
    unit = VecX::Zero(nz);
    unit[k] = 1.0;
    velocity(q, unit, v_unit);
    for (Eigen::Index a = 0; a < nf; ++a) {
      const int i = free_[static_cast<std::size_t>(a)];
      T(a, k) = v_unit[i] - v_zero[i];
    }
  }
  return T;
}

}  // namespace momenta::analysis::detail
