#include "momenta/analysis/transfer_function.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>
#include <Eigen/Householder>
#include <Eigen/LU>

#include "balance.hpp"
#include "momenta/common/error.hpp"

namespace momenta::analysis {
namespace {

// A cosine between the unit input and output directions below this is structural zero plus the
// round-off of a few orthogonal transformations (~n·ε); above it the pencil is regular.
constexpr double kNegligibleCosine = 1e-10;

// Poles within √ε·ρ(A) of the origin count as at the origin: a double (defective) eigenvalue
// at 0 comes out of the QR iteration only to ~√ε·‖A‖.
const double kOriginTolerance = std::sqrt(std::numeric_limits<double>::epsilon());

void sort_roots(std::vector<Complex>& roots) {
  std::stable_sort(roots.begin(), roots.end(), [](const Complex& a, const Complex& b) {
    return std::make_tuple(std::abs(a), a.real(), -a.imag()) <
           std::make_tuple(std::abs(b), b.real(), -b.imag());
  });
}

// Invariant zeros and leading gain K of the SISO system (A, b, c, d), state already balanced.
struct ZerosAndGain {
  std::vector<Complex> zeros;
  double gain = 0.0;
};

ZerosAndGain siso_zeros(MatX A, VecX b, Eigen::RowVectorXd c, double d) {
  ZerosAndGain result;
  const double norm_A = A.size() == 0 ? 0.0 : A.norm();
  double factor = 1.0;  // G = factor · G_current: the scalings taken out so far.

  // A strictly proper pair: deflate one infinite eigenvalue per step until the feedthrough of
  // the current system is significant (Emami-Naeini & Van Dooren 1982, SISO).
  if (d == 0.0) {
    const double norm_b = b.norm();
    const double norm_c = c.norm();
    if (norm_b == 0.0 || norm_c == 0.0) return result;  // G ≡ 0
    factor = norm_b * norm_c;
    b /= norm_b;
    c /= norm_c;
    for (;;) {
      // Reflector H = Hᵀ = H⁻¹ with H cᵀ = β e₁: in coordinates H x the output reads state 0.
      const Eigen::Index n = A.rows();
      VecX direction = c.transpose();
      VecX essential(n - 1);
      double tau = 0.0;
      double beta = 0.0;
      direction.makeHouseholder(essential, tau, beta);
      VecX workspace(n);
      A.applyHouseholderOnTheLeft(essential, tau, workspace.data());
      A.applyHouseholderOnTheRight(essential, tau, workspace.data());
      b.applyHouseholderOnTheLeft(essential, tau, workspace.data());
      // det P = β · det P' where P' is the pencil of (A₁₁, b₁, a₂₁, b₂): the state read by the
      // output is dropped and its derivative becomes the new output.
      factor *= beta;
      const double b2 = b[0];
      MatX A11 = A.bottomRightCorner(n - 1, n - 1);
      Eigen::RowVectorXd a21 = A.row(0).tail(n - 1);
      VecX b1 = b.tail(n - 1);
      if (std::abs(b2) > kNegligibleCosine) {
        // Regular: the new feedthrough is b₂.
        A = std::move(A11);
        b = std::move(b1);
        c = std::move(a21);
        d = b2;
        break;
      }
      // Still strictly proper: renormalize and go on, unless nothing is left.
      const double norm_a21 = a21.norm();
      const double norm_b1 = b1.norm();
      if (n == 1 || norm_a21 <= 1e-13 * norm_A || norm_b1 == 0.0) return result;  // G ≡ 0
      factor *= norm_a21 * norm_b1;
      A = std::move(A11);
      b = b1 / norm_b1;
      c = a21 / norm_a21;
    }
  }
  result.gain = factor * d;

  // Regular pencil S v = λ E v, S = [A b; c d], E = diag(I, 0): n finite zeros and one simple
  // infinite eigenvalue, told apart by |β|/(|α| + |β|).
  const Eigen::Index n = A.rows();
  if (n == 0) return result;
  MatX S(n + 1, n + 1);
  S << A, b, c, d;
  MatX E = MatX::Zero(n + 1, n + 1);
  E.topLeftCorner(n, n).setIdentity();
  Eigen::GeneralizedEigenSolver<MatX> qz;
  qz.compute(S, E, /*computeEigenvectors=*/false);
  if (qz.info() != Eigen::Success) {
    // Eigen's QZ can fail to converge where LAPACK's does not: seen on an undamped rotor whose
    // zeros are a double imaginary pair and a double zero (exactly decoupled states). With the
    // feedthrough d regular, the zeros are also the eigenvalues of A − b c / d (Hessenberg QR,
    // which converges there); its backward error grows as ε ‖b‖‖c‖/|d|, so only where that
    // stays within 1e6 of ε max(1, ‖A‖) is this way taken.
    if (b.norm() * c.norm() > 1e6 * std::abs(d) * std::max(1.0, A.norm())) {
      throw NumericalError(
          fmt::format("transfer_function: the QZ iteration did not converge on the {}×{} system "
                      "pencil",
                      n + 1, n + 1));
    }
    const MatX A_closed = A - b * c / d;
    Eigen::EigenSolver<MatX> eigen(A_closed, /*computeEigenvectors=*/false);
    if (eigen.info() != Eigen::Success) {
      throw NumericalError(
          fmt::format("transfer_function: neither QZ on the {0}×{0} system pencil nor the "
                      "eigenvalue iteration on A − b c / d converged",
                      n + 1));
    }
    for (Eigen::Index i = 0; i < n; ++i) result.zeros.push_back(eigen.eigenvalues()[i]);
    return result;
  }
  const Eigen::VectorXcd alpha = qz.alphas();
  const VecX beta = qz.betas();
  Eigen::Index infinite = 0;
  double smallest = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i <= n; ++i) {
    const double finiteness = std::abs(beta[i]) / (std::abs(alpha[i]) + std::abs(beta[i]));
    if (finiteness < smallest) {
      smallest = finiteness;
      infinite = i;
    }
  }
  for (Eigen::Index i = 0; i <= n; ++i) {
    if (i != infinite) result.zeros.push_back(alpha[i] / beta[i]);
  }
  return result;
}

void check_pair(const StateSpace& system, std::size_t input, std::size_t output, const char* who) {
  if (input >= system.input_count() || output >= system.output_count()) {
    throw InvalidArgument(fmt::format(
        "{}: pair (input {}, output {}) out of range: the system has {} inputs and {} outputs", who,
        input, output, system.input_count(), system.output_count()));
  }
}

}  // namespace

