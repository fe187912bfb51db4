#include "momenta/identify/inertia_estimate.hpp"

#include <array>
#include <cmath>

#include <fmt/format.h>
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <boost/math/distributions/students_t.hpp>

#include "momenta/common/error.hpp"
#include "momenta/identify/inertial_regressor.hpp"
#include "momenta/inertia/mass_properties.hpp"
#include "residual_whiteness.hpp"

namespace momenta::identify {
namespace {

void check_samples(const Model& model, const InertiaSamples& s) {
  const Eigen::Index n = s.q.rows();
  const auto check = [&](const MatX& m, const char* name, int cols, const char* what) {
    if (m.rows() != n || m.cols() != cols) {
      throw InvalidArgument(fmt::format(
          "estimate_inertia: {} is {} × {}; expected {} × {} (one row per sample, {} columns)",
          name, m.rows(), m.cols(), n, cols, what));
    }
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
      for (Eigen::Index j = 0; j < m.cols(); ++j) {
        if (!std::isfinite(m(i, j))) {
          throw InvalidArgument(
              fmt::format("estimate_inertia: {} row {} column {} is {}: "
                          "measured data must be finite",
                          name, i, j, m(i, j)));
        }
      }
    }
  };
  check(s.q, "q", model.nq(), "nq");
  check(s.v, "v", model.nv(), "nv");
  check(s.vdot, "vdot", model.nv(), "nv");
  check(s.tau, "tau", model.nv(), "nv");
}

// The model's own size of parameter k: a mass the bodies' mean mass M, a first moment M L, an
// inertia M L², with L the bodies' radius of gyration about their own origins, √(Σ tr I_O / 2
// Σ m) (1 m for a model without mass, where any scale serves).
double parameter_scale(const Model& model, int k) {
  double mass = 0.0, trace = 0.0;
  for (int b = 1; b < model.num_bodies(); ++b) {
    mass += model.spatial_inertia(b).mass;
    trace += model.spatial_inertia(b).I_O.trace();
  }
  const double M = mass > 0.0 ? mass / (model.num_bodies() - 1) : 1.0;
  const double L = mass > 0.0 && trace > 0.0 ? std::sqrt(trace / (2.0 * mass)) : 1.0;
  const int kind = k % kParametersPerBody;
  return kind == 0 ? M : kind < 4 ? M * L : M * L * L;
}

// Row and column of I_O's entry k (4 … 9 of a body's ten).
constexpr int kEntryRow[10] = {0, 0, 0, 0, 0, 0, 0, 1, 1, 2};
constexpr int kEntryCol[10] = {0, 0, 0, 0, 0, 1, 2, 1, 2, 2};

// An inertia about the centre I_C whose `fixed` entries equal `target`'s and whose second moment
// Σ = ½ tr(I_C) 1 − I_C is positive semidefinite — what a mass distribution has (the triangle
// inequalities and positive moments together; Wensing, Kim & Slotine 2017) — where one exists:
// alternating projections between the two sets, from `start` (von Neumann; they reach a point
// of the intersection where it is not empty). The fixed entries are exact in the result.
Mat3 consistent_completion(const Mat3& start, const Mat3& target,
                           const std::array<bool, 10>& fixed) {
  const auto impose = [&](Mat3& I) {
    for (int k = 4; k < 10; ++k) {
      if (!fixed[k]) continue;
      I(kEntryRow[k], kEntryCol[k]) = I(kEntryCol[k], kEntryRow[k]) =
          target(kEntryRow[k], kEntryCol[k]);
    }
  };
  Mat3 I = start;
  impose(I);
  for (int iteration = 0; iteration < 2000; ++iteration) {
    const Mat3 sigma = 0.5 * I.trace() * Mat3::Identity() - I;
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(sigma);
    if (eigen.eigenvalues()[0] >=
        -1e-15 * std::max(eigen.eigenvalues().cwiseAbs().maxCoeff(), 1e-300))
      break;
    const Mat3 projected = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() *
                           eigen.eigenvectors().transpose();
    I = projected.trace() * Mat3::Identity() - projected;
    impose(I);
  }
  return I;
}

// A π with regrouping π = β: the independent parameters solved from β with the model's values
// for the regrouped ones. Then each body's never-felt entries, which change no joint force:
// first moments at the model's centre-of-mass coordinates times the estimated mass, and the
// inertia's never-felt entries chosen so that the body can exist (consistent_completion) from
// the model's inertia about its centre carried to the estimated centre.
VecX completed_parameters(const Model& model, const BaseParameters& base, const VecX& beta) {
  VecX pi = inertial_parameters(model);
  const VecX dependent_share = base.regrouping * pi;
  for (int i = 0; i < base.rank(); ++i) {
    const int k = base.independent[i];
    pi[k] = beta[i] - (dependent_share[i] - pi[k]);
  }
  std::vector<bool> never_felt(pi.size(), false);
  for (int k : base.no_effect) never_felt[k] = true;
  for (int body = 1; body < model.num_bodies(); ++body) {
    const int first = kParametersPerBody * (body - 1);
    const double m = pi[first];
    const SpatialInertia& prior = model.spatial_inertia(body);
    if (!(m > 0.0) || !(prior.mass > 0.0)) continue;
    const Vec3 c_prior = prior.h / prior.mass;
    for (int a = 0; a < 3; ++a) {
      if (never_felt[first + 1 + a]) pi[first + 1 + a] = m * c_prior[a];
    }
    const Vec3 c = pi.segment<3>(first + 1) / m;
    using inertia::point_mass_inertia;  // the parallel-axis term
    const Mat3 I_C_prior = prior.I_O - point_mass_inertia(prior.mass, c_prior);
    const Mat3 I_C_estimated =
        spatial_inertia_of(pi.segment<kParametersPerBody>(first)).I_O - point_mass_inertia(m, c);
    std::array<bool, 10> felt{};
    for (int k = 4; k < kParametersPerBody; ++k) felt[k] = !never_felt[first + k];
    const Mat3 I_O =
        consistent_completion(I_C_prior, I_C_estimated, felt) + point_mass_inertia(m, c);
    const Vec10 completed = parameters_of({m, m * c, I_O});
    for (int k = 4; k < kParametersPerBody; ++k) {
      if (never_felt[first + k]) pi[first + k] = completed[k];
    }
  }
  return pi;
}

}  // namespace

