#pragma once
// Where a function of time on a step's dense output reaches zero: the one root finder the run's
// events (event_monitor.cpp) and its stops and contacts (unilaterals.cpp) locate instants with.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <boost/math/tools/toms748_solve.hpp>

namespace momenta::simulate::detail {

/// The first time in [a, b] where f ≤ 0, given f(a) = fa ≥ 0 > fb = f(b): Alefeld–Potra–Shi's
/// TOMS 748 to a bracket of 1e-14 relative in time, and the bracket's end where f ≤ 0 (a itself
/// where fa = 0, or where the step has no length: b = a).
template <class F>
double crossing_time(F&& f, double a, double b, double fa, double fb) {
  if (fa == 0.0 || !(b > a)) return a;  // a step of no length (an instant acted on twice)
  const auto close_enough = [](double x, double y) {
    return std::abs(y - x) <= 1e-14 * std::max(std::abs(x), std::abs(y));
  };
  std::uintmax_t iterations = 200;
  const auto [lo, hi] =
      boost::math::tools::toms748_solve(f, a, b, fa, fb, close_enough, iterations);
  return f(hi) <= 0.0 ? hi : lo;
}

}  // namespace momenta::simulate::detail
