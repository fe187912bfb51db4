// Linearizations of the example models (examples/*.yaml) against their textbook closed forms,
// and the linear step response of a nonlinear model against its nonlinear simulation.

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/analysis/equilibrium.hpp"
#include "momenta/analysis/joint_steady_motion.hpp"
#include "momenta/analysis/linearize.hpp"
#include "momenta/analysis/time_response.hpp"
#include "momenta/analysis/transfer_function.hpp"
#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/model/model_builder.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

io::ModelFile example(const std::string& name) {
  return io::read_model_file(test::source_dir() + "/examples/" + name + ".yaml");
}

LinearModel linearize_file(const io::ModelFile& file, const OperatingPoint& point,
                           std::vector<std::string> inputs = {},
                           std::vector<std::string> outputs = {}) {
  LinearizationOptions options;
  options.output_specs = file.outputs;
  options.inputs = std::move(inputs);
  options.outputs = std::move(outputs);
  return linearize(file.model, point, options);
}

TEST(ModelLinearization, CruiseControlIsFirstOrder) {
  // m v̇ + b v = u: G(s) = 1/(m s + b), pole −b/m, step v = (u/b)(1 − e^(−bt/m)).
  const double m = 1000.0, b = 50.0, u = 500.0;
  const io::ModelFile file = example("cruise_control");
  const LinearModel lin = linearize_file(file, initial_operating_point(file.model));
  ASSERT_EQ(lin.system.input_names(), std::vector<std::string>{"u"});
  const TransferFunction tf = transfer_function(lin.system, "u", "speed");
  // The position state is invisible in the speed: its origin pole cancels.
  ASSERT_EQ(tf.poles.size(), 1u);
  // Damping and load derivatives are exact: round-off of b/m and 1/m.
  EXPECT_TRUE(test::relatively_near(tf.poles[0].real(), -b / m, 1e-15));
  EXPECT_TRUE(test::relatively_near(tf.gain, 1.0 / m, 1e-15));
  EXPECT_TRUE(test::relatively_near(tf.dc_gain, 1.0 / b, 1e-14));
  // The signal output reads the input itself: D = 1.
  EXPECT_EQ(lin.system.D()(lin.system.output_index("u"), 0), 1.0);
  // Step of 500 N against the closed form; ZOH samples are exact: 1e-12 of 10 m/s.
  const TimeResponse r = step_response(lin.system, 0, {120.0, 1201}, u);
  const std::size_t speed = lin.system.output_index("speed");
  double error = 0.0;
  for (Eigen::Index k = 0; k < r.time.size(); ++k) {
    const double exact = (u / b) * (1.0 - std::exp(-b * r.time[k] / m));
    error = std::max(error, std::abs(r.outputs(k, static_cast<Eigen::Index>(speed)) - exact));
  }
  EXPECT_LT(error, 1e-11);
}

TEST(ModelLinearization, QuarterCarPolesFrequenciesAndRoadTransfer) {
  // FPE eq. 2.12 with m1 = 20, m2 = 375, ks = 130 000, kw = 1e6, b = 9 800; x wheel, y body.
  const double m1 = 20, m2 = 375, ks = 130000, kw = 1e6, b = 9800;
  const io::ModelFile file = example("quarter_car");
  const LinearModel lin = linearize_file(file, initial_operating_point(file.model), {"road"});
  ASSERT_EQ(lin.system.state_names(),
            (std::vector<std::string>{"wheel_travel.position", "body_travel.position",
                                      "wheel_travel.position_rate", "body_travel.position_rate"}));
  // Hand-derived M, C, K over (x, y).
  MatX M(2, 2), C(2, 2), K(2, 2);
  M << m1, 0, 0, m2;
  C << b, -b, -b, b;
  K << ks + kw, -ks, -ks, ks;
  // The springs act along one line: positions enter linearly, so the differences are exact to
  // round-off of k·ℓ/h ≈ 1e-13 relative; damping is exact.
  EXPECT_MATRIX_NEAR(lin.mass, M, 1e-12);
  EXPECT_MATRIX_NEAR(lin.stiffness, K, 1e-7);  // of entries ~1e6
  EXPECT_MATRIX_NEAR(lin.damping, C, 1e-9);
  EXPECT_FALSE(lin.states_shifted);  // the tyre is a pure spring: only r itself enters
  // Four poles against the hand-built companion form.
  const Modes reference = damped_modes(M, C, K);
  const Modes poles = modes(lin.system);
  ASSERT_EQ(poles.modes.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_LT(std::abs(poles.modes[i].eigenvalue - reference.modes[i].eigenvalue),
              1e-11 * std::abs(reference.modes[i].eigenvalue))
        << i;
  }
  // Undamped natural frequencies: K φ = ω² M φ.
  const NormalModes undamped = undamped_modes(lin);
  const NormalModes hand = normal_modes(M, K);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_TRUE(test::relatively_near(undamped.modes[i].natural_frequency,
                                      hand.modes[i].natural_frequency, 1e-12));
  }
  // Road r → body y: Y/R = kw (b s + ks) / det(M s² + C s + K); zero −ks/b, gain kw b/(m1 m2).
  const TransferFunction tf = transfer_function(lin.system, "road", "body_y");
  ASSERT_EQ(tf.zeros.size(), 1u);
  EXPECT_TRUE(test::relatively_near(tf.zeros[0].real(), -ks / b, 1e-10));
  EXPECT_TRUE(test::relatively_near(tf.gain, kw * b / (m1 * m2), 1e-12));
  EXPECT_TRUE(test::relatively_near(tf.dc_gain, 1.0, 1e-12));
  for (const Complex s : {Complex(0, 1), Complex(0, 20), Complex(0, 230), Complex(-5, 60)}) {
    const Eigen::Matrix2cd Z =
        M.cast<Complex>() * s * s + C.cast<Complex>() * s + K.cast<Complex>();
    const Complex exact = kw * (b * s + ks) / Z.determinant();
    const Complex g =
        evaluate(lin.system, lin.system.input_index("road"), lin.system.output_index("body_y"), s);
    EXPECT_LT(std::abs(g - exact), 1e-10 * std::abs(exact)) << s;
  }
}

