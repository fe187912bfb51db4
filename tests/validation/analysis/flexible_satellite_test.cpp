// Flexible satellite, Franklin, Powell & Emami-Naeini, Example 2.4 (the numbers of their
// Example 10.x design): two inertias joined by a torsional spring k and damper b, the control
// torque Tc on the first:
//   I1 θ̈1 + b (θ̇1 − θ̇2) + k (θ1 − θ2) = Tc
//   I2 θ̈2 + b (θ̇2 − θ̇1) + k (θ2 − θ1) = 0
// I1 = 1, I2 = 0.1 kg·m², k = 0.091 N·m/rad, b = 0.0036 N·m·s/rad. With
// Δ(s) = I1 I2 s² + b (I1 + I2) s + k (I1 + I2):
//   collocated     Θ1/Tc = (I2 s² + b s + k) / (s² Δ(s))
//   non-collocated Θ2/Tc = (b s + k)         / (s² Δ(s))
// Poles 0, 0 and the flexible pair ωn² = k (I1+I2)/(I1 I2), 2 ζ ωn = b (I1+I2)/(I1 I2)
// (ωn ≈ 1 rad/s, ζ ≈ 0.02); collocated zeros ωz² = k/I2, 2 ζz ωz = b/I2 (an antiresonance
// below the resonance); the non-collocated zero −k/b.

#include <cmath>

#include <gtest/gtest.h>

#include "momenta/analysis/frequency_response.hpp"
#include "momenta/analysis/modes.hpp"
#include "momenta/analysis/transfer_function.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

constexpr double I1 = 1.0;    // kg·m²
constexpr double I2 = 0.1;    // kg·m²
constexpr double k = 0.091;   // N·m/rad
constexpr double b = 0.0036;  // N·m·s/rad
constexpr double kDeg = 180.0 / M_PI;

const double wn = std::sqrt(k * (I1 + I2) / (I1 * I2));
const double zeta = b * (I1 + I2) / (I1 * I2) / (2 * wn);

// States [θ1, θ̇1, θ2, θ̇2], input Tc, outputs θ1 and θ2, by hand.
StateSpace flexible_satellite() {
  MatX A(4, 4), B(4, 1), C(2, 4);
  A << 0, 1, 0, 0,                       //
      -k / I1, -b / I1, k / I1, b / I1,  //
      0, 0, 0, 1,                        //
      k / I2, b / I2, -k / I2, -b / I2;
  B << 0, 1 / I1, 0, 0;
  C << 1, 0, 0, 0,  //
      0, 0, 1, 0;
  return StateSpace(A, B, C, MatX(), {"theta1", "theta1_dot", "theta2", "theta2_dot"}, {"Tc"},
                    {"theta1", "theta2"});
}

TEST(FlexibleSatellite, HandWrittenAndSecondOrderFormsAgree) {
  MatX M(2, 2), D(2, 2), K(2, 2), F(2, 1), Cq(2, 2), Cv(2, 2);
  M << I1, 0, 0, I2;
  D << b, -b, -b, b;
  K << k, -k, -k, k;
  F << 1, 0;
  Cq.setIdentity();
  Cv.setZero();
  const StateSpace second = second_order_state_space(M, D, K, F, Cq, Cv, {"theta1", "theta2"});
  // Reorder [θ1, θ2, θ̇1, θ̇2] → [θ1, θ̇1, θ2, θ̇2].
  Eigen::PermutationMatrix<4> P;
  P.indices() << 0, 2, 1, 3;
  const StateSpace hand = flexible_satellite();
  EXPECT_MATRIX_NEAR(P * second.A() * P.transpose(), hand.A(), 1e-15);
  EXPECT_MATRIX_NEAR(P * second.B(), hand.B(), 0.0);
}

