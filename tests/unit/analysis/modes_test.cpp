#include "momenta/analysis/modes.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

TEST(Modes, SecondOrderSystemNaturalFrequencyAndDamping) {
  // ẍ + 2ζωn ẋ + ωn² x = 0: λ = −ζωn ± jωn√(1−ζ²), |λ| = ωn.
  const double wn = 3.7;
  const double zeta = 0.15;
  MatX A(2, 2);
  A << 0, 1, -wn * wn, -2 * zeta * wn;
  const Modes m = modes(A, {"x", "x_dot"});
  ASSERT_EQ(m.modes.size(), 2u);
  for (const Mode& mode : m.modes) {
    // Eigenvalues of a 2×2 matrix with O(10) entries: a few ε relative.
    EXPECT_REL_NEAR(mode.natural_frequency, wn, 1e-14);
    EXPECT_REL_NEAR(mode.damping_ratio, zeta, 1e-13);
    EXPECT_REL_NEAR(mode.damped_frequency, wn * std::sqrt(1 - zeta * zeta), 1e-14);
  }
  // Pair order: Im > 0 first, exact conjugates.
  EXPECT_GT(m.modes[0].eigenvalue.imag(), 0.0);
  EXPECT_EQ(m.modes[1].eigenvalue, std::conj(m.modes[0].eigenvalue));
  EXPECT_EQ(m.state_names[1], "x_dot");
}

TEST(Modes, ShapesAreNormalizedEigenvectors) {
  MatX A(3, 3);
  A << -1, 2, 0.5, -3, -0.2, 1, 0.1, 0.4, -2;
  const Modes m = modes(A);
  ASSERT_EQ(m.modes.size(), 3u);
  for (const Mode& mode : m.modes) {
    EXPECT_NEAR(mode.shape.norm(), 1.0, 1e-15);
    Eigen::Index largest = 0;
    mode.shape.cwiseAbs().maxCoeff(&largest);
    EXPECT_EQ(mode.shape[largest].imag(), 0.0);
    EXPECT_GT(mode.shape[largest].real(), 0.0);
    // Residual of A φ = λ φ: round-off of O(1) matrices.
    const VecXc residual = A.cast<Complex>() * mode.shape - mode.eigenvalue * mode.shape;
    EXPECT_LT(residual.norm(), 1e-14);
  }
  // Ascending natural frequency.
  EXPECT_LE(m.modes[0].natural_frequency, m.modes[1].natural_frequency);
  EXPECT_LE(m.modes[1].natural_frequency, m.modes[2].natural_frequency);
}

TEST(Modes, RealAndZeroPoles) {
  MatX A(3, 3);
  A << 0, 0, 0, 0, -2, 0, 0, 0, 2;
  const Modes m = modes(A);
  EXPECT_EQ(m.modes[0].natural_frequency, 0.0);
  EXPECT_TRUE(std::isnan(m.modes[0].damping_ratio));
  // Equal |λ| = 2: the stable one first; ζ = ±1 for real poles.
  EXPECT_EQ(m.modes[1].eigenvalue, Complex(-2, 0));
  EXPECT_EQ(m.modes[1].damping_ratio, 1.0);
  EXPECT_EQ(m.modes[2].damping_ratio, -1.0);
}

