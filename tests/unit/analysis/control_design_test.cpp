// The control designer's tools against closed forms and independent routes:
//   - Lyapunov: the Gramians of ẍ + 2ζω ẋ + ω² x = u, diag(1/(4ζω³), 1/(4ζω)); the Stein
//     equation against its series Σ Aᵏ Q Aᵏᵀ;
//   - Riccati and LQR: the double integrator's K = [√(q₁/r), √(q₂/r + 2√(q₁/r))] (Anderson &
//     Moore, Optimal Control, §3.3), the scalar equations' roots, and on random systems the
//     optimal cost x₀ᵀ S x₀ equal to the closed loop's cost from a Lyapunov equation (a second
//     equation, not the Riccati one);
//   - c2d: the double integrator's zero-order hold [1 T; 0 1], [T²/2; T], and Tustin's
//     H(z) = G((2/T)(z − 1)/(z + 1)) at points of the z-plane;
//   - controllability and observability: ranks and hidden modes of a system built with them,
//     unchanged by an orthogonal change of state;
//   - pole placement: the double integrator's K = [p₁p₂, −(p₁ + p₂)] (the characteristic
//     polynomial's coefficients), and on random single- and two-input systems the eigenvalues of
//     A − B K equal to those asked for;
//   - root locus: K/(s (s + 1)(s + 5)) breaks away where 3s² + 12s + 5 = 0 and crosses the
//     imaginary axis at ω = √5, k = 30 (Routh); (s + 2)/(s (s + 1)) leaves the axis at −2 + √2
//     and returns at −2 − √2 with k = 3 ∓ 2√2 (its circle about the zero).
// Tolerances: residuals relative to the largest term, at 1e-12 (backward-stable Schur methods on
// condition numbers below 1e3 lose at most a few digits of 16).

#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "analysis_test_systems.hpp"
#include "momenta/analysis/controllability.hpp"
#include "momenta/analysis/discretize.hpp"
#include "momenta/analysis/frequency_response.hpp"
#include "momenta/analysis/lqr.hpp"
#include "momenta/analysis/matrix_equations.hpp"
#include "momenta/analysis/pole_placement.hpp"
#include "momenta/analysis/root_locus.hpp"
#include "momenta/analysis/time_response.hpp"
#include "momenta/analysis/transfer_function.hpp"
#include "momenta/common/error.hpp"