Complex TransferFunction::operator()(Complex s) const {
  Complex value = gain;
  for (const Complex& z : zeros) value *= s - z;
  for (const Complex& p : poles) value /= s - p;
  return value;
}

TransferFunction transfer_function(const StateSpace& system, std::size_t input, std::size_t output,
                                   double cancellation_tolerance) {
  check_pair(system, input, output, "transfer_function");
  if (!(cancellation_tolerance >= 0.0)) {
    throw InvalidArgument(fmt::format("transfer_function: cancellation tolerance {} must be >= 0",
                                      cancellation_tolerance));
  }
  TransferFunction tf;
  tf.input_name = system.input_names()[input];
  tf.output_name = system.output_names()[output];

  // Balance the states (exact power-of-2 similarity): G is unchanged, round-off shrinks.
  const auto i = static_cast<Eigen::Index>(input);
  const auto o = static_cast<Eigen::Index>(output);
  const VecX scale = detail::balancing_scale(system.A());
  const MatX A = scale.cwiseInverse().asDiagonal() * system.A() * scale.asDiagonal();
  const VecX b = scale.cwiseInverse().cwiseProduct(system.B().col(i));
  const Eigen::RowVectorXd c = system.C().row(o).cwiseProduct(scale.transpose());
  const double d = system.D()(o, i);

  // Poles: every eigenvalue of A.
  std::vector<Complex> poles;
  if (A.rows() > 0) {
    const Eigen::EigenSolver<MatX> eigen(A, /*computeEigenvectors=*/false);
    if (eigen.info() != Eigen::Success) {
      throw NumericalError("transfer_function: the eigenvalue iteration on A did not converge");
    }
    for (const Complex& p : eigen.eigenvalues()) poles.push_back(p);
  }
  double spectral_radius = 0.0;
  for (const Complex& p : poles) spectral_radius = std::max(spectral_radius, std::abs(p));

  // Zeros and gain; G ≡ 0 has neither zeros nor anything to cancel.
  ZerosAndGain zg = siso_zeros(A, b, c, d);
  tf.gain = zg.gain;
  sort_roots(poles);
  sort_roots(zg.zeros);

  // Cancel each zero against its nearest remaining pole when they agree to the tolerance.
  std::vector<bool> pole_used(poles.size(), false);
  for (const Complex& z : zg.zeros) {
    std::size_t nearest = poles.size();
    double distance = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < poles.size(); ++k) {
      if (!pole_used[k] && std::abs(poles[k] - z) < distance) {
        distance = std::abs(poles[k] - z);
        nearest = k;
      }
    }
    const double allowed = nearest < poles.size()
                               ? cancellation_tolerance * std::max({std::abs(poles[nearest]),
                                                                    std::abs(z), spectral_radius})
                               : 0.0;
    if (nearest < poles.size() && distance <= allowed) {
      pole_used[nearest] = true;
      tf.cancelled.push_back(poles[nearest]);
    } else {
      tf.zeros.push_back(z);
    }
  }
  for (std::size_t k = 0; k < poles.size(); ++k) {
    if (!pole_used[k]) tf.poles.push_back(poles[k]);
  }

  // DC gain, at s₀ = 0 (or z₀ = 1 when sampled): a remaining pole there makes it infinite,
  // signed as G on the real axis just above s₀.
  if (tf.is_zero()) {
    tf.dc_gain = 0.0;
    return tf;
  }
  const double dc = system.is_discrete() ? 1.0 : 0.0;
  const double near = kOriginTolerance * std::max(spectral_radius, dc);
  const auto at_dc = [near, dc](const Complex& r) { return std::abs(r - dc) <= near; };
  if (std::any_of(tf.poles.begin(), tf.poles.end(), at_dc)) {
    double sign = tf.gain > 0.0 ? 1.0 : -1.0;
    for (const Complex& z : tf.zeros) {
      if (!at_dc(z) && z.imag() == 0.0 && z.real() > dc) sign = -sign;
    }
    for (const Complex& p : tf.poles) {
      if (!at_dc(p) && p.imag() == 0.0 && p.real() > dc) sign = -sign;
    }
    tf.dc_gain = sign * std::numeric_limits<double>::infinity();
    return tf;
  }
  const MatX shifted = A - dc * MatX::Identity(A.rows(), A.cols());
  const Eigen::FullPivLU<MatX> lu(shifted);
  if (A.rows() == 0) {
    tf.dc_gain = d;
  } else if (lu.isInvertible()) {
    tf.dc_gain = d - c.dot(lu.solve(b));
  } else {
    // Singular only through a cancelled pole at s₀: use the minimal factors.
    tf.dc_gain = tf(Complex(dc, 0.0)).real();
  }
  return tf;
}

TransferFunction transfer_function(const StateSpace& system, std::string_view input,
                                   std::string_view output, double cancellation_tolerance) {
  return transfer_function(system, system.input_index(input), system.output_index(output),
                           cancellation_tolerance);
}

Eigen::MatrixXcd evaluate(const StateSpace& system, Complex s) {
  // (sI − A) X = B by LU with partial pivoting; G = C X + D.
  const Eigen::Index n = system.A().rows();
  Eigen::MatrixXcd resolvent = -system.A().cast<Complex>();
  resolvent.diagonal().array() += s;
  const Eigen::MatrixXcd X =
      n == 0 ? Eigen::MatrixXcd(0, system.B().cols())
             : Eigen::MatrixXcd(resolvent.partialPivLu().solve(system.B().cast<Complex>()));
  return system.C().cast<Complex>() * X + system.D().cast<Complex>();
}

Complex evaluate(const StateSpace& system, std::size_t input, std::size_t output, Complex s) {
  check_pair(system, input, output, "evaluate");
  return evaluate(system.siso(input, output), s)(0, 0);
}

double dc_gain(const StateSpace& system, std::size_t input, std::size_t output) {
  return transfer_function(system, input, output).dc_gain;
}

}  // namespace momenta::analysis
