#include "momenta/inertia/amount.hpp"

#include <cmath>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::inertia {

double Amount::mass_for(double measure, std::string_view what) const {
  if (kind_ == Kind::kMass) {
    if (!std::isfinite(value_) || !(value_ > 0.0)) {
      throw InvalidArgument(fmt::format("{}: mass {} kg is not positive and finite", what, value_));
    }
    return value_;
  }
  if (!std::isfinite(value_) || !(value_ > 0.0)) {
    throw InvalidArgument(fmt::format("{}: density {} is not positive and finite", what, value_));
  }
  if (!std::isfinite(measure) || !(measure > 0.0)) {
    throw InvalidArgument(fmt::format(
        "{}: its volume, area or length {} is not positive, so a density gives it no mass", what,
        measure));
  }
  return value_ * measure;
}

}  // namespace momenta::inertia
