// A rod sliding on its foot towards Painlevé's point (integrate::UndefinedAcceleration): a uniform
// rod, m = 1 kg, L = 1 m, tilted φ from the vertical about y, its foot on a rough floor
// (μs = μk = μ = 2) and slipping foot first, away from the rod's lean. While it slides, the floor's
// normal force is N = m (g − (L/2) cos φ φ̇²) / D with
//
//   D(φ) = 1 + 3 sin² φ − 3 μ sin φ cos φ,
//
// zero at φ_J = 52.63° for μ = 2 and negative below it to 10.8°: there the friction would press
// the foot into the floor faster than N lifts it, and sliding has no normal force at all (the
// rod's contact forces turn it upright, towards φ_J). Two cases, each under dopri5 and bdf:
// - from φ₀ = 60°, φ̇₀ = −1 rad/s, slipping at 4 m/s: the slip stops at t_s = 0.06285 s, short of
//   φ_J (D = 0.083 there), and the foot sticks. An adaptive method's long step that straddles
//   t_s tries points past it that still slide (the stop is found after the step), and those
//   reach φ_J: the methods retry shorter steps and find the stop; the time is checked against rk4
//   at 0.1 ms (a second method whose steps stay short of φ_J). rk4 at 10 ms meets φ_J in its own
//   trial points and stops the run, saying which methods retry.
// - from φ₀ = 55°, φ̇₀ = −1 rad/s, slipping at 6 m/s: the slip is still running where D reaches
//   zero, at t_J = 0.018365 s, and the run stops there under both, which say the motion reaches it.

#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/simulate/simulation.hpp"
#include "unilateral_runs.hpp"

