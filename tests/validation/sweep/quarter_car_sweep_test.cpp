// The quarter car swept (examples/sweeps/): every run's poles are the roots of Franklin's
// characteristic polynomial det(M s² + C s + K) at that run's parameters; every run's metrics are
// those of the model run on its own with the same numbers, to the bit; and the results do not
// depend on the thread count.

#include <algorithm>
#include <complex>

#include <gtest/gtest.h>

#include "momenta/io/file_template.hpp"
#include "momenta/io/sweep_file.hpp"
#include "momenta/simulate/run_request.hpp"
#include "momenta/sweep/execution.hpp"
#include "momenta/sweep/metrics.hpp"
#include "momenta/sweep/results_file.hpp"

namespace momenta::sweep {
namespace {

std::vector<RunOutcome> run_all(const SweepRunner& runner, int threads) {
  std::vector<long> runs(static_cast<std::size_t>(runner.run_count()));
  for (std::size_t k = 0; k < runs.size(); ++k) runs[k] = static_cast<long>(k);
  std::vector<RunOutcome> outcomes;
  run_in_order(runner, runs, threads, [&](RunOutcome&& o) { outcomes.push_back(std::move(o)); });
  return outcomes;
}

// det(M s² + C s + K) for the wheel (m1, x) and body (m2, y) of FPE eq. 2.12:
//   m1 m2 s⁴ + b (m1 + m2) s³ + (m1 ks + m2 (ks + kw)) s² + b kw s + kw ks.
// Its roots' elementary symmetric functions are ±a_k / a_4 (Vieta).
TEST(QuarterCarSweep, EveryRunsPolesAreTheRootsOfTheClosedFormCharacteristicPolynomial) {
  const SweepRunner runner(io::read_sweep_file("examples/sweeps/quarter_car_poles.yaml"));
  ASSERT_EQ(runner.run_count(), 9 * 7 * 3);
  const double m1 = 20.0, kw = 1e6;
  for (const RunOutcome& o : run_all(runner, 2)) {
    ASSERT_TRUE(o.ok) << o.message;
    const double ks = o.parameters[0], b = o.parameters[1], m2 = o.parameters[2];
    const double a4 = m1 * m2, a3 = b * (m1 + m2), a2 = m1 * ks + m2 * (ks + kw), a1 = b * kw,
                 a0 = kw * ks;
    std::vector<std::complex<double>> s;
    for (int i = 0; i < 4; ++i) s.emplace_back(o.metrics[2 * i], o.metrics[2 * i + 1]);
    const auto e1 = s[0] + s[1] + s[2] + s[3];
    const auto e2 =
        s[0] * s[1] + s[0] * s[2] + s[0] * s[3] + s[1] * s[2] + s[1] * s[3] + s[2] * s[3];
    const auto e3 =
        s[0] * s[1] * s[2] + s[0] * s[1] * s[3] + s[0] * s[2] * s[3] + s[1] * s[2] * s[3];
    const auto e4 = s[0] * s[1] * s[2] * s[3];
    // Relative 1e-9: the linearization is exact to round-off for this linear model, and the
    // eigenvalues of a 4×4 A with a 1e3 spread of scales carry ~1e-12 relative error.
    EXPECT_LT(std::abs(e1 + a3 / a4), 1e-9 * a3 / a4) << o.run;
    EXPECT_LT(std::abs(e2 - a2 / a4), 1e-9 * a2 / a4) << o.run;
    EXPECT_LT(std::abs(e3 + a1 / a4), 1e-9 * a1 / a4) << o.run;
    EXPECT_LT(std::abs(e4 - a0 / a4), 1e-9 * a0 / a4) << o.run;
    // ωn and ζ are those of each pole.
    for (int i = 0; i < 4; ++i) {
      EXPECT_DOUBLE_EQ(o.metrics[8 + i], std::abs(s[static_cast<std::size_t>(i)]));
      EXPECT_DOUBLE_EQ(o.metrics[12 + i], -s[static_cast<std::size_t>(i)].real() /
                                              std::abs(s[static_cast<std::size_t>(i)]));
    }
  }
}

TEST(QuarterCarSweep, RowsEqualTheModelRunOnItsOwnAndDoNotDependOnTheThreadCount) {
  const SweepRunner runner(io::read_sweep_file("examples/sweeps/quarter_car_ride.yaml"));
  const std::vector<RunOutcome> one = run_all(runner, 1);
  const std::vector<RunOutcome> three = run_all(runner, 3);
  ASSERT_EQ(one.size(), three.size());
  for (std::size_t k = 0; k < one.size(); ++k) {
    EXPECT_EQ(results_row(one[k], false, ""), results_row(three[k], false, ""));
  }
  // Run 13 on its own: the model file with its two numbers, integrated as `momenta simulate`
  // does with the sweep's options, the metrics taken from the whole table.
  const RunOutcome& o = one[13];
  const io::ModelFile file = io::read_model_file_with(
      "examples/quarter_car.yaml", {{"forces.suspension.stiffness", o.parameters[0]},
                                    {"forces.suspension.damping", o.parameters[1]}});
  simulate::RunRequest request;
  request.settings.duration = 2.0;
  request.settings.step = 0.001;
  request.settings.integrator = "rk4";
  simulate::Simulation simulation(file.model, file.outputs,
                                  simulate::resolve_run(request, file.simulation).options);
  simulate::TableSink table;
  simulation.run(table);
  const int y = table.column("body_y");
  const int force = table.column("suspension_force");
  double y_max = -1e300, force_max = 0.0;
  for (const auto& row : table.rows) {
    y_max = std::max(y_max, row[static_cast<std::size_t>(y)]);
    force_max = std::max(force_max, std::abs(row[static_cast<std::size_t>(force)]));
  }
  EXPECT_EQ(o.metrics[0], y_max);
  EXPECT_EQ(o.metrics[3], force_max);
  // The overshoot over the settled 5 cm, from the same samples.
  const double final_y = table.rows.back()[static_cast<std::size_t>(y)];
  EXPECT_NEAR(o.metrics[1], 100.0 * (y_max - final_y) / final_y, 1e-12 * 100.0);
}

}  // namespace
}  // namespace momenta::sweep
