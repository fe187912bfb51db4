// The closed loop simulated (model/controller.hpp, system/closed_loop_system.hpp), against
// independent references: Franklin's cruise control with a PI controller against the closed form
// of its second-order loop (and its saturated start against the first-order lag it then is); the
// inverted pendulum on a cart under LQR state feedback against the linear closed loop's own
// solution, e^{(A − BK) t} x0; a satellite under a discrete PD at 10 Hz against the discrete
// recursion of the plant held between samples (c2d by hand).

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>
#include <unsupported/Eigen/MatrixFunctions>

#include "momenta/analysis/discretize.hpp"
#include "momenta/analysis/linearize.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/simulate/simulation.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta {
namespace {

io::ModelFile example_file(const std::string& name) {
  return io::read_model_file(std::filesystem::path("examples") / (name + ".yaml"));
}

simulate::TableSink simulate_file(const io::ModelFile& file, simulate::SimulationOptions options) {
  simulate::Simulation simulation(file.model, file.outputs, std::move(options));
  simulate::TableSink sink;
  simulation.run(sink);
  return sink;
}

simulate::SimulationOptions rk4(double duration, double step) {
  simulate::SimulationOptions o;
  o.duration = duration;
  o.step = step;
  return o;
}

// The cruise control of examples/cruise_control_pi.yaml with its text changed.
io::ModelFile cruise_with(const std::string& from, const std::string& to) {
  std::ifstream in("examples/cruise_control_pi.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  return io::parse_model_file(text, "cruise.yaml", "examples");
}

// --- Cruise control, PI -------------------------------------------------------------------------

// m v̇ + b v = kp e + ki ∫e, e = r − v: V/R = (0.8 s + 0.04)/((s + 0.8)(s + 0.05)), the zero
// cancelling the slow pole, so v = r (1 − e^{−0.8 τ}) and u = b r + (kp − b) r e^{−0.8 τ},
// the integral term I = ki ∫e = (ki r / 0.8)(1 − e^{−0.8 τ}), τ = t − 1 s after the step.
TEST(ClosedLoop, CruiseControlPiFollowsTheSecondOrderClosedForm) {
  const io::ModelFile file = example_file("cruise_control_pi");
  for (const std::string integrator : {"rk4", "dopri5"}) {
    simulate::SimulationOptions options = rk4(10.0, 0.01);
    options.integrator = integrator;
    options.tolerances = {1e-11, 1e-11};
    const simulate::TableSink table = simulate_file(file, options);
    const int t = table.column("time"), v = table.column("x.position_rate");
    const int u = table.column("cruise.engine"), I = table.column("cruise.integral");
    const int e = table.column("cruise.error");
    double worst_v = 0.0, worst_u = 0.0, worst_i = 0.0;
    for (const auto& row : table.rows) {
      const double tau = row[t] - 1.0;
      const double r = tau >= 0.0 ? 10.0 : 0.0;
      const double decay = tau >= 0.0 ? std::exp(-0.8 * tau) : 1.0;
      worst_v = std::max(worst_v, std::abs(row[v] - r * (1.0 - decay)));
      worst_u = std::max(worst_u, std::abs(row[u] - (50.0 * r + 750.0 * r * decay)));
      worst_i = std::max(worst_i, std::abs(row[I] - 40.0 * r / 0.8 * (1.0 - decay)));
      EXPECT_NEAR(row[e], r - row[v], 1e-15 * r + 1e-300);
    }
    // RK4 at h = 0.01 on the rate 0.8: a relative error (0.8 h)⁵/120 ≈ 3e-13 a step, over 900
    // steps on a 10 m/s swing, ~3e-9 m/s; dopri5 holds 1e-11 per step. The force is 800 times
    // the speed error.
    SCOPED_TRACE(integrator);
    EXPECT_LT(worst_v, 5e-9);
    EXPECT_LT(worst_i, 5e-6);
    EXPECT_LT(worst_u, 5e-6);
    // Before the step the loop rests; at t = 1 s the row holds the reference's new value and
    // the proportional kick kp · 10 = 8000 N.
    for (const auto& row : table.rows) {
      if (row[t] < 1.0) {
        EXPECT_EQ(row[u], 0.0);
      } else if (row[t] == 1.0) {
        EXPECT_NEAR(row[u], 8000.0, 1e-9);
      }
    }
  }
}

// Saturated at 5000 N (< kp · 10), the car first accelerates as the open lag m v̇ + b v = 5000,
// v = 100 (1 − e^{−0.05 τ}), and the integral holds at zero (conditional integration) until
// kp (10 − v) falls to 5000 N, at v = 3.75 m/s, τ* = −20 ln(1 − 0.0375) = 0.76433 s.
TEST(ClosedLoop, SaturatedPiHoldsItsIntegralWhileThePushIsOutOfRange) {
  const io::ModelFile file =
      cruise_with("    drives: engine", "    drives: engine\n    actuator: {max: 5000}");
  const simulate::TableSink table = simulate_file(file, rk4(4.0, 0.001));
  const int t = table.column("time"), v = table.column("x.position_rate");
  const int u = table.column("cruise.engine"), I = table.column("cruise.integral");
  const double tau_star = -20.0 * std::log1p(-0.0375);
  int saturated = 0, after = 0;
  for (const auto& row : table.rows) {
    const double tau = row[t] - 1.0;
    if (tau <= 0.0) continue;
    if (tau < tau_star - 1e-3) {
      ++saturated;
      EXPECT_EQ(row[u], 5000.0);
      EXPECT_EQ(row[I], 0.0);
      EXPECT_NEAR(row[v], 100.0 * -std::expm1(-0.05 * tau), 1e-11);
    } else if (tau > tau_star + 1e-3) {
      ++after;
      EXPECT_LT(row[u], 5000.0);
      EXPECT_GT(row[I], 0.0);
    }
  }
  EXPECT_GT(saturated, 700);
  EXPECT_GT(after, 2000);
  // Then the loop settles without the wound-up overshoot: the speed never passes 10 m/s by
  // more than the unsaturated loop's (which has none: its only mode is −0.8).
  double most = 0.0;
  for (const auto& row : table.rows) most = std::max(most, row[v]);
  EXPECT_LT(most, 10.0 + 1e-6);
}

// --- Inverted pendulum, LQR
// -----------------------------------------------------------------------

// The nonlinear closed loop from 10° against the linear one, x(t) = e^{(A − BK) t} x0 with A, B
// the plant's linearization about upright (momenta's, checked against the closed form in
// control_design_test) and K the file's: they agree to second order in the 0.17 rad start, and
// the nonlinear pendulum settles within the linear prediction's 2 % settling time.
TEST(ClosedLoop, InvertedPendulumLqrRecoversFromTenDegreesAsTheLinearLoopPredicts) {
  const io::ModelFile file = example_file("cart_pendulum_lqr");
  analysis::LinearizationOptions lin;
  lin.inputs = {"force"};
  lin.close_loops = false;  // the plant, its force an input
  analysis::OperatingPoint upright{0.0, VecX::Zero(2), VecX::Zero(2)};
  const analysis::LinearModel plant = analysis::linearize(file.model, upright, lin);
  const MatX& K = file.model.controllers()[0].spec.gain;
  const MatX A_cl = plant.system.A() - plant.system.B() * K;
  // The closed loop is the one `momenta lqr` reported: −0.849388 ± 0.832271j, −5.60061 ± 0.40678j.
  const Eigen::VectorXcd poles = A_cl.eigenvalues();
  double slowest = -1e300;
  for (const auto& p : poles) slowest = std::max(slowest, p.real());
  EXPECT_NEAR(slowest, -0.849388, 1e-6);

  const simulate::TableSink table = simulate_file(file, rk4(8.0, 0.001));
  const int t = table.column("time"), phi = table.column("tilt.angle");
  const double phi0 = 10.0 * std::numbers::pi / 180.0;
  VecX x0(4);
  x0 << 0.0, phi0, 0.0, 0.0;
  double worst = 0.0, settle_linear = 0.0, settle_nonlinear = 0.0;
  for (const auto& row : table.rows) {
    const VecX x = (A_cl * row[t]).exp() * x0;
    worst = std::max(worst, std::abs(row[phi] - x[1]));
    if (std::abs(x[1]) > 0.02 * phi0) settle_linear = row[t];
    if (std::abs(row[phi]) > 0.02 * phi0) settle_nonlinear = row[t];
  }
  // The neglected terms are O(φ³) against O(φ): (0.17)² ≈ 3 % of the start.
  EXPECT_LT(worst, 0.03 * phi0);
  EXPECT_GT(settle_linear, 3.0);
  EXPECT_LE(settle_nonlinear, settle_linear * 1.02);
  // And it ends upright and at rest.
  EXPECT_LT(std::abs(table.rows.back()[phi]), 1e-3);
}

// --- Cart pendulum with its cart's acceleration commanded ---------------------------------------

// The servo cart of examples/cart_pendulum_servo.yaml: the controller commands the cart's
// acceleration a = −K [x, φ, ẋ, φ̇], so the whole loop is the four equations
//   ẍ = a,   J φ̈ = m g l sin φ − m l a cos φ   (J = I + m l² = 0.024 kg·m²),
// integrated here by the test's own RK4 at a tenth of the run's step (an independent solution);
// the drive's force is Newton's for the cart and the pendulum's centre together,
//   F = (M + m) a + m l (φ̈ cos φ − φ̇² sin φ).
struct ServoCart {
  static constexpr double M = 0.5, m = 0.2, l = 0.3, J = 0.006 + 0.2 * 0.3 * 0.3, g = 9.81;
  Eigen::RowVector4d K;
  double acceleration(const Eigen::Vector4d& x) const { return -K.dot(x); }  // x = [x, φ, ẋ, φ̇]
  double tilt_acceleration(const Eigen::Vector4d& x, double a) const {
    return (m * g * l * std::sin(x[1]) - m * l * a * std::cos(x[1])) / J;
  }
  Eigen::Vector4d rate(const Eigen::Vector4d& x) const {
    const double a = acceleration(x);
    return {x[2], x[3], a, tilt_acceleration(x, a)};
  }
};

TEST(ClosedLoop, CommandedCartAccelerationMovesThePendulumAsItsEquations) {
  const io::ModelFile file = example_file("cart_pendulum_servo");
  ServoCart cart;
  cart.K = file.model.controllers()[0].spec.gain.row(0);
  const simulate::TableSink table = simulate_file(file, rk4(8.0, 0.001));
  const int t = table.column("time"), x = table.column("x.position");
  const int phi = table.column("tilt.angle"), xd = table.column("x.position_rate");
  const int phid = table.column("tilt.angle_rate"), a = table.column("balance.cart_drive");
  const int force = table.column("cart_force");
  Eigen::Vector4d ref(0.0, 10.0 * std::numbers::pi / 180.0, 0.0, 0.0);
  const double h = 1e-4;
  double at = 0.0, worst = 0.0, worst_force = 0.0;
  for (const auto& row : table.rows) {
    while (at < row[t] - 0.5 * h) {  // RK4 on the four equations up to this row
      const Eigen::Vector4d k1 = cart.rate(ref), k2 = cart.rate(ref + 0.5 * h * k1);
      const Eigen::Vector4d k3 = cart.rate(ref + 0.5 * h * k2), k4 = cart.rate(ref + h * k3);
      ref += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      at += h;
    }
    const Eigen::Vector4d state(row[x], row[phi], row[xd], row[phid]);
    worst = std::max(worst, (state - ref).cwiseAbs().maxCoeff());
    EXPECT_NEAR(row[a], cart.acceleration(state), 1e-13);
    const double phi_dd = cart.tilt_acceleration(state, row[a]);
    const double F = (ServoCart::M + ServoCart::m) * row[a] +
                     ServoCart::m * ServoCart::l *
                         (phi_dd * std::cos(row[phi]) - row[phid] * row[phid] * std::sin(row[phi]));
    worst_force = std::max(worst_force, std::abs(row[force] - F));
  }
  // Both RK4, at h = 1 ms and 0.1 ms on rates up to ~5 1/s: (5 · 1e-3)⁴ ≈ 6e-10 a step relative
  // for the run's, far less for the reference's; over 8000 steps on a 0.17 rad swing, ~1e-9.
  EXPECT_LT(worst, 2e-9);
  EXPECT_LT(worst_force, 1e-11);
  // Held up: upright and home at the end.
  EXPECT_LT(std::abs(table.rows.back()[phi]), 1e-2);
}

// Sampled at 100 Hz the commanded acceleration is held between samples, so the cart's coordinate
// is exactly the held double integrator's: x⁺ = x + T ẋ + T² a/2, ẋ⁺ = ẋ + T a (RK4 is exact on
// the quadratic), whatever the pendulum does.
TEST(ClosedLoop, SampledCommandedAccelerationIsTheHeldDoubleIntegrator) {
  std::ifstream in("examples/cart_pendulum_servo.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string drives = "    drives: cart_drive\n";
  text.replace(text.find(drives), drives.size(), drives + "    sample_time: 0.01\n");
  const io::ModelFile file = io::parse_model_file(text, "servo_sampled.yaml", "examples");
  const simulate::TableSink table = simulate_file(file, rk4(3.0, 0.001));
  const int t = table.column("time"), x = table.column("x.position");
  const int xd = table.column("x.position_rate"), a = table.column("balance.cart_drive");
  const double T = 0.01;
  double worst = 0.0;
  int samples = 0;
  const std::vector<double>* previous = nullptr;
  for (const auto& row : table.rows) {
    if (std::abs(row[t] / T - std::round(row[t] / T)) > 1e-9) continue;
    if (previous != nullptr) {
      const auto& p = *previous;
      worst = std::max({worst, std::abs(row[x] - (p[x] + T * p[xd] + 0.5 * T * T * p[a])),
                        std::abs(row[xd] - (p[xd] + T * p[a])) * T});
      ++samples;
    }
    previous = &row;
  }
  EXPECT_EQ(samples, 300);
  EXPECT_LT(worst, 1e-14);
}

// --- Satellite attitude, discrete PD at 10 Hz ----------------------------------------------------

// I θ̈ = u held over each sample T = 0.1 s: x = (θ, ω), x⁺ = Φ x + Γ u with Φ = [1 T; 0 1],
// Γ = [T²/(2I); T/I] (c2d by hand), and u_k = kp e_k + kd (e_k − e_{k−1})/T, e = r − θ.
TEST(ClosedLoop, SatelliteDiscretePdEqualsTheSampledRecursion) {
  const io::ModelFile file = example_file("satellite_attitude_pd");
  const model::Controller& pd = file.model.controllers()[0].spec;
  ASSERT_EQ(pd.sample_time, 0.1);
  const double T = pd.sample_time, I = 5000.0, kp = pd.pid.kp, kd = pd.pid.kd, r = pd.setpoint;

  // c2d of momenta's own linearization against the hand's Φ, Γ.
  analysis::LinearizationOptions lin;
  lin.inputs = {"thrust"};
  lin.close_loops = false;  // the plant, its torque an input
  lin.outputs = {"attitude.angle"};
  const analysis::LinearModel plant = analysis::linearize(
      file.model, analysis::OperatingPoint{0.0, VecX::Zero(1), VecX::Zero(1)}, lin);
  const analysis::StateSpace held = analysis::c2d(plant.system, T);
  Eigen::Matrix2d Phi;
  Phi << 1.0, T, 0.0, 1.0;
  const Eigen::Vector2d Gamma(T * T / (2.0 * I), T / I);
  EXPECT_LT((held.A() - Phi).norm(), 1e-14);
  EXPECT_LT((held.B() - Gamma).norm(), 1e-17);

  // The closed loop ξ = (θ, ω, e_{k−1}) is linear in ξ and r: its poles inside the unit circle.
  Eigen::Matrix3d A_cl;
  const double a = kp + kd / T;  // ∂u/∂e_k; ∂u/∂e_{k−1} = −kd/T, e_k = r − θ_k
  A_cl << Phi(0, 0) - Gamma[0] * a, Phi(0, 1), Gamma[0] * (-kd / T), -Gamma[1] * a, Phi(1, 1),
      Gamma[1] * (-kd / T),  //
      -1.0, 0.0, 0.0;
  for (const auto& z : A_cl.eigenvalues()) EXPECT_LT(std::abs(z), 1.0);

  // The sampled simulation against the recursion: RK4 is exact on the cubic each held step
  // gives (θ is a quadratic in t), so only round-off separates them.
  const simulate::TableSink table = simulate_file(file, rk4(20.0, 0.01));
  const int t = table.column("time"), theta = table.column("attitude.angle");
  const int w = table.column("attitude.angle_rate"), u = table.column("attitude_pd.thrust");
  double th = 0.0, om = 0.0, e_last = r;  // e_{−1} = e_0
  std::size_t row = 0;
  double worst = 0.0;
  for (int k = 0; k <= 200; ++k) {
    const double tk = k * T;
    while (row < table.rows.size() && std::abs(table.rows[row][t] - tk) > 1e-9) ++row;
    ASSERT_LT(row, table.rows.size()) << "no row at t = " << tk;
    const double e = r - th;
    const double uk = kp * e + kd * (e - e_last) / T;
    worst = std::max(
        {worst, std::abs(table.rows[row][theta] - th), std::abs(table.rows[row][w] - om) * T});
    EXPECT_NEAR(table.rows[row][u], uk, 1e-12 * 1e4);
    const double th_next = th + T * om + Gamma[0] * uk;
    om += Gamma[1] * uk;
    th = th_next;
    e_last = e;
  }
  EXPECT_LT(worst, 1e-12);
  // The recursion settles on the reference.
  EXPECT_NEAR(th, r, 1e-3 * r);
}

// The output is held between samples: constant over each 0.1 s, changing only at t = kT, also
// under an adaptive method whose steps the samples cut.
TEST(ClosedLoop, DiscreteOutputsChangeOnlyAtTheirSamples) {
  const io::ModelFile file = example_file("satellite_attitude_pd");
  simulate::SimulationOptions options = rk4(2.0, 0.01);
  options.integrator = "dopri5";
  const simulate::TableSink table = simulate_file(file, options);
  const int t = table.column("time"), u = table.column("attitude_pd.thrust");
  for (std::size_t i = 1; i < table.rows.size(); ++i) {
    const double t0 = table.rows[i - 1][t], t1 = table.rows[i][t];
    const bool sample_between = std::floor(t1 / 0.1 + 1e-9) > std::floor(t0 / 0.1 + 1e-9);
    if (!sample_between) {
      EXPECT_EQ(table.rows[i][u], table.rows[i - 1][u]) << "t = " << t1;
    }
  }
}

}  // namespace
}  // namespace momenta