namespace momenta::simulate {
namespace painleve_jam {
namespace {

using namespace unilateral_test;

constexpr double kMu = 2.0, kHalfLength = 0.5;

double painleve_d(double phi) {
  return 1.0 + 3.0 * std::sin(phi) * std::sin(phi) - 3.0 * kMu * std::sin(phi) * std::cos(phi);
}

// The rod at φ₀ (deg) turning at φ̇₀ (rad/s) about y, its foot on the floor and slipping at
// `slip` (m/s) along x (negative: away from the lean).
std::string sliding_rod(double phi0_deg, double phi_rate, double slip) {
  const double phi = phi0_deg * std::numbers::pi / 180.0;
  const double r_x = -kHalfLength * std::sin(phi), r_z = -kHalfLength * std::cos(phi);
  // The centre's velocity: the foot's less ω × r (ω along y: ω × r = (ω r_z, 0, −ω r_x)).
  const double v_x = slip - phi_rate * r_z, v_z = phi_rate * r_x;
  return fmt::format(
      "gravity: [0, 0, -9.81]\n"
      "bodies: [{{name: rod, mass: 1.0, inertia: [0.08333333333333333, 0.08333333333333333, "
      "1.0e-4]}}]\n"
      "joints:\n"
      "  - name: free\n"
      "    type: free\n"
      "    parent: world\n"
      "    child: rod\n"
      "    q0: {{position: [{:.17g}, 0, {:.17g}], euler: {{sequence: XYZ, angles_deg: [0, {}, "
      "0]}}}}\n"
      "    v0: [0, {:.17g}, 0, {:.17g}, 0, {:.17g}]\n"
      "constraints:\n"
      "  - {{name: foot, type: contact, body: rod, point: [0, 0, -0.5], restitution: 0.0, "
      "friction: {{static: {}, kinetic: {}}}}}\n",
      -r_x, -r_z, phi0_deg, phi_rate, v_x, v_z, kMu, kMu);
}

struct RodRun {
  SimulationSummary summary;
  TableSink table;
  std::string error;  // what stopped the run, or empty
};

RodRun run_rod(const std::string& text, const std::string& integrator, double step,
               integrate::Tolerances tolerances, double duration = 0.1) {
  SimulationOptions options;
  options.duration = duration;
  options.step = step;
  options.integrator = integrator;
  options.tolerances = tolerances;
  const model::Model model = load(text);  // Simulation refers to it
  Simulation simulation(model, {}, options);
  RodRun r;
  try {
    r.summary = simulation.run(r.table);
  } catch (const NumericalError& e) {
    r.error = e.what();
  }
  return r;
}

// The rod's tilt φ (rad) in a row: its turn about y.
double tilt(const TableSink& table, const std::vector<double>& row) {
  return 2.0 * std::atan2(row[table.column("free.qy")], row[table.column("free.qw")]);
}

TEST(PainleveJam, TheClosedFormsPointsAreWhereTheTestSaysTheyAre) {
  EXPECT_NEAR(painleve_d(60.0 * std::numbers::pi / 180.0), 0.6519, 1e-4);
  EXPECT_LT(painleve_d(52.60 * std::numbers::pi / 180.0), 0.0);
  EXPECT_GT(painleve_d(52.65 * std::numbers::pi / 180.0), 0.0);
  EXPECT_GT(painleve_d(55.0 * std::numbers::pi / 180.0), 0.0);
}

TEST(PainleveJam, ASlipThatStopsShortOfTheJamSticksThereUnderEveryAdaptiveMethod) {
  const std::string rod = sliding_rod(60.0, -1.0, -4.0);
  // The reference: rk4 at 0.1 ms (its trial points stay short of φ_J).
  const RodRun reference = run_rod(rod, "rk4", 1e-4, {});
  ASSERT_EQ(reference.error, "");
  ASSERT_GE(reference.summary.stop_events.size(), 2u);
  const StopEvent& stop = reference.summary.stop_events[1];
  ASSERT_EQ(stop.kind, StopEventKind::stick);
  const double t_s = stop.time;
  EXPECT_NEAR(t_s, 0.0628525610, 1e-9);  // and dopri5 at rtol 1e-10: 0.062852561009 s
  // Short of the jam: D at the stop, from the rod's tilt in the stop's row.
  for (const std::vector<double>& row : reference.table.rows) {
    if (row[0] == t_s) {
      EXPECT_NEAR(painleve_d(tilt(reference.table, row)), 0.0827, 1e-3);
    }
  }

  // Each method with steps up to 50 ms: its long steps straddle t_s and try points past φ_J.
  // The stop's instant is the slip's error over its deceleration (195 m/s² there): dopri5 at
  // atol = rtol = 1e-5 has the slip to ~1e-5 m/s, 5e-8 s (measured 5.0e-8 s); bdf at 1e-8 finds
  // it in its halved step's cubic interpolant (measured 6.7e-8 s).
  struct Case {
    const char* integrator;
    integrate::Tolerances tolerances;
    double within;
  };
  for (const Case& c : {Case{"dopri5", {1e-5, 1e-5}, 1e-7}, Case{"dopri5", {1e-8, 1e-10}, 1e-9},
                        Case{"bdf", {1e-8, 1e-10}, 1e-7}}) {
    SCOPED_TRACE(fmt::format("{} at rtol {}", c.integrator, c.tolerances.relative));
    const RodRun r = run_rod(rod, c.integrator, 0.05, c.tolerances);
    ASSERT_EQ(r.error, "");
    ASSERT_GE(r.summary.stop_events.size(), 2u);
    EXPECT_EQ(r.summary.stop_events[1].kind, StopEventKind::stick);
    EXPECT_NEAR(r.summary.stop_events[1].time, t_s, c.within);
    EXPECT_GT(r.summary.statistics.rejected_steps, 0);
    // Friction takes energy while the foot slides (to round-off: 1e-12 J of the rod's 5 J).
    const int energy = r.table.column("energy_total");
    for (std::size_t k = 1; k < r.table.rows.size() && r.table.rows[k][0] <= t_s; ++k) {
      EXPECT_LE(r.table.rows[k][energy], r.table.rows[k - 1][energy] + 1e-12) << r.table.rows[k][0];
    }
  }

  // rk4 at 10 ms: its own trial points reach φ_J, and the run stops naming the way on.
  const RodRun fixed = run_rod(rod, "rk4", 0.01, {});
  EXPECT_NE(fixed.error.find("contact 'foot'"), std::string::npos) << fixed.error;
  EXPECT_NE(fixed.error.find("Painlevé's paradox"), std::string::npos) << fixed.error;
  EXPECT_NE(fixed.error.find("rk4 takes fixed steps"), std::string::npos) << fixed.error;
  EXPECT_NE(fixed.error.find("dopri5 or integrator bdf retries smaller steps"), std::string::npos)
      << fixed.error;  // (the library spells options so; the CLI as --integrator dopri5)
}

TEST(PainleveJam, ASlipThatRunsIntoTheJamStopsTheRunThereUnderEveryAdaptiveMethod) {
  const std::string rod = sliding_rod(55.0, -1.0, -6.0);
  // Where D reaches zero (the system's test is det > 1e-9), to the methods' tolerance: the two
  // agree to 1.0e-8 s (measured).
  for (const char* integrator : {"dopri5", "bdf"}) {
    SCOPED_TRACE(integrator);
    const RodRun r = run_rod(rod, integrator, 1e-3, {1e-8, 1e-10});
    EXPECT_NE(r.error.find("contact 'foot'"), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("the motion reaches it"), std::string::npos) << r.error;
    EXPECT_EQ(r.error.find("takes fixed steps"), std::string::npos) << r.error;
    const std::size_t at = r.error.find("at t = ");
    ASSERT_NE(at, std::string::npos);
    const double t = std::stod(r.error.substr(at + 7));
    EXPECT_NEAR(t, 0.0183651725, 1e-7);
    // The slip was running when the run stopped: the last row still slides at over 0.1 m/s.
    const std::vector<double>& last = r.table.rows.back();
    const double phi = tilt(r.table, last);
    const double foot_vx = last[r.table.column("free.vx")] -
                           last[r.table.column("free.wy")] * kHalfLength * std::cos(phi);
    EXPECT_LT(foot_vx, -0.1) << last[0];
    EXPECT_GT(painleve_d(phi), 0.0) << last[0];
  }
}

}  // namespace
}  // namespace painleve_jam
}  // namespace momenta::simulate
