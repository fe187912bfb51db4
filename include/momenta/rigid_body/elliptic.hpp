#pragma once
// Jacobi elliptic functions and Legendre elliptic integrals of a parameter m (m = k², the square
// of the modulus) given together with its complement mc = 1 − m.
//
// Why the complement: near m = 1 (the separatrix of a free rigid body, where 1 − m ≈ 1e-6 is
// common) sn, cn, dn and K computed from k = √m lose six digits, because 1 − m itself is only
// known to 1e-16 / 1e-6 relatively. Every formula here forms 1 − m from mc: the AGM starts from
// b0 = √mc (Abramowitz & Stegun 16.4 and 17.6), dn = √(cn² + mc sn²), and Carlson's symmetric
// forms take Δ² = cos²φ + mc sin²φ (Carlson 1995; DLMF 19.25). A caller that can form mc without
// cancellation (from invariants, as the free rigid body does) gets full precision up to m = 1.

#include <limits>

namespace momenta::rigid_body {

/// sn, cn, dn and the amplitude am (sn = sin am, cn = cos am) at one argument.
struct JacobiValues {
  double sn = std::numeric_limits<double>::quiet_NaN();
  double cn = std::numeric_limits<double>::quiet_NaN();
  double dn = std::numeric_limits<double>::quiet_NaN();
  double am = std::numeric_limits<double>::quiet_NaN();
};

/// A parameter m with its complement, and the AGM table that Jacobi's functions of it need
/// (computed once, so repeated evaluation costs only the descending Landen steps).
class EllipticParameter {
 public:
  /// `m` in [0, 1] and `complement` = 1 − m in [0, 1], both given so that the caller keeps the
  /// digits of whichever is small; they must agree to 4 ulps (|m + complement − 1| <= 4.5e-16).
  /// m = 1 (complement 0) is the separatrix limit: sn = tanh, cn = dn = sech, K = ∞.
  /// Throws InvalidArgument otherwise, showing both numbers.
  EllipticParameter(double m, double complement);

  double m() const { return m_; }
  double complement() const { return mc_; }
  /// K(m), the quarter period of sn and cn (+∞ at m = 1).
  double quarter_period() const { return quarter_period_; }

  /// sn(u|m), cn(u|m), dn(u|m) and am(u|m) for any real u. Absolute error a few ulps of
  /// max(1, |u|) for m < 1 (the argument is reduced by the period 4K first).
  JacobiValues jacobi(double u) const;

  /// Incomplete integral of the first kind F(φ|m) = ∫₀^φ dθ / √(1 − m sin²θ), any real φ
  /// (|φ| < π/2 at m = 1, where it is atanh(sin φ)). Throws InvalidArgument outside.
  double first_kind(double phi) const;

  /// Incomplete integral of the third kind Π(n; φ|m) = ∫₀^φ dθ / ((1 − n sin²θ) √(1 − m sin²θ))
  /// for n < 1 (the characteristic with the A&S sign: 1 − n sin²θ), any real φ (|φ| < π/2 at
  /// m = 1). Throws InvalidArgument for n >= 1 or φ outside.
  double third_kind(double n, double phi) const;

  /// Complete Π(n|m) = Π(n; π/2|m), n < 1 (+∞ at m = 1).
  double complete_third_kind(double n) const;

 private:
  double m_, mc_, quarter_period_;
  int steps_ = 0;
  double scale_ = 1.0;
  double ratio_[24] = {};
  double ratio_complement_[24] = {};
};

}  // namespace momenta::rigid_body
