#pragma once
// Numbers as a person reads them, shared by the command line's text and the Python reprs: one
// rule for how a figure is shown, JSON keeping every bit elsewhere.

#include <complex>
#include <string>
#include <string_view>

namespace momenta {

/// x with `digits` significant digits; 0: the shortest text that reads back to the same double;
/// "undefined" where x is not finite (a figure that does not exist, never "nan"); −0 as 0.
std::string number_text(double x, int digits);

/// number_text followed by `unit` (" s", " %"), or "undefined" alone where x is not finite: a
/// figure that does not exist has no unit.
std::string quantity_text(double x, int digits, std::string_view unit);

/// "−0.5 + 3.1j", parts with `digits` significant digits (0: the shortest that read back
/// exactly); a part below 1e-12 of |z| — round-off, a real pole's imaginary part — shown as 0.
std::string complex_text(std::complex<double> z, int digits = 6);

}  // namespace momenta
