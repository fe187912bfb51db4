#pragma once
// Numbers as a person reads them, shared by the command line's text and the Python reprs: one
// rule for how a figure is shown, JSON keeping every bit elsewhere.

#include <complex>
#include <string>
#include <string_view>

namespace momenta {

/// The round-off bound, relative to the scale of the computation a figure comes from: a sum of
/// terms of size `scale` that cancels leaves a few ulps of it (1e-16), and the chains of such
/// sums momenta prints stay far below 1e-12 of it. Below that a figure is shown as 0.
inline constexpr double kRoundOffRelative = 1e-12;

/// x as text shows it: 0 where |x| ≤ kRoundOffRelative × scale (round-off of a computation of
/// that scale: the products of inertia of a symmetric part, the imaginary part of a real pole),
/// −0 as 0, x itself otherwise. JSON keeps x.
double shown_value(double x, double scale);

/// x with `digits` significant digits; 0: the shortest text that reads back to the same double;
/// "undefined" where x is not finite (a figure that does not exist, never "nan"); −0 as 0.
std::string number_text(double x, int digits);

/// number_text followed by `unit` (" s", " %"), or "undefined" alone where x is not finite: a
/// figure that does not exist has no unit.
std::string quantity_text(double x, int digits, std::string_view unit);

/// "−0.5 + 3.1j", parts with `digits` significant digits (0: the shortest that read back
/// exactly); a part that is round-off of |z| (shown_value) — a real pole's imaginary part — 0.
std::string complex_text(std::complex<double> z, int digits = 6);

}  // namespace momenta
