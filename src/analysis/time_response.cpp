#include "momenta/analysis/time_response.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>
#include <unsupported/Eigen/MatrixFunctions>

#include "momenta/common/error.hpp"

namespace momenta::analysis {
namespace {

// Poles with |Re λ| at most this fraction of |λ| are undamped (an exact double integrator's
// eigenvalues come out of the QR iteration only to round-off).
constexpr double kUndampedRatio = 1e-9;

Eigen::VectorXcd eigenvalues(const MatX& A) {
  if (A.rows() == 0) return Eigen::VectorXcd(0);
  const Eigen::EigenSolver<MatX> eigen(A, /*computeEigenvectors=*/false);
  if (eigen.info() != Eigen::Success) {
    throw NumericalError("time response: the eigenvalue iteration on A did not converge");
  }
  return eigen.eigenvalues();
}

// Final time and sample count, automatic where the grid leaves them 0.
struct Resolved {
  double final_time;
  std::size_t samples;
};

// A sampled system's samples are its own, t_k = k T: `samples` fixes the final time, or the
// final time (rounded to whole samples) the count.
Resolved resolve_sampled(const StateSpace& system, const TimeGrid& grid) {
  const double T = system.sample_time();
  if (grid.samples == 1) {
    throw InvalidArgument("time response: 1 sample requested; at least 2 are needed");
  }
  if (grid.samples > 0) {
    const double final_time = static_cast<double>(grid.samples - 1) * T;
    if (grid.final_time != 0.0 && std::abs(grid.final_time - final_time) > 1e-9 * final_time) {
      throw InvalidArgument(fmt::format(
          "time response: a system sampled every {} s answers at t = k T: {} samples end at {} "
          "s, not {} s; give the final time or the samples",
          T, grid.samples, final_time, grid.final_time));
    }
    return {final_time, grid.samples};
  }
  const double wanted = grid.final_time != 0.0 ? grid.final_time : automatic_final_time(system);
  if (!(wanted > 0.0) || !std::isfinite(wanted)) {
    throw InvalidArgument(
        fmt::format("time response: final time {} s must be positive and finite", wanted));
  }
  const double steps = std::max(1.0, std::floor(wanted / T * (1.0 + 1e-12)));
  if (steps > 1e7) {
    throw InvalidArgument(
        fmt::format("time response: {} s is {:.3g} samples of {} s; choose a shorter final time",
                    wanted, steps, T));
  }
  return {steps * T, static_cast<std::size_t>(steps) + 1};
}

Resolved resolve(const StateSpace& system, const TimeGrid& grid) {
  if (system.is_discrete()) return resolve_sampled(system, grid);
  Resolved r{grid.final_time, grid.samples};
  if (r.final_time == 0.0) r.final_time = automatic_final_time(system);
  if (!(r.final_time > 0.0) || !std::isfinite(r.final_time)) {
    throw InvalidArgument(
        fmt::format("time response: final time {} s must be positive and finite", r.final_time));
  }
  if (r.samples == 0) {
    // 20 samples per period of the fastest oscillation, 501 to 20001 samples in all.
    double fastest = 0.0;
    for (const std::complex<double>& p : eigenvalues(system.A()))
      fastest = std::max(fastest, std::abs(p.imag()));
    const double periods = r.final_time * fastest / (2.0 * M_PI);
    r.samples =
        static_cast<std::size_t>(std::clamp(std::ceil(20.0 * periods) + 1.0, 501.0, 20001.0));
  } else if (r.samples < 2) {
    throw InvalidArgument(
        fmt::format("time response: {} samples requested; at least 2 are needed", r.samples));
  }
  return r;
}

void check_input(const StateSpace& system, std::size_t input) {
  if (input >= system.input_count()) {
    throw InvalidArgument(fmt::format("time response: input index {} but the system has {} inputs",
                                      input, system.input_count()));
  }
}

TimeResponse empty_response(const StateSpace& system, std::size_t input, const Resolved& r) {
  TimeResponse response;
  response.input_name = system.input_names()[input];
  response.output_names = system.output_names();
  response.state_names = system.state_names();
  const StateSpace::Units& units = system.units();
  if (!units.inputs.empty()) response.input_unit = units.inputs[input];
  response.output_units = units.outputs;
  response.state_units = units.states;
  response.time = VecX::LinSpaced(static_cast<Eigen::Index>(r.samples), 0.0, r.final_time);
  response.outputs.resize(static_cast<Eigen::Index>(r.samples),
                          static_cast<Eigen::Index>(system.output_count()));
  response.states.resize(static_cast<Eigen::Index>(r.samples),
                         static_cast<Eigen::Index>(system.state_count()));
  return response;
}

void check_finite(const TimeResponse& response) {
  if (!response.states.allFinite() || !response.outputs.allFinite()) {
    throw NumericalError(fmt::format(
        "time response: the response to '{}' overflows before t = {} s; choose a shorter final "
        "time",
        response.input_name, response.time[response.time.size() - 1]));
  }
}

}  // namespace

Discretization zero_order_hold(const StateSpace& system, double h) {
  return zero_order_hold(system.A(), system.B(), h);
}

Discretization zero_order_hold(const MatX& A, const MatX& B, double h) {
  if (A.rows() != A.cols() || B.rows() != A.rows()) {
    throw InvalidArgument(
        fmt::format("zero_order_hold: A is {}×{} and B {}×{}; A must be square "
                    "and B have as many rows",
                    A.rows(), A.cols(), B.rows(), B.cols()));
  }
  if (!(h > 0.0) || !std::isfinite(h)) {
    throw InvalidArgument(fmt::format("zero_order_hold: time step {} s must be positive", h));
  }
  // exp([A B; 0 0] h) = [Φ Γ; 0 I].
  const Eigen::Index n = A.rows();
  const Eigen::Index m = B.cols();
  MatX augmented = MatX::Zero(n + m, n + m);
  augmented.topLeftCorner(n, n) = A * h;
  augmented.topRightCorner(n, m) = B * h;
  const MatX exponential = augmented.exp();
  if (!exponential.allFinite()) {
    throw NumericalError(
        fmt::format("zero_order_hold: exp(A h) overflows for h = {} s; use a shorter step", h));
  }
  return {exponential.topLeftCorner(n, n), exponential.topRightCorner(n, m)};
}

double automatic_final_time(const StateSpace& system) {
  if (system.is_discrete()) {
    // The continuous rule on s = ln z / T (a pole at z = 0 dies in one sample), in whole samples.
    const double T = system.sample_time();
    std::vector<std::complex<double>> s;
    for (const std::complex<double>& z : eigenvalues(system.A())) {
      if (std::abs(z) > 0.0) s.push_back(std::log(z) / T);
    }
    MatX diagonal = MatX::Zero(2 * static_cast<Eigen::Index>(s.size()),
                               2 * static_cast<Eigen::Index>(s.size()));
    for (std::size_t k = 0; k < s.size(); ++k) {  // a real 2×2 block per pole, same spectrum
      const auto i = 2 * static_cast<Eigen::Index>(k);
      diagonal(i, i) = diagonal(i + 1, i + 1) = s[k].real();
      diagonal(i, i + 1) = s[k].imag();
      diagonal(i + 1, i) = -s[k].imag();
    }
    const StateSpace continuous(diagonal, MatX::Zero(diagonal.rows(), 0),
                                MatX::Zero(0, diagonal.rows()), MatX());
    return std::max(1.0, std::ceil(automatic_final_time(continuous) / T)) * T;
  }
  double fastest_growth = 0.0;
  double slowest_decay = std::numeric_limits<double>::infinity();
  double slowest_undamped = std::numeric_limits<double>::infinity();  // rad/s
  for (const std::complex<double>& p : eigenvalues(system.A())) {
    const double magnitude = std::abs(p);
    if (magnitude == 0.0) continue;
    if (std::abs(p.real()) <= kUndampedRatio * magnitude) {
      if (p.imag() != 0.0) slowest_undamped = std::min(slowest_undamped, std::abs(p.imag()));
    } else if (p.real() > 0.0) {
      fastest_growth = std::max(fastest_growth, p.real());
    } else {
      slowest_decay = std::min(slowest_decay, -p.real());
    }
  }
  if (fastest_growth > 0.0) return 5.0 / fastest_growth;
  double horizon = 0.0;
  if (std::isfinite(slowest_decay)) horizon = 7.0 / slowest_decay;
  if (std::isfinite(slowest_undamped)) {
    horizon = std::max(horizon, 5.0 * 2.0 * M_PI / slowest_undamped);
  }
  return horizon > 0.0 ? horizon : 10.0;
}

TimeResponse step_response(const StateSpace& system, std::size_t input, const TimeGrid& grid,
                           double amplitude) {
  check_input(system, input);
  if (!std::isfinite(amplitude)) {
    throw InvalidArgument(fmt::format("step_response: amplitude {} is not finite", amplitude));
  }
  const Resolved r = resolve(system, grid);
  TimeResponse response = empty_response(system, input, r);
  const double h = r.final_time / static_cast<double>(r.samples - 1);

  // x_{k+1} = Φ x_k + Γ u, exact for the constant input u = amplitude.
  // A sampled system is its own recursion.
  const Discretization zoh =
      system.is_discrete()
          ? Discretization{system.A(), system.B().col(static_cast<Eigen::Index>(input))}
          : zero_order_hold(system.A(), system.B().col(static_cast<Eigen::Index>(input)), h);
  const VecX forced = zoh.input.col(0) * amplitude;
  const VecX feedthrough = system.D().col(static_cast<Eigen::Index>(input)) * amplitude;
  VecX x = VecX::Zero(system.A().rows());
  VecX next(x.size());
  for (Eigen::Index k = 0; k < response.time.size(); ++k) {
    response.states.row(k) = x.transpose();
    response.outputs.row(k) = (system.C() * x + feedthrough).transpose();
    next.noalias() = zoh.transition * x;
    x = next + forced;
  }
  check_finite(response);
  return response;
}

TimeResponse impulse_response(const StateSpace& system, std::size_t input, const TimeGrid& grid) {
  check_input(system, input);
  const Resolved r = resolve(system, grid);
  TimeResponse response = empty_response(system, input, r);
  const double h = r.final_time / static_cast<double>(r.samples - 1);

  if (system.is_discrete()) {
    // The unit pulse u[0] = 1: y[0] = D e_input, x[1] = B e_input, then x[k+1] = A x[k].
    const auto i = static_cast<Eigen::Index>(input);
    VecX x = VecX::Zero(system.A().rows());
    for (Eigen::Index k = 0; k < response.time.size(); ++k) {
      response.states.row(k) = x.transpose();
      response.outputs.row(k) = (system.C() * x).transpose();
      if (k == 0) {
        response.outputs.row(0) += system.D().col(i).transpose();
        x = system.B().col(i);
      } else {
        x = system.A() * x;
      }
    }
    check_finite(response);
    return response;
  }
  // x(0⁺) = B e_input, then free motion x_{k+1} = Φ x_k.
  const Discretization zoh =
      zero_order_hold(system.A(), system.B().col(static_cast<Eigen::Index>(input)), h);
  VecX x = system.B().col(static_cast<Eigen::Index>(input));
  VecX next(x.size());
  for (Eigen::Index k = 0; k < response.time.size(); ++k) {
    response.states.row(k) = x.transpose();
    response.outputs.row(k) = (system.C() * x).transpose();
    next.noalias() = zoh.transition * x;
    x = next;
  }
  check_finite(response);
  return response;
}

}  // namespace momenta::analysis