namespace momenta::analysis::control_design_test {
namespace {

double max_abs(const MatX& M) { return M.cwiseAbs().maxCoeff(); }

// A random n×n matrix with every eigenvalue's real part shifted by `shift`.
MatX random_matrix(Eigen::Index n, Eigen::Index m, unsigned seed) {
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal;
  MatX M(n, m);
  for (Eigen::Index j = 0; j < m; ++j)
    for (Eigen::Index i = 0; i < n; ++i) M(i, j) = normal(generator);
  return M;
}

MatX random_orthogonal(Eigen::Index n, unsigned seed) {
  return Eigen::HouseholderQR<MatX>(random_matrix(n, n, seed)).householderQ();
}

MatX oscillator(double omega, double zeta) {
  MatX A(2, 2);
  A << 0, 1, -omega * omega, -2 * zeta * omega;
  return A;
}

// ---- Lyapunov ----

TEST(Lyapunov, TheGramiansOfADampedOscillator) {
  const double omega = 3.0, zeta = 0.2;
  MatX B(2, 1);
  B << 0, 1;
  const MatX W = solve_continuous_lyapunov(oscillator(omega, zeta), B * B.transpose());
  EXPECT_NEAR(W(0, 0), 1.0 / (4 * zeta * std::pow(omega, 3)), 1e-15);
  EXPECT_NEAR(W(1, 1), 1.0 / (4 * zeta * omega), 1e-14);
  EXPECT_NEAR(W(0, 1), 0.0, 1e-15);
  EXPECT_NEAR(W(1, 0), 0.0, 1e-15);
}

TEST(Lyapunov, ARandomStableSystemSatisfiesItsEquation) {
  const MatX A = random_matrix(8, 8, 3) - 4.0 * MatX::Identity(8, 8);
  const MatX F = random_matrix(8, 3, 4);
  const MatX Q = F * F.transpose();
  const MatX X = solve_continuous_lyapunov(A, Q);
  const double scale = max_abs(A) * max_abs(X) + max_abs(Q);
  EXPECT_LT(max_abs(A * X + X * A.transpose() + Q), 1e-13 * scale);
  EXPECT_EQ(X, X.transpose());
}

TEST(Lyapunov, TheSteinEquationAgainstItsSeries) {
  MatX A = random_matrix(6, 6, 5);
  A *= 0.8 / Eigen::EigenSolver<MatX>(A, false).eigenvalues().cwiseAbs().maxCoeff();
  const MatX F = random_matrix(6, 2, 6);
  const MatX Q = F * F.transpose();
  MatX series = MatX::Zero(6, 6), term = Q;
  for (int k = 0; k < 2000; ++k) {
    series += term;
    term = A * term * A.transpose();
  }
  const MatX X = solve_discrete_lyapunov(A, Q);
  EXPECT_LT(max_abs(X - series), 1e-12 * max_abs(series));
}

TEST(Lyapunov, NoUniqueSolutionIsAnError) {
  MatX A(2, 2);
  A << 1, 0, 0, -1;  // 1 + (−1) = 0
  EXPECT_THROW(solve_continuous_lyapunov(A, MatX::Identity(2, 2)), NumericalError);
  EXPECT_THROW(solve_discrete_lyapunov(MatX::Identity(2, 2), MatX::Identity(2, 2)), NumericalError);
  EXPECT_THROW(solve_continuous_lyapunov(A, MatX::Identity(3, 3)), InvalidArgument);
}

// ---- Riccati and LQR ----

StateSpace double_integrator() {
  MatX A(2, 2), B(2, 1), C(1, 2);
  A << 0, 1, 0, 0;
  B << 0, 1;
  C << 1, 0;
  return StateSpace(A, B, C, MatX(), {"x", "x_dot"}, {"force"}, {"position"});
}

TEST(Lqr, TheDoubleIntegratorAsAndersonAndMooreHaveIt) {
  const double q1 = 4.0, q2 = 0.5, r = 0.25;
  const LqrDesign d = lqr(double_integrator(), Eigen::Vector2d(q1, q2).asDiagonal().toDenseMatrix(),
                          MatX::Constant(1, 1, r));
  const double k1 = std::sqrt(q1 / r);
  const double k2 = std::sqrt(q2 / r + 2 * k1);
  EXPECT_NEAR(d.K(0, 0), k1, 1e-13 * k1);
  EXPECT_NEAR(d.K(0, 1), k2, 1e-13 * k2);
  EXPECT_NEAR(d.S(0, 1), r * k1, 1e-13);
  EXPECT_NEAR(d.S(1, 1), r * k2, 1e-13);
  EXPECT_NEAR(d.S(0, 0), r * k1 * k2, 1e-12);
  // s² + k2 s + k1 = 0.
  for (const Complex& p : d.closed_loop_poles)
    EXPECT_NEAR(std::abs(p * p + k2 * p + k1), 0.0, 1e-12);
  EXPECT_EQ(d.input_names, std::vector<std::string>{"force"});
  EXPECT_EQ(d.sample_time, 0.0);
}

TEST(Riccati, TheScalarEquationsRoots) {
  const double a = 1.0, b = 2.0, q = 3.0, r = 0.5;
  // Continuous: 2 a s − b² s²/r + q = 0, positive root.
  const double s = (a * r + std::sqrt(a * a * r * r + b * b * q * r)) / (b * b);
  EXPECT_NEAR(solve_continuous_riccati(MatX::Constant(1, 1, a), MatX::Constant(1, 1, b),
                                       MatX::Constant(1, 1, q), MatX::Constant(1, 1, r))(0, 0),
              s, 1e-14 * s);
  // Discrete: b² x² + (r − a² r − q b²) x − q r = 0, positive root.
  const double ad = 1.2, bd = 0.5, qd = 2.0, rd = 0.3;
  const double c1 = rd - ad * ad * rd - qd * bd * bd;
  const double x = (-c1 + std::sqrt(c1 * c1 + 4 * bd * bd * qd * rd)) / (2 * bd * bd);
  EXPECT_NEAR(solve_discrete_riccati(MatX::Constant(1, 1, ad), MatX::Constant(1, 1, bd),
                                     MatX::Constant(1, 1, qd), MatX::Constant(1, 1, rd))(0, 0),
              x, 1e-13 * x);
}

// A random unstable system with its weights: 7 states, 3 inputs, a cross term.
struct Problem {
  MatX A, B, Q, R, N;
};
Problem random_problem(unsigned seed) {
  Problem p;
  p.A = random_matrix(7, 7, seed);
  p.B = random_matrix(7, 3, seed + 1);
  const MatX F = random_matrix(10, 10, seed + 2);
  const MatX joint = F * F.transpose() + MatX::Identity(10, 10);  // [Q N; Nᵀ R] > 0
  p.Q = joint.topLeftCorner(7, 7);
  p.N = joint.topRightCorner(7, 3);
  p.R = joint.bottomRightCorner(3, 3);
  return p;
}

TEST(Lqr, AContinuousDesignsCostIsItsRiccatiSolution) {
  const Problem p = random_problem(11);
  const StateSpace sys(p.A, p.B, MatX::Zero(0, 7), MatX());
  const LqrDesign d = lqr(sys, p.Q, p.R, p.N);
  const MatX& S = d.S;
  const MatX residual = p.A.transpose() * S + S * p.A -
                        (S * p.B + p.N) * p.R.ldlt().solve(p.B.transpose() * S + p.N.transpose()) +
                        p.Q;
  EXPECT_LT(max_abs(residual), 1e-12 * max_abs(p.A) * max_abs(S));
  for (const Complex& z : d.closed_loop_poles) EXPECT_LT(z.real(), 0.0);
  // J = ∫ xᵀ Q x + uᵀ R u + 2 xᵀ N u with u = −K x: the Lyapunov equation of the closed loop.
  const MatX closed = p.A - p.B * d.K;
  const MatX weight =
      p.Q + d.K.transpose() * p.R * d.K - p.N * d.K - d.K.transpose() * p.N.transpose();
  const MatX cost = solve_continuous_lyapunov(closed.transpose(), weight);
  EXPECT_LT(max_abs(cost - S), 1e-11 * max_abs(S));
}

TEST(Lqr, ADiscreteDesignsCostIsItsRiccatiSolution) {
  const Problem p = random_problem(21);
  const StateSpace sys(0.5 * p.A, p.B, MatX::Zero(0, 7), MatX(), {}, {}, {}, 0.1);
  const LqrDesign d = lqr(sys, p.Q, p.R, p.N);
  const MatX& A = sys.A();
  const MatX& S = d.S;
  const MatX gain =
      (p.R + p.B.transpose() * S * p.B).ldlt().solve(p.B.transpose() * S * A + p.N.transpose());
  const MatX residual = A.transpose() * S * A - S - (A.transpose() * S * p.B + p.N) * gain + p.Q;
  EXPECT_LT(max_abs(residual), 1e-11 * max_abs(S) * std::max(1.0, max_abs(A) * max_abs(A)));
  EXPECT_LT(max_abs(d.K - gain), 1e-12 * max_abs(gain));
  for (const Complex& z : d.closed_loop_poles) EXPECT_LT(std::abs(z), 1.0);
  const MatX closed = A - p.B * d.K;
  const MatX weight =
      p.Q + d.K.transpose() * p.R * d.K - p.N * d.K - d.K.transpose() * p.N.transpose();
  const MatX cost = solve_discrete_lyapunov(closed.transpose(), weight);
  EXPECT_LT(max_abs(cost - S), 1e-10 * max_abs(S));
  EXPECT_EQ(d.sample_time, 0.1);
}

TEST(Lqr, WhatNoFeedbackCanStabilizeIsAnError) {
  // The unstable mode at +1 is not moved by the input.
  MatX A(2, 2), B(2, 1);
  A << 1, 0, 0, -1;
  B << 0, 1;
  const StateSpace sys(A, B, MatX::Zero(0, 2), MatX());
  EXPECT_THROW(lqr(sys, MatX::Identity(2, 2), MatX::Identity(1, 1)), NumericalError);
  const MatX sampled_A = Eigen::Vector2d(std::exp(1.0), std::exp(-1.0)).asDiagonal();
  const StateSpace sampled(sampled_A, B, MatX::Zero(0, 2), MatX(), {}, {}, {}, 1.0);
  EXPECT_THROW(lqr(sampled, MatX::Identity(2, 2), MatX::Identity(1, 1)), NumericalError);
  // An undamped oscillation that Q does not weigh keeps its poles on the axis.
  EXPECT_THROW(lqr(StateSpace(oscillator(1.0, 0.0), B, MatX::Zero(0, 2), MatX()), MatX::Zero(2, 2),
                   MatX::Identity(1, 1)),
               NumericalError);
}

TEST(Lqr, BadWeightsAreNamed) {
  const StateSpace sys = double_integrator();
  EXPECT_THROW(lqr(sys, MatX::Identity(3, 3), MatX::Identity(1, 1)), InvalidArgument);
  EXPECT_THROW(lqr(sys, MatX::Identity(2, 2), MatX::Zero(1, 1)), InvalidArgument);
  EXPECT_THROW(lqr(sys, -MatX::Identity(2, 2), MatX::Identity(1, 1)), InvalidArgument);
  MatX asymmetric(2, 2);
  asymmetric << 1, 1, 0, 1;
  EXPECT_THROW(lqr(sys, asymmetric, MatX::Identity(1, 1)), InvalidArgument);
  try {
    lqr(sys, -MatX::Identity(2, 2), MatX::Identity(1, 1));
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("Q must be positive semidefinite"), std::string::npos);
  }
}

// ---- c2d ----

TEST(C2d, TheDoubleIntegratorHeldConstant) {
  const double T = 0.1;
  const StateSpace d = c2d(double_integrator(), T);
  EXPECT_EQ(d.sample_time(), T);
  EXPECT_TRUE(d.is_discrete());
  EXPECT_NEAR(d.A()(0, 0), 1.0, 1e-15);
  EXPECT_NEAR(d.A()(0, 1), T, 1e-16);
  EXPECT_NEAR(d.A()(1, 0), 0.0, 1e-16);
  EXPECT_NEAR(d.A()(1, 1), 1.0, 1e-15);
  EXPECT_NEAR(d.B()(0, 0), T * T / 2, 1e-17);
  EXPECT_NEAR(d.B()(1, 0), T, 1e-16);
  EXPECT_EQ(d.input_names(), std::vector<std::string>{"force"});
  EXPECT_THROW(c2d(d, T), InvalidArgument);
  EXPECT_THROW(c2d(double_integrator(), 0.0), InvalidArgument);
  EXPECT_THROW(c2d(double_integrator(), -1.0), InvalidArgument);
}

TEST(C2d, TustinIsTheBilinearMap) {
  const MatX A = random_matrix(4, 4, 31) - 2.0 * MatX::Identity(4, 4);
  const StateSpace g(A, random_matrix(4, 2, 32), random_matrix(3, 4, 33), random_matrix(3, 2, 34));
  const double T = 0.05;
  const StateSpace h = c2d(g, T, DiscretizationMethod::tustin);
  for (const Complex z : {Complex(0.3, 0.4), Complex(-0.7, 0.1), Complex(1.5, -0.2)}) {
    const Eigen::MatrixXcd Hz = evaluate(h, z);
    const Eigen::MatrixXcd Gs = evaluate(g, (2.0 / T) * (z - 1.0) / (z + 1.0));
    EXPECT_LT((Hz - Gs).cwiseAbs().maxCoeff(), 1e-12 * Gs.cwiseAbs().maxCoeff()) << z;
  }
  EXPECT_EQ(discretization_method("bilinear"), DiscretizationMethod::tustin);
  EXPECT_THROW(discretization_method("foh"), InvalidArgument);
}

TEST(C2d, ADiscreteSystemIsRefusedWhereOnlyContinuousIsMeant) {
  const StateSpace d = c2d(double_integrator(), 0.1);
  // Its modes are those it samples: z = 1 twice, s = ln(z)/T = 0 (a Jordan block: round-off
  // moves a defective double eigenvalue by √ε, so 1e-7).
  for (const Mode& mode : modes(d).modes) {
    EXPECT_LT(std::abs(mode.z - 1.0), 1e-7);
    EXPECT_LT(std::abs(mode.eigenvalue), 1e-6);
    EXPECT_LT(std::abs(std::exp(mode.eigenvalue * 0.1) - mode.z), 1e-15);
  }
  EXPECT_THROW(frequency_response(d, 0, 0, (VecX(1) << 40.0).finished()), InvalidArgument);
  EXPECT_THROW(
      StateSpace(MatX::Zero(1, 1), MatX::Zero(1, 0), MatX::Zero(0, 1), MatX(), {}, {}, {}, -0.1),
      InvalidArgument);
}

// A first-order lag held: H(z) = (1 − a)/(z − a) with a = e^(−T/τ) (Franklin, Powell &
// Workman ch. 4); its step at the samples is the continuous one, 1 − e^(−kT/τ).
TEST(C2d, ASampledLagsTransferFunctionStepAndFrequencyResponse) {
  const double tau = 0.5, T = 0.1, a = std::exp(-T / tau);
  const StateSpace lag(MatX::Constant(1, 1, -1.0 / tau), MatX::Constant(1, 1, 1.0 / tau),
                       MatX::Constant(1, 1, 1.0), MatX(), {"x"}, {"u"}, {"y"});
  const StateSpace held = c2d(lag, T);
  const TransferFunction h = transfer_function(held, 0, 0);
  ASSERT_EQ(h.poles.size(), 1u);
  EXPECT_NEAR(h.poles[0].real(), a, 1e-15);
  EXPECT_TRUE(h.zeros.empty());
  EXPECT_NEAR(h.gain, 1.0 - a, 1e-15);
  EXPECT_NEAR(h.dc_gain, 1.0, 1e-14);  // H(1)
  const TimeResponse step = step_response(held, 0, TimeGrid{2.0, 0});
  ASSERT_EQ(step.time.size(), 21);
  for (Eigen::Index k = 0; k < step.time.size(); ++k) {
    EXPECT_NEAR(step.time[k], static_cast<double>(k) * T, 1e-15);
    EXPECT_NEAR(step.outputs(k, 0), 1.0 - std::exp(-step.time[k] / tau), 1e-14);
  }
  const TimeResponse pulse = impulse_response(held, 0, TimeGrid{0.0, 4});
  EXPECT_EQ(pulse.outputs(0, 0), 0.0);
  EXPECT_NEAR(pulse.outputs(1, 0), 1.0 - a, 1e-15);
  EXPECT_NEAR(pulse.outputs(3, 0), (1.0 - a) * a * a, 1e-15);
  // H(e^{jωT}) and its phase −ωT/2·… from the factor: arg(1 − a) − arg(e^{jωT} − a).
  const VecX w = (VecX(3) << 0.1, 5.0, M_PI / T).finished();
  const FrequencyResponse f = frequency_response(held, 0, 0, w);
  for (Eigen::Index k = 0; k < w.size(); ++k) {
    const Complex z = std::exp(Complex(0.0, w[k] * T));
    const Complex expected = (1.0 - a) / (z - a);
    EXPECT_NEAR(std::abs(f.response[k] - expected), 0.0, 1e-14);
    EXPECT_NEAR(f.phase_deg[k], -std::arg(z - a) * 180.0 / M_PI, 1e-11);
  }
  EXPECT_THROW(step_response(held, 0, TimeGrid{1.0, 5}), InvalidArgument);  // 5 samples end at 0.4
}

// ---- controllability and observability ----

TEST(Controllability, AHiddenModeIsFoundWhateverTheStates) {
  // diag(−1, −2, −3): B reaches the first two, C sees the last two.
  MatX A = Eigen::Vector3d(-1, -2, -3).asDiagonal();
  MatX B(3, 1), C(1, 3);
  B << 1, 1, 0;
  C << 0, 1, 1;
  const MatX P = random_orthogonal(3, 41);
  const StateSpace sys(P.transpose() * A * P, P.transpose() * B, C * P, MatX());
  const Reachability c = controllability(sys);
  EXPECT_EQ(c.rank, 2u);
  EXPECT_FALSE(c.complete());
  ASSERT_EQ(c.hidden_poles.size(), 1u);
  EXPECT_NEAR(std::abs(c.hidden_poles[0] - Complex(-3.0)), 0.0, 1e-13);
  const Reachability o = observability(sys);
  EXPECT_EQ(o.rank, 2u);
  ASSERT_EQ(o.hidden_poles.size(), 1u);
  EXPECT_NEAR(std::abs(o.hidden_poles[0] - Complex(-1.0)), 0.0, 1e-13);
  // Stable: Gramians exist, singular in the hidden direction.
  ASSERT_TRUE(c.gramian_condition.has_value());
  EXPECT_GT(*c.gramian_condition, 1e12);
}

TEST(Controllability, AnOscillatorDrivenByForceIsControllable) {
  const double omega = 2.0, zeta = 0.1;
  MatX B(2, 1), C(1, 2);
  B << 0, 1;
  C << 1, 0;
  const StateSpace sys(oscillator(omega, zeta), B, C, MatX());
  const Reachability c = controllability(sys);
  EXPECT_TRUE(c.complete());
  EXPECT_TRUE(c.hidden_poles.empty());
  // diag(1/(4ζω³), 1/(4ζω)): condition ω².
  ASSERT_TRUE(c.gramian_condition.has_value());
  EXPECT_NEAR(*c.gramian_condition, omega * omega, 1e-12);
  EXPECT_TRUE(observability(sys).complete());
  // Undamped, its poles a round-off from the axis: not stable, so no Gramian (and no error).
  const Reachability undamped = controllability(StateSpace(oscillator(omega, 0.0), B, C, MatX()));
  EXPECT_TRUE(undamped.complete());
  EXPECT_FALSE(undamped.gramian_condition.has_value());
  // A double integrator is unstable: ranks, no Gramian.
  const Reachability di = controllability(double_integrator());
  EXPECT_EQ(di.rank, 2u);
  EXPECT_FALSE(di.gramian_condition.has_value());
  EXPECT_EQ(di.gramian.size(), 0);
}

TEST(Controllability, TheDiscreteGramianSolvesSteinsEquation) {
  const StateSpace d =
      c2d(StateSpace(oscillator(2.0, 0.1), Eigen::Vector2d(0, 1), MatX::Zero(0, 2), MatX()), 0.1);
  const Reachability c = controllability(d);
  EXPECT_TRUE(c.complete());
  ASSERT_EQ(c.gramian.rows(), 2);
  const MatX residual =
      d.A() * c.gramian * d.A().transpose() - c.gramian + d.B() * d.B().transpose();
  EXPECT_LT(max_abs(residual), 1e-13 * max_abs(c.gramian));
}

// ---- pole placement ----

// Every requested pole matched by one of A − B K's, each used once.
void expect_placed(const std::vector<Complex>& wanted, const VecXc& got, double tolerance) {
  ASSERT_EQ(static_cast<Eigen::Index>(wanted.size()), got.size());
  std::vector<bool> used(wanted.size(), false);
  for (const Complex& g : got) {
    std::size_t best = wanted.size();
    for (std::size_t i = 0; i < wanted.size(); ++i) {
      if (!used[i] &&
          (best == wanted.size() || std::abs(wanted[i] - g) < std::abs(wanted[best] - g))) {
        best = i;
      }
    }
    ASSERT_LT(best, wanted.size());
    used[best] = true;
    EXPECT_NEAR(std::abs(wanted[best] - g), 0.0, tolerance * std::max(1.0, std::abs(g))) << g;
  }
}

TEST(PolePlacement, TheDoubleIntegratorsGainIsItsCharacteristicPolynomial) {
  // s² + k₂ s + k₁ = (s + 1)(s + 2): K = [2, 3].
  const PolePlacement p = place_poles(double_integrator(), {Complex(-1.0), Complex(-2.0)});
  EXPECT_NEAR(p.K(0, 0), 2.0, 1e-14);
  EXPECT_NEAR(p.K(0, 1), 3.0, 1e-14);
  // (s + 1)² + 4 = s² + 2 s + 5: K = [5, 2].
  const PolePlacement c =
      place_poles(double_integrator(), {Complex(-1.0, 2.0), Complex(-1.0, -2.0)});
  EXPECT_NEAR(c.K(0, 0), 5.0, 1e-13);
  EXPECT_NEAR(c.K(0, 1), 2.0, 1e-13);
}

TEST(PolePlacement, RandomSystemsGetThePolesAskedFor) {
  const std::vector<Complex> wanted{Complex(-1.0), Complex(-2.0, 1.0), Complex(-2.0, -1.0),
                                    Complex(-3.0), Complex(-0.5, 4.0), Complex(-0.5, -4.0)};
  const StateSpace single(random_matrix(6, 6, 51), random_matrix(6, 1, 52), MatX::Zero(0, 6),
                          MatX());
  // One input leaves no freedom: the eigenvectors are as conditioned as the system makes them
  // (κ(X) of a random 6-state system is 1e2–1e4), and the poles land to about κ ε ‖A‖.
  const PolePlacement one = place_poles(single, wanted);
  expect_placed(wanted, one.closed_loop_poles, 1e-8);
  const StateSpace two(random_matrix(6, 6, 53), random_matrix(6, 2, 54), MatX::Zero(0, 6), MatX());
  const PolePlacement p = place_poles(two, wanted);
  expect_placed(wanted, p.closed_loop_poles, 1e-10);
  EXPECT_LT(p.eigenvector_condition, one.eigenvector_condition);  // the freedom used
  // A pole twice with two inputs.
  const std::vector<Complex> twice{Complex(-1.0), Complex(-1.0), Complex(-2.0),
                                   Complex(-3.0), Complex(-4.0), Complex(-5.0)};
  expect_placed(twice, place_poles(two, twice).closed_loop_poles, 1e-7);
}

TEST(PolePlacement, WhatCannotBePlacedIsSaid) {
  EXPECT_THROW(place_poles(double_integrator(), {Complex(-1.0)}), InvalidArgument);
  EXPECT_THROW(place_poles(double_integrator(), {Complex(-1.0, 1.0), Complex(-2.0)}),
               InvalidArgument);  // no conjugate
  EXPECT_THROW(place_poles(double_integrator(), {Complex(-1.0), Complex(-1.0)}),
               InvalidArgument);  // twice with one input
  MatX A(2, 2), B(2, 1);
  A << -1, 0, 0, -2;
  B << 1, 0;
  EXPECT_THROW(
      place_poles(StateSpace(A, B, MatX::Zero(0, 2), MatX()), {Complex(-3.0), Complex(-4.0)}),
      NumericalError);
}

// ---- root locus ----

// (b_{n−1} s^{n−1} + … + b₀)/(sⁿ + a_{n−1} s^{n−1} + … + a₀), both lists highest power first,
// in controllable canonical form (analysis_test_systems.hpp), input "u", output "y".
StateSpace canonical(const std::vector<double>& numerator, const std::vector<double>& denominator) {
  const StateSpace c = test::canonical_form(denominator, {numerator.rbegin(), numerator.rend()});
  return StateSpace(c.A(), c.B(), c.C(), c.D(), {}, {"u"}, {"y"});
}

TEST(RootLocus, ATypeOneLoopBreaksAwayAndCrossesWhereRouthSays) {
  // 1/(s (s + 1)(s + 5)) = 1/(s³ + 6 s² + 5 s).
  const StateSpace g = canonical({0, 0, 1}, {6, 5, 0});
  const RootLocus locus = root_locus(g, 0, 0, log_gain_grid(0.01, 1000.0, 200));
  ASSERT_EQ(locus.breakaway.size(), 1u);
  const double s_break = (-12.0 + std::sqrt(84.0)) / 6.0;
  EXPECT_NEAR(locus.breakaway[0].s.real(), s_break, 1e-13);
  EXPECT_EQ(locus.breakaway[0].s.imag(), 0.0);
  EXPECT_NEAR(locus.breakaway[0].gain, -s_break * (s_break + 1) * (s_break + 5), 1e-12);
  ASSERT_EQ(locus.crossings.size(), 1u);
  EXPECT_NEAR(locus.crossings[0].s.imag(), std::sqrt(5.0), 1e-13);
  EXPECT_EQ(locus.crossings[0].s.real(), 0.0);
  EXPECT_NEAR(locus.crossings[0].gain, 30.0, 1e-12);
  EXPECT_NEAR(locus.asymptote_centroid, -2.0, 1e-14);
  ASSERT_EQ(locus.asymptote_angles_deg.size(), 3u);
  EXPECT_NEAR(locus.asymptote_angles_deg[0], 60.0, 1e-12);
  EXPECT_NEAR(locus.asymptote_angles_deg[1], 180.0, 1e-12);
  EXPECT_NEAR(locus.asymptote_angles_deg[2], 300.0, 1e-12);
  // The branches: the open-loop poles at k = 0; at k = 30 a pair on the axis at ±j√5.
  EXPECT_EQ(locus.gains[0], 0.0);
  const RootLocus one = root_locus(g, 0, 0, (VecX(1) << 30.0).finished());
  int on_axis = 0;
  for (Eigen::Index j = 0; j < 3; ++j) {
    if (std::abs(std::abs(one.poles(0, j).imag()) - std::sqrt(5.0)) < 1e-12) ++on_axis;
  }
  EXPECT_EQ(on_axis, 2);
}

TEST(RootLocus, AZeroDrawsACircleBetweenBreakAwayAndBreakIn) {
  // (s + 2)/(s (s + 1)) = (s + 2)/(s² + s).
  const StateSpace g = canonical({1, 2}, {1, 0});
  const RootLocus locus = root_locus(g, 0, 0, log_gain_grid(0.01, 100.0, 400));
  ASSERT_EQ(locus.breakaway.size(), 2u);
  EXPECT_NEAR(locus.breakaway[0].s.real(), -2.0 + std::sqrt(2.0), 1e-13);
  EXPECT_NEAR(locus.breakaway[0].gain, 3.0 - 2.0 * std::sqrt(2.0), 1e-13);
  EXPECT_NEAR(locus.breakaway[1].s.real(), -2.0 - std::sqrt(2.0), 1e-13);
  EXPECT_NEAR(locus.breakaway[1].gain, 3.0 + 2.0 * std::sqrt(2.0), 1e-12);
  EXPECT_TRUE(locus.crossings.empty());
  // Between them every closed-loop pole lies on the circle |s + 2| = √2.
  for (Eigen::Index k = 0; k < locus.gains.size(); ++k) {
    if (locus.gains[k] <= locus.breakaway[0].gain + 1e-3 ||
        locus.gains[k] >= locus.breakaway[1].gain - 1e-3) {
      continue;
    }
    for (Eigen::Index j = 0; j < 2; ++j) {
      EXPECT_NEAR(std::abs(locus.poles(k, j) + 2.0), std::sqrt(2.0), 1e-12) << locus.gains[k];
    }
  }
  ASSERT_EQ(locus.asymptote_angles_deg.size(), 1u);
  EXPECT_NEAR(locus.asymptote_angles_deg[0], 180.0, 1e-12);
}

// A sampled loop's locus in the z-plane: 1/((z − 1)(z − a)), a = 1/2. The characteristic
// equation z² − (1 + a) z + a + k = 0 has a double root where dk/dz = 0, z = (1 + a)/2 = 3/4 at
// k = (1 − a)²/4 = 1/16; beyond it a conjugate pair with |z|² = a + k, which meets the unit
// circle at k = 1 − a = 1/2, where 2 cos θ = 1 + a.
TEST(RootLocus, ASampledLoopLeavesTheUnitCircleWhereItsCharacteristicEquationSays) {
  const double a = 0.5, T = 0.1;
  const StateSpace c = canonical({0, 1}, {-(1.0 + a), a});
  const StateSpace g(c.A(), c.B(), c.C(), c.D(), {}, {"u"}, {"y"}, T);
  const RootLocus locus = root_locus(g, 0, 0, log_gain_grid(0.01, 10.0, 200));
  EXPECT_EQ(locus.sample_time, T);
  ASSERT_EQ(locus.breakaway.size(), 1u);
  EXPECT_NEAR(locus.breakaway[0].s.real(), 0.75, 1e-13);
  EXPECT_EQ(locus.breakaway[0].s.imag(), 0.0);
  EXPECT_NEAR(locus.breakaway[0].gain, 1.0 / 16.0, 1e-13);
  ASSERT_EQ(locus.crossings.size(), 1u);
  EXPECT_NEAR(locus.crossings[0].s.real(), 0.75, 1e-13);
  EXPECT_NEAR(locus.crossings[0].s.imag(), std::sqrt(1.0 - 0.75 * 0.75), 1e-13);
  EXPECT_NEAR(locus.crossings[0].gain, 0.5, 1e-13);
  // The branches at that gain are on the circle.
  const RootLocus there = root_locus(g, 0, 0, (VecX(1) << 0.5).finished());
  for (Eigen::Index j = 0; j < 2; ++j) EXPECT_NEAR(std::abs(there.poles(0, j)), 1.0, 1e-14);
}

// The sampled integrator T/(z − 1): its one pole z = 1 − kT leaves the circle through z = −1 at
// k = 2/T, a crossing the circle's polynomial has as a double root (z = ±1 are tried as such).
TEST(RootLocus, ASampledIntegratorLeavesThroughMinusOne) {
  const double T = 0.1;
  const StateSpace g = c2d(canonical({1}, {0}), T);
  const RootLocus locus = root_locus(g, 0, 0, log_gain_grid(0.1, 100.0, 50));
  ASSERT_EQ(locus.crossings.size(), 1u);
  EXPECT_EQ(locus.crossings[0].s, Complex(-1.0, 0.0));
  EXPECT_NEAR(locus.crossings[0].gain, 2.0 / T, 1e-12);
  EXPECT_TRUE(locus.breakaway.empty());
}

// A zero on the circle ends a branch at k = ∞ there; it is no crossing. (z − 1)/((z − ½)(z − ⅕)):
// z² + (k − 0.7) z + 0.1 − k = 0 has z = −1 at k = 0.9, and its pair |z|² = 0.1 − k inside.
TEST(RootLocus, ASampledZeroOnTheCircleIsNoCrossing) {
  const StateSpace c = canonical({1, -1}, {-0.7, 0.1});
  const StateSpace g(c.A(), c.B(), c.C(), c.D(), {}, {"u"}, {"y"}, 0.1);
  const RootLocus locus = root_locus(g, 0, 0, log_gain_grid(0.01, 100.0, 50));
  ASSERT_EQ(locus.crossings.size(), 1u);
  EXPECT_EQ(locus.crossings[0].s, Complex(-1.0, 0.0));
  EXPECT_NEAR(locus.crossings[0].gain, 0.9, 1e-13);
}

TEST(RootLocus, BadGainsAreRefused) {
  const StateSpace g = canonical({0, 1}, {1, 0});
  EXPECT_THROW(root_locus(g, 0, 0, (VecX(1) << -1.0).finished()), InvalidArgument);
  EXPECT_THROW(log_gain_grid(0.0, 1.0, 10), InvalidArgument);
}

}  // namespace
}  // namespace momenta::analysis::control_design_test
