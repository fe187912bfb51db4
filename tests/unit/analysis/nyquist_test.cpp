// Nyquist's count Z = N + P against the closed loop's eigenvalues (an independent reference: the
// count never forms the closed loop) and against Routh's bound: K/(s (s + 1)(s + 5)) is stable for
// K < 30 and has two right-half-plane poles beyond; K/(s − 1) is stable for K > 1, encircling −1
// once counter-clockwise; a sampled loop k/((z − 1)(z − ½)) is stable for k < ½.

#include "momenta/analysis/nyquist.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "analysis_test_systems.hpp"
#include "momenta/common/error.hpp"

namespace momenta::analysis::nyquist_test {
namespace {

// gain / (sⁿ + a_{n−1} sⁿ⁻¹ + … + a₀), denominator a_{n−1} … a₀ (analysis_test_systems.hpp).
StateSpace all_pole(double gain, const std::vector<double>& denominator, double sample_time = 0.0) {
  std::vector<double> numerator(denominator.size(), 0.0);
  numerator[0] = gain;
  const StateSpace c = test::canonical_form(denominator, numerator);
  return StateSpace(c.A(), c.B(), c.C(), c.D(), {}, {"u"}, {"y"}, sample_time);
}

// The closed loop's unstable poles, counted from its eigenvalues: the reference.
int unstable_closed_loop_poles(const StateSpace& L) {
  const MatX closed = L.A() - L.B() * L.C() / (1.0 + L.D()(0, 0));
  const Eigen::EigenSolver<MatX> eigen(closed, false);
  int unstable = 0;
  for (const Complex& p : eigen.eigenvalues()) {
    if (L.sample_time() > 0.0 ? std::abs(p) > 1.0 : p.real() > 0.0) ++unstable;
  }
  return unstable;
}

TEST(Nyquist, ATypeOneLoopTurnsUnstableAtRouthsGain) {
  for (const double K : {1.0, 10.0, 29.0, 31.0, 50.0, 1000.0}) {
    const StateSpace L = all_pole(K, {6.0, 5.0, 0.0});  // s³ + 6 s² + 5 s
    const NyquistCount c = nyquist_count(L, 0, 0);
    EXPECT_EQ(c.open_loop_unstable, 0) << K;
    EXPECT_EQ(c.boundary_poles, 1) << K;  // s = 0, gone round on its right
    EXPECT_FALSE(c.through_critical_point) << K;
    EXPECT_EQ(c.encirclements, K < 30.0 ? 0 : 2) << K;
    EXPECT_EQ(c.closed_loop_unstable, unstable_closed_loop_poles(L)) << K;
  }
  // At K = 30 the closed loop has poles at ±j√5: L passes through −1.
  EXPECT_TRUE(nyquist_count(all_pole(30.0, {6.0, 5.0, 0.0}), 0, 0).through_critical_point);
}

TEST(Nyquist, AnUnstablePlantIsStabilizedByEncirclingMinusOneCounterClockwise) {
  for (const double K : {0.5, 2.0, 100.0}) {
    const StateSpace L = all_pole(K, {-1.0});  // K/(s − 1)
    const NyquistCount c = nyquist_count(L, 0, 0);
    EXPECT_EQ(c.open_loop_unstable, 1);
    EXPECT_EQ(c.encirclements, K > 1.0 ? -1 : 0) << K;
    EXPECT_EQ(c.closed_loop_unstable, K > 1.0 ? 0 : 1) << K;
    EXPECT_EQ(c.closed_loop_unstable, unstable_closed_loop_poles(L)) << K;
  }
}

TEST(Nyquist, ADoubleIntegratorWithLeadIsGoneRoundAtTheOrigin) {
  // (s + 1)/s²: a double pole on the axis (from the eigenvalue iteration ~1e-8 apart), stable
  // for every K > 0 (s² + K s + K).
  MatX A(2, 2), B(2, 1), C(1, 2);
  A << 0, 1, 0, 0;
  B << 0, 1;
  C << 2, 2;
  const StateSpace L(A, B, C, MatX(), {}, {"u"}, {"y"});
  const NyquistCount c = nyquist_count(L, 0, 0);
  EXPECT_EQ(c.boundary_poles, 2);
  EXPECT_EQ(c.encirclements, 0);
  EXPECT_EQ(c.closed_loop_unstable, 0);
  EXPECT_EQ(unstable_closed_loop_poles(L), 0);
}

TEST(Nyquist, ASampledLoopCountsPolesOutsideTheUnitCircle) {
  // k/((z − 1)(z − ½)) = k/(z² − 1.5 z + 0.5): |z|² = ½ + k for the complex pair.
  for (const double k : {0.05, 0.25, 0.45, 0.55, 1.0, 3.0}) {
    const StateSpace L = all_pole(k, {-1.5, 0.5}, 0.1);
    const NyquistCount c = nyquist_count(L, 0, 0);
    EXPECT_EQ(c.sample_time, 0.1);
    EXPECT_EQ(c.open_loop_unstable, 0);
    EXPECT_EQ(c.boundary_poles, 1) << k;  // z = 1, gone round outside
    EXPECT_EQ(c.closed_loop_unstable, k < 0.5 ? 0 : 2) << k;
    EXPECT_EQ(c.closed_loop_unstable, unstable_closed_loop_poles(L)) << k;
  }
}

TEST(Nyquist, AnIllPosedLoopOrABadPairIsRefused) {
  MatX A(1, 1), B(1, 1), C(1, 1), D(1, 1);
  A << -1;
  B << 1;
  C << 1;
  D << -1;
  EXPECT_THROW(nyquist_count(StateSpace(A, B, C, D), 0, 0), InvalidArgument);
  EXPECT_THROW(nyquist_count(all_pole(1.0, {1.0}), 1, 0), InvalidArgument);
}

}  // namespace
}  // namespace momenta::analysis::nyquist_test
