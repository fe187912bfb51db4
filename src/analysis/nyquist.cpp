#include "momenta/analysis/nyquist.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include "momenta/analysis/transfer_function.hpp"
#include "momenta/common/error.hpp"

namespace momenta::analysis {
namespace {

constexpr double kPi = std::numbers::pi;

// One piece of the contour: s(t) for t from `begin` to `end`.
struct Piece {
  std::function<Complex(double)> point;
  double begin;
  double end;
};

// Follows arg f along the pieces in order; returns the total turn (radians), or NaN when f
// vanishes on the contour (a step that cannot be resolved).
class ArgumentTracker {
 public:
  explicit ArgumentTracker(std::function<Complex(Complex)> f) : f_(std::move(f)) {}

  double turn(const std::vector<Piece>& pieces) {
    double total = 0.0;
    bool first = true;
    Complex last;
    for (const Piece& piece : pieces) {
      constexpr int kStart = 64;
      Complex f0 = value(piece.point(piece.begin));
      if (!first) total += step(last, f0);  // the pieces meet, to round-off
      first = false;
      for (int k = 0; k < kStart; ++k) {
        const double t0 = piece.begin + (piece.end - piece.begin) * k / kStart;
        const double t1 = piece.begin + (piece.end - piece.begin) * (k + 1) / kStart;
        const Complex f1 = value(piece.point(t1));
        total += sweep(piece, t0, f0, t1, f1, 0);
        f0 = f1;
      }
      last = f0;
    }
    return total;
  }

 private:
  // f at s; NaN when it is zero or not finite, which no step can cross.
  Complex value(Complex s) const {
    const Complex f = f_(s);
    if (!std::isfinite(f.real()) || !std::isfinite(f.imag()) || std::abs(f) <= 1e-12)
      return {std::nan(""), 0.0};
    return f;
  }
  static double step(Complex a, Complex b) { return std::arg(b / a); }

  double sweep(const Piece& piece, double t0, Complex f0, double t1, Complex f1, int depth) {
    if (std::isnan(f0.real()) || std::isnan(f1.real())) return std::nan("");
    const double turn = step(f0, f1);
    const double ratio = std::abs(f1) / std::abs(f0);
    if (std::abs(turn) <= kPi / 8 && ratio <= 2.0 && ratio >= 0.5) return turn;
    if (depth >= 44) return std::nan("");
    const double tm = 0.5 * (t0 + t1);
    const Complex fm = value(piece.point(tm));
    return sweep(piece, t0, f0, tm, fm, depth + 1) + sweep(piece, tm, fm, t1, f1, depth + 1);
  }

