#include "momenta/analysis/transfer_function.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <Eigen/QR>

#include "analysis_test_systems.hpp"
#include "momenta/common/error.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

using test::canonical_form;
using test::random_system;

// |a − b| ≤ rel·|b| for complex numbers.
::testing::AssertionResult complex_near(Complex a, Complex b, double rel) {
  if (std::abs(a - b) <= rel * std::abs(b)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a << " vs " << b << " (|diff| " << std::abs(a - b) << ")";
}

TEST(TransferFunction, KnownZerosPolesGain) {
  // G(s) = (s + 2)/((s + 1)(s + 3)) = (s + 2)/(s² + 4 s + 3).
  const TransferFunction tf = transfer_function(canonical_form({4, 3}, {2, 1}), 0, 0);
  ASSERT_EQ(tf.zeros.size(), 1u);
  ASSERT_EQ(tf.poles.size(), 2u);
  // Eigenvalues of O(1) 2×2 and 3×3 problems: a few ε.
  EXPECT_NEAR(tf.zeros[0].real(), -2.0, 1e-14);
  EXPECT_NEAR(tf.poles[0].real(), -1.0, 1e-14);
  EXPECT_NEAR(tf.poles[1].real(), -3.0, 1e-14);
  EXPECT_NEAR(tf.gain, 1.0, 1e-14);
  EXPECT_NEAR(tf.dc_gain, 2.0 / 3.0, 1e-15);
  EXPECT_EQ(tf.relative_degree(), 1);
  EXPECT_TRUE(tf.cancelled.empty());
}

TEST(TransferFunction, NonMinimumPhaseZeroAndNegativeGain) {
  // G(s) = (1 − s)/(s + 2)² : zero at +1, K = −1, G(0) = 1/4.
  const TransferFunction tf = transfer_function(canonical_form({4, 4}, {1, -1}), 0, 0);
  ASSERT_EQ(tf.zeros.size(), 1u);
  EXPECT_NEAR(tf.zeros[0].real(), 1.0, 1e-14);
  EXPECT_NEAR(tf.gain, -1.0, 1e-14);
  EXPECT_NEAR(tf.dc_gain, 0.25, 1e-15);
  // The double pole at −2 is defective: the QR iteration finds it to ~√ε.
  EXPECT_NEAR(tf.poles[0].real(), -2.0, 1e-7);
}

TEST(TransferFunction, HighRelativeDegreeHasNoSpuriousZeros) {
  // G(s) = 5/(s + 1)^6: relative degree 6; a raw QZ of the pencil would split the 6-fold
  // infinite eigenvalue into "zeros" of size ε^(−1/6) ≈ 400.
  const TransferFunction tf =
      transfer_function(canonical_form({6, 15, 20, 15, 6, 1}, {5, 0, 0, 0, 0, 0}), 0, 0);
  EXPECT_TRUE(tf.zeros.empty());
  EXPECT_EQ(tf.relative_degree(), 6);
  // K = C A⁵ B from a chain of unit entries: exact up to a few roundings of the scaling.
  EXPECT_REL_NEAR(tf.gain, 5.0, 1e-14);
  EXPECT_REL_NEAR(tf.dc_gain, 5.0, 1e-14);
}

TEST(TransferFunction, HighRelativeDegreeSurvivesARotationOfTheStates) {
  // The same 5/(s + 1)⁶ in coordinates turned by a random orthogonal Q: no structural zeros
  // left for round-off to hide in. A raw QZ of this pencil returns five spurious finite
  // eigenvalues of modulus ~2000 (measured); the deflation must find none.
  const StateSpace canonical = canonical_form({6, 15, 20, 15, 6, 1}, {5, 0, 0, 0, 0, 0});
  const MatX Q = Eigen::HouseholderQR<MatX>(random_system(6, 6, 1, 17u, false).B()).householderQ();
  const StateSpace rotated(Q.transpose() * canonical.A() * Q, Q.transpose() * canonical.B(),
                           canonical.C() * Q, MatX());
  const TransferFunction tf = transfer_function(rotated, 0, 0, 0.0);
  EXPECT_TRUE(tf.zeros.empty());
  // Six backward-stable deflation steps on O(20) entries; measured 4e-13 relative.
  EXPECT_REL_NEAR(tf.gain, 5.0, 1e-11);
}

TEST(TransferFunction, FactoredFormEqualsStateSpaceEvaluation) {
  // A second algorithm: K ∏(s − z)/∏(s − p) from the zeros and gain must equal the LU
  // evaluation C (sI − A)⁻¹ B + D. Random 7-state systems, strictly proper and biproper, every
  // pair. Tolerance: zeros and poles of random O(1) matrices are accurate to ~1e-14 relative
  // (they are simple and well separated); the product over 7 factors amplifies that near the
  // roots only, which the sample points s stay away from.
  for (const bool feedthrough : {false, true}) {
    const StateSpace system = random_system(7, 2, 3, feedthrough ? 11u : 7u, feedthrough);
    for (std::size_t i = 0; i < 2; ++i) {
      for (std::size_t o = 0; o < 3; ++o) {
        const TransferFunction tf = transfer_function(system, i, o, 0.0);
        EXPECT_EQ(tf.poles.size(), 7u);
        EXPECT_EQ(tf.zeros.size(), feedthrough ? 7u : 6u);
        for (const Complex s :
             {Complex(0.3, 0.0), Complex(0.0, 2.0), Complex(-0.5, 4.0), Complex(10.0, -10.0)}) {
          EXPECT_TRUE(complex_near(tf(s), evaluate(system, i, o, s), 1e-11))
              << "pair " << i << "→" << o << " at s = " << s;
        }
        EXPECT_TRUE(::momenta::test::relatively_near(tf.dc_gain, evaluate(system, i, o, 0.0).real(),
                                                     1e-12, 1e-14));
      }
    }
  }
}

TEST(TransferFunction, ZerosAreWhereThePencilLosesRank) {
  // At each zero z the Rosenbrock matrix [zI − A, −b; c, d] is singular: its smallest singular
  // value relative to the largest is round-off (1e-13 for a 6×6 of O(1) entries).
  const StateSpace system = random_system(5, 1, 1, 3u, false);
  const TransferFunction tf = transfer_function(system, 0, 0, 0.0);
  ASSERT_EQ(tf.zeros.size(), 4u);
  for (const Complex& z : tf.zeros) {
    Eigen::MatrixXcd P(6, 6);
    P.topLeftCorner(5, 5) = z * Eigen::MatrixXcd::Identity(5, 5) - system.A().cast<Complex>();
    P.topRightCorner(5, 1) = -system.B().cast<Complex>();
    P.bottomLeftCorner(1, 5) = system.C().cast<Complex>();
    P(5, 5) = system.D()(0, 0);
    const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(P);
    EXPECT_LT(svd.singularValues()[5] / svd.singularValues()[0], 1e-13) << "zero " << z;
  }
}

TEST(TransferFunction, UncontrollableModeCancels) {
  // A = diag(−1, −2), b = [1; 0]: the mode at −2 is uncontrollable, G(s) = 1/(s + 1).
  MatX A(2, 2), B(2, 1), C(1, 2);
  A << -1, 0, 0, -2;
  B << 1, 0;
  C << 1, 1;
  const StateSpace system(A, B, C, MatX());
  const TransferFunction minimal = transfer_function(system, 0, 0);
  ASSERT_EQ(minimal.poles.size(), 1u);
  EXPECT_TRUE(minimal.zeros.empty());
  ASSERT_EQ(minimal.cancelled.size(), 1u);
  EXPECT_NEAR(minimal.cancelled[0].real(), -2.0, 1e-14);
  EXPECT_NEAR(minimal.poles[0].real(), -1.0, 1e-14);
  EXPECT_NEAR(minimal.gain, 1.0, 1e-14);
  // With cancellation off, the invariant zero stays.
  const TransferFunction full = transfer_function(system, 0, 0, 0.0);
  EXPECT_EQ(full.poles.size(), 2u);
  ASSERT_EQ(full.zeros.size(), 1u);
  EXPECT_NEAR(full.zeros[0].real(), -2.0, 1e-14);
}

TEST(TransferFunction, IdenticallyZeroAndStaticPairs) {
  MatX A(2, 2), B(2, 2), C(1, 2), D(1, 2);
  A << -1, 0, 0, -2;
  B << 1, 0, 0, 0;  // input 2 reaches no state
  C << 1, 0;
  D << 0, 3;
  const StateSpace system(A, B, C, D);
  // Input 2 → output: only the feedthrough, G ≡ 3: every pole cancels against a zero.
  const TransferFunction stat = transfer_function(system, 1, 0);
  EXPECT_EQ(stat.gain, 3.0);
  EXPECT_TRUE(stat.poles.empty());
  EXPECT_EQ(stat.cancelled.size(), 2u);
  EXPECT_EQ(stat.dc_gain, 3.0);
  // A system whose output reads an unreached state: G ≡ 0.
  MatX C2(1, 2);
  C2 << 0, 1;
  const TransferFunction none = transfer_function(StateSpace(A, B.leftCols(1), C2, MatX()), 0, 0);
  EXPECT_TRUE(none.is_zero());
  EXPECT_EQ(none.dc_gain, 0.0);
}

TEST(TransferFunction, IntegratorsHaveInfiniteSignedDcGain) {
  // G = 2/s and G = −2/(s (s − 1)) → +∞ and, near 0⁺, −2/(s·(−1)) > 0 → +∞; −2/s → −∞.
  EXPECT_EQ(transfer_function(canonical_form({0}, {2}), 0, 0).dc_gain,
            std::numeric_limits<double>::infinity());
  EXPECT_EQ(transfer_function(canonical_form({0}, {-2}), 0, 0).dc_gain,
            -std::numeric_limits<double>::infinity());
  EXPECT_EQ(transfer_function(canonical_form({-1, 0}, {-2, 0}), 0, 0).dc_gain,
            std::numeric_limits<double>::infinity());
}

TEST(TransferFunction, MimoEvaluationAndErrors) {
  const StateSpace system = random_system(4, 2, 2, 5u, true);
  const Complex s(0.1, 1.3);
  const Eigen::MatrixXcd G = evaluate(system, s);
  for (std::size_t i = 0; i < 2; ++i) {
    for (std::size_t o = 0; o < 2; ++o) {
      EXPECT_EQ(G(static_cast<Eigen::Index>(o), static_cast<Eigen::Index>(i)),
                evaluate(system, i, o, s));
    }
  }
  EXPECT_THROW(transfer_function(system, 2, 0), InvalidArgument);
  EXPECT_THROW(transfer_function(system, 0, 0, -1.0), InvalidArgument);
  EXPECT_THROW(evaluate(system, 0, 2, s), InvalidArgument);
  EXPECT_THROW(transfer_function(system, "u1", "y3"), InvalidArgument);
  EXPECT_EQ(transfer_function(system, "u2", "y1").input_name, "u2");
}

}  // namespace
}  // namespace momenta::analysis