TEST(FlexibleSatellite, PolesNaturalFrequencyAndDamping) {
  const Modes m = modes(flexible_satellite());
  ASSERT_EQ(m.modes.size(), 4u);
  // The rigid-body pair is a defective double eigenvalue at 0: found to ~√ε·‖A‖.
  EXPECT_LT(m.modes[0].natural_frequency, 1e-7);
  EXPECT_LT(m.modes[1].natural_frequency, 1e-7);
  // The flexible mode: simple eigenvalues, relative 1e-13.
  EXPECT_REL_NEAR(m.modes[2].natural_frequency, wn, 1e-13);
  EXPECT_REL_NEAR(m.modes[2].damping_ratio, zeta, 1e-12);
  EXPECT_REL_NEAR(m.modes[3].natural_frequency, wn, 1e-13);
  // In the flexible mode the inertias swing against each other with momentum balance
  // I1 θ1 + I2 θ2 = 0, so θ2/θ1 = −I1/I2 = −10.
  const VecXc& shape = m.modes[2].shape;
  const Complex ratio = shape[2] / shape[0];
  EXPECT_NEAR(ratio.real(), -I1 / I2, 1e-11);
  EXPECT_NEAR(ratio.imag(), 0.0, 1e-11);
}

TEST(FlexibleSatellite, CollocatedZerosBelowTheResonance) {
  const TransferFunction tf = transfer_function(flexible_satellite(), "Tc", "theta1");
  ASSERT_EQ(tf.zeros.size(), 2u);
  ASSERT_EQ(tf.poles.size(), 4u);
  const double wz = std::sqrt(k / I2);
  const double zeta_z = b / I2 / (2 * wz);
  // Closed-form zeros (−b ± j√(4 I2 k − b²))/(2 I2).
  const Complex z0(-b / (2 * I2), std::sqrt(4 * I2 * k - b * b) / (2 * I2));
  EXPECT_LT(std::abs(tf.zeros[0] - z0), 1e-13 * wz);
  EXPECT_LT(std::abs(tf.zeros[1] - std::conj(z0)), 1e-13 * wz);
  EXPECT_REL_NEAR(-tf.zeros[0].real() / std::abs(tf.zeros[0]), zeta_z, 1e-12);
  EXPECT_LT(wz, wn);  // antiresonance before resonance: collocated alternation
  EXPECT_REL_NEAR(tf.gain, 1 / I1, 1e-13);
}

TEST(FlexibleSatellite, NonCollocatedZero) {
  const TransferFunction tf = transfer_function(flexible_satellite(), "Tc", "theta2");
  ASSERT_EQ(tf.zeros.size(), 1u);
  EXPECT_EQ(tf.relative_degree(), 3);
  EXPECT_REL_NEAR(tf.zeros[0].real(), -k / b, 1e-12);
  EXPECT_REL_NEAR(tf.gain, b / (I1 * I2), 1e-12);
}

TEST(FlexibleSatellite, BodePhaseOfBothPairs) {
  // Phases from the closed-form factors, each continuous in ω (atan2 of the factor's real and
  // imaginary parts on s = jω): −180° for 1/s², + arg numerator − arg Δ(jω).
  const StateSpace system = flexible_satellite();
  const FrequencyResponse co = frequency_response(system, 0, 0, 0.01, 100.0, 400);
  const FrequencyResponse non = frequency_response(system, 0, 1, 0.01, 100.0, 400);
  for (Eigen::Index i = 0; i < co.frequency.size(); ++i) {
    const double w = co.frequency[i];
    const double delta = std::atan2(b * (I1 + I2) * w, k * (I1 + I2) - I1 * I2 * w * w) * kDeg;
    const double collocated = -180.0 + std::atan2(b * w, k - I2 * w * w) * kDeg - delta;
    const double noncollocated = -180.0 + std::atan2(b * w, k) * kDeg - delta;
    // Both are computed to round-off; the lightly damped factors amplify it near ωn and ωz
    // (|G| changes by 1/(2ζ) ≈ 25), hence 1e-9° rather than 1e-12°.
    EXPECT_NEAR(co.phase_deg[i], collocated, 1e-9) << "ω = " << w;
    EXPECT_NEAR(non.phase_deg[i], noncollocated, 1e-9) << "ω = " << w;
    // Collocated: poles and zeros alternate, the phase stays within [−180°, 0°].
    EXPECT_LE(co.phase_deg[i], 1e-9);
    EXPECT_GE(co.phase_deg[i], -180.0 - 1e-9);
  }
  // Non-collocated: the resonance takes the phase to −360° before the zero at k/b ≈ 25 rad/s
  // lifts it to −270°.
  EXPECT_LT(non.phase_deg[non.phase_deg.size() - 1], -265.0);
}

}  // namespace
}  // namespace momenta::analysis
