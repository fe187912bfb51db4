#include "momenta/identify/base_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include <fmt/format.h>
#include <Eigen/QR>

#include "momenta/common/number_text.hpp"
#include "momenta/identify/inertial_regressor.hpp"

namespace momenta::identify {
namespace {

// The regressor stacked over random states: rows num_states · nv.
MatX stacked_regressor(const Model& model, int num_states, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), rate(-1.0, 1.0);
  const int nv = model.nv();
  const VecX q_neutral = model::neutral(model);
  InertialRegressor regressor(model);
  MatX W(static_cast<Eigen::Index>(num_states) * nv, num_inertial_parameters(model));
  VecX tangent(nv), v(nv), vdot(nv);
  for (int s = 0; s < num_states; ++s) {
    for (int i = 0; i < nv; ++i) tangent[i] = angle(rng);
    for (int i = 0; i < nv; ++i) v[i] = rate(rng);
    for (int i = 0; i < nv; ++i) vdot[i] = rate(rng);
    const VecX q = model::integrate(model, q_neutral, tangent, 1.0);
    W.middleRows(static_cast<Eigen::Index>(s) * nv, nv) = regressor.compute(q, v, vdot);
  }
  return W;
}

}  // namespace

BaseParameters base_parameters(const Model& model, int num_states, unsigned seed) {
  BaseParameters base;
  base.num_parameters = num_inertial_parameters(model);
  const int n = base.num_parameters;
  if (n == 0 || model.nv() == 0) {
    base.regrouping = MatX::Zero(0, n);
    for (int k = 0; k < n; ++k) base.dependent.push_back(k), base.no_effect.push_back(k);
    return base;
  }
  if (num_states <= 0) num_states = std::max(8, (4 * n + model.nv() - 1) / model.nv());
  const MatX W = stacked_regressor(model, num_states, seed);

  // Gram–Schmidt (twice, for orthogonality to round-off) on the unit columns, in π's order.
  const VecX norms = W.colwise().norm();
  const double largest = norms.maxCoeff();
  MatX Q(W.rows(), n);
  int kept = 0;
  for (int k = 0; k < n; ++k) {
    if (!(norms[k] > 1e-12 * largest)) {
      base.dependent.push_back(k);
      base.no_effect.push_back(k);
      continue;
    }
    VecX w = W.col(k) / norms[k];
    for (int pass = 0; pass < 2; ++pass) {
      w -= Q.leftCols(kept) * (Q.leftCols(kept).transpose() * w);
    }
    const double distance = w.norm();
    if (distance > kIndependenceTolerance) {
      Q.col(kept++) = w / distance;
      base.independent.push_back(k);
    } else {
      base.dependent.push_back(k);
    }
  }

  // Y_D = Y_I K_d by least squares on the full-rank Y_I; coefficients whose share of a column is
  // round-off are zero.
  const int r = kept;
  MatX W_I(W.rows(), r), W_D(W.rows(), static_cast<Eigen::Index>(base.dependent.size()));
  for (int i = 0; i < r; ++i) W_I.col(i) = W.col(base.independent[i]);
  for (std::size_t d = 0; d < base.dependent.size(); ++d) W_D.col(d) = W.col(base.dependent[d]);
  MatX K_d = W_I.householderQr().solve(W_D);
  for (Eigen::Index d = 0; d < K_d.cols(); ++d) {
    for (int i = 0; i < r; ++i) {
      if (std::abs(K_d(i, d)) * norms[base.independent[i]] <= 1e-10 * norms[base.dependent[d]])
        K_d(i, d) = 0.0;
    }
  }
  base.regrouping = MatX::Zero(r, n);
  for (int i = 0; i < r; ++i) base.regrouping(i, base.independent[i]) = 1.0;
  for (std::size_t d = 0; d < base.dependent.size(); ++d) {
    base.regrouping.col(base.dependent[d]) = K_d.col(static_cast<Eigen::Index>(d));
  }
  return base;
}

std::vector<int> BaseParameters::regrouped() const {
  std::vector<int> out;
  for (int d : dependent) {
    if (std::find(no_effect.begin(), no_effect.end(), d) == no_effect.end()) out.push_back(d);
  }
  return out;
}

std::string BaseParameters::describe(const Model& model, int k) const {
  std::string text = parameter_name(model, independent.at(k));
  for (int d : dependent) {
    const double c = regrouping(k, d);
    if (c == 0.0) continue;
    text += fmt::format(" {} {}·{}", c < 0 ? "−" : "+", number_text(std::abs(c), 6),
                        parameter_name(model, d));
  }
  return text;
}

}  // namespace momenta::identify
