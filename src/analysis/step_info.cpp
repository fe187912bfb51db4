#include "momenta/analysis/step_info.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <fmt/format.h>
#include <boost/math/tools/toms748_solve.hpp>

#include "momenta/analysis/transfer_function.hpp"
#include "momenta/common/error.hpp"

namespace momenta::analysis {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Time at which the samples (t, y) first reach `level` going up (y measured along the
// direction of the final value), interpolated linearly; NaN if never.
double first_crossing(const VecX& t, const VecX& y, double level) {
  if (y[0] >= level) return t[0];
  for (Eigen::Index k = 1; k < y.size(); ++k) {
    if (y[k] >= level) {
      return t[k - 1] + (level - y[k - 1]) / (y[k] - y[k - 1]) * (t[k] - t[k - 1]);
    }
  }
  return kNaN;
}

// The unit step response of one input–output pair, exact at any time: the state is
// x(t) = Γ(t) b with Γ(t) = ∫₀ᵗ e^{Aτ} dτ and the rate ẏ(t) = C e^{At} b, both from the exponential
// of [A b; 0 0] t (Van Loan), which zero_order_hold computes.
class AnalyticStep {
 public:
  AnalyticStep(const StateSpace& system, std::size_t input, std::size_t output)
      : A_(system.A()),
        b_(system.B().col(static_cast<Eigen::Index>(input))),
        c_(system.C().row(static_cast<Eigen::Index>(output)).transpose()),
        d_(system.D()(static_cast<Eigen::Index>(output), static_cast<Eigen::Index>(input))) {}

  double value(double t) const {
    if (t <= 0.0 || A_.rows() == 0) return d_;
    return c_.dot(zero_order_hold(A_, b_, t).input.col(0)) + d_;
  }
  double rate(double t) const {
    if (A_.rows() == 0) return 0.0;
    if (t <= 0.0) return c_.dot(b_);
    return c_.dot(zero_order_hold(A_, b_, t).transition * b_);
  }

 private:
  MatX A_;
  VecX b_, c_;
  double d_;
};

// The root of f in [a, b], where f(a) and f(b) differ in sign, to full double precision (TOMS
// 748); NaN when they do not bracket one.
template <class F>
double root_between(F f, double a, double b) {
  const double fa = f(a), fb = f(b);
  if (fa == 0.0) return a;
  if (fb == 0.0) return b;
  if ((fa > 0.0) == (fb > 0.0) || !std::isfinite(fa) || !std::isfinite(fb)) return kNaN;
  std::uintmax_t iterations = 200;
  const auto [lo, hi] = boost::math::tools::toms748_solve(
      f, a, b, fa, fb, boost::math::tools::eps_tolerance<double>(), iterations);
  return 0.5 * (lo + hi);
}

// The time of the extremum a sampled extreme at sample k stands for: the root of ẏ in the
// interval on either side of it; the sample's own time at the grid's ends or when ẏ keeps its
// sign (a corner the grid does not resolve).
double extremum_time(const AnalyticStep& s, const VecX& t, Eigen::Index k) {
  if (k == 0 || k + 1 >= t.size()) return t[k];
  const auto rate = [&](double time) { return s.rate(time); };
  double at = root_between(rate, t[k - 1], t[k]);
  if (std::isnan(at)) at = root_between(rate, t[k], t[k + 1]);
  return std::isnan(at) ? t[k] : at;
}

}  // namespace

StepInfo step_info(const TimeResponse& response, std::size_t output, double final_value,
                   double settling_band) {
  if (output >= static_cast<std::size_t>(response.outputs.cols())) {
    throw InvalidArgument(fmt::format("step_info: output index {} but the response has {} outputs",
                                      output, response.outputs.cols()));
  }
  if (!(settling_band > 0.0 && settling_band < 1.0)) {
    throw InvalidArgument(
        fmt::format("step_info: settling band {} must lie in (0, 1), e.g. 0.02", settling_band));
  }
  const VecX y = response.outputs.col(static_cast<Eigen::Index>(output));
  const VecX& t = response.time;
  StepInfo info{final_value, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN};

  // Peak: largest |y| sample.
  Eigen::Index peak = 0;
  info.peak = y.cwiseAbs().maxCoeff(&peak);
  info.peak_time = t[peak];
  if (!std::isfinite(final_value) || final_value == 0.0 || y.size() == 0) return info;

  // Work along the direction of the final value, normalized: z → 1.
  const VecX z = y / final_value;
  info.rise_time = first_crossing(t, z, 0.9) - first_crossing(t, z, 0.1);
  info.overshoot = std::max(0.0, z.maxCoeff() - 1.0) * 100.0;
  info.undershoot = std::max(0.0, -z.minCoeff()) * 100.0;

  // Settling: the last sample outside the band; interpolate the exit between it and the next.
  Eigen::Index last_outside = -1;
  for (Eigen::Index k = z.size() - 1; k >= 0; --k) {
    if (std::abs(z[k] - 1.0) > settling_band) {
      last_outside = k;
      break;
    }
  }
  if (last_outside < 0) {
    info.settling_time = t[0];
  } else if (last_outside + 1 < z.size()) {
    const Eigen::Index k = last_outside;
    const double edge = z[k] > 1.0 ? 1.0 + settling_band : 1.0 - settling_band;
    info.settling_time = t[k] + (edge - z[k]) / (z[k + 1] - z[k]) * (t[k + 1] - t[k]);
  }
  return info;
}

StepInfo step_info(const StateSpace& system, std::size_t input, std::size_t output,
                   const TimeGrid& grid, double settling_band) {
  const double final_value = dc_gain(system, input, output);
  const TimeResponse sampled = step_response(system, input, grid);
  // The sampled figures (and the argument checks); each is then refined on the exact response.
  StepInfo info = step_info(sampled, output, final_value, settling_band);
  const AnalyticStep s(system, input, output);
  const VecX& t = sampled.time;
  const VecX y = sampled.outputs.col(static_cast<Eigen::Index>(output));

  // Peak: the largest |y|, at a root of ẏ.
  Eigen::Index k = 0;
  y.cwiseAbs().maxCoeff(&k);
  info.peak_time = extremum_time(s, t, k);
  info.peak = std::abs(s.value(info.peak_time));
  if (!std::isfinite(final_value) || final_value == 0.0) return info;

  // Along the direction of the final value, normalized: z → 1.
  const VecX z = y / final_value;
  const auto z_at = [&](double time) { return s.value(time) / final_value; };
  // The first time z reaches `level`: a root of z(t) − level in the first sample interval
  // that ends at or above it.
  const auto reaches = [&](double level) {
    for (Eigen::Index j = 0; j < z.size(); ++j) {
      if (z[j] < level) continue;
      if (j == 0) return t[0];
      const double at =
          root_between([&](double time) { return z_at(time) - level; }, t[j - 1], t[j]);
      return std::isnan(at) ? t[j] : at;
    }
    return kNaN;
  };
  info.rise_time = reaches(0.9) - reaches(0.1);
  z.maxCoeff(&k);
  info.overshoot = std::max(0.0, z_at(extremum_time(s, t, k)) - 1.0) * 100.0;
  z.minCoeff(&k);
  info.undershoot = std::max(0.0, -z_at(extremum_time(s, t, k))) * 100.0;

  // Settling: the exit from the band after the last sample outside it.
  Eigen::Index last_outside = -1;
  for (Eigen::Index j = z.size() - 1; j >= 0; --j) {
    if (std::abs(z[j] - 1.0) > settling_band) {
      last_outside = j;
      break;
    }
  }
  if (last_outside >= 0 && last_outside + 1 < z.size()) {
    const Eigen::Index j = last_outside;
    const double edge = z[j] > 1.0 ? 1.0 + settling_band : 1.0 - settling_band;
    const double at = root_between([&](double time) { return z_at(time) - edge; }, t[j], t[j + 1]);
    if (!std::isnan(at)) info.settling_time = at;
  }
  return info;
}

}  // namespace momenta::analysis
