#pragma once
// Internal to momenta::identify: whether a residual sequence is white — what both routes
// (inertia_estimate, grey_box) report per measured channel.

#include <algorithm>

#include "momenta/math/types.hpp"

namespace momenta::identify::detail {

/// The Ljung–Box statistic of a sequence over lags 1 … m and its p-value under χ²(m) (Ljung &
/// Box 1978): Q = N (N + 2) Σ ρ_k² / (N − k), ρ_k the sample autocorrelation at lag k. 1 for a
/// constant sequence or m < 1.
double ljung_box_p(const VecX& x, int m);

/// The lags the reports use: min(20, N / 5).
inline int whiteness_lags(Eigen::Index samples) {
  return static_cast<int>(std::min<Eigen::Index>(20, samples / 5));
}

}  // namespace momenta::identify::detail