TEST(ModelLinearization, SatelliteAttitudeIsADoubleIntegrator) {
  // I θ̈ = T: G(s) = 1/(I s²), I = 5000 kg·m².
  const io::ModelFile file = example("satellite_attitude");
  const LinearModel lin = linearize_file(file, initial_operating_point(file.model));
  const TransferFunction tf = transfer_function(lin.system, "thrust", "theta");
  ASSERT_EQ(tf.poles.size(), 2u);
  EXPECT_EQ(tf.poles[0], Complex(0, 0));
  EXPECT_EQ(tf.poles[1], Complex(0, 0));
  EXPECT_TRUE(tf.zeros.empty());
  EXPECT_TRUE(test::relatively_near(tf.gain, 1.0 / 5000.0, 1e-15));
}

TEST(ModelLinearization, FlexibleSatelliteModesAndZeros) {
  // FPE Ex. 2.4: I1 = 1, I2 = 0.1, k = 0.091, b = 0.0036.
  const double I1 = 1, I2 = 0.1, k = 0.091, b = 0.0036;
  const io::ModelFile file = example("flexible_satellite");
  const LinearModel lin = linearize_file(file, initial_operating_point(file.model), {"tc"});
  const double wn = std::sqrt(k * (I1 + I2) / (I1 * I2));
  const double zeta = b * (I1 + I2) / (2 * I1 * I2 * wn);
  const Modes m = modes(lin.system);
  ASSERT_EQ(m.modes.size(), 4u);
  // Two rigid-body poles at 0, then the flexible pair. The zero pole is defective (a Jordan
  // block: free drift θ1 = θ2 = ωt), so a round-off perturbation δ ~ 1e-16 of K moves it by √δ
  // ~ 1e-8: 1e-7.
  EXPECT_LT(std::abs(m.modes[0].eigenvalue), 1e-7);
  EXPECT_LT(std::abs(m.modes[1].eigenvalue), 1e-7);
  EXPECT_TRUE(test::relatively_near(m.modes[2].natural_frequency, wn, 1e-12));
  EXPECT_TRUE(test::relatively_near(m.modes[2].damping_ratio, zeta, 1e-10));
  // Collocated θ1: zeros (−b ± j√(4 I2 k − b²)) / (2 I2), gain 1/I1.
  const TransferFunction collocated = transfer_function(lin.system, "tc", "theta1");
  ASSERT_EQ(collocated.zeros.size(), 2u);
  const Complex z(-b / (2 * I2), std::sqrt(4 * I2 * k - b * b) / (2 * I2));
  for (const Complex& zero : collocated.zeros) {
    EXPECT_LT(std::min(std::abs(zero - z), std::abs(zero - std::conj(z))), 1e-10 * std::abs(z));
  }
  EXPECT_TRUE(test::relatively_near(collocated.gain, 1.0 / I1, 1e-13));
  // Non-collocated θ2: one zero −k/b, gain b/(I1 I2).
  const TransferFunction remote = transfer_function(lin.system, "tc", "theta2");
  ASSERT_EQ(remote.zeros.size(), 1u);
  EXPECT_TRUE(test::relatively_near(remote.zeros[0].real(), -k / b, 1e-10));
  EXPECT_TRUE(test::relatively_near(remote.gain, b / (I1 * I2), 1e-11));
}

