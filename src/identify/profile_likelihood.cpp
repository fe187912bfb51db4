#include "profile_likelihood.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "momenta/common/error.hpp"

namespace momenta::identify::detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The cost of the others with parameter `fixed` held at `value`: the full residuals, the
// Jacobian less that column.
class WithOneHeld final : public ceres::CostFunction {
 public:
  WithOneHeld(const RunResiduals& full, Eigen::Index fixed, double value)
      : full_(full), fixed_(fixed), value_(value) {
    const int np = full.parameter_block_sizes()[0];
    set_num_residuals(full.num_residuals());
    mutable_parameter_block_sizes()->push_back(np - 1);
    theta_.resize(static_cast<std::size_t>(np));
    jacobian_.resize(static_cast<std::size_t>(np) * static_cast<std::size_t>(num_residuals()));
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const auto np = static_cast<Eigen::Index>(theta_.size());
    for (Eigen::Index k = 0, j = 0; k < np; ++k)
      theta_[std::size_t(k)] = k == fixed_ ? value_ : parameters[0][j++];
    const bool wants = jacobians != nullptr && jacobians[0] != nullptr;
    const double* block = theta_.data();
    double* full_jacobian = jacobian_.data();
    if (!full_.Evaluate(&block, residuals, wants ? &full_jacobian : nullptr)) return false;
    if (!wants) return true;
    for (Eigen::Index r = 0; r < num_residuals(); ++r) {
      for (Eigen::Index k = 0, j = 0; k < np; ++k) {
        if (k != fixed_) jacobians[0][r * (np - 1) + j++] = jacobian_[std::size_t(r * np + k)];
      }
    }
    return true;
  }

 private:
  const RunResiduals& full_;
  Eigen::Index fixed_;
  double value_;
  mutable std::vector<double> theta_, jacobian_;
};

double sum_of_squares(const RunResiduals& cost, const std::vector<double>& theta) {
  std::vector<double> residuals(static_cast<std::size_t>(cost.num_residuals()));
  const double* block = theta.data();
  if (!cost.Evaluate(&block, residuals.data(), nullptr)) return kNaN;
  double s = 0.0;
  for (double r : residuals) s += r * r;
  return s;
}

}  // namespace

ProfileLikelihood::ProfileLikelihood(RunResiduals& cost, const Parameterization& scale,
                                     const std::vector<GreyBoxParameter>& parameters,
                                     std::vector<double> theta, double best_sum_squares, double s2,
                                     int max_iterations)
    : cost_(cost),
      scale_(scale),
      parameters_(parameters),
      theta_(std::move(theta)),
      best_(best_sum_squares),
      s2_(s2),
      max_iterations_(max_iterations) {}

double ProfileLikelihood::linear_root(Eigen::Index i, double delta, const MatX& covariance) {
  const VecX p_hat = scale_.values(theta_.data());
  const VecX p = p_hat + delta * covariance.col(i) / covariance(i, i);
  std::vector<double> theta(theta_.size());
  for (std::size_t j = 0; j < theta.size(); ++j) {
    const GreyBoxParameter& g = parameters_[j];
    const double x = p[Eigen::Index(j)];
    if (x < g.lower || x > g.upper || (scale_.positive[j] && !(x > 0.0))) return kNaN;
    theta[j] = scale_.theta(j, x);
  }
  const double s = sum_of_squares(cost_, theta);
  if (!std::isfinite(s)) return kNaN;  // a run failed there (std::max would hide the NaN)
  return std::copysign(std::sqrt(std::max(0.0, s - best_) / s2_), delta);
}

double ProfileLikelihood::profile_root(Eigen::Index i, double value, std::vector<double>& start) {
  ++fits_;
  start[std::size_t(i)] = value;
  const double sign = value >= theta_[std::size_t(i)] ? 1.0 : -1.0;
  if (theta_.size() == 1) {
    const double s = sum_of_squares(cost_, start);
    if (!std::isfinite(s)) return kNaN;  // a run failed there (std::max would hide the NaN)
    return sign * std::sqrt(std::max(0.0, s - best_) / s2_);
  }
  std::vector<double> others;
  for (std::size_t j = 0; j < start.size(); ++j)
    if (Eigen::Index(j) != i) others.push_back(start[j]);
  // Where the run fails at the start, so would Ceres' first evaluation (and log it).
  if (!std::isfinite(sum_of_squares(cost_, start))) return kNaN;
  WithOneHeld held(cost_, i, value);
  ceres::Problem::Options options;
  options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem least_squares(options);
  least_squares.AddResidualBlock(&held, nullptr, others.data());
  for (std::size_t j = 0, k = 0; j < start.size(); ++j) {
    if (Eigen::Index(j) == i) continue;
    set_bounds(least_squares, others.data(), int(k++), parameters_[j], scale_, j);
  }
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options(max_iterations_), &least_squares, &summary);
  if (summary.termination_type == ceres::FAILURE || !std::isfinite(summary.final_cost)) return kNaN;
  for (std::size_t j = 0, k = 0; j < start.size(); ++j)
    if (Eigen::Index(j) != i) start[j] = others[k++];
  // A profile point a little below S(p̂) is the optimum's own tolerance: z = 0 there.
  return sign * std::sqrt(std::max(0.0, 2.0 * summary.final_cost - best_) / s2_);
}

