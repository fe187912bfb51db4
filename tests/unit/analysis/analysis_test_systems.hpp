#pragma once
// Hand-built state spaces shared by the analysis tests.

#include <random>

#include "momenta/analysis/state_space.hpp"

namespace momenta::analysis::test {

/// Controllable canonical form of
///   G(s) = (c₁ + c₂ s + … + cₙ s^(n−1)) / (s^n + a₁ s^(n−1) + … + aₙ) + d,
/// `denominator` = [a₁ … aₙ], `numerator` = [c₁ … cₙ] (lowest power first).
inline StateSpace canonical_form(const std::vector<double>& denominator,
                                 const std::vector<double>& numerator, double d = 0.0) {
  const auto n = static_cast<Eigen::Index>(denominator.size());
  MatX A = MatX::Zero(n, n);
  A.topRightCorner(n - 1, n - 1).setIdentity();
  for (Eigen::Index k = 0; k < n; ++k)
    A(n - 1, k) = -denominator[static_cast<std::size_t>(n - 1 - k)];
  MatX B = MatX::Zero(n, 1);
  B(n - 1, 0) = 1.0;
  MatX C(1, n);
  for (Eigen::Index k = 0; k < n; ++k) C(0, k) = numerator[static_cast<std::size_t>(k)];
  MatX D(1, 1);
  D << d;
  return StateSpace(A, B, C, D);
}

/// A random stable-ish MIMO system with entries uniform in [−1, 1] (fixed seed).
inline StateSpace random_system(int n, int m, int p, unsigned seed, bool feedthrough) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const auto fill = [&](int rows, int cols) {
    MatX X(rows, cols);
    for (int j = 0; j < cols; ++j) {
      for (int i = 0; i < rows; ++i) X(i, j) = uniform(generator);
    }
    return X;
  };
  MatX A = fill(n, n) - 1.5 * MatX::Identity(n, n);
  MatX B = fill(n, m);
  MatX C = fill(p, n);
  MatX D = feedthrough ? fill(p, m) : MatX::Zero(p, m);
  return StateSpace(A, B, C, D);
}

}  // namespace momenta::analysis::test
