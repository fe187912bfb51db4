// A controller's gains swept (examples/sweeps/cruise_pi_gains.yaml): every run's closed-loop poles
// against the roots of the PI loop's characteristic polynomial m s² + (b + kp) s + ki (and the
// position's 0), and the damping ratio of each pair.

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/io/sweep_file.hpp"
#include "momenta/sweep/execution.hpp"

namespace momenta::sweep {
namespace {

using Complex = std::complex<double>;

bool before(const Complex& a, const Complex& b) {
  return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag();
}

TEST(ControllerSweep, EveryPiLoopHasTheRootsOfItsCharacteristicPolynomial) {
  const SweepRunner runner(io::read_sweep_file("examples/sweeps/cruise_pi_gains.yaml"));
  ASSERT_EQ(runner.run_count(), 20);
  std::vector<long> runs(20);
  for (long k = 0; k < 20; ++k) runs[static_cast<std::size_t>(k)] = k;
  std::vector<RunOutcome> outcomes;
  run_in_order(runner, runs, 2, [&](RunOutcome&& o) { outcomes.push_back(std::move(o)); });
  const double m = 1000.0, b = 50.0;
  int oscillating = 0;
  for (const RunOutcome& o : outcomes) {
    ASSERT_TRUE(o.ok) << o.message;
    const double kp = o.parameters[0], ki = o.parameters[1];
    // The roots, by the quadratic formula (complex when the discriminant is negative).
    const double p = (b + kp) / m, q = ki / m;
    const Complex root = std::sqrt(Complex(p * p / 4.0 - q, 0.0));
    std::vector<Complex> expected = {0.0, -p / 2.0 + root, -p / 2.0 - root};
    std::vector<Complex> found;
    for (int k = 0; k < 3; ++k)
      found.emplace_back(o.metrics[static_cast<std::size_t>(2 * k)],
                         o.metrics[static_cast<std::size_t>(2 * k + 1)]);
    std::sort(expected.begin(), expected.end(), before);
    std::sort(found.begin(), found.end(), before);
    // Eigenvalues of a 3 × 3 companion-like matrix with entries up to 1.45: 1e-12 absolute.
    for (int k = 0; k < 3; ++k)
      EXPECT_LT(
          std::abs(found[static_cast<std::size_t>(k)] - expected[static_cast<std::size_t>(k)]),
          1e-12)
          << "kp " << kp << ", ki " << ki;
    // ζ = p / (2 √q) for a complex pair (1 for real ones, as modes reports them).
    const double zeta = std::min(1.0, p / (2.0 * std::sqrt(q)));
    EXPECT_NEAR(o.metrics[7], zeta, 1e-9) << "kp " << kp << ", ki " << ki;
    if (zeta < 1.0) ++oscillating;
  }
  // The grid spans both regimes.
  EXPECT_GT(oscillating, 0);
  EXPECT_LT(oscillating, 20);
}

}  // namespace
}  // namespace momenta::sweep
