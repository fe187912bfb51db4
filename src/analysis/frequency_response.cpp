#include "momenta/analysis/frequency_response.hpp"

#include <cmath>
#include <complex>
#include <limits>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include "momenta/analysis/transfer_function.hpp"
#include "momenta/common/error.hpp"

namespace momenta::analysis {
namespace {

constexpr double kDegreesPerRadian = 180.0 / M_PI;

// Solves (s I − H) y = r for upper Hessenberg H by Gaussian elimination with partial pivoting:
// column k has one subdiagonal entry, so each step compares and combines rows k and k+1 only.
// T and y are workspaces of the right size, overwritten. Returns false if (s I − H) is singular.
bool solve_shifted_hessenberg(const MatX& H, Complex s, Eigen::MatrixXcd& T, Eigen::VectorXcd& y) {
  const Eigen::Index n = H.rows();
  T = -H.cast<Complex>();
  T.diagonal().array() += s;
  for (Eigen::Index k = 0; k + 1 < n; ++k) {
    if (std::abs(T(k + 1, k)) > std::abs(T(k, k))) {
      T.row(k).tail(n - k).swap(T.row(k + 1).tail(n - k));
      std::swap(y[k], y[k + 1]);
    }
    if (T(k, k) == Complex(0.0, 0.0)) return false;
    const Complex l = T(k + 1, k) / T(k, k);
    T.row(k + 1).tail(n - k - 1) -= l * T.row(k).tail(n - k - 1);
    y[k + 1] -= l * y[k];
  }
  if (n > 0 && T(n - 1, n - 1) == Complex(0.0, 0.0)) return false;
  T.triangularView<Eigen::Upper>().solveInPlace(y);
  return true;
}

// Principal argument in degrees, (−180°, 180°].
double arg_deg(Complex z) { return std::arg(z) * kDegreesPerRadian; }

}  // namespace

std::complex<double> frequency_point(const StateSpace& system, double omega) {
  const double period = system.sample_time();
  return period > 0.0 ? std::exp(Complex(0.0, omega * period)) : Complex(0.0, omega);
}

VecX log_frequency_grid(double omega_min, double omega_max, std::size_t points) {
  if (!(omega_min > 0.0) || !(omega_max > omega_min) || !std::isfinite(omega_max)) {
    throw InvalidArgument(
        fmt::format("log_frequency_grid: need 0 < omega_min < omega_max (rad/s), got {} and {}",
                    omega_min, omega_max));
  }
  if (points < 2) {
    throw InvalidArgument(fmt::format("log_frequency_grid: {} points; at least 2", points));
  }
  VecX grid = VecX::LinSpaced(static_cast<Eigen::Index>(points), std::log10(omega_min),
                              std::log10(omega_max));
  grid = grid.unaryExpr([](double e) { return std::pow(10.0, e); });
  // Exact ends, whatever pow's rounding.
  grid[0] = omega_min;
  grid[grid.size() - 1] = omega_max;
  return grid;
}

FrequencyResponse frequency_response(const StateSpace& system, std::size_t input,
                                     std::size_t output, const VecX& frequencies) {
  const double period = system.sample_time();
  if (input >= system.input_count() || output >= system.output_count()) {
    throw InvalidArgument(fmt::format(
        "frequency_response: pair (input {}, output {}) out of range: the system has {} inputs "
        "and {} outputs",
        input, output, system.input_count(), system.output_count()));
  }
  for (Eigen::Index k = 0; k < frequencies.size(); ++k) {
    if (!(frequencies[k] >= 0.0) || !std::isfinite(frequencies[k])) {
      throw InvalidArgument(
          fmt::format("frequency_response: frequency {} = {} rad/s must be finite and >= 0", k,
                      frequencies[k]));
    }
    if (period > 0.0 && frequencies[k] > M_PI / period * (1.0 + 1e-12)) {
      throw InvalidArgument(fmt::format(
          "frequency_response: {} rad/s is above the Nyquist frequency π/T = {} rad/s of a "
          "system sampled every {} s (above it the response repeats)",
          frequencies[k], M_PI / period, period));
    }
  }
  FrequencyResponse result;
  result.input_name = system.input_names()[input];
  result.output_name = system.output_names()[output];
  result.frequency = frequencies;
  const Eigen::Index count = frequencies.size();
  result.response.resize(count);

  const auto point = [&system](double omega) { return frequency_point(system, omega); };

  // Hessenberg form once: A = Q H Qᵀ, so G(s) = c Q (sI − H)⁻¹ Qᵀ b + d.
  const auto i = static_cast<Eigen::Index>(input);
  const auto o = static_cast<Eigen::Index>(output);
  const Eigen::Index n = system.A().rows();
  const double d = system.D()(o, i);
  MatX H;
  VecX b_h;
  Eigen::RowVectorXd c_h;
  if (n > 0) {
    const Eigen::HessenbergDecomposition<MatX> hessenberg(system.A());
    H = hessenberg.matrixH();
    const MatX Q = hessenberg.matrixQ();
    b_h = Q.transpose() * system.B().col(i);
    c_h = system.C().row(o) * Q;
  }

  // One O(n²) solve per frequency.
  Eigen::MatrixXcd T(n, n);
  Eigen::VectorXcd y(n);
  for (Eigen::Index k = 0; k < count; ++k) {
    const Complex s = point(frequencies[k]);
    y = b_h.cast<Complex>();
    if (n == 0) {
      result.response[k] = d;
    } else if (solve_shifted_hessenberg(H, s, T, y)) {
      result.response[k] = (c_h.cast<Complex>() * y).value() + d;
    } else {
      const double inf = std::numeric_limits<double>::infinity();
      result.response[k] = Complex(inf, inf);
    }
  }

  // Magnitude, dB and raw phase.
  result.magnitude = result.response.cwiseAbs();
  result.magnitude_db = result.magnitude.unaryExpr([](double m) { return 20.0 * std::log10(m); });
  result.phase_deg.resize(count);
  for (Eigen::Index k = 0; k < count; ++k) result.phase_deg[k] = arg_deg(result.response[k]);

  // Unwrap: keep each step within ±180°.
  for (Eigen::Index k = 1; k < count; ++k) {
    const double step = result.phase_deg[k] - result.phase_deg[k - 1];
    result.phase_deg[k] -= 360.0 * std::round(step / 360.0);
  }

  // Branch at the first frequency from the factored form.
  if (count > 0 && std::isfinite(result.phase_deg[0])) {
    const TransferFunction tf = transfer_function(system, input, output);
    if (!tf.is_zero()) {
      const Complex s = point(frequencies[0]);
      double reference = tf.gain > 0.0 ? 0.0 : -180.0;
      for (const Complex& z : tf.zeros) reference += arg_deg(s - z);
      for (const Complex& p : tf.poles) reference -= arg_deg(s - p);
      const double shift = 360.0 * std::round((reference - result.phase_deg[0]) / 360.0);
      result.phase_deg.array() += shift;
    }
  }
  return result;
}

FrequencyResponse frequency_response(const StateSpace& system, std::size_t input,
                                     std::size_t output, double omega_min, double omega_max,
                                     std::size_t points) {
  return frequency_response(system, input, output,
                            log_frequency_grid(omega_min, omega_max, points));
}

}  // namespace momenta::analysis
