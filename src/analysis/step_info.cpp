#include "momenta/analysis/step_info.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

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
  return step_info(step_response(system, input, grid), output, final_value, settling_band);
}

}  // namespace momenta::analysis
