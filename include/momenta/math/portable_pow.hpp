#pragma once
// x^y for x ≥ 0 from the four basic operations and exact scalings alone, so that it gives the
// same bits on every platform: the C libraries' pow differ in their last bit (glibc's against
// musl's, the one the report's in-page engine (wasm/) links), and a step-size controller fed
// either chooses steps that part after the first such bit — the same model then yields rows at
// other times in the page than on the command line. With this, an adaptive run whose model
// calls no other transcendental function is the same run, bit for bit, in both builds
// (tests/wasm).
//
// Method: log x = e ln 2 + 2 atanh(s), x = m 2^e with m in [√½, √2), s = (m − 1)/(m + 1), the
// atanh series to s²¹; then exp t = 2^k exp r, r = t − k ln 2 (ln 2 in two parts), by Taylor's
// series to r¹⁴. Relative error below 1e-15 (1 + |y log x|) (tests/unit/math/portable_pow_test
// against std::pow): meant for step-size factors and the like, not for correctly rounded
// results. No fused multiply–add is formed: the native build compiles for x86-64 without FMA,
// and WebAssembly has none.

#include <cmath>
#include <limits>

namespace momenta::math {

namespace detail {

inline double portable_log(double x) {
  int e = 0;
  double m = std::frexp(x, &e);  // x = m 2^e, m in [½, 1)
  if (m < 0.70710678118654752440) {
    m *= 2.0;
    --e;
  }
  const double s = (m - 1.0) / (m + 1.0);  // |s| ≤ 0.1716
  const double z = s * s;
  // 2 atanh s = 2 s (1 + z/3 + z²/5 + … + z¹⁰/21): the next term is below 1e-17 of the sum.
  double series = 1.0 / 21.0;
  for (int k = 19; k >= 1; k -= 2) series = 1.0 / k + z * series;
  constexpr double kLn2 = 0.69314718055994530942;
  return e * kLn2 + 2.0 * s * series;
}

inline double portable_exp(double t) {
  if (t > 709.78) return std::numeric_limits<double>::infinity();
  if (t < -745.2) return 0.0;
  constexpr double kLn2High = 0x1.62e42fee00000p-1;  // ln 2 to 32 bits: k ln2High is exact
  constexpr double kLn2Low = 0x1.a39ef35793c76p-33;  // the rest
  constexpr double kInvLn2 = 1.44269504088896340736;
  const double k = std::nearbyint(t * kInvLn2);
  const double r = (t - k * kLn2High) - k * kLn2Low;  // |r| ≤ ½ ln 2 (and a little)
  // exp r = Σ rⁿ/n! to n = 14: r¹⁵/15! < 4e-18 of it.
  double sum = 1.0;
  for (int n = 14; n >= 1; --n) sum = 1.0 + r / n * sum;
  return std::ldexp(sum, static_cast<int>(k));
}

}  // namespace detail

/// x^y for x ≥ 0 and finite y, the same bits on every platform; at x = 0 and x = ∞ what
/// std::pow gives (0 or ∞ by the sign of y, 1 for y = 0); NaN for x < 0 or a NaN argument.
inline double portable_pow(double x, double y) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  if (std::isnan(x) || std::isnan(y) || x < 0.0) return std::numeric_limits<double>::quiet_NaN();
  if (y == 0.0) return 1.0;
  if (x == 0.0) return y > 0.0 ? 0.0 : kInfinity;
  if (x == kInfinity) return y > 0.0 ? kInfinity : 0.0;
  return detail::portable_exp(y * detail::portable_log(x));
}

}  // namespace momenta::math
