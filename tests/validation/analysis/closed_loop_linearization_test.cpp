// The closed loop linearized (analysis::linearize of a model with controllers,
// LinearizationOptions:: close_loops): against the cruise control's closed-loop transfer function,
// the LQR design's closed-loop poles, and central differences of the closed loop the simulation
// integrates (system::ClosedLoopSystem) — a second, independent way to the same A.

#include <algorithm>
#include <cmath>
#include <complex>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "momenta/analysis/linearize.hpp"
#include "momenta/analysis/lqr.hpp"
#include "momenta/analysis/modes.hpp"
#include "momenta/analysis/transfer_function.hpp"
#include "momenta/common/error.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/simulate/simulation.hpp"
#include "momenta/system/closed_loop_system.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

io::ModelFile loop_example(const std::string& name) {
  return io::read_model_file(std::filesystem::path("examples") / (name + ".yaml"));
}

OperatingPoint rest(const model::Model& model) {
  return {0.0, VecX::Zero(model.nq()), VecX::Zero(model.nv())};
}

// V/R = (kp s + ki)/(m s² + (b + kp) s + ki) = (0.8 s + 0.04)/(s² + 0.85 s + 0.04).
TEST(ClosedLoopLinearization, CruiseControlIsFranklinsSecondOrderLoop) {
  const io::ModelFile file = loop_example("cruise_control_pi");
  LinearizationOptions options;
  options.outputs = {"speed"};
  options.output_specs = file.outputs;
  const LinearModel closed = linearize(file.model, rest(file.model), options);
  const StateSpace& s = closed.system;
  EXPECT_EQ(s.state_names(),
            (std::vector<std::string>{"x.position", "x.position_rate", "cruise.integral"}));
  EXPECT_EQ(s.input_names(), (std::vector<std::string>{"target_speed"}));
  // Poles: the position's 0, and −0.8, −0.05.
  std::vector<double> poles;
  for (const std::complex<double> p : s.A().eigenvalues()) poles.push_back(p.real());
  std::sort(poles.begin(), poles.end());
  ASSERT_EQ(poles.size(), 3u);
  EXPECT_NEAR(poles[0], -0.8, 1e-12);
  EXPECT_NEAR(poles[1], -0.05, 1e-12);
  EXPECT_NEAR(poles[2], 0.0, 1e-12);
  // C (sI − A)⁻¹ B + D against the closed form along the imaginary axis (near ω = 0: 1, the
  // integral leaves no steady error; the position's pole at 0 is not seen by the speed).
  for (const double w : {1e-4, 0.05, 0.3, 1.0, 7.0}) {
    const std::complex<double> j_w(0.0, w);
    const Eigen::MatrixXcd resolvent =
        (j_w * Eigen::MatrixXcd::Identity(3, 3) - s.A().cast<std::complex<double>>()).inverse();
    const std::complex<double> h = (s.C().cast<std::complex<double>>() * resolvent *
                                    s.B().cast<std::complex<double>>())(0, 0) +
                                   s.D()(0, 0);
    const std::complex<double> exact = (0.8 * j_w + 0.04) / (j_w * j_w + 0.85 * j_w + 0.04);
    EXPECT_LT(std::abs(h - exact), 1e-12 * std::abs(exact)) << "ω = " << w;
  }
  // The plant alone: the engine's force its input (the reference acts on nothing there), 1/(m s +
  // b).
  options.close_loops = false;
  const LinearModel plant = linearize(file.model, rest(file.model), options);
  EXPECT_EQ(plant.system.input_names(), (std::vector<std::string>{"engine"}));
  EXPECT_REL_NEAR(transfer_function(plant.system, "engine", "speed").dc_gain, 1.0 / 50.0, 1e-12);
}