TEST(ModelLinearization, PendulumBottomOscillatesTopDiverges) {
  // Point mass, L = 1 m: about the bottom λ = ±j√(g/L), about the top λ = ±√(g/L).
  const double w = std::sqrt(9.81 / 1.0);
  const io::ModelFile file = example("pendulum");
  const LinearModel bottom = linearize_file(file, {0.0, VecX::Zero(1), VecX::Zero(1)});
  const Modes mb = modes(bottom.system);
  for (const Mode& mode : mb.modes) {
    // Richardson: 1e-12 relative; Re λ at round-off (A = [0 1; −g/L 0]).
    EXPECT_TRUE(test::relatively_near(std::abs(mode.eigenvalue.imag()), w, 1e-12));
    EXPECT_LT(std::abs(mode.eigenvalue.real()), 1e-14 * w);
  }
  // Newton from the file's 120° goes over the top (the nearest equilibrium by Newton's step):
  // reported unstable, with λ = +√(g/L).
  const Equilibrium top = find_equilibrium(file.model, file.model.initial_q());
  EXPECT_NEAR(top.point.q[0], std::numbers::pi, 1e-10);
  ASSERT_EQ(top.unstable_eigenvalues.size(), 1u);
  EXPECT_TRUE(test::relatively_near(top.unstable_eigenvalues[0].real(), w, 1e-11));
}

TEST(ModelLinearization, DoublePendulumNormalModes) {
  // Equal point masses on equal rods: ω² = (g/L)(2 ∓ √2).
  const double g = 9.81;
  const io::ModelFile file = example("double_pendulum");
  const LinearModel lin = linearize_file(file, {0.0, VecX::Zero(2), VecX::Zero(2)});
  const NormalModes nm = undamped_modes(lin);
  ASSERT_EQ(nm.modes.size(), 2u);
  EXPECT_TRUE(
      test::relatively_near(nm.modes[0].squared_frequency, g * (2 - std::sqrt(2.0)), 1e-11));
  EXPECT_TRUE(
      test::relatively_near(nm.modes[1].squared_frequency, g * (2 + std::sqrt(2.0)), 1e-11));
}

TEST(ModelLinearization, TennisRacketSpinAboutTheIntermediateAxisIsUnstable) {
  // Euler's equations I ω̇ = (Iω) × ω linearize to J = I⁻¹([Iω₀]× − [ω₀]× I); spinning at Ω
  // about the intermediate axis, λ = ±Ω √((I2 − I1)(I3 − I2)/(I1 I3)).
  const io::ModelFile file = example("free_body_tennis_racket");
  const model::Model& model = file.model;
  ASSERT_EQ(model.nv(), 6);
  const Vec3 I(1, 2, 3);
  const double Omega = 2.0;
  VecX v = VecX::Zero(6);
  v[1] = Omega;
  const LinearModel lin = linearize_file(file, {0.0, model::neutral(model), v}, {}, {});
  const auto skew = [](const Vec3& a) {
    Mat3 S;
    S << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
    return S;
  };
  const Vec3 w0 = v.head<3>();
  const Mat3 J =
      I.cwiseInverse().asDiagonal() * (skew(I.cwiseProduct(w0)) - skew(w0) * Mat3(I.asDiagonal()));
  // Velocity derivatives are exact: round-off.
  EXPECT_MATRIX_NEAR(lin.system.A().block(6, 6, 3, 3), J, 1e-14);
  const double growth = Omega * std::sqrt((I[1] - I[0]) * (I[2] - I[1]) / (I[0] * I[2]));
  double largest = 0.0;
  for (const Mode& mode : modes(lin.system).modes)
    largest = std::max(largest, mode.eigenvalue.real());
  EXPECT_TRUE(test::relatively_near(largest, growth, 1e-12));
}