TEST(NormalModes, TwoMassChainClosedForm) {
  // Wall–k–m–k–m: M = m I, K = k [2 −1; −1 1]; ω² = (k/m)(3 ∓ √5)/2,
  // shapes ∝ [1, (1 ± √5)/2] (the golden ratio chain).
  const double m = 2.5;
  const double k = 1000.0;
  MatX M = m * MatX::Identity(2, 2);
  MatX K(2, 2);
  K << 2 * k, -k, -k, k;
  const NormalModes modes = normal_modes(M, K, {"q_left", "q_right"});
  ASSERT_EQ(modes.modes.size(), 2u);
  const double w1sq = k / m * (3 - std::sqrt(5.0)) / 2;
  const double w2sq = k / m * (3 + std::sqrt(5.0)) / 2;
  // Symmetric eigenproblem of a 2×2 with O(1000) entries: a few ε relative.
  EXPECT_REL_NEAR(modes.modes[0].squared_frequency, w1sq, 1e-14);
  EXPECT_REL_NEAR(modes.modes[1].squared_frequency, w2sq, 1e-14);
  EXPECT_REL_NEAR(modes.modes[0].natural_frequency, std::sqrt(w1sq), 1e-14);
  const double golden = (1 + std::sqrt(5.0)) / 2;
  EXPECT_REL_NEAR(modes.modes[0].shape[1] / modes.modes[0].shape[0], golden, 1e-14);
  EXPECT_REL_NEAR(modes.modes[1].shape[1] / modes.modes[1].shape[0], 1 - golden, 1e-13);
  // Mass normalization and K-orthogonality: Φᵀ M Φ = I, Φᵀ K Φ = diag ω².
  MatX Phi(2, 2);
  Phi << modes.modes[0].shape, modes.modes[1].shape;
  EXPECT_MATRIX_NEAR(Phi.transpose() * M * Phi, MatX::Identity(2, 2), 1e-14);
  MatX expected = MatX::Zero(2, 2);
  expected.diagonal() << w1sq, w2sq;
  EXPECT_MATRIX_NEAR(Phi.transpose() * K * Phi, expected, 1e-10);
  EXPECT_GT(modes.modes[0].shape.cwiseAbs().maxCoeff(), 0.0);
}

TEST(NormalModes, RigidBodyAndDivergentModes) {
  // Free–free pair of masses: one rigid-body mode (ω = 0 exactly, not NaN).
  MatX M(2, 2), K(2, 2);
  M << 1, 0, 0, 3;
  K << 5, -5, -5, 5;
  const NormalModes free = normal_modes(M, K);
  EXPECT_EQ(free.modes[0].natural_frequency, 0.0);
  // ω² of the elastic mode: k (1/m1 + 1/m2).
  EXPECT_REL_NEAR(free.modes[1].squared_frequency, 5 * (1 + 1.0 / 3), 1e-14);
  // Negative stiffness: a divergent mode, ω² < 0 and ω NaN.
  MatX negative(1, 1);
  negative << -4;
  const NormalModes divergent = normal_modes(MatX::Identity(1, 1), negative);
  EXPECT_EQ(divergent.modes[0].squared_frequency, -4.0);
  EXPECT_TRUE(std::isnan(divergent.modes[0].natural_frequency));
}

TEST(NormalModes, BadMatricesThrow) {
  MatX M = MatX::Identity(2, 2);
  MatX asymmetric(2, 2);
  asymmetric << 1, 2, 0, 1;
  EXPECT_THROW(normal_modes(M, asymmetric), InvalidArgument);
  EXPECT_THROW(normal_modes(M, MatX::Identity(3, 3)), InvalidArgument);
  EXPECT_THROW(normal_modes(-M, M), InvalidArgument);
  EXPECT_THROW(normal_modes(M, M, {"one"}), InvalidArgument);
}

TEST(DampedModes, MatchTheUndampedLimitAndProportionalDamping) {
  // Rayleigh damping C = α M + β K keeps the undamped shapes; each mode has
  // 2 ζ ω = α + β ω² (Géradin & Rixen, Mechanical Vibrations, §4.4).
  MatX M(2, 2), K(2, 2);
  M << 2, 0, 0, 1;
  K << 30, -10, -10, 10;
  const double alpha = 0.05;
  const double beta = 0.002;
  const MatX C = alpha * M + beta * K;
  const NormalModes undamped = normal_modes(M, K);
  const Modes damped = damped_modes(M, C, K, {"a", "b"});
  ASSERT_EQ(damped.modes.size(), 4u);
  EXPECT_EQ(damped.state_names[2], "a_dot");
  for (std::size_t k = 0; k < 2; ++k) {
    const double w = undamped.modes[k].natural_frequency;
    const Mode& mode = damped.modes[2 * k];
    // 4×4 eigenproblem with O(30) entries.
    EXPECT_REL_NEAR(mode.natural_frequency, w, 1e-13);
    EXPECT_REL_NEAR(mode.damping_ratio, (alpha + beta * w * w) / (2 * w), 1e-12);
    // Position part of the shape ∝ the undamped shape (complex multiple).
    const VecXc q = mode.shape.head(2);
    const VecXc phi = undamped.modes[k].shape.cast<Complex>();
    const Complex ratio = q[0] / phi[0];
    EXPECT_LT((q - ratio * phi).norm(), 1e-13);
  }
}

}  // namespace
}  // namespace momenta::analysis
