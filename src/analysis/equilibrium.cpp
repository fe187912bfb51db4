#include "momenta/analysis/equilibrium.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include <fmt/format.h>
#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "model_residual.hpp"
#include "momenta/common/error.hpp"

namespace momenta::analysis {
namespace {

using detail::ModelResidual;

// Pivots below this fraction of the largest count as zero in K's decomposition.
constexpr double kRankThreshold = 1e-9;
// The Armijo constant of the line search and the smallest step fraction before it gives up.
constexpr double kArmijo = 1e-4;
constexpr double kSmallestFraction = 1e-10;
// Largest rotation of one Newton step, rad.
constexpr double kLargestTurn = 1.0;

// The model's force scale F (see EquilibriumOptions::tolerance).
double model_force_scale(const model::Model& model, double t) {
  const double L = characteristic_length(model);
  double forces = model.total_mass() * model.gravity().norm();
  double moments = 0.0;
  for (const model::ForceElement& element : model.force_elements()) {
    if (const auto* s = std::get_if<model::LinearSpringDamper>(&element)) {
      forces += s->stiffness * L;
    } else if (const auto* k = std::get_if<model::TorsionalSpringDamper>(&element)) {
      moments += k->stiffness;
    } else if (const auto* f = std::get_if<model::AppliedForce>(&element)) {
      const double u = f->signal_index < 0
                           ? 1.0
                           : model.signals()[static_cast<std::size_t>(f->signal_index)].value(t);
      forces += f->vector.norm() * std::abs(u);
    } else if (const auto* m = std::get_if<model::AppliedTorque>(&element)) {
      const double u = m->signal_index < 0
                           ? 1.0
                           : model.signals()[static_cast<std::size_t>(m->signal_index)].value(t);
      moments += m->vector.norm() * std::abs(u);
    }
  }
  return L * forces + moments;
}

// "'hinge.angle' = 3.2" for the largest residual entry.
std::string largest_entry(const VecX& r, const std::vector<std::string>& names) {
  if (r.size() == 0) return "none";
  Eigen::Index i = 0;
  r.cwiseAbs().maxCoeff(&i);
  return fmt::format("'{}' = {:.6g}", names[static_cast<std::size_t>(i)], r[i]);
}

}  // namespace

Equilibrium find_equilibrium(const model::Model& model, const VecX& q_guess,
                             const EquilibriumOptions& options) {
  if (!std::isfinite(options.t) || !(options.tolerance > 0.0) ||
      !std::isfinite(options.tolerance) || options.max_iterations < 1) {
    throw InvalidArgument(
        fmt::format("find_equilibrium: t = {} must be finite, tolerance = {} positive and finite, "
                    "max_iterations = {} at least 1",
                    options.t, options.tolerance, options.max_iterations));
  }
  ModelResidual residual(model);
  const double t = options.t;
  const int nf = residual.nf();
  const std::vector<int>& free = residual.free();
  const std::vector<std::string> state_names = linear_state_names(model);

  // At rest: v = 0 on the free coordinates, prescribed ones from their signals, v̇_f = 0.
  VecX v = VecX::Zero(model.nv());
  VecX q = detail::checked_configuration(model, q_guess, v, "find_equilibrium: initial guess");
  residual.system().apply_prescribed_motion(t, q, v);
  const VecX a_zero = VecX::Zero(nf);
  VecX r;
  double guess_scale = 0.0;
  residual.residual_and_scale(t, q, v, a_zero, r, guess_scale);
  double F = std::max(model_force_scale(model, t), guess_scale);
  if (!(F > 0.0) || !std::isfinite(F)) F = 1.0;
  const double allowed = options.tolerance * F;
  const auto converged = [&](const VecX& x) {
    return x.size() == 0 || x.cwiseAbs().maxCoeff() <= allowed;
  };

  // Configuration steps as linearize() takes them.
  const double length = characteristic_length(model);
  const auto step = [&](int i) {
    return detail::is_angle_coordinate(model, i) ? 1e-3 : 1e-3 * length;
  };

  Equilibrium result;
  MatX K(nf, nf);
  VecX plus, minus, coarse, d, tangent, q_step, r_trial, delta_f, delta(model.nv()), q_trial;
  int iteration = 0;
  for (; iteration < options.max_iterations && !converged(r); ++iteration) {
    // K = ∂r/∂δq at q.
    for (int k = 0; k < nf; ++k) {
      const int i = free[static_cast<std::size_t>(k)];
      detail::richardson_difference(
          [&](double s, VecX& out) {
            detail::displace(model, q, i, s, tangent, q_step);
            residual.residual(t, q_step, v, a_zero, out);
          },
          step(i), plus, minus, coarse, d);
      K.col(k) = d;
    }
    if (!K.allFinite()) {
      throw NumericalError(fmt::format(
          "find_equilibrium: the stiffness ∂r/∂q is not finite at iteration {}", iteration));
    }
    // Newton step, least squares and minimum norm where K is singular.
    Eigen::CompleteOrthogonalDecomposition<MatX> cod(K);
    cod.setThreshold(kRankThreshold);
    delta_f = -cod.solve(r);
    delta.setZero();
    double turn = 0.0;
    for (int k = 0; k < nf; ++k) {
      const int i = free[static_cast<std::size_t>(k)];
      delta[i] = delta_f[k];
      if (detail::is_angle_coordinate(model, i)) turn = std::max(turn, std::abs(delta_f[k]));
    }
    if (turn > kLargestTurn) delta *= kLargestTurn / turn;

    // Backtracking line search on ½‖r‖²; where the Newton step fails (K singular along r, as
    // at a pendulum held horizontal, where ∂r/∂q = 0 and ‖r‖ is largest), the direction the
    // system falls from rest, −M⁻¹ r, turning at most kLargestTurn / 2 (plain decrease of ‖r‖).
    const double merit = r.squaredNorm();
    const auto accept = [&](const VecX& direction, double armijo) {
      for (double alpha = 1.0; alpha >= kSmallestFraction; alpha *= 0.5) {
        model::integrate(model, q, direction, alpha, q_trial);
        residual.residual(t, q_trial, v, a_zero, r_trial);
        const double trial = r_trial.squaredNorm();
        if (std::isfinite(trial) && trial < merit && trial <= (1.0 - armijo * alpha) * merit)
          return true;
      }
      return false;
    };
    bool moved = delta.allFinite() && accept(delta, kArmijo);
    if (!moved) {
      const Eigen::LLT<MatX> llt(residual.free_mass(t, q));
      const VecX fall_f = -llt.solve(r);
      VecX fall = VecX::Zero(model.nv());
      double largest = 0.0;
      for (int k = 0; k < nf; ++k) {
        const int i = free[static_cast<std::size_t>(k)];
        fall[i] = fall_f[k];
        largest = std::max(
            largest, std::abs(fall_f[k]) / (detail::is_angle_coordinate(model, i) ? 1.0 : length));
      }
      if (largest > 0.0 && fall.allFinite()) {
        fall *= 0.5 * kLargestTurn / largest;
        moved = accept(fall, 0.0);
      }
    }
    if (!moved) {
      throw NumericalError(fmt::format(
          "find_equilibrium: no equilibrium found: the generalized forces cannot be balanced "
          "near this configuration (the line search stalls after {} iterations with largest "
          "residual {} against tolerance {:.3g}; ∂r/∂q has rank {} of {}) — a constant load on a "
          "coordinate without a restoring force has no static equilibrium",
          iteration, largest_entry(r, state_names), allowed, cod.rank(), nf));
    }
    q = q_trial;
    r = r_trial;
  }
  if (!converged(r)) {
    throw NumericalError(fmt::format(
        "find_equilibrium: no equilibrium found in {} Newton iterations: largest residual {} "
        "against tolerance {:.3g}",
        options.max_iterations, largest_entry(r, state_names), allowed));
  }

  // The equilibrium, its linearization, rank and stability.
  result.point = {t, q, v};
  result.residual = r;
  result.force_scale = F;
  result.iterations = iteration;
  result.linear = linearize(model, result.point);
  if (nf > 0) {
    Eigen::CompleteOrthogonalDecomposition<MatX> cod(result.linear.stiffness);
    cod.setThreshold(kRankThreshold);
    result.stiffness_rank = static_cast<int>(cod.rank());
  }
  const Modes m = modes(result.linear.system);
  double rho = 0.0;
  for (const Mode& mode : m.modes) rho = std::max(rho, std::abs(mode.eigenvalue));
  for (const Mode& mode : m.modes) {
    if (mode.eigenvalue.real() > 1e-6 * rho) result.unstable_eigenvalues.push_back(mode.eigenvalue);
  }
  return result;
}

}  // namespace momenta::analysis
