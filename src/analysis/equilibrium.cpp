#include "momenta/analysis/equilibrium.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "charted_derivatives.hpp"
#include "constraint_chart.hpp"
#include "linearize_parts.hpp"
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
    } else if (const auto* tendon = std::get_if<model::FixedTendon>(&element)) {
      // Its stiffness on its joints, k cᵢ², in the unit of its first joint's coordinate.
      double stiffness = 0.0;
      for (const model::TendonTerm& term : tendon->terms) {
        stiffness += tendon->stiffness * term.coefficient * term.coefficient;
      }
      const bool sliding =
          model.joint(tendon->terms.front().joint_index).type == model::JointType::prismatic;
      (sliding ? forces : moments) += sliding ? stiffness * L : stiffness;
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

// What Newton's method balances: the generalized forces r (n of them) of a configuration, and
// how a step in the n unknowns moves it. Without constraints the unknowns are the free
// coordinates' tangents and r = r_f; with constraints they are the independent coordinates of a
// chart anchored at the current configuration (re-anchored after every step) and r = Tᵀ M_ff v̇_f,
// the generalized forces along them (Gᵀλ drops out: G T = 0).
class StaticProblem {
 public:
  StaticProblem(const model::Model& model, ModelResidual& residual, double t, const VecX& v)
      : model_(model), residual_(residual), t_(t), v_(v), a_zero_(VecX::Zero(residual.nf())) {}

  int unknowns() const {
    return chart_ ? static_cast<int>(chart_->positions().size()) : residual_.nf();
  }
  // Velocity index of unknown k.
  int coordinate(int k) const {
    return (chart_ ? chart_->positions() : residual_.free())[static_cast<std::size_t>(k)];
  }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (int k = 0; k < unknowns(); ++k) out.push_back(detail::tangent_name(model_, coordinate(k)));
    return out;
  }

  // Anchors the unknowns at q (a consistent configuration).
  void anchor(const VecX& q) {
    if (model_.has_constraints())
      chart_.emplace(model_, residual_.free(), q, v_, std::vector<std::string>{});
  }

  // q_out = q moved by α·step (in the unknowns).
  void move(const VecX& q, const VecX& step, double alpha, VecX& q_out) {
    if (chart_) {
      chart_->configuration(alpha * step, q_out, delta_);
      return;
    }
    delta_ = VecX::Zero(model_.nv());
    for (int k = 0; k < unknowns(); ++k) delta_[coordinate(k)] = step[k];
    model::integrate(model_, q, delta_, alpha, q_out);
  }

  void residual(const VecX& q, VecX& r) {
    if (!chart_) {
      residual_.residual(t_, q, v_, a_zero_, r);
      return;
    }
    const MatX T = chart_->velocity_map(q);
    const VecX& vdot = residual_.system().evaluate(t_, q, v_);
    VecX a_f(residual_.nf());
    for (int k = 0; k < residual_.nf(); ++k)
      a_f[k] = vdot[residual_.free()[static_cast<std::size_t>(k)]];
    r = T.transpose() * (residual_.free_mass(t_, q) * a_f);
  }

  // K = ∂r/∂(unknowns) at q, analytic. Without constraints the free rows and columns of ∂τ/∂δq
  // less the force elements' (ModelResidual::derivatives, as linearize() takes them). On a
  // constraint chart r = Tᵀ M T ζ̇ (at rest v̇ = T ζ̇), and K = Tᵀ M T ∂ζ̇/∂ξ
  // (charted_state_matrix): the part ∂(Tᵀ M T)/∂ξ ζ̇ is left out, which vanishes with r, so Newton
  // still converges quadratically.
  void stiffness(const VecX& q, MatX& K) {
    if (!chart_) {
      residual_.derivatives(t_, q, v_, a_zero_, K, dr_dv_);
      return;
    }
    const auto nx = static_cast<Eigen::Index>(chart_->positions().size());
    const auto nz = static_cast<Eigen::Index>(chart_->velocities().size());
    const MatX A = detail::charted_state_matrix(residual_, *chart_, {t_, q, v_});
    K = mass(q) * A.block(nx, 0, nz, nx);
  }

  MatX mass(const VecX& q) {
    const MatX M = residual_.free_mass(t_, q);
    if (!chart_) return M;
    const MatX T = chart_->velocity_map(q);
    return T.transpose() * M * T;
  }

 private:
  const model::Model& model_;
  ModelResidual& residual_;
  double t_;
  VecX v_, a_zero_, delta_;
  MatX dr_dv_;
  std::optional<detail::ConstraintChart> chart_;
};

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

  // At rest: v = 0 on the free coordinates, prescribed ones from their signals, v̇_f = 0; on the
  // constraints (the guess made consistent as a simulation's first state is).
  VecX v = VecX::Zero(model.nv());
  VecX q = detail::checked_configuration(model, q_guess, v, "find_equilibrium: initial guess");
  residual.system().apply_prescribed_motion(t, q, v);
  residual.system().make_consistent(t, q, v);
  StaticProblem problem(model, residual, t, v);
  problem.anchor(q);
  const int n = problem.unknowns();
  const std::vector<std::string> names = problem.names();
  VecX r;
  double guess_scale = 0.0;
  residual.residual_and_scale(t, q, v, VecX::Zero(residual.nf()), r, guess_scale);
  problem.residual(q, r);
  double F = std::max(model_force_scale(model, t), guess_scale);
  if (!(F > 0.0) || !std::isfinite(F)) F = 1.0;
  const double allowed = options.tolerance * F;
  const auto converged = [&](const VecX& x) {
    return x.size() == 0 || x.cwiseAbs().maxCoeff() <= allowed;
  };

  const double length = characteristic_length(model);
  const auto is_angle = [&](int k) {
    return detail::is_angle_coordinate(model, problem.coordinate(k));
  };

  Equilibrium result;
  MatX K;  // square unless nonholonomic rows leave fewer velocities than unknowns
  VecX r_trial, delta, q_trial;
  int iteration = 0;
  for (; iteration < options.max_iterations && !converged(r); ++iteration) {
    problem.stiffness(q, K);
    if (!K.allFinite()) {
      throw NumericalError(fmt::format(
          "find_equilibrium: the stiffness ∂r/∂q is not finite at iteration {}", iteration));
    }
    // Newton step, least squares and minimum norm where K is singular.
    Eigen::CompleteOrthogonalDecomposition<MatX> cod(K);
    cod.setThreshold(kRankThreshold);
    delta = -cod.solve(r);
    double turn = 0.0;
    for (int k = 0; k < n; ++k)
      if (is_angle(k)) turn = std::max(turn, std::abs(delta[k]));
    if (turn > kLargestTurn) delta *= kLargestTurn / turn;

    // Backtracking line search on ½‖r‖²; where the Newton step fails (K singular along r, as
    // at a pendulum held horizontal, where ∂r/∂q = 0 and ‖r‖ is largest), the direction the
    // system falls from rest, −M⁻¹ r, turning at most kLargestTurn / 2 (plain decrease of ‖r‖).
    const double merit = r.squaredNorm();
    const auto accept = [&](const VecX& direction, double armijo) {
      for (double alpha = 1.0; alpha >= kSmallestFraction; alpha *= 0.5) {
        try {
          problem.move(q, direction, alpha, q_trial);
        } catch (const NumericalError&) {
          continue;  // a chart cannot reach that far: a shorter step
        }
        problem.residual(q_trial, r_trial);
        const double trial = r_trial.squaredNorm();
        if (std::isfinite(trial) && trial < merit && trial <= (1.0 - armijo * alpha) * merit)
          return true;
      }
      return false;
    };
    bool moved = delta.allFinite() && accept(delta, kArmijo);
    if (!moved && r.size() == n) {
      const Eigen::LLT<MatX> llt(problem.mass(q));
      VecX fall = -llt.solve(r);
      double largest = 0.0;
      for (int k = 0; k < n; ++k)
        largest = std::max(largest, std::abs(fall[k]) / (is_angle(k) ? 1.0 : length));
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
          iteration, largest_entry(r, names), allowed, cod.rank(), n));
    }
    q = q_trial;
    problem.anchor(q);
    problem.residual(q, r);
  }
  if (!converged(r)) {
    throw NumericalError(fmt::format(
        "find_equilibrium: no equilibrium found in {} Newton iterations: largest residual {} "
        "against tolerance {:.3g}",
        options.max_iterations, largest_entry(r, names), allowed));
  }

  // The equilibrium, its linearization, rank and stability.
  result.point = {t, q, v};
  result.residual = r;
  result.force_scale = F;
  result.iterations = iteration;
  result.linear = linearize(model, result.point);
  if (result.linear.stiffness.size() > 0) {
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