  std::function<Complex(Complex)> f_;
};

// The boundary poles, merged where closer than `merge`, by position along the boundary.
std::vector<double> boundary_positions(std::vector<double> positions, double merge) {
  std::sort(positions.begin(), positions.end());
  std::vector<double> merged;
  for (double x : positions) {
    if (merged.empty() || x - merged.back() > merge) merged.push_back(x);
  }
  return merged;
}

// Up the imaginary axis from −jR to jR, round each boundary pole jω on its right at radius ε,
// then back round the right half-plane. Along the axis ω = w0 sinh(t): steps even in log |ω|
// beyond w0, even in ω below it.
std::vector<Piece> s_plane_contour(const std::vector<double>& omegas, double epsilon, double R,
                                   double w0) {
  std::vector<Piece> pieces;
  const auto axis = [&](double from, double to) {
    pieces.push_back({[w0](double t) { return Complex(0.0, w0 * std::sinh(t)); },
                      std::asinh(from / w0), std::asinh(to / w0)});
  };
  double from = -R;
  for (double w : omegas) {
    axis(from, w - epsilon);
    pieces.push_back(
        {[w, epsilon](double phi) { return Complex(0.0, w) + std::polar(epsilon, phi); }, -kPi / 2,
         kPi / 2});
    from = w + epsilon;
  }
  axis(from, R);
  pieces.push_back({[R](double phi) { return std::polar(R, phi); }, kPi / 2, -kPi / 2});
  return pieces;
}

// Counter-clockwise round the unit circle, round each boundary pole e^{jθ} outside it at radius
// ε, starting in the middle of the widest gap between them.
std::vector<Piece> z_plane_contour(const std::vector<double>& thetas, double epsilon) {
  std::vector<Piece> pieces;
  const auto arc = [&](double from, double to) {
    pieces.push_back({[](double t) { return std::polar(1.0, t); }, from, to});
  };
  if (thetas.empty()) {
    arc(-kPi, kPi);
    return pieces;
  }
  // The widest gap, circularly, and its middle as the start.
  std::size_t widest = thetas.size() - 1;
  double gap = thetas.front() + 2 * kPi - thetas.back();
  for (std::size_t k = 0; k + 1 < thetas.size(); ++k) {
    if (thetas[k + 1] - thetas[k] > gap) {
      gap = thetas[k + 1] - thetas[k];
      widest = k;
    }
  }
  const double start = thetas[widest] + 0.5 * gap;
  std::vector<double> ahead;  // the poles' angles from the start, in (start, start + 2π)
  for (double theta : thetas) ahead.push_back(theta < start ? theta + 2 * kPi : theta);
  std::sort(ahead.begin(), ahead.end());
  const double half_angle = 2.0 * std::asin(0.5 * epsilon);  // |e^{j(θ±δ)} − e^{jθ}| = ε
  double from = start;
  for (double theta : ahead) {
    arc(from, theta - half_angle);
    const Complex center = std::polar(1.0, theta);
    pieces.push_back({[center, epsilon](double phi) { return center + std::polar(epsilon, phi); },
                      theta - kPi / 2 - half_angle / 2, theta + kPi / 2 + half_angle / 2});
    from = theta + half_angle;
  }
  arc(from, start + 2 * kPi);
  return pieces;
}

}  // namespace

NyquistCount nyquist_count(const StateSpace& system, std::size_t input, std::size_t output) {
  if (input >= system.input_count() || output >= system.output_count()) {
    throw InvalidArgument(fmt::format(
        "nyquist_count: pair (input {}, output {}) out of range: the system has {} inputs and {} "
        "outputs",
        input, output, system.input_count(), system.output_count()));
  }
  const auto i = static_cast<Eigen::Index>(input);
  const auto o = static_cast<Eigen::Index>(output);
  const double d = system.D()(o, i);
  if (std::abs(1.0 + d) <= 1e-12) {
    throw InvalidArgument("nyquist_count: 1 + D = 0: the unity-feedback loop is not well posed");
  }
  NyquistCount count;
  count.sample_time = system.sample_time();
  const bool sampled = count.sample_time > 0.0;
  const Eigen::Index n = system.A().rows();

  // P, and the poles the contour goes round.
  Eigen::VectorXcd poles;
  if (n > 0) {
    const Eigen::EigenSolver<MatX> eigen(system.A(), false);
    if (eigen.info() != Eigen::Success)
      throw NumericalError("nyquist_count: the eigenvalue iteration on A did not converge");
    poles = eigen.eigenvalues();
  }
  double scale = 1.0;
  for (const Complex& p : poles) scale = std::max(scale, std::abs(p));
  const double on_boundary = 1e-7 * (sampled ? 1.0 : scale);
  std::vector<double> boundary;  // ω of each s = jω, or θ of each z = e^{jθ}
  for (const Complex& p : poles) {
    const double distance = sampled ? std::abs(p) - 1.0 : p.real();
    if (std::abs(distance) <= on_boundary) {
      boundary.push_back(sampled ? std::arg(p) : p.imag());
      ++count.boundary_poles;
    } else if (distance > 0.0) {
      ++count.open_loop_unstable;
    }
  }
  const double merge = 10.0 * on_boundary;
  boundary = boundary_positions(boundary, merge);
  // ε: well beyond a multiple pole's spread, well inside the distance to any other pole.
  double epsilon = 1e-5 * (sampled ? 1.0 : scale);
  for (double b : boundary) {
    const Complex at = sampled ? std::polar(1.0, b) : Complex(0.0, b);
    for (const Complex& p : poles) {
      const double gap = std::abs(p - at);
      if (gap > merge) epsilon = std::min(epsilon, 0.25 * gap);
    }
  }

  ArgumentTracker tracker([&](Complex s) { return 1.0 + evaluate(system, input, output, s); });
  std::vector<Piece> contour;
  if (sampled) {
    contour = z_plane_contour(boundary, epsilon);
  } else {
    // R beyond every open- and closed-loop pole: the Frobenius norm bounds the spectral radius.
    const MatX closed = system.A() - system.B().col(i) * system.C().row(o) / (1.0 + d);
    const double R = 10.0 * std::max({scale, n > 0 ? closed.norm() : 0.0,
                                      boundary.empty() ? 0.0 : std::abs(boundary.back())});
    double w0 = scale;  // the smallest nonzero pole magnitude, for the axis's spacing
    for (const Complex& p : poles) {
      if (std::abs(p) > merge) w0 = std::min(w0, std::abs(p));
    }
    contour = s_plane_contour(boundary, epsilon, R, 1e-2 * w0);
  }
  const double turn = tracker.turn(contour);
  if (std::isnan(turn)) {
    count.through_critical_point = true;
    return count;
  }
  const double turns = -turn / (2.0 * kPi);
  if (std::abs(turns - std::round(turns)) > 1e-6) {
    throw NumericalError(
        fmt::format("nyquist_count: the contour's turns came to {}, not a whole number", turns));
  }
  count.encirclements = static_cast<int>(std::lround(turns));
  count.closed_loop_unstable = count.encirclements + count.open_loop_unstable;
  return count;
}

}  // namespace momenta::analysis
