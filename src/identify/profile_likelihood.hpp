#pragma once
// Internal to momenta::identify: profile-likelihood intervals of the grey-box fit (grey_box.cpp),
// for parameters whose cost is clearly not quadratic over their Fisher interval.
//
// With S(p) the weighted sum of squares and s² its scale (1 with every noise given, else the
// optimum's χ²/(N − n_p)), the profile of parameter i is S_i(c) = min over the others of S with
// p_i = c, and its signed root z(c) = sign(c − p̂_i) √((S_i(c) − S(p̂))/s²). The 95 % profile
// interval is where |z| ≤ q, q the quantile the Fisher interval p̂ ± q·SE uses: where S is
// quadratic, z is linear, (c − p̂_i)/SE_i, and the two intervals agree.

#include <vector>

#include "grey_box_residuals.hpp"
#include "momenta/identify/grey_box.hpp"
#include "momenta/math/types.hpp"

namespace momenta::identify::detail {

/// One end of a profile interval: the value where |z| = q, or — when the data do not bound the
/// parameter on that side — the bound or the last value reached, with `bounded` false.
struct ProfileEnd {
  double value = 0.0;
  bool bounded = true;
  /// Not bounded because the fits failed beyond `value` (values the model refuses, runs that
  /// blow up): the profile could not be followed further.
  bool fits_failed = false;
};

struct ProfileInterval {
  ProfileEnd lower, upper;
};

class ProfileLikelihood {
 public:
  /// At the optimum `theta` (θ = ln p for positive parameters) with S(p̂) = `best_sum_squares`.
  ProfileLikelihood(RunResiduals& cost, const Parameterization& scale,
                    const std::vector<GreyBoxParameter>& parameters, std::vector<double> theta,
                    double best_sum_squares, double s2, int max_iterations);

  /// The signed root z at p_i = p̂_i + δ along the line where, to first order, the others follow
  /// (δ p_j = δ cov_ji / cov_ii) — without refitting: how far S is from quadratic at the ends
  /// of the Fisher interval (z = ±q when it is). NaN where the line leaves a bound.
  double linear_root(Eigen::Index i, double delta, const MatX& covariance);

  /// The 95 % profile interval of parameter i: |z| = q found on each side by secant steps in θ
  /// (to 10⁻⁶ of q), starting from the Fisher interval's ends; each z a fit of the others with
  /// θ_i held (from where the covariance predicts them).
  ProfileInterval interval(Eigen::Index i, double q, const MatX& covariance);

  long fits() const { return fits_; }

 private:
  // z at θ_i = value: the others refitted (from `start`, updated to their optimum).
  double profile_root(Eigen::Index i, double value, std::vector<double>& start);
  ProfileEnd side(Eigen::Index i, double sign, double q, double se_theta, const VecX& follow_theta);

  RunResiduals& cost_;
  const Parameterization& scale_;
  const std::vector<GreyBoxParameter>& parameters_;
  std::vector<double> theta_;
  double best_, s2_;
  int max_iterations_;
  long fits_ = 0;
};

}  // namespace momenta::identify::detail
