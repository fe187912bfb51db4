// A part swept (examples/sweeps/flywheel_rim.yaml): each run's mass and axial moment of inertia
// against the closed forms of the flywheel's hollow cylinders less its four windows, and the
// Monte Carlo example's Latin hypercube runs every car.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "momenta/io/sweep_file.hpp"
#include "momenta/sweep/execution.hpp"

namespace momenta::sweep {
namespace {

std::vector<RunOutcome> every_run(const SweepRunner& runner) {
  std::vector<long> runs(static_cast<std::size_t>(runner.run_count()));
  for (std::size_t k = 0; k < runs.size(); ++k) runs[k] = static_cast<long>(k);
  std::vector<RunOutcome> outcomes;
  run_in_order(runner, runs, 2, [&](RunOutcome&& o) { outcomes.push_back(std::move(o)); });
  return outcomes;
}

// A ring (hollow cylinder about its axis): m = ρ π (R² − r²) L, I = ½ m (R² + r²).
struct Ring {
  double mass, axial;
};
Ring ring(double rho, double R, double r, double L) {
  const double m = rho * std::numbers::pi * (R * R - r * r) * L;
  return {m, 0.5 * m * (R * R + r * r)};
}

TEST(PartSweep, EveryRunsMassAndAxialInertiaAreTheClosedForms) {
  const SweepRunner runner(io::read_sweep_file("examples/sweeps/flywheel_rim.yaml"));
  ASSERT_EQ(runner.run_count(), 44);
  const double rho = 7200.0, mm = 1e-3;
  // The four Ø60 windows through the 20 mm web, on a 190 mm pitch circle (parallel axes).
  const Ring window = ring(rho, 30 * mm, 0.0, 20 * mm);
  const double d = 95 * mm;
  const Ring web = ring(rho, 150 * mm, 40 * mm, 20 * mm),
             hub = ring(rho, 40 * mm, 15 * mm, 50 * mm);
  for (const RunOutcome& o : every_run(runner)) {
    ASSERT_TRUE(o.ok) << o.message;
    const Ring rim = ring(rho, o.parameters[0] * mm, 150 * mm, o.parameters[1] * mm);
    const double mass = rim.mass + web.mass + hub.mass - 4 * window.mass;
    const double axial =
        rim.axial + web.axial + hub.axial - 4 * (window.axial + window.mass * d * d);
    // Sums of a few terms of one sign each but the windows: round-off, 1e-13 relative.
    EXPECT_NEAR(o.metrics[0], mass, 1e-13 * mass) << o.run;
    EXPECT_NEAR(o.metrics[3], axial, 1e-13 * axial) << o.run;  // I.zz
    EXPECT_NEAR(o.metrics[9], axial, 1e-13 * axial) << o.run;  // the largest principal moment
    // Products of inertia vanish: the windows sit symmetrically.
    for (int k = 4; k < 7; ++k)
      EXPECT_NEAR(o.metrics[static_cast<std::size_t>(k)], 0.0, 1e-15 * axial);
  }
}

TEST(PartSweep, TheMonteCarloExampleRunsEveryCarWithinItsBounds) {
  const SweepRunner runner(io::read_sweep_file("examples/sweeps/quarter_car_monte_carlo.yaml"));
  ASSERT_EQ(runner.run_count(), 200);
  for (const RunOutcome& o : every_run(runner)) {
    ASSERT_TRUE(o.ok) << o.message;
    EXPECT_GE(o.parameters[0], 250.0);
    EXPECT_LE(o.parameters[0], 500.0);
    EXPECT_GT(o.parameters[2], 0.0);  // log-normal damping
    for (double wn : std::span(o.metrics).first(4)) EXPECT_GT(wn, 0.0);
  }
}

// Each results column's unit: a parameter's from where its number sits (the part file's mm, a
// body's mass, a spring's stiffness and damping), a metric's from what it measures.
TEST(SweepColumnUnits, ParametersAndMetricsCarryTheirUnits) {
  using Units = std::vector<std::string>;
  const SweepRunner rim(io::read_sweep_file("examples/sweeps/flywheel_rim.yaml"));
  EXPECT_EQ(rim.parameter_units(), (Units{"mm", "mm"}));
  EXPECT_EQ(rim.metric_units(), (Units{"kg", "kg·m²", "kg·m²", "kg·m²", "kg·m²", "kg·m²", "kg·m²",
                                       "kg·m²", "kg·m²", "kg·m²"}));
  const SweepRunner cars(io::read_sweep_file("examples/sweeps/quarter_car_monte_carlo.yaml"));
  EXPECT_EQ(cars.parameter_units(), (Units{"kg", "N/m", "N·s/m"}));
  ASSERT_EQ(cars.metric_units().size(), 8u);  // four natural frequencies, four damping ratios
  EXPECT_EQ(cars.metric_units()[0], "rad/s");
  EXPECT_EQ(cars.metric_units()[7], "1");
  const SweepRunner ride(io::read_sweep_file("examples/sweeps/quarter_car_ride.yaml"));
  EXPECT_EQ(ride.parameter_units(), (Units{"N/m", "N·s/m"}));
  EXPECT_EQ(ride.metric_units(), (Units{"m", "%", "s", "N", "m"}));
}

}  // namespace
}  // namespace momenta::sweep
