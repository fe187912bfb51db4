#include "momenta/common/number_text.hpp"

#include <cmath>

#include <fmt/format.h>

namespace momenta {

double shown_value(double x, double scale) {
  return std::abs(x) <= kRoundOffRelative * std::abs(scale) ? 0.0 : x + 0.0;
}

std::string number_text(double x, int digits) {
  if (!std::isfinite(x)) return "undefined";
  if (digits <= 0) return fmt::format("{}", x + 0.0);  // the shortest text that reads back to x
  return fmt::format("{:.{}g}", x + 0.0, digits);
}

std::string quantity_text(double x, int digits, std::string_view unit) {
  if (!std::isfinite(x)) return "undefined";
  return number_text(x, digits) + std::string(unit);
}

std::string complex_text(std::complex<double> z, int digits) {
  const double scale = std::abs(z);
  z = {shown_value(z.real(), scale), shown_value(z.imag(), scale)};
  if (z.imag() == 0.0) return number_text(z.real(), digits);
  return fmt::format("{} {} {}j", number_text(z.real(), digits), z.imag() < 0 ? "−" : "+",
                     number_text(std::abs(z.imag()), digits));
}

}  // namespace momenta