ProfileEnd ProfileLikelihood::side(Eigen::Index i, double sign, double q, double se_theta,
                                   const VecX& follow_theta) {
  const auto ii = std::size_t(i);
  const double centre = theta_[ii];
  const auto [lower, upper] = scale_.bounds(ii, parameters_[ii]);
  const double limit = sign > 0.0 ? upper - centre : centre - lower;  // how far δ may go
  const auto value_at = [&](double delta) {
    return scale_.positive[ii] ? std::exp(centre + sign * delta) : centre + sign * delta;
  };
  // Where the data do not bound it: its bound, else 0 below a positive parameter, else ±∞.
  const GreyBoxParameter& g = parameters_[ii];
  const double open_end = sign < 0.0 ? (std::isfinite(g.lower) ? g.lower
                                        : scale_.positive[ii]  ? 0.0
                                                               : -kInf)
                                     : (std::isfinite(g.upper) ? g.upper : kInf);

  // Secant steps on |z|(δ) = q: extrapolated through the last two points below q (at most
  // fourfold) until one above brackets it, then kept inside the bracket; halfway back towards
  // the last good point where the fits fail.
  double previous = 0.0, z_previous = 0.0;  // the optimum: z = 0
  double below = 0.0, z_below = 0.0;        // the farthest δ known with |z| < q
  double above = kInf, z_above = kInf;      // the nearest δ known with |z| > q
  double failed = kInf;                     // the nearest δ where the fits fail
  double delta = std::min(q * se_theta, limit);
  std::vector<double> start = theta_;
  for (int step = 0; step < 60; ++step) {
    for (std::size_t j = 0; j < start.size(); ++j)
      start[j] = theta_[j] + sign * delta * follow_theta[Eigen::Index(j)];
    const double z = std::abs(profile_root(i, centre + sign * delta, start));
    if (!std::isfinite(z)) {
      failed = delta;
      if (failed - below <= 1e-6 * se_theta) return {value_at(below), false, true};
      delta = 0.5 * (below + failed);
      continue;
    }
    if (std::abs(z - q) <= 1e-6 * q) return {value_at(delta), true};
    if (z < q) {
      // Reached the bound, or far out and the profile flat: the data do not bound it here.
      const bool flat = delta > 8.0 * q * se_theta && z - z_below < 1e-3 * q;
      if (delta >= limit || flat) return {open_end, false};
      previous = below;
      z_previous = z_below;
      below = delta;
      z_below = z;
    } else {
      above = delta;
      z_above = z;
    }
    double next;
    if (std::isfinite(above)) {
      next = below + (q - z_below) * (above - below) / (z_above - z_below);
      if (!(next > below && next < above)) next = 0.5 * (below + above);
    } else {
      next = z_below > z_previous
                 ? below + (q - z_below) * (below - previous) / (z_below - z_previous)
                 : 4.0 * below;
      next = std::min(next, 4.0 * below);
    }
    if (next >= failed) next = 0.5 * (below + failed);
    if (!(next > 0.0)) return {open_end, false};  // (a NaN step too)
    delta = std::min(next, limit);
  }
  return {open_end, false};
}

ProfileInterval ProfileLikelihood::interval(Eigen::Index i, double q, const MatX& covariance) {
  // The covariance in θ: ∂θ/∂p = 1/p for a positive parameter.
  const VecX p = scale_.values(theta_.data());
  VecX d(p.size());
  for (Eigen::Index j = 0; j < p.size(); ++j)
    d[j] = scale_.positive[std::size_t(j)] ? 1.0 / p[j] : 1.0;
  const MatX covariance_theta = d.asDiagonal() * covariance * d.asDiagonal();
  const VecX follow = covariance_theta.col(i) / covariance_theta(i, i);
  const double se_theta = std::sqrt(covariance_theta(i, i));
  const ProfileEnd lower = side(i, -1.0, q, se_theta, follow);
  const ProfileEnd upper = side(i, +1.0, q, se_theta, follow);
  return {lower, upper};
}

}  // namespace momenta::identify::detail
