// Satellite attitude, Franklin, Powell & Emami-Naeini, ch. 2: I θ̈ = T (thruster torque
// T = Fc d; disturbance left out). G(s) = Θ/T = 1/(I s²): a double pole at the origin, no
// zeros. Unit step torque: θ(t) = t²/(2I); unit impulse: θ(t) = t/I. Bode: |G(jω)| = 1/(I ω²),
// a −40 dB/decade line, and phase −180° at every frequency.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "momenta/analysis/frequency_response.hpp"
#include "momenta/analysis/modes.hpp"
#include "momenta/analysis/time_response.hpp"
#include "momenta/analysis/transfer_function.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

constexpr double kInertia = 2500.0;  // kg·m², a small satellite about one axis

StateSpace satellite() {
  MatX A(2, 2), B(2, 1), C(1, 2);
  A << 0, 1, 0, 0;
  B << 0, 1.0 / kInertia;
  C << 1, 0;
  return StateSpace(A, B, C, MatX(), {"theta", "theta_dot"}, {"torque"}, {"theta"});
}

TEST(SatelliteAttitude, DoublePoleAtTheOrigin) {
  const TransferFunction tf = transfer_function(satellite(), 0, 0);
  ASSERT_EQ(tf.poles.size(), 2u);
  EXPECT_EQ(tf.poles[0], Complex(0.0, 0.0));
  EXPECT_EQ(tf.poles[1], Complex(0.0, 0.0));
  EXPECT_TRUE(tf.zeros.empty());
  EXPECT_REL_NEAR(tf.gain, 1.0 / kInertia, 1e-15);
  EXPECT_EQ(tf.dc_gain, std::numeric_limits<double>::infinity());
  // Rigid-body modes: ωn = 0, ζ undefined.
  for (const Mode& mode : modes(satellite()).modes) {
    EXPECT_EQ(mode.natural_frequency, 0.0);
    EXPECT_TRUE(std::isnan(mode.damping_ratio));
  }
}

TEST(SatelliteAttitude, StepIsAParabolaImpulseARamp) {
  // No time scale in the poles: automatic horizon 10 s.
  const TimeResponse step = step_response(satellite(), 0);
  const TimeResponse impulse = impulse_response(satellite(), 0);
  EXPECT_EQ(step.time[step.time.size() - 1], 10.0);
  for (Eigen::Index k = 0; k < step.time.size(); ++k) {
    const double t = step.time[k];
    // Polynomial response from an exactly representable Φ = [1 h; 0 1]: round-off of ~500
    // additions, relative ~500 ε ≈ 1e-13 of the largest value.
    EXPECT_NEAR(step.outputs(k, 0), t * t / (2 * kInertia), 1e-13 * 100 / (2 * kInertia));
    EXPECT_NEAR(impulse.outputs(k, 0), t / kInertia, 1e-13 * 10 / kInertia);
    EXPECT_NEAR(step.states(k, 1), t / kInertia, 1e-13 * 10 / kInertia);
  }
}

TEST(SatelliteAttitude, BodeOfADoubleIntegrator) {
  const FrequencyResponse fr = frequency_response(satellite(), 0, 0, 1e-3, 1e2, 51);
  for (Eigen::Index k = 0; k < fr.frequency.size(); ++k) {
    const double w = fr.frequency[k];
    // Two divisions in a 2×2 Hessenberg solve: a few ε.
    EXPECT_REL_NEAR(fr.magnitude[k], 1.0 / (kInertia * w * w), 1e-14);
    EXPECT_NEAR(fr.phase_deg[k], -180.0, 1e-12);
  }
  // −40 dB per decade: 5 decades over 50 intervals.
  EXPECT_NEAR(fr.magnitude_db[50] - fr.magnitude_db[0], -200.0, 1e-11);
}

}  // namespace
}  // namespace momenta::analysis
