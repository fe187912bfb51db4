#include "momenta/analysis/root_locus.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include "momenta/common/error.hpp"

namespace momenta::analysis {
namespace {

using ComplexPolynomial = std::vector<Complex>;  // ascending powers

// ∏(s − rᵢ), monic.
ComplexPolynomial from_roots(const std::vector<Complex>& roots) {
  ComplexPolynomial p{1.0};
  for (const Complex& r : roots) {
    ComplexPolynomial next(p.size() + 1, 0.0);
    for (std::size_t k = 0; k < p.size(); ++k) {
      next[k + 1] += p[k];
      next[k] -= r * p[k];
    }
    p = std::move(next);
  }
  return p;
}

ComplexPolynomial derivative(const ComplexPolynomial& p) {
  ComplexPolynomial d(p.size() > 1 ? p.size() - 1 : 1, 0.0);
  for (std::size_t k = 1; k < p.size(); ++k) d[k - 1] = static_cast<double>(k) * p[k];
  return d;
}

ComplexPolynomial product(const ComplexPolynomial& a, const ComplexPolynomial& b) {
  ComplexPolynomial c(a.size() + b.size() - 1, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
  return c;
}

// The roots of p from its companion matrix, trailing coefficients below round-off dropped.
std::vector<Complex> roots_of(ComplexPolynomial p) {
  double largest = 0.0;
  for (const Complex& c : p) largest = std::max(largest, std::abs(c));
  while (p.size() > 1 && std::abs(p.back()) <= 1e-13 * largest) p.pop_back();
  const auto degree = static_cast<Eigen::Index>(p.size()) - 1;
  if (degree < 1) return {};
  Eigen::MatrixXcd companion = Eigen::MatrixXcd::Zero(degree, degree);
  for (Eigen::Index k = 0; k < degree; ++k) companion(0, k) = -p[degree - 1 - k] / p[degree];
  for (Eigen::Index k = 1; k < degree; ++k) companion(k, k - 1) = 1.0;
  const Eigen::ComplexEigenSolver<Eigen::MatrixXcd> eigen(companion, false);
  if (eigen.info() != Eigen::Success) {
    throw NumericalError("root_locus: the eigenvalue iteration on a companion matrix failed");
  }
  return {eigen.eigenvalues().begin(), eigen.eigenvalues().end()};
}

// k(s) = −D(s)/(K N(s)) from the factors.
Complex gain_at(const TransferFunction& g, Complex s) {
  Complex ratio = -1.0 / g.gain;
  for (const Complex& p : g.poles) ratio *= s - p;
  for (const Complex& z : g.zeros) ratio /= s - z;
  return ratio;
}

// A point of the locus where k(s) is real and positive (to `tolerance` relative), or none.
std::optional<LocusPoint> locus_point(const TransferFunction& g, Complex s, double scale) {
  const Complex k = gain_at(g, s);
  if (!std::isfinite(k.real()) || !std::isfinite(k.imag())) return std::nullopt;
  if (!(k.real() > 0.0) || std::abs(k.imag()) > 1e-7 * std::abs(k)) return std::nullopt;
  if (std::abs(s.imag()) <= 1e-10 * scale) s = Complex(s.real(), 0.0);
  if (std::abs(s.real()) <= 1e-10 * scale) s = Complex(0.0, s.imag());
  return LocusPoint{s, k.real()};
}

// Break-away and break-in points: Σ 1/(s − p) = Σ 1/(s − z), from N′D − N D′ = 0, polished.
std::vector<LocusPoint> breakaway_points(const TransferFunction& g, double scale) {
  const ComplexPolynomial N = from_roots(g.zeros);
  const ComplexPolynomial D = from_roots(g.poles);
  ComplexPolynomial P = product(derivative(N), D);
  const ComplexPolynomial ND = product(N, derivative(D));
  P.resize(std::max(P.size(), ND.size()), 0.0);
  for (std::size_t k = 0; k < ND.size(); ++k) P[k] -= ND[k];
  std::vector<LocusPoint> points;
  for (Complex s : roots_of(P)) {
    for (int step = 0; step < 4; ++step) {  // Newton on f = Σ 1/(s − p) − Σ 1/(s − z)
      Complex f = 0.0, df = 0.0;
      for (const Complex& p : g.poles) {
        f += 1.0 / (s - p);
        df -= 1.0 / ((s - p) * (s - p));
      }
      for (const Complex& z : g.zeros) {
        f -= 1.0 / (s - z);
        df += 1.0 / ((s - z) * (s - z));
      }
      if (!std::isfinite(std::abs(f / df)) || df == 0.0) break;
      s -= f / df;
    }
    if (const auto point = locus_point(g, s, scale)) points.push_back(*point);
  }
  return points;
}

// Crossings of the imaginary axis: real roots ω ≥ 0 of Im[D(jω) conj N(jω)].
std::vector<LocusPoint> axis_crossings(const TransferFunction& g, double scale) {
  const ComplexPolynomial N = from_roots(g.zeros);
  const ComplexPolynomial D = from_roots(g.poles);
  // As polynomials in ω: D(jω) = Σ d_k j^k ω^k, conj N(jω) = Σ conj(n_k) (−j)^k ω^k.
  const auto in_omega = [](const ComplexPolynomial& p, Complex unit) {
    ComplexPolynomial q(p.size());
    Complex power = 1.0;
    for (std::size_t k = 0; k < p.size(); ++k, power *= unit) q[k] = p[k] * power;
    return q;
  };
  ComplexPolynomial conj_N = N;
  for (Complex& c : conj_N) c = std::conj(c);
  const ComplexPolynomial both =
      product(in_omega(D, Complex(0, 1)), in_omega(conj_N, Complex(0, -1)));
  ComplexPolynomial Q(both.size());
  for (std::size_t k = 0; k < both.size(); ++k) Q[k] = both[k].imag();
  std::vector<double> omegas{0.0};
  for (const Complex& w : roots_of(Q)) {
    if (std::abs(w.imag()) <= 1e-6 * std::max(1.0, std::abs(w)) &&
        w.real() > 1e-7 * scale) {  // ω = 0 is taken as such, below
      omegas.push_back(w.real());
    }
  }
  std::vector<LocusPoint> points;
  for (double w : omegas) {
    if (const auto point = locus_point(g, Complex(0.0, w), scale)) points.push_back(*point);
  }
  return points;
}

// Crossings of the unit circle: the roots z = e^{jθ} of Im[D(z) conj N(z)] on it. There conj z
// = 1/z, so z^n · 2j Im[…] = z^{n−m} D(z) N̄ʳ(z) − D̄ʳ(z) N(z), N̄ʳ(z) = z^m conj N(1/conj z)
// (conjugated coefficients, reversed), a polynomial of degree ≤ 2n. z = ±1 are always tried: a
// real polynomial's Im part vanishes there, the polynomial's roots then come in close pairs.
std::vector<LocusPoint> circle_crossings(const TransferFunction& g, double scale) {
  const ComplexPolynomial N = from_roots(g.zeros);
  const ComplexPolynomial D = from_roots(g.poles);
  const auto reversed_conjugate = [](const ComplexPolynomial& p) {
    ComplexPolynomial r(p.rbegin(), p.rend());
    for (Complex& c : r) c = std::conj(c);
    return r;
  };
  const std::size_t shift = D.size() - N.size();  // n − m ≥ 0 for a proper G
  ComplexPolynomial first = product(D, reversed_conjugate(N));
  first.insert(first.begin(), shift, 0.0);
  const ComplexPolynomial second = product(reversed_conjugate(D), N);
  first.resize(std::max(first.size(), second.size()), 0.0);
  for (std::size_t k = 0; k < second.size(); ++k) first[k] -= second[k];
  std::vector<Complex> candidates{Complex(1.0, 0.0), Complex(-1.0, 0.0)};
  for (const Complex& z : roots_of(first)) {
    if (std::abs(std::abs(z) - 1.0) <= 1e-6 && z.imag() > 1e-7)
      candidates.push_back(z / std::abs(z));
  }
  // A zero or pole on the circle is where a branch ends or starts (k = ∞ or 0), not a crossing.
  const auto at_a_root = [&](Complex z) {
    for (const auto* list : {&g.zeros, &g.poles}) {
      for (const Complex& r : *list) {
        if (std::abs(z - r) <= 1e-7 * scale) return true;
      }
    }
    return false;
  };
  std::vector<LocusPoint> points;
  for (const Complex& z : candidates) {
    if (at_a_root(z)) continue;
    if (const auto point = locus_point(g, z, scale)) points.push_back(*point);
  }
  return points;
}

void by_gain(std::vector<LocusPoint>& points) {
  std::sort(points.begin(), points.end(), [](const LocusPoint& a, const LocusPoint& b) {
    return a.gain != b.gain ? a.gain < b.gain : a.s.imag() > b.s.imag();
  });
  // A conjugate pair gives one point each side; keep the upper one of each.
  std::vector<LocusPoint> kept;
  for (const LocusPoint& p : points) {
    const bool mirrored = std::any_of(kept.begin(), kept.end(), [&](const LocusPoint& q) {
      return std::abs(q.s - std::conj(p.s)) <= 1e-9 * std::max(1.0, std::abs(p.s)) ||
             std::abs(q.s - p.s) <= 1e-9 * std::max(1.0, std::abs(p.s));
    });
    if (!mirrored) kept.push_back(p);
  }
  points = std::move(kept);
}

// The eigenvalues of `A`, ordered to continue `previous` (nearest neighbour, greedily).
Eigen::VectorXcd continued(const MatX& A, const Eigen::VectorXcd* previous) {
  const Eigen::EigenSolver<MatX> eigen(A, false);
  if (eigen.info() != Eigen::Success) {
    throw NumericalError("root_locus: the eigenvalue iteration on A − k B C did not converge");
  }
  Eigen::VectorXcd now = eigen.eigenvalues();
  if (previous == nullptr) return now;
  Eigen::VectorXcd ordered(now.size());
  std::vector<bool> used(static_cast<std::size_t>(now.size()), false);
  for (Eigen::Index j = 0; j < now.size(); ++j) {
    Eigen::Index best = -1;
    for (Eigen::Index i = 0; i < now.size(); ++i) {
      if (used[static_cast<std::size_t>(i)]) continue;
      if (best < 0 || std::abs(now[i] - (*previous)[j]) < std::abs(now[best] - (*previous)[j])) {
        best = i;
      }
    }
    used[static_cast<std::size_t>(best)] = true;
    ordered[j] = now[best];
  }
  return ordered;
}

}  // namespace

VecX log_gain_grid(double k_min, double k_max, std::size_t points) {
  if (!(k_min > 0.0) || !(k_max > k_min) || !std::isfinite(k_max) || points < 2) {
    throw InvalidArgument(fmt::format(
        "root locus gains: need 0 < k_min < k_max, finite, and at least 2 points; got {} to {}, "
        "{} points",
        k_min, k_max, points));
  }
  VecX gains(static_cast<Eigen::Index>(points) + 1);
  gains[0] = 0.0;
  const double ratio = std::log(k_max / k_min) / static_cast<double>(points - 1);
  for (std::size_t k = 0; k < points; ++k) {
    gains[static_cast<Eigen::Index>(k) + 1] = k_min * std::exp(ratio * static_cast<double>(k));
  }
  gains[gains.size() - 1] = k_max;
  return gains;
}

RootLocus root_locus(const StateSpace& system, std::size_t input, std::size_t output,
                     const VecX& gains) {
  RootLocus locus;
  locus.sample_time = system.sample_time();
  locus.open_loop = transfer_function(system, input, output);
  locus.input_name = locus.open_loop.input_name;
  locus.output_name = locus.open_loop.output_name;
  const TransferFunction& g = locus.open_loop;
  if (g.is_zero()) {
    throw InvalidArgument(fmt::format(
        "root_locus: the output '{}' does not respond to the input '{}' (G ≡ 0): feedback "
        "cannot move a pole",
        locus.output_name, locus.input_name));
  }

  // The branches, from the state space.
  const auto i = static_cast<Eigen::Index>(input);
  const auto o = static_cast<Eigen::Index>(output);
  const VecX b = system.B().col(i);
  const Eigen::RowVectorXd c = system.C().row(o);
  const double d = system.D()(o, i);
  locus.gains = gains;
  locus.poles.resize(gains.size(), system.A().rows());
  Eigen::VectorXcd previous;
  for (Eigen::Index k = 0; k < gains.size(); ++k) {
    const double gain = gains[k];
    if (!(gain >= 0.0) || !std::isfinite(gain)) {
      throw InvalidArgument(
          fmt::format("root_locus: gain {} = {} must be finite and ≥ 0", k, gain));
    }
    if (std::abs(1.0 + gain * d) <= 1e-12) {
      throw InvalidArgument(
          fmt::format("root_locus: at k = {} the loop is not well posed (1 + k D = 0)", gain));
    }
    const MatX closed = system.A() - (gain / (1.0 + gain * d)) * b * c;
    const Eigen::VectorXcd now = continued(closed, k > 0 ? &previous : nullptr);
    locus.poles.row(k) = now.transpose();
    previous = now;
  }

  // The landmarks, from the factors, each within 1e-7 of the largest of them of an axis put on
  // it: a multiple pole comes out of the eigenvalue iteration about √ε apart (a double
  // integrator's as ±1e-9j), which would otherwise draw crossings at gains near 0.
  double scale = 1.0;
  for (const Complex& p : g.poles) scale = std::max(scale, std::abs(p));
  for (const Complex& z : g.zeros) scale = std::max(scale, std::abs(z));
  TransferFunction snapped = g;
  for (auto* list : {&snapped.poles, &snapped.zeros}) {
    for (Complex& x : *list) {
      x = Complex(std::abs(x.real()) <= 1e-7 * scale ? 0.0 : x.real(),
                  std::abs(x.imag()) <= 1e-7 * scale ? 0.0 : x.imag());
    }
  }
  locus.breakaway = breakaway_points(snapped, scale);
  by_gain(locus.breakaway);
  locus.crossings =
      locus.sample_time > 0.0 ? circle_crossings(snapped, scale) : axis_crossings(snapped, scale);
  by_gain(locus.crossings);
  const int excess = g.relative_degree();
  if (excess > 0) {
    Complex sum = 0.0;
    for (const Complex& p : g.poles) sum += p;
    for (const Complex& z : g.zeros) sum -= z;
    locus.asymptote_centroid = sum.real() / excess;
    for (int l = 0; l < excess; ++l) {
      // 1 + k G = 0 with k > 0: arg G = 180° (K > 0); the complementary 0° rule when K < 0.
      const double odd = g.gain > 0 ? 2.0 * l + 1.0 : 2.0 * l;
      locus.asymptote_angles_deg.push_back(std::fmod(odd * 180.0 / excess, 360.0));
    }
  }
  return locus;
}

}  // namespace momenta::analysis
