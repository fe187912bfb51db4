#include "momenta/integrate/stiffness.hpp"

#include "momenta/integrate/acceleration_jacobian.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

namespace momenta::integrate {

Eigen::VectorXcd linearization_eigenvalues(SecondOrderSystem& system, const State& state) {
  const int n = system.nv();
  if (n == 0) return {};
  // The v̇ rows (acceleration_jacobian.hpp).
  VecX a0(n);
  MatX dadq(n, n), dadv(n, n);
  JacobianWorkspace work;
  work.resize(system.nq(), n);
  system.begin_step(state.t, std::numeric_limits<double>::infinity());
  system.acceleration(state.t, state.q, state.v, a0);
  acceleration_jacobian(system, state.t, state.q, state.v, a0, dadq, dadv, work);
  // The δ̇ rows: ∂(dexp⁻¹_δ v)/∂δ at δ = 0 by differences (zero on vector coordinates), and
  // ∂/∂v = 1 exactly.
  MatX jacobian = MatX::Zero(2 * n, 2 * n);
  const double probe = std::sqrt(std::numeric_limits<double>::epsilon());
  VecX delta = VecX::Zero(n), rate(n);
  for (int j = 0; j < n; ++j) {
    delta.setZero();
    delta[j] = probe;
    system.local_coordinate_rate(delta, state.v, rate);
    jacobian.col(j).head(n) = (rate - state.v) / probe;
    jacobian(j, n + j) = 1.0;
  }
  jacobian.bottomLeftCorner(n, n) = dadq;
  jacobian.bottomRightCorner(n, n) = dadv;
  if (!jacobian.allFinite()) return {};
  return Eigen::EigenSolver<MatX>(jacobian, false).eigenvalues();
}

double amplification(std::string_view integrator, std::complex<double> z) {
  // Horner on the Taylor polynomial's coefficients, highest first.
  const auto polynomial = [&](std::initializer_list<double> coefficients) {
    std::complex<double> r(0.0, 0.0);
    for (const double c : coefficients) r = r * z + c;
    return std::abs(r);
  };
  if (integrator == "rk4") return polynomial({1.0 / 24, 1.0 / 6, 0.5, 1.0, 1.0});
  if (integrator == "dopri5") {
    return polynomial({1.0 / 600, 1.0 / 120, 1.0 / 24, 1.0 / 6, 0.5, 1.0, 1.0});
  }
  return std::numeric_limits<double>::quiet_NaN();
}

StepStability check_step_stability(std::string_view integrator, const Eigen::VectorXcd& eigenvalues,
                                   double h) {
  StepStability result;
  if (std::isnan(amplification(integrator, {0.0, 0.0}))) return result;
  double worst = -1.0;
  for (const std::complex<double>& lambda : eigenvalues) {
    if (!(lambda.real() <= 1e-9 * std::abs(lambda))) continue;  // growing: unstable in any method
    const double r = amplification(integrator, h * lambda);
    if (r > worst) {
      worst = r;
      result.eigenvalue = lambda;
    }
  }
  if (worst < 0.0) return result;
  result.stable = worst <= 1.0 + 1e-9;
  // The largest step along the worst mode's ray that stays inside: bisection on |R(s λ)| = 1 from
  // a step that is inside (the origin's neighbourhood, for Re λ < 0 or small |λ h|).
  const std::complex<double> lambda = result.eigenvalue;
  double inside = 0.0, outside = std::max(h, 10.0 / std::max(std::abs(lambda), 1e-300));
  while (amplification(integrator, outside * lambda) <= 1.0 + 1e-9 && outside < 1e300) outside *= 2;
  for (int i = 0; i < 200 && outside - inside > 1e-12 * outside; ++i) {
    const double mid = 0.5 * (inside + outside);
    (amplification(integrator, mid * lambda) <= 1.0 + 1e-9 ? inside : outside) = mid;
  }
  result.largest_stable_step = inside;
  return result;
}

}  // namespace momenta::integrate
