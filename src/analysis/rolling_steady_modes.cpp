// rolling_steady_modes(): the perturbed motion about a rolling body's steady motion, seen from
// the frame that moves with it (rolling_steady_motion.hpp), linearized in independent
// coordinates.
#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "constraint_chart.hpp"
#include "linearize_parts.hpp"
#include "model_residual.hpp"
#include "momenta/analysis/rolling_steady_motion.hpp"
#include "rolling_symmetry.hpp"

namespace momenta::analysis {
namespace {

using detail::ConstraintChart;
using detail::ModelResidual;
using detail::SymmetryMotion;

// Below this fraction of the rates' scale an eigenvalue is zero: the differences leave ~1e-10,
// and a zero eigenvalue in a Jordan block of two (a drift along the symmetry) splits by its
// square root.
constexpr double kZeroEigenvalue = 1e-4;

// g(ξ, ζ) = [ξ̇; ζ̇] of x̃̇ = f(x̃) − ξ_steady(x̃): the configuration moves at v less the
// symmetry motion's velocity there, the velocity at v̇ less the rate at which the motion turns v.
class MovingFrameMotion {
 public:
  MovingFrameMotion(ModelResidual& residual, ConstraintChart& chart,
                    const SymmetryMotion& generator, double t)
      : model_(residual.model()),
        system_(residual.system()),
        chart_(chart),
        generator_(generator),
        t_(t) {}

  void evaluate(const VecX& xi, const VecX& zeta, VecX& out) {
    const std::vector<int>& positions = chart_.positions();
    const std::vector<int>& velocities = chart_.velocities();
    chart_.configuration(xi, q_, delta_);
    chart_.velocity(q_, zeta, v_);
    const VecX& vdot = system_.evaluate(t_, q_, v_);
    generator_.velocity(q_, v_steady_);
    generator_.velocity_rate(q_, v_, turn_rate_);
    model::local_coordinate_rate(model_, delta_, v_ - v_steady_, delta_rate_);
    const auto nx = static_cast<Eigen::Index>(positions.size());
    out.resize(nx + static_cast<Eigen::Index>(velocities.size()));
    for (std::size_t k = 0; k < positions.size(); ++k)
      out[static_cast<Eigen::Index>(k)] = delta_rate_[positions[k]];
    for (std::size_t k = 0; k < velocities.size(); ++k) {
      out[nx + static_cast<Eigen::Index>(k)] = vdot[velocities[k]] - turn_rate_[velocities[k]];
    }
  }

