#pragma once
// Internal to momenta::dynamics: a dual number x + ẋ ε (ε² = 0), the scalar of forward-mode
// differentiation along one direction, usable as an Eigen scalar. The constraint rows
// (constraint_row_formulas.hpp) are written once for double and Dual; evaluated on Dual inputs
// whose ε parts are the inputs' derivatives along a direction, they return their own
// derivatives along it, exactly (constraint_derivatives.cpp).

#include <cmath>

#include <Eigen/Core>

namespace momenta::dynamics::detail {

struct Dual {
  double value = 0.0;
  double slope = 0.0;  // the derivative along the direction

  Dual() = default;
  Dual(double v) : value(v) {}  // NOLINT(google-explicit-constructor): a constant
  Dual(double v, double s) : value(v), slope(s) {}

  Dual& operator+=(const Dual& b) { return *this = {value + b.value, slope + b.slope}; }
  Dual& operator-=(const Dual& b) { return *this = {value - b.value, slope - b.slope}; }
  Dual& operator*=(const Dual& b) {
    return *this = {value * b.value, slope * b.value + value * b.slope};
  }
  Dual& operator/=(const Dual& b) {
    return *this = {value / b.value, (slope * b.value - value * b.slope) / (b.value * b.value)};
  }
};

inline Dual operator+(Dual a, const Dual& b) { return a += b; }
inline Dual operator-(Dual a, const Dual& b) { return a -= b; }
inline Dual operator*(Dual a, const Dual& b) { return a *= b; }
inline Dual operator/(Dual a, const Dual& b) { return a /= b; }
inline Dual operator-(const Dual& a) { return {-a.value, -a.slope}; }
inline Dual operator+(const Dual& a) { return a; }
inline bool operator==(const Dual& a, const Dual& b) {
  return a.value == b.value && a.slope == b.slope;
}
inline bool operator!=(const Dual& a, const Dual& b) { return !(a == b); }

// √x: the slope ẋ / 2√x (x > 0: the rows take the norms of non-degenerate vectors only).
inline Dual sqrt(const Dual& x) {
  const double root = std::sqrt(x.value);
  return {root, x.slope / (2.0 * root)};
}

// The value, for the rows' degeneracy tests and messages.
inline double value_of(double x) { return x; }
inline double value_of(const Dual& x) { return x.value; }

}  // namespace momenta::dynamics::detail

template <>
struct Eigen::NumTraits<momenta::dynamics::detail::Dual> : Eigen::NumTraits<double> {
  using Real = momenta::dynamics::detail::Dual;
  using NonInteger = momenta::dynamics::detail::Dual;
  using Nested = momenta::dynamics::detail::Dual;
  using Literal = double;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 2,
    AddCost = 2,
    MulCost = 3
  };
};

// A double times a Dual (a constant times a vector of duals) is a Dual.
template <typename BinaryOp>
struct Eigen::ScalarBinaryOpTraits<momenta::dynamics::detail::Dual, double, BinaryOp> {
  using ReturnType = momenta::dynamics::detail::Dual;
};
template <typename BinaryOp>
struct Eigen::ScalarBinaryOpTraits<double, momenta::dynamics::detail::Dual, BinaryOp> {
  using ReturnType = momenta::dynamics::detail::Dual;
};
