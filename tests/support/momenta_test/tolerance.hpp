#pragma once
// Comparison helpers shared by every momenta test. Each tolerance a test passes here must be
// justified where it is used (round-off of the arithmetic, truncation order of a method, ...).

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Core>

namespace momenta::test {

/// Machine epsilon of double.
inline constexpr double kEps = 2.220446049250313e-16;

/// Passes when both operands are finite everywhere and max |a − b| <= tolerance elementwise;
/// prints both matrices otherwise. A NaN or infinity in either operand always fails: Eigen's
/// maxCoeff skips NaN, so the finiteness check comes first and is not left to the comparison.
template <typename A, typename B>
::testing::AssertionResult matrices_near(const Eigen::MatrixBase<A>& a,
                                         const Eigen::MatrixBase<B>& b, double tolerance) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) {
    return ::testing::AssertionFailure() << "sizes differ: " << a.rows() << "x" << a.cols()
                                         << " vs " << b.rows() << "x" << b.cols();
  }
  std::ostringstream out;
  out.precision(17);
  if (!a.allFinite() || !b.allFinite()) {
    out << "non-finite entry in " << (a.allFinite() ? "b" : "a") << "\na =\n"
        << a << "\nb =\n"
        << b;
    return ::testing::AssertionFailure() << out.str();
  }
  const double error = a.size() == 0 ? 0.0 : (a - b).cwiseAbs().maxCoeff();
  if (error <= tolerance) return ::testing::AssertionSuccess();
  out << "max |a − b| = " << error << " > " << tolerance << "\na =\n" << a << "\nb =\n" << b;
  return ::testing::AssertionFailure() << out.str();
}

/// Passes when both are finite and |a − b| <= rel * max(|a|, |b|) (+ abs_floor).
inline ::testing::AssertionResult relatively_near(double a, double b, double rel,
                                                  double abs_floor = 0.0) {
  if (!std::isfinite(a) || !std::isfinite(b)) {
    return ::testing::AssertionFailure() << "non-finite operand: " << a << " vs " << b;
  }
  const double error = std::abs(a - b);
  const double allowed = rel * std::max(std::abs(a), std::abs(b)) + abs_floor;
  if (error <= allowed) return ::testing::AssertionSuccess();
  std::ostringstream out;
  out.precision(17);
  out << a << " vs " << b << ": |difference| " << error << " > " << allowed;
  return ::testing::AssertionFailure() << out.str();
}

/// The repository root, for tests that read examples/ or tests/data/.
inline std::string source_dir() {
  const char* dir = std::getenv("MOMENTA_SOURCE_DIR");
  return dir ? std::string(dir) : std::string(".");
}

}  // namespace momenta::test

#define EXPECT_MATRIX_NEAR(a, b, tol) EXPECT_TRUE(::momenta::test::matrices_near((a), (b), (tol)))
#define ASSERT_MATRIX_NEAR(a, b, tol) ASSERT_TRUE(::momenta::test::matrices_near((a), (b), (tol)))
#define EXPECT_REL_NEAR(a, b, rel) EXPECT_TRUE(::momenta::test::relatively_near((a), (b), (rel)))