 private:
  const model::Model& model_;
  system::MultibodySystem& system_;
  ConstraintChart& chart_;
  const SymmetryMotion& generator_;
  double t_;
  VecX q_, v_, delta_, delta_rate_, v_steady_, turn_rate_;
};

// Which states move the body across the floor: a free joint's translations in the plane.
std::vector<bool> translation_states(const detail::RollingBody& body,
                                     const std::vector<int>& positions, Eigen::Index states) {
  std::vector<bool> across(static_cast<std::size_t>(states), false);
  if (body.info.pivoted) return across;
  const int first = body.joint->v_index + 3;
  const Mat3 R_WJ = body.joint->X_PJ.R;
  for (std::size_t k = 0; k < positions.size(); ++k) {
    const int i = positions[k];
    if (i < first || i > first + 2) continue;
    // A translation along the floor, not off it.
    across[k] = std::abs(body.up_W.dot(R_WJ.col(i - first))) < 1.0 - 1e-12;
  }
  return across;
}

// True when the mode's shape lies on the marked states (to 1e-6 of its size).
bool moves_only(const Eigen::VectorXcd& shape, const std::vector<bool>& marked) {
  double on = 0.0, off = 0.0;
  for (Eigen::Index i = 0; i < shape.size(); ++i) {
    (marked[static_cast<std::size_t>(i)] ? on : off) += std::norm(shape[i]);
  }
  return on > 0.0 && off <= 1e-12 * on;
}

}  // namespace

RollingSteadyModes rolling_steady_modes(const model::Model& model,
                                        const RollingSteadyMotion& motion) {
  const detail::RollingBody body = detail::rolling_body(model);
  ModelResidual residual(model);
  const OperatingPoint& p = motion.point;
  ConstraintChart chart(model, residual.free(), p.q, p.v, {});
  const detail::TurnRates rates{motion.precession, motion.relative_spin,
                                motion.speed * motion.heading_W};
  const Vec3 p_WoG_W = detail::body_pose(body, p.q).apply(body.p_BoG_B);
  const SymmetryMotion generator(body, rates, p_WoG_W);
  MovingFrameMotion moving(residual, chart, generator, p.t);

  // A = ∂g/∂(ξ, ζ) at ξ = 0, ζ = ζ₀ (Richardson on ξ; g is quadratic in ζ: exact differences).
  const std::vector<int>& positions = chart.positions();
  const std::vector<int>& velocities = chart.velocities();
  const auto nx = static_cast<Eigen::Index>(positions.size());
  const auto nz = static_cast<Eigen::Index>(velocities.size());
  const detail::DifferenceSteps steps(model, LinearizationOptions{});
  const VecX xi0 = VecX::Zero(nx);
  VecX zeta0(nz);
  for (Eigen::Index k = 0; k < nz; ++k) zeta0[k] = p.v[velocities[static_cast<std::size_t>(k)]];
  MatX A(nx + nz, nx + nz);
  VecX plus, minus, coarse, d, xi, zeta;
  for (Eigen::Index k = 0; k < nx; ++k) {
    detail::richardson_difference(
        [&](double s, VecX& out) {
          xi = xi0;
          xi[k] += s;
          moving.evaluate(xi, zeta0, out);
        },
        steps.configuration(positions[static_cast<std::size_t>(k)], p.q), plus, minus, coarse, d);
    A.col(k) = d;
  }
  for (Eigen::Index k = 0; k < nz; ++k) {
    detail::central_difference(
        [&](double s, VecX& out) {
          zeta = zeta0;
          zeta[k] += s;
          moving.evaluate(xi0, zeta, out);
        },
        detail::kExactStep, plus, minus, d);
    A.col(nx + k) = d;
  }
  detail::check_derivative_finite(A, "rolling steady motion: the linearization");

  RollingSteadyModes result;
  result.motion = motion;
  result.coordinates = positions;
  std::vector<std::string> names;
  for (int i : positions) names.push_back(detail::tangent_name(model, i));
  for (int i : velocities) names.push_back(model.v_name(i));
  // Eigenvalues: the zero ones counted, each conjugate pair once, ascending |λ|.
  const double r = body.info.radius;
  const Vec3 w = motion.precession * body.up_W +
                 motion.relative_spin * detail::body_pose(body, p.q).R * body.axis_B;
  const double scale = std::sqrt(body.g / r + w.squaredNorm() + std::pow(motion.speed / r, 2));
  const Eigen::EigenSolver<MatX> eigen(A, true);
  const std::vector<bool> across_floor = translation_states(body, positions, nx + nz);
  for (Eigen::Index i = 0; i < eigen.eigenvalues().size(); ++i) {
    const std::complex<double> z = eigen.eigenvalues()[i];
    if (std::abs(z) <= kZeroEigenvalue * scale) {
      ++result.zero_eigenvalues;
      continue;
    }
    if (z.imag() < 0.0) continue;
    if (moves_only(eigen.eigenvectors().col(i), across_floor)) {
      result.circle_shift.push_back(z);
    } else {
      result.eigenvalues.push_back(z);
    }
    result.growth_rate = std::max(result.growth_rate, z.real());
  }
  std::sort(result.eigenvalues.begin(), result.eigenvalues.end(),
            [](const auto& a, const auto& b) { return std::abs(a) < std::abs(b); });
  result.stable = !(result.growth_rate > kZeroEigenvalue * scale);
  if (result.stable) result.growth_rate = 0.0;
  result.reduced =
      StateSpace(std::move(A), MatX(nx + nz, 0), MatX(0, nx + nz), MatX(0, 0), names, {}, {});
  return result;
}

}  // namespace momenta::analysis