InertiaEstimate estimate_inertia(const Model& model, const InertiaSamples& samples,
                                 const BaseParameters& base) {
  check_samples(model, samples);
  if (base.num_parameters != num_inertial_parameters(model)) {
    throw InvalidArgument(fmt::format(
        "estimate_inertia: the base parameters are of a model with {} inertial parameters; "
        "this one has {}",
        base.num_parameters, num_inertial_parameters(model)));
  }
  const int N = static_cast<int>(samples.q.rows()), nv = model.nv(), r = base.rank();
  const Eigen::Index rows = static_cast<Eigen::Index>(N) * nv;
  if (rows <= r) {
    throw InvalidArgument(fmt::format(
        "estimate_inertia: {} samples × {} joint coordinates give {} equations for {} base "
        "parameters; at least {} samples are needed (and many more, at states that excite every "
        "parameter, for a useful estimate)",
        N, nv, rows, r, r / nv + 1));
  }

  // The stacked system Y_I β = τ − armature ∘ v̇, equations of sample s at rows s nv …
  InertialRegressor regressor(model);
  MatX A(rows, r);
  VecX b(rows);
  for (int s = 0; s < N; ++s) {
    const VecX q = samples.q.row(s).transpose(), v = samples.v.row(s).transpose(),
               vdot = samples.vdot.row(s).transpose();
    const MatX& Y = regressor.compute(q, v, vdot);
    for (int i = 0; i < r; ++i) A.block(s * nv, i, nv, 1) = Y.col(base.independent[i]);
    b.segment(s * nv, nv) = samples.tau.row(s).transpose() - regressor.armature_torque(vdot);
  }
  const Eigen::ColPivHouseholderQR<MatX> unweighted(A);
  if (unweighted.rank() < r) {
    throw InvalidArgument(fmt::format(
        "estimate_inertia: the samples excite only {} of the {} base parameters (the stacked "
        "regressor's rank): move every joint, with varied speeds and accelerations",
        unweighted.rank(), r));
  }

  InertiaEstimate e;
  e.base = base;
  e.samples = N;
  e.degrees_of_freedom = static_cast<int>(rows) - r;
  const double dof_correction = std::sqrt(double(rows) / e.degrees_of_freedom);
  const auto joint_rms = [&](const VecX& residual) {
    VecX rms = VecX::Zero(nv);
    for (int s = 0; s < N; ++s) rms += residual.segment(s * nv, nv).cwiseAbs2();
    return VecX((rms / N).cwiseSqrt());
  };

  // Each joint's noise from the unweighted fit, floored where a joint's data is exact.
  const VecX residual0 = b - A * unweighted.solve(b);
  e.noise = joint_rms(residual0) * dof_correction;
  const double floor = 1e-12 * std::max(b.cwiseAbs().maxCoeff(), 1e-300);
  for (int j = 0; j < nv; ++j) e.noise[j] = std::max(e.noise[j], floor);

  MatX Aw = A;
  VecX bw = b;
  for (int s = 0; s < N; ++s) {
    for (int j = 0; j < nv; ++j) {
      Aw.row(s * nv + j) /= e.noise[j];
      bw[s * nv + j] /= e.noise[j];
    }
  }
  const Eigen::ColPivHouseholderQR<MatX> weighted(Aw);
  e.beta = weighted.solve(bw);
  const VecX residual_w = bw - Aw * e.beta;
  const double s2 = residual_w.squaredNorm() / e.degrees_of_freedom;
  // (Aᵀ A)⁻¹ from R: P R⁻¹ R⁻ᵀ Pᵀ.
  const MatX R = weighted.matrixR().topLeftCorner(r, r).triangularView<Eigen::Upper>();
  const MatX R_inv = R.triangularView<Eigen::Upper>().solve(MatX::Identity(r, r));
  const MatX P = weighted.colsPermutation();
  e.covariance = s2 * P * R_inv * R_inv.transpose() * P.transpose();
  e.standard_error = e.covariance.diagonal().cwiseSqrt();
  // Correlations; a parameter the data fixes exactly (exact efforts: zero standard error) is
  // uncorrelated with the rest rather than 0/0.
  const VecX inverse_se =
      (e.standard_error.array() > 0.0).select(e.standard_error.cwiseInverse(), 0.0);
  e.correlation = inverse_se.asDiagonal() * e.covariance * inverse_se.asDiagonal();
  e.correlation.diagonal().setOnes();

  const boost::math::students_t t(e.degrees_of_freedom);
  const double t975 = boost::math::quantile(t, 0.975);
  e.lower = e.beta - t975 * e.standard_error;
  e.upper = e.beta + t975 * e.standard_error;
  const VecX fitted = A * e.beta;
  e.residual_rms = joint_rms(b - fitted);
  e.fitted = samples.tau;
  for (int s = 0; s < N; ++s) {
    e.fitted.row(s) += (fitted.segment(s * nv, nv) - b.segment(s * nv, nv)).transpose();
  }

  // Excitation: the weighted regressor's singular values with each column scaled by the model's
  // own size of its parameter (parameter_scale).
  VecX scale(r);
  for (int i = 0; i < r; ++i) scale[i] = parameter_scale(model, base.independent[i]);
  const MatX scaled = Aw * scale.asDiagonal();
  const Eigen::JacobiSVD<MatX> svd(scaled, Eigen::ComputeThinV);
  const VecX& sigma = svd.singularValues();
  e.excitation = sigma / sigma[0];
  e.condition_number = sigma[0] / sigma[r - 1];
  e.least_determined = svd.matrixV().col(r - 1);
  if (e.least_determined.cwiseAbs().maxCoeff() != e.least_determined.maxCoeff())
    e.least_determined = -e.least_determined;  // its largest entry positive: one sign every call

  // Whiteness of each joint's residuals, in sample order.
  e.whiteness_lags = detail::whiteness_lags(N);
  e.whiteness_p = VecX::Ones(nv);
  const VecX residual = b - fitted;
  for (int j = 0; j < nv; ++j) {
    VecX sequence(N);
    for (int s = 0; s < N; ++s) sequence[s] = residual[s * nv + j];
    e.whiteness_p[j] = detail::ljung_box_p(sequence, e.whiteness_lags);
  }

  e.parameters = completed_parameters(model, base, e.beta);
  for (int body = 1; body < model.num_bodies(); ++body) {
    e.consistency.push_back(physical_consistency(
        e.parameters.segment<kParametersPerBody>(kParametersPerBody * (body - 1))));
  }
  return e;
}

}  // namespace momenta::identify
