// The textbook first- and second-order systems every control course starts from
// (Franklin, Powell & Emami-Naeini ch. 3 and 6; Ogata, Modern Control Engineering ch. 5).

#include <cmath>

#include <gtest/gtest.h>

#include "momenta/analysis/frequency_response.hpp"
#include "momenta/analysis/modes.hpp"
#include "momenta/analysis/time_response.hpp"
#include "momenta/analysis/transfer_function.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

TEST(FirstOrderLag, CornerFrequencyIsMinus3DbAndMinus45Degrees) {
  // G(s) = 1/(s + 1): |G(j1)| = 1/√2 = −3.0103 dB, arg G(j1) = −45°.
  MatX a(1, 1), b(1, 1), c(1, 1);
  a << -1;
  b << 1;
  c << 1;
  const FrequencyResponse fr = frequency_response(StateSpace(a, b, c, MatX()), 0, 0, 0.01, 100, 5);
  EXPECT_EQ(fr.frequency[2], 1.0);
  EXPECT_NEAR(fr.magnitude_db[2], 20 * std::log10(1 / std::sqrt(2.0)), 1e-14);
  EXPECT_NEAR(fr.magnitude_db[2], -3.0103, 5e-5);  // the number on every Bode chart
  EXPECT_NEAR(fr.phase_deg[2], -45.0, 1e-13);
  // Asymptotes: −20 dB/decade and −90° two decades above the corner (to 1e-4 dB, 0.6°).
  EXPECT_NEAR(fr.magnitude_db[4], -40.0, 5e-4);
  EXPECT_NEAR(fr.phase_deg[4], -90.0 + std::atan(0.01) * 180 / M_PI, 1e-12);
}

TEST(SecondOrderSystem, ModesOvershootAndPeakTime) {
  // G(s) = ωn²/(s² + 2ζωn s + ωn²): poles with |λ| = ωn, −Re λ/|λ| = ζ; step peak overshoot
  // Mp = exp(−πζ/√(1−ζ²)) at tp = π/ωd.
  const double wn = 4.0, zeta = 0.25;
  MatX A(2, 2), B(2, 1), C(1, 2);
  A << 0, 1, -wn * wn, -2 * zeta * wn;
  B << 0, wn * wn;
  C << 1, 0;
  const StateSpace system(A, B, C, MatX());
  for (const Mode& mode : modes(system).modes) {
    EXPECT_REL_NEAR(mode.natural_frequency, wn, 1e-15);
    EXPECT_REL_NEAR(mode.damping_ratio, zeta, 1e-14);
  }
  const TransferFunction tf = transfer_function(system, 0, 0);
  EXPECT_REL_NEAR(tf.dc_gain, 1.0, 1e-15);

  const double wd = wn * std::sqrt(1 - zeta * zeta);
  const TimeResponse r = step_response(system, 0, {3.0, 30001});
  const double h = 3.0 / 30000;
  Eigen::Index peak = 0;
  const double y_max = r.outputs.col(0).maxCoeff(&peak);
  // The sampled maximum misses the true one by at most ½ |y''(tp)| (h/2)² with
  // |y''| = |g'| ≤ ωn²/√(1−ζ²) (g the impulse response); tp by at most h/2.
  const double miss = 0.5 * wn * wn / std::sqrt(1 - zeta * zeta) * (h / 2) * (h / 2);
  EXPECT_NEAR(y_max, 1 + std::exp(-M_PI * zeta / std::sqrt(1 - zeta * zeta)), miss + 1e-13);
  EXPECT_NEAR(r.time[peak], M_PI / wd, h / 2 + 1e-12);
}

}  // namespace
}  // namespace momenta::analysis