TEST(ModelLinearization, LinearStepResponseApproachesTheNonlinearOneQuadratically) {
  // A pendulum held at θ₀ = asin(τ₀/(m g l)) by a constant torque τ₀, then given a torque step
  // δτ. The linear response is exact to first order; sin θ has a quadratic term about θ₀, so the
  // nonlinear response differs by O(δτ²): halving δτ quarters the error.
  const double m = 1.0, l = 1.0, g = 9.81, tau0 = 4.0;
  model::ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -g));
  b.add_body("bob", inertia::MassProperties(m, Vec3(0, 0, -l), Mat3::Zero()));
  model::Joint pivot;
  pivot.name = "pivot";
  pivot.type = model::JointType::revolute;
  pivot.parent = "world";
  pivot.child = "bob";
  pivot.axis = Vec3::UnitY();
  b.add_joint(pivot);
  b.add_signal(model::Signal("tau", model::ConstantSignal{tau0}));
  b.add_force_element(
      model::AppliedTorque{"motor", "bob", model::LoadFrame::world, Vec3(0, -1, 0), "tau"});
  const model::Model model = b.build();
  const Equilibrium eq = find_equilibrium(model, VecX::Zero(1));
  EXPECT_NEAR(eq.point.q[0], -std::asin(tau0 / (m * g * l)), 1e-10);
  const LinearModel& lin = eq.linear;

  // Linear unit-step response on the RK4 grid.
  const double T = 3.0, h = 1e-3;
  const auto steps = static_cast<std::size_t>(std::lround(T / h));
  const TimeResponse unit = step_response(lin.system, 0, {T, steps + 1});
  system::MultibodySystem system(model);
  std::vector<double> errors;
  for (double dtau : {0.4, 0.2, 0.1, 0.05}) {
    const std::vector<double> value{dtau}, zero{0.0};
    system.set_signal_offsets(value, zero, zero);
    integrate::RungeKutta4 rk4;
    integrate::State state{0.0, eq.point.q, eq.point.v};
    rk4.initialize(system, state);
    double error = 0.0;
    for (std::size_t k = 1; k <= steps; ++k) {
      rk4.step(system, state, h);
      const double linear = eq.point.q[0] + dtau * unit.outputs(static_cast<Eigen::Index>(k), 0);
      error = std::max(error, std::abs(state.q[0] - linear));
    }
    errors.push_back(error);
  }
  // RK4 at ωh ≈ 3e-3 is accurate to ~1e-12 rad, far below the smallest nonlinear error (~1e-4).
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double ratio = errors[i - 1] / errors[i];
    EXPECT_GT(ratio, 3.6) << "errors " << errors[i - 1] << " → " << errors[i];
    EXPECT_LT(ratio, 4.4) << "errors " << errors[i - 1] << " → " << errors[i];
  }
}

// The rotor on bearings about its steady spin, force at bearing B to its y displacement: with the
// analytic derivatives the spin's rigid-body state is exactly decoupled, and Eigen's QZ does not
// converge on the system pencil (LAPACK's does: zeros ±193.64917j, each double to ~5e-7, and a
// double 0 of which one cancels the spin's pole). transfer_function takes them from A − b c / d
// then; each must make G vanish: G grows from a double zero like δ², so |G| at 10⁻⁴ |z| from the
// zero is 10⁻⁴ of |G| at 10⁻² |z| (toward the origin, away from the poles at 198.6 and 202.6);
// a zero misplaced by 10⁻⁴ |z| or more would leave the ratio near 1. Held at 1e-3.
TEST(ModelLinearization, RotorZerosWhereQzCycles) {
  const io::ModelFile file =
      io::read_model_file(test::source_dir() + "/examples/rotor_on_bearings.yaml");
  LinearizationOptions options;
  options.output_specs = file.outputs;
  const JointSteadyMotion steady =
      joint_steady_motion(file.model, initial_operating_point(file.model), options);
  const StateSpace& sys = steady.reduced;
  const std::size_t output = sys.output_index("bearing_B.y");
  const TransferFunction tf = transfer_function(sys, 0, output);
  ASSERT_EQ(tf.zeros.size(), 5u);
  int imaginary = 0;
  for (const Complex& z : tf.zeros) {
    if (std::abs(z.imag()) > 1.0) {
      ++imaginary;
      EXPECT_NEAR(std::abs(z.imag()), 193.6491669, 1e-5);
      EXPECT_LT(std::abs(z.real()), 1e-5);
    } else {
      EXPECT_LT(std::abs(z), 1e-9);
    }
  }
  EXPECT_EQ(imaginary, 4);
  const auto G = [&](Complex s) {
    const Eigen::MatrixXcd M =
        s * Eigen::MatrixXcd::Identity(sys.A().rows(), sys.A().cols()) - sys.A().cast<Complex>();
    return (sys.C().row(output).cast<Complex>() *
            M.partialPivLu().solve(sys.B().col(0).cast<Complex>()))(0);
  };
  for (const Complex& z : tf.zeros) {
    if (std::abs(z.imag()) < 1.0) continue;
    EXPECT_LT(std::abs(G(z * (1.0 - 1e-4))), 1e-3 * std::abs(G(z * (1.0 - 1e-2)))) << z;
  }
}

}  // namespace
}  // namespace momenta::analysis
