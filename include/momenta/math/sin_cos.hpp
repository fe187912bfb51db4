#pragma once
// sin and cos of one angle together, inline, for the joint transforms of the dynamics hot paths
// (a revolute chain's CRBA spent a fifth of its time in the C library's sincos call).
//
// The method is fdlibm's (Sun Microsystems 1993; as in musl and FreeBSD): the angle is reduced to
// r = x − n π/2 with |r| ≤ π/4 by Cody–Waite subtraction of π/2 split into 33-bit pieces (exact
// to 151 bits, so the reduction is exact for |x| < 2²⁰ π/2), the remainder kept as a head and a
// tail, then sin r and cos r from fdlibm's minimax polynomials of degree 13 and 14. Results
// are within 1 ulp of the exact values (tests/unit/math/sin_cos_test.cpp holds them to 1 ulp of
// the C library's over 10⁶ angles and at the multiples of π/2). Angles beyond 2²⁰ π/2 (1.6e6
// rad), and non-finite ones, go to the C library.

#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

namespace momenta::math {

namespace detail {

// sin(x + y) for |x| ≤ π/4, y the tail of x (|y| ≤ ½ ulp(x)).
inline double kernel_sin(double x, double y) {
  constexpr double S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
                   S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
                   S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
  const double z = x * x, w = z * z;
  const double r = S2 + z * (S3 + z * S4) + z * w * (S5 + z * S6);
  const double v = z * x;
  return x - ((z * (0.5 * y - v * r) - y) - v * S1);
}

// cos(x + y) for |x| ≤ π/4.
inline double kernel_cos(double x, double y) {
  constexpr double C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
                   C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
                   C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;
  const double z = x * x, w = z * z;
  const double r = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
  const double hz = 0.5 * z;
  const double one_minus_hz = 1.0 - hz;
  return one_minus_hz + (((1.0 - one_minus_hz) - hz) + (z * r - x * y));
}

// The bits of a double and back, by memcpy (compiled to a move): std::bit_cast is missing from
// the libc++ of emscripten 3.1.6, which compiles the report's in-page engine (wasm/).
inline std::uint64_t bits_of(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}

inline double double_of(std::uint64_t bits) {
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

inline int exponent_of(double x) { return static_cast<int>((bits_of(x) >> 52) & 0x7ff); }

inline double with_sign_flipped_if(bool flip, double x) {
  return double_of(bits_of(x) ^ (static_cast<std::uint64_t>(flip) << 63));
}

}  // namespace detail

/// {sin x, cos x}, each within 1 ulp. Branch-free but for the rare cancellations of the
/// reduction: joint angles arrive in no predictable quadrant.
[[gnu::always_inline]] inline std::pair<double, double> sin_cos(double x) {
  constexpr double kLargest = 0x1.921fb54442d18p+20;  // 2²⁰ π/2
  if (!(std::abs(x) < kLargest)) [[unlikely]] {
    return {std::sin(x), std::cos(x)};
  }

  // n = nearest integer to x 2/π, r = x − n π/2 as head y0 and tail y1.
  constexpr double kTwoOverPi = 6.36619772367581382433e-01;
  constexpr double kPio2_1 = 1.57079632673412561417e+00, kPio2_1t = 6.07710050650619224932e-11;
  constexpr double kPio2_2 = 6.07710050630396597660e-11, kPio2_2t = 2.02226624879595063154e-21;
  constexpr double kPio2_3 = 2.02226624871116645580e-21, kPio2_3t = 8.47842766036889956997e-32;
  // Rounded to the nearest integer by adding and taking away 1.5·2⁵² (no libm call on a CPU
  // without SSE4.1's round instruction).
  constexpr double kToInteger = 6755399441055744.0;
  const double fn = (x * kTwoOverPi + kToInteger) - kToInteger;
  const int n = static_cast<int>(fn);
  double r = x - fn * kPio2_1;
  double w = fn * kPio2_1t;
  double y0 = r - w;
  const int ex = detail::exponent_of(x);
  if (ex - detail::exponent_of(y0) > 16) {  // cancellation: a second piece of π/2
    double t = r;
    w = fn * kPio2_2;
    r = t - w;
    w = fn * kPio2_2t - ((t - r) - w);
    y0 = r - w;
    if (ex - detail::exponent_of(y0) > 49) {  // and a third
      t = r;
      w = fn * kPio2_3;
      r = t - w;
      w = fn * kPio2_3t - ((t - r) - w);
      y0 = r - w;
    }
  }
  const double y1 = (r - y0) - w;
  const double s = detail::kernel_sin(y0, y1), c = detail::kernel_cos(y0, y1);
  // Quadrant n mod 4: (s, c), (c, −s), (−s, −c), (−c, s).
  const bool odd = (n & 1) != 0;
  const double sin_x = detail::with_sign_flipped_if((n & 2) != 0, odd ? c : s);
  const double cos_x = detail::with_sign_flipped_if(((n + 1) & 2) != 0, odd ? s : c);
  return {sin_x, cos_x};
}

}  // namespace momenta::math