// The LQR loop's poles: those `momenta lqr` designed, eig(A − B K).
TEST(ClosedLoopLinearization, LqrLoopHasTheDesignedPoles) {
  const io::ModelFile file = loop_example("cart_pendulum_lqr");
  const LinearModel closed = linearize(file.model, rest(file.model));
  EXPECT_EQ(closed.system.A().rows(), 4);
  EXPECT_EQ(closed.system.B().cols(), 0);  // no input left: the force is the controller's
  LinearizationOptions open;
  open.close_loops = false;
  const LinearModel plant = linearize(file.model, rest(file.model), open);
  const MatX expected = plant.system.A() - plant.system.B() * file.model.controllers()[0].spec.gain;
  EXPECT_LT((closed.system.A() - expected).norm(), 1e-13 * expected.norm());
  const Eigen::VectorXcd poles = closed.system.A().eigenvalues();
  for (const std::complex<double> p : poles) EXPECT_LT(p.real(), -0.84);
}

// A filtered PID holding the pendulum up (a nonlinear plant, a controller with two states):
// linearize's A against central differences of the closed loop's own right-hand side
// [v; v̇; ż](q, v, z) — the system the run integrates.
TEST(ClosedLoopLinearization, MatchesCentralDifferencesOfTheClosedLoop) {
  std::ifstream in("examples/cart_pendulum_lqr.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto from = text.find("controllers:"), to = text.find("bodies:");
  text.replace(from, to - from, R"(controllers:
  - name: tilt_pid
    type: pid
    measure: tilt.angle
    kp: -40
    ki: -20
    kd: -4
    derivative_filter: 0.02
    drives: force

)");
  const io::ModelFile file = io::parse_model_file(text, "pid_pendulum.yaml", "examples");
  OperatingPoint point = rest(file.model);
  point.q[1] = 0.05;  // off upright, where the pendulum's nonlinearity shows
  const LinearModel closed = linearize(file.model, point);
  const MatX& A = closed.system.A();
  ASSERT_EQ(A.rows(), 6);  // x, tilt, their rates, the integral and the filter

  system::MultibodySystem plant(file.model);
  system::ClosedLoopSystem loop(plant);
  // f(x) = [v; v̇; ż] at x = (q, v, z); the integral's configuration twin is not a state.
  const auto f = [&](const VecX& x) {
    VecX q = VecX::Zero(loop.nq()), v = VecX::Zero(loop.nv()), vdot = VecX::Zero(loop.nv());
    q.head(2) = x.head(2);
    v.head(2) = x.segment(2, 2);
    v.tail(2) = x.tail(2);
    loop.begin_step(0.0, 1.0);
    loop.acceleration(0.0, q, v, vdot);
    VecX out(6);
    out << x.segment(2, 2), vdot;
    return out;
  };
  // The point as linearize takes it: the integral zero, the filter at the error −0.05.
  VecX x0 = VecX::Zero(6);
  x0[1] = 0.05;
  x0[5] = -0.05;
  MatX differences(6, 6);
  const double h = 1e-6;
  for (int j = 0; j < 6; ++j) {
    VecX plus = x0, minus = x0;
    plus[j] += h;
    minus[j] -= h;
    differences.col(j) = (f(plus) - f(minus)) / (2 * h);
  }
  // Central differences at h = 1e-6: truncation ~h² |f'''| and round-off ~ε |f| / h ≈ 1e-9 of
  // the entries (up to ~2000: kd/Tf over the masses).
  EXPECT_LT((A - differences).cwiseAbs().maxCoeff(), 1e-6 * A.cwiseAbs().maxCoeff())
      << "A\n"
      << A << "\ndifferences\n"
      << differences;
}

// A measured output enters the closed loop by its row of C: the cruise PI measuring the car's
// velocity as a body output (its x component) has the closed-loop A of the PI on the joint's rate.
TEST(ClosedLoopLinearization, AMeasuredOutputEntersByItsRow) {
  std::ifstream in("examples/cruise_control_pi.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const io::ModelFile coordinate = io::parse_model_file(text, "cruise.yaml", "examples");
  const std::string from = "measure: x.position_rate";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(), "measure: car_velocity");
  text.replace(text.find("outputs:\n"), 9,
               "outputs:\n  - {name: car_velocity, body: car, quantity: velocity, component: x}\n");
  const io::ModelFile output = io::parse_model_file(text, "cruise.yaml", "examples");
  const LinearModel a = linearize(coordinate.model, rest(coordinate.model));
  const LinearModel b = linearize(output.model, rest(output.model));
  ASSERT_EQ(a.system.A().rows(), b.system.A().rows());
  EXPECT_LT((a.system.A() - b.system.A()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((a.system.B() - b.system.B()).cwiseAbs().maxCoeff(), 1e-12);
}

// The satellite's 10 Hz PD (kp = 1250, kd = 3500, Tf = 0: u_k = kp e_k + kd (e_k − e_(k−1))/T)
// linearized as the sampled loop it is: x = [θ, ω, e_(k−1)], A equal to the matrix assembled by
// hand from Φ = [1 T; 0 1], Γ = [T²/2I; T/I], and the sampled run equal to its recursion
// X_(k+1) = A X_k + c (c the constant the setpoint adds) at every sample after the first.
TEST(ClosedLoopLinearization, ASampledLoopIsTheRecursionItsRunFollows) {
  const io::ModelFile file = loop_example("satellite_attitude_pd");
  const LinearModel linear = linearize(file.model, rest(file.model));
  const StateSpace& S = linear.system;
  const double T = 0.1, I = 5000.0, kp = 1250.0, kd = 3500.0, r = 0.1;
  ASSERT_EQ(S.sample_time(), T);
  ASSERT_EQ(S.state_names(), (std::vector<std::string>{"attitude.angle", "attitude.angle_rate",
                                                       "attitude_pd.last_error"}));
  const double b = kd / T, De = kp + b;
  const Eigen::Vector2d gamma(T * T / (2 * I), T / I);
  MatX expected(3, 3);
  expected << 1 - gamma[0] * De, T, -gamma[0] * b,  //
      -gamma[1] * De, 1, -gamma[1] * b,             //
      -1, 0, 0;
  EXPECT_LT((S.A() - expected).cwiseAbs().maxCoeff(), 1e-14) << S.A();
  // Its modes: each z of A as the s it samples, z = e^(sT); the pair is the PD's, ζ ≈ 0.71.
  const Modes m = modes(S);
  const Eigen::VectorXcd z = Eigen::EigenSolver<MatX>(S.A()).eigenvalues();
  ASSERT_EQ(m.modes.size(), 3u);
  for (const Mode& mode : m.modes) {
    EXPECT_LT(std::abs(std::exp(mode.eigenvalue * T) - mode.z), 1e-14);
    EXPECT_LT((z.array() - mode.z).abs().minCoeff(), 1e-14);
  }
  EXPECT_NEAR(m.modes[0].damping_ratio, 0.7127, 1e-4);

  // The run's samples: θ, ω and the controller's last error.
  simulate::SimulationOptions options;
  options.duration = 5.0;
  options.step = 0.01;
  options.integrator = "rk4";
  simulate::Simulation simulation(file.model, file.outputs, options);
  simulate::TableSink table;
  simulation.run(table);
  const int t = table.column("time"), theta = table.column("attitude.angle"),
            omega = table.column("attitude.angle_rate"),
            last = table.column("attitude_pd.last_error");
  std::vector<Eigen::Vector3d> samples;
  for (const auto& row : table.rows) {
    const double k = row[t] / T;
    if (std::abs(k - std::round(k)) < 1e-9) samples.emplace_back(row[theta], row[omega], row[last]);
  }
  ASSERT_EQ(samples.size(), 51u);
  // A row at t_k holds the sample's own error as last_error: the state e_(k−1) is the row before's.
  const auto state = [&](std::size_t k) {
    return Eigen::Vector3d(samples[k][0], samples[k][1], samples[k - 1][2]);
  };
  const Eigen::Vector3d c(gamma[0] * De * r, gamma[1] * De * r, r);
  for (std::size_t k = 1; k + 1 < samples.size(); ++k) {
    const Eigen::Vector3d residual = state(k + 1) - S.A() * state(k) - c;
    EXPECT_LT(residual.cwiseAbs().maxCoeff(), 1e-12) << "sample " << k << ": " << residual;
  }
}

// A commanded coordinate joins the states with its acceleration as the input: the servo cart of
// examples/cart_pendulum_servo.yaml about upright is, by hand (J = I + m l² = 0.024 kg·m²),
//   φ̈ = (m g l / J) φ − (m l / J) a = 24.525 φ − 2.5 a,   ẍ = a,
// over the states [tilt.angle, tilt.angle_rate, x.position, x.position_rate]. The file's gain is
// SciPy's LQR for Q = diag(1, 1) on x and φ, R = 1; momenta's on its own plant equals it, and the
// closed loop is A − B K.
TEST(ClosedLoopLinearization, ACommandedCoordinateIsADoubleIntegratorOfItsInput) {
  const io::ModelFile file = loop_example("cart_pendulum_servo");
  LinearizationOptions open;
  open.close_loops = false;
  const LinearModel plant = linearize(file.model, rest(file.model), open);
  const StateSpace& P = plant.system;
  ASSERT_EQ(P.state_names(), (std::vector<std::string>{"tilt.angle", "tilt.angle_rate",
                                                       "x.position", "x.position_rate"}));
  EXPECT_EQ(P.input_names(), (std::vector<std::string>{"cart_drive"}));
  EXPECT_EQ(P.units().inputs, (std::vector<std::string>{"m/s²"}));
  MatX A(4, 4), B(4, 1);
  A << 0, 1, 0, 0, 0.2 * 9.81 * 0.3 / 0.024, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0;
  B << 0, -0.2 * 0.3 / 0.024, 0, 1;
  EXPECT_LT((P.A() - A).cwiseAbs().maxCoeff(), 1e-11 * A.norm());
  EXPECT_LT((P.B() - B).cwiseAbs().maxCoeff(), 1e-12 * B.norm());

  // LQR on it, Q on x and φ: the file's gain, its columns [x, φ, ẋ, φ̇] in the plant's order.
  MatX Q = MatX::Zero(4, 4);
  Q(0, 0) = Q(2, 2) = 1.0;
  const LqrDesign design = lqr(P, Q, MatX::Identity(1, 1));
  const MatX& K_file = file.model.controllers()[0].spec.gain;
  MatX K(1, 4);
  K << K_file(0, 1), K_file(0, 3), K_file(0, 0), K_file(0, 2);
  EXPECT_LT((design.K - K).cwiseAbs().maxCoeff(), 1e-8 * K.norm());

  const LinearModel closed = linearize(file.model, rest(file.model));
  EXPECT_EQ(closed.system.state_names(), P.state_names());
  const MatX expected = P.A() - P.B() * K;
  EXPECT_LT((closed.system.A() - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.norm());
  for (const std::complex<double> p : closed.system.A().eigenvalues()) {
    EXPECT_LT(p.real(), -0.70) << p;  // −4.9586 ± 0.2519j, −0.7054 ± 0.7051j
  }
}

TEST(ClosedLoopLinearization, RefusesWhatItCannotLinearize) {
  // Sampled and continuous together, or at two sample times: no one linear model.
  const auto both = [](const std::string& second) {
    std::ifstream in("examples/satellite_attitude_pd.yaml");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find("controllers:\n"), 13,
                 "controllers:\n  - {name: second, type: pid, measure: attitude.angle, kp: 1, "
                 "drives: extra" +
                     second + "}\n");
    text.replace(text.find("forces:\n"), 8,
                 "forces:\n  - {name: push, type: torque, body: satellite, vector: [0, 0, 1], "
                 "signal: extra}\n");
    const io::ModelFile file = io::parse_model_file(text, "two.yaml", "examples");
    try {
      linearize(file.model, rest(file.model));
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(both("").find("is continuous"), std::string::npos) << both("");
  EXPECT_NE(both(", sample_time: 0.05")
                .find("'second' and 'attitude_pd' are sampled every 0.05 s and 0.1 s"),
            std::string::npos)
      << both(", sample_time: 0.05");
  EXPECT_EQ(both(", sample_time: 0.1"), "(no error)");
  const io::ModelFile cruise = loop_example("cruise_control_pi");
  LinearizationOptions options;
  options.inputs = {"engine"};
  EXPECT_THROW(linearize(cruise.model, rest(cruise.model), options), InvalidArgument);
}

}  // namespace
}  // namespace momenta::analysis
