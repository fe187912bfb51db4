// Quarter car, Franklin, Powell & Emami-Naeini, Feedback Control of Dynamic Systems, Example 2.2:
// wheel m1 = 20 kg on tyre stiffness kw = 1 000 000 N/m over the road r, body m2 = 375 kg on the
// suspension ks = 130 000 N/m, b = 9 800 N·s/m:
//   m1 ẍ + b (ẋ − ẏ) + ks (x − y) + kw (x − r) = 0
//   m2 ÿ + b (ẏ − ẋ) + ks (y − x)             = 0
// By Cramer's rule on (M s² + C s + K) [X; Y] = [kw R; 0]:
//   Y/R = kw (b s + ks) / det(M s² + C s + K),
//   det/(m1 m2) = s⁴ + (b/m1 + b/m2) s³ + (ks/m1 + ks/m2 + kw/m1) s² + (b kw/(m1 m2)) s
//                 + kw ks/(m1 m2)
// (FPE eq. 2.12): one zero at −ks/b, gain kw b/(m1 m2), DC gain 1 (the body follows the road).

#include <cmath>

#include <gtest/gtest.h>
#include <unsupported/Eigen/Polynomials>

#include "momenta/analysis/modes.hpp"
#include "momenta/analysis/time_response.hpp"
#include "momenta/analysis/transfer_function.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

constexpr double m1 = 20.0;       // kg, wheel
constexpr double m2 = 375.0;      // kg, quarter of the body
constexpr double ks = 130000.0;   // N/m, suspension spring
constexpr double kw = 1000000.0;  // N/m, tyre
constexpr double b = 9800.0;      // N·s/m, damper

// States [x, ẋ, y, ẏ], input r, outputs y (body) and x (wheel), written out by hand.
StateSpace quarter_car() {
  MatX A(4, 4), B(4, 1), C(2, 4);
  A << 0, 1, 0, 0,                                //
      -(ks + kw) / m1, -b / m1, ks / m1, b / m1,  //
      0, 0, 0, 1,                                 //
      ks / m2, b / m2, -ks / m2, -b / m2;
  B << 0, kw / m1, 0, 0;
  C << 0, 0, 1, 0,  //
      1, 0, 0, 0;
  return StateSpace(A, B, C, MatX(), {"x", "x_dot", "y", "y_dot"}, {"r"}, {"y", "x"});
}

// Monic characteristic polynomial coefficients, lowest power first (FPE eq. 2.12).
Eigen::Matrix<double, 5, 1> characteristic_polynomial() {
  Eigen::Matrix<double, 5, 1> a;
  a << kw * ks / (m1 * m2), b * kw / (m1 * m2), ks / m1 + ks / m2 + kw / m1, b / m1 + b / m2, 1.0;
  return a;
}

TEST(QuarterCar, PolesAreTheRootsOfTheCharacteristicPolynomial) {
  const TransferFunction tf = transfer_function(quarter_car(), "r", "y");
  ASSERT_EQ(tf.poles.size(), 4u);
  const auto a = characteristic_polynomial();
  for (const Complex& p : tf.poles) {
    // Backward error of the root: |det(p)| against Σ|a_k||p|^k. A pole computed to a relative
    // 1e-13 (‖A‖ ~ 5·10⁴ balanced down, eigenvalues ~ 10..250) leaves a residual below 1e-12.
    Complex value = 0.0;
    double scale = 0.0;
    for (int k = 4; k >= 0; --k) {
      value = value * p + a[k];
      scale = scale * std::abs(p) + std::abs(a[k]);
    }
    EXPECT_LT(std::abs(value) / scale, 1e-12) << "pole " << p;
  }
  // And against an independent root finder: Eigen's balanced companion-matrix PolynomialSolver
  // on the coefficients. The roots are simple and separated (|p| ≈ 17 and ≈ 240), so both
  // agree to the conditioning of the quartic, about 1e-11 relative.
  const Eigen::PolynomialSolver<double, 4> roots(a);
  std::vector<Complex> reference(roots.roots().data(), roots.roots().data() + 4);
  for (const Complex& p : tf.poles) {
    double nearest = 1e300;
    for (const Complex& r : reference) nearest = std::min(nearest, std::abs(p - r));
    EXPECT_LT(nearest, 1e-11 * std::abs(p)) << "pole " << p;
  }
}

TEST(QuarterCar, RoadToBodyZeroGainAndDcGain) {
  const TransferFunction tf = transfer_function(quarter_car(), "r", "y");
  ASSERT_EQ(tf.zeros.size(), 1u);
  EXPECT_EQ(tf.relative_degree(), 3);
  // Zero of a 2×2 pencil after three orthogonal deflation steps on a balanced 4×4.
  EXPECT_REL_NEAR(tf.zeros[0].real(), -ks / b, 1e-13);
  EXPECT_EQ(tf.zeros[0].imag(), 0.0);
  EXPECT_REL_NEAR(tf.gain, kw * b / (m1 * m2), 1e-13);
  EXPECT_REL_NEAR(tf.dc_gain, 1.0, 1e-13);
  // The frequency response against the hand-written rational function (Horner on the
  // coefficients is fine at these moderate |s|; 1e-12 covers its round-off).
  const auto a = characteristic_polynomial();
  for (const double w : {0.5, 5.0, 17.0, 60.0, 240.0, 1000.0}) {
    const Complex s(0.0, w);
    Complex den = 0.0;
    for (int k = 4; k >= 0; --k) den = den * s + a[k];
    const Complex expected = kw * (b * s + ks) / (m1 * m2) / den;
    const Complex got = evaluate(quarter_car(), 0, 0, s);
    EXPECT_LT(std::abs(got - expected), 1e-12 * std::abs(expected)) << "ω = " << w;
    EXPECT_LT(std::abs(tf(s) - expected), 1e-12 * std::abs(expected)) << "ω = " << w;
  }
}

TEST(QuarterCar, RoadToWheelAndSettledStep) {
  // X/R = kw (m2 s² + b s + ks) / det: a complex zero pair at ωz = √(ks/m2), 2ζωz = b/m2.
  const TransferFunction wheel = transfer_function(quarter_car(), "r", "x");
  ASSERT_EQ(wheel.zeros.size(), 2u);
  EXPECT_EQ(wheel.relative_degree(), 2);
  EXPECT_REL_NEAR(std::abs(wheel.zeros[0]), std::sqrt(ks / m2), 1e-13);
  EXPECT_REL_NEAR(-2 * wheel.zeros[0].real(), b / m2, 1e-13);
  EXPECT_REL_NEAR(wheel.gain, kw / m1, 1e-13);
  // A unit road step: after the automatic horizon (7 slowest time constants) body and wheel
  // have settled on the road to within e⁻⁷·(modal amplitudes ≤ 2) ≈ 2e-3.
  const TimeResponse r = step_response(quarter_car(), 0);
  const Eigen::Index last = r.time.size() - 1;
  EXPECT_NEAR(r.outputs(last, 0), 1.0, 2e-3);
  EXPECT_NEAR(r.outputs(last, 1), 1.0, 2e-3);
}

}  // namespace
}  // namespace momenta::analysis
