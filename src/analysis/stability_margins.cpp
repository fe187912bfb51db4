#include "momenta/analysis/stability_margins.hpp"

#include <cmath>
#include <complex>
#include <cstdint>
#include <numbers>

#include <boost/math/tools/toms748_solve.hpp>

#include "momenta/analysis/frequency_response.hpp"
#include "momenta/analysis/transfer_function.hpp"

namespace momenta::analysis {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

// The root of f in [a, b] (f(a), f(b) of opposite signs) to 1e-12 relative in ω.
template <class F>
double locate(F f, double a, double b, double fa, double fb) {
  std::uintmax_t iterations = 200;
  const auto close_enough = [](double x, double y) {
    return std::abs(x - y) <= 1e-12 * std::max(std::abs(x), std::abs(y));
  };
  const auto [lo, hi] =
      boost::math::tools::toms748_solve(f, a, b, fa, fb, close_enough, iterations);
  return 0.5 * (lo + hi);
}

// x wrapped into (−180°, 180°].
double wrapped(double degrees) {
  double x = std::fmod(degrees + 180.0, 360.0);
  if (x <= 0.0) x += 360.0;
  return x - 180.0;
}

}  // namespace

StabilityMargins stability_margins(const StateSpace& system, std::size_t input, std::size_t output,
                                   double omega_min, double omega_max, std::size_t points) {
  const FrequencyResponse f =
      frequency_response(system, input, output, omega_min, omega_max, points);
  const auto G = [&](double omega) {
    return evaluate(system, input, output, frequency_point(system, omega));
  };
  StabilityMargins m;
  for (Eigen::Index k = 0; k + 1 < f.frequency.size(); ++k) {
    const double a = f.frequency[k], b = f.frequency[k + 1];
    if (!std::isfinite(f.magnitude[k]) || !std::isfinite(f.magnitude[k + 1])) continue;
    // Gain crossover: log |G| changes sign.
    const double la = std::log(f.magnitude[k]), lb = std::log(f.magnitude[k + 1]);
    if (std::isfinite(la) && std::isfinite(lb) && (la < 0.0) != (lb < 0.0)) {
      const double w =
          la == 0.0 ? a : locate([&](double x) { return std::log(std::abs(G(x))); }, a, b, la, lb);
      m.gain_crossovers.push_back({w, wrapped(180.0 + std::arg(G(w)) * kDegrees)});
    }
    // Phase crossover: the unwrapped phase passes −180° + 360° j. Between neighbours the phase
    // moves less than 180°, so the phase at x is the neighbour's plus the wrapped change.
    const double pa = f.phase_deg[k], pb = f.phase_deg[k + 1];
    const double ja = std::floor((pa + 180.0) / 360.0), jb = std::floor((pb + 180.0) / 360.0);
    if (ja != jb && f.magnitude[k] > 0.0 && f.magnitude[k + 1] > 0.0) {
      const double target = -180.0 + 360.0 * std::max(ja, jb);
      const auto phase_offset = [&](double x) {
        return pa + wrapped(std::arg(G(x)) * kDegrees - pa) - target;
      };
      const double fa = pa - target, fb = pb - target;
      const double w = fa == 0.0 ? a : locate(phase_offset, a, b, fa, fb);
      m.phase_crossovers.push_back({w, 1.0 / std::abs(G(w))});
    }
  }
  for (const Crossing& c : m.phase_crossovers) {
    const double db = 20.0 * std::log10(c.margin);
    if (std::abs(db) < std::abs(m.gain_margin_db)) {
      m.gain_margin = c.margin;
      m.gain_margin_db = db;
      m.phase_crossover = c.frequency;
    }
  }
  for (const Crossing& c : m.gain_crossovers) {
    if (std::abs(c.margin) < std::abs(m.phase_margin_deg)) {
      m.phase_margin_deg = c.margin;
      m.gain_crossover = c.frequency;
    }
  }
  return m;
}

}  // namespace momenta::analysis
