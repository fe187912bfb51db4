#pragma once
// How much material a body has: its total mass, or a density from which the mass follows.

#include <string_view>

namespace momenta::inertia {

/// A total mass (kg) or a density. The density's unit follows the body's dimension: kg/m³ for
/// solids, kg/m² for thin plates and shells, kg/m for slender rods and rings.
class Amount {
 public:
  static Amount mass(double kg) { return Amount(Kind::kMass, kg); }
  static Amount density(double value) { return Amount(Kind::kDensity, value); }

  bool is_mass() const { return kind_ == Kind::kMass; }
  double value() const { return value_; }

  /// The mass of a body of the given measure (volume, area or length). Throws InvalidArgument,
  /// naming `what`, if the mass or density is not positive and finite, or the measure not positive.
  double mass_for(double measure, std::string_view what) const;

 private:
  enum class Kind { kMass, kDensity };
  Amount(Kind kind, double value) : kind_(kind), value_(value) {}
  Kind kind_;
  double value_;
};

}  // namespace momenta::inertia
