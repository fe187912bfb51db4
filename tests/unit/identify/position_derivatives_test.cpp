// Savitzky–Golay derivatives against closed forms: exact on cubics at every sample (the log's
// ends included), and converging at the orders the cubic fit has on a sine.
#include "momenta/identify/position_derivatives.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"

namespace momenta::identify {
namespace {

VecX uniform_time(int N, double h) { return VecX::LinSpaced(N, 0.0, h * (N - 1)); }

// A cubic's rate and acceleration to round-off, in the centre and in the shifted end windows.
TEST(PositionDerivatives, AreExactOnCubicsAtEverySample) {
  const VecX t = uniform_time(40, 0.05);
  MatX q(40, 1);
  for (int i = 0; i < 40; ++i)
    q(i, 0) = 0.3 - 1.1 * t[i] + 0.7 * t[i] * t[i] - 0.4 * std::pow(t[i], 3);
  for (int window : {5, 9, 21}) {
    const PositionDerivatives d = differentiate_positions(t, q, window);
    for (int i = 0; i < 40; ++i) {
      EXPECT_NEAR(d.rate(i, 0), -1.1 + 1.4 * t[i] - 1.2 * t[i] * t[i], 1e-11) << window << " " << i;
      EXPECT_NEAR(d.acceleration(i, 0), 1.4 - 2.4 * t[i], 1e-10) << window << " " << i;
    }
  }
}

// sin(5 t) in the middle of the log: halving the step divides the rate's error by ~16 (O(h⁴))
// and the acceleration's by ~4 (O(h²)), the orders of the centred cubic fit.
TEST(PositionDerivatives, ConvergeAtTheCubicFitsOrders) {
  const auto errors = [](double h) {
    const int N = static_cast<int>(std::round(2.0 / h)) + 1;
    const VecX t = uniform_time(N, h);
    const MatX q = t.unaryExpr([](double x) { return std::sin(5 * x); });
    const PositionDerivatives d = differentiate_positions(t, q, 5);
    const int mid = N / 2;
    return std::pair(std::abs(d.rate(mid, 0) - 5 * std::cos(5 * t[mid])),
                     std::abs(d.acceleration(mid, 0) + 25 * std::sin(5 * t[mid])));
  };
  const auto [rate1, acc1] = errors(0.02);
  const auto [rate2, acc2] = errors(0.01);
  EXPECT_NEAR(rate1 / rate2, 16.0, 1.0) << rate1 << " " << rate2;
  EXPECT_NEAR(acc1 / acc2, 4.0, 0.25) << acc1 << " " << acc2;
}

TEST(PositionDerivatives, RefuseUnevenStepsAndBadWindows) {
  VecX t = uniform_time(20, 0.1);
  const MatX q = MatX::Zero(20, 1);
  EXPECT_THROW(differentiate_positions(t, q, 4), InvalidArgument);
  EXPECT_THROW(differentiate_positions(t, q, 3), InvalidArgument);
  EXPECT_THROW(differentiate_positions(t, q, 21), InvalidArgument);
  t[7] += 0.01;
  try {
    differentiate_positions(t, q, 5);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("the time step before row 7"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace momenta::identify
