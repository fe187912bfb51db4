#include "momenta/rigid_body/elliptic.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "elliptic_impl.hpp"
#include "momenta/common/error.hpp"

namespace momenta::rigid_body {

namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

EllipticParameter::EllipticParameter(double m, double complement) : m_(m), mc_(complement) {
  const bool in_range = m >= 0.0 && m <= 1.0 && complement >= 0.0 && complement <= 1.0;
  if (!in_range || std::abs((m - 1.0) + complement) > 4.5e-16) {
    throw InvalidArgument(
        fmt::format("elliptic parameter m = {:.17g} with complement {:.17g}: need 0 <= m <= 1 "
                    "and complement = 1 − m (to 4 ulps)",
                    m, complement));
  }
  if (complement == 0.0) {
    quarter_period_ = std::numeric_limits<double>::infinity();
    return;
  }
  // The table is built in long double and rounded once, so K and the ratios carry no AGM
  // round-off of their own.
  const auto table = detail::make_agm_table<long double>(m, complement);
  steps_ = table.steps;
  scale_ = static_cast<double>(table.scale);
  for (int i = 0; i < steps_; ++i) {
    ratio_[i] = static_cast<double>(table.ratio[i]);
    ratio_complement_[i] = static_cast<double>(table.complement[i]);
  }
  quarter_period_ = static_cast<double>(table.quarter_period);
}

JacobiValues EllipticParameter::jacobi(double u) const {
  JacobiValues v;
  if (mc_ == 0.0) {
    // Separatrix: sn = tanh u, cn = dn = sech u, am = gd(u).
    v.sn = std::tanh(u);
    v.cn = v.dn = 1.0 / std::cosh(u);
    v.am = std::atan(std::sinh(u));
    return v;
  }
  // Reduce u = u_r + 2jK, |u_r| <= K: am(u) = am(u_r) + jπ, sn and cn change sign with j.
  const double j = std::nearbyint(u / (2.0 * quarter_period_));
  const double u_r = u - 2.0 * j * quarter_period_;
  double phi = scale_ * u_r;
  for (int n = steps_; n > 0; --n) {
    phi = detail::landen_descent_step(phi, ratio_[n - 1], ratio_complement_[n - 1]);
  }
  const double sign = std::fmod(j, 2.0) == 0.0 ? 1.0 : -1.0;
  v.sn = sign * std::sin(phi);
  v.cn = sign * std::cos(phi);
  v.dn = std::sqrt(v.cn * v.cn + mc_ * v.sn * v.sn);
  v.am = phi + j * kPi;
  return v;
}

double EllipticParameter::first_kind(double phi) const {
  if (mc_ == 0.0) {
    if (!(std::abs(phi) < 0.5 * kPi)) {
      throw InvalidArgument(
          fmt::format("F(φ|1) = atanh(sin φ) is infinite for |φ| >= π/2; got φ = {:.17g}", phi));
    }
    return std::atanh(std::sin(phi));
  }
  return detail::elliptic_f<double>(phi, mc_, quarter_period_);
}

double EllipticParameter::third_kind(double n, double phi) const {
  if (!(n < 1.0)) {
    throw InvalidArgument(fmt::format("Π(n; φ|m) needs n < 1; got n = {:.17g}", n));
  }
  if (mc_ == 0.0) {
    // m = 1: with u = atanh(sin φ), Π = ∫₀^u dv / (1 − n tanh²v) in closed form.
    const double u = first_kind(phi);
    const double t = std::sin(phi);
    if (n < 0.0) return (u + std::sqrt(-n) * std::atan(std::sqrt(-n) * t)) / (1.0 - n);
    if (n > 0.0) return (u - std::sqrt(n) * std::atanh(std::sqrt(n) * t)) / (1.0 - n);
    return u;
  }
  return detail::elliptic_pi<double>(n, phi, mc_, complete_third_kind(n));
}

double EllipticParameter::complete_third_kind(double n) const {
  if (!(n < 1.0)) {
    throw InvalidArgument(fmt::format("Π(n|m) needs n < 1; got n = {:.17g}", n));
  }
  if (mc_ == 0.0) return std::numeric_limits<double>::infinity();
  return static_cast<double>(detail::elliptic_pi_complete<long double>(n, mc_));
}

}  // namespace momenta::rigid_body
