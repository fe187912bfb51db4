#pragma once
// Private: Jacobi elliptic functions and Legendre elliptic integrals of a parameter m given
// together with its complement mc = 1 − m, generic in the floating-point type (double for the
// hot paths, long double for the constants the free rigid body precomputes).
//
// Near m = 1 (the separatrix of the free rigid body) every quantity that depends on 1 − m is
// formed from mc itself, never from 1 − m: the AGM starts from b0 = √mc (Abramowitz & Stegun
// 16.4, 17.6) and Carlson's forms take Δ² = cos²φ + mc sin²φ instead of 1 − m sin²φ. A double mc
// of 1e-6 keeps its 16 digits that way, where sn, cn, dn computed from k = √m keep only ten.

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>

namespace momenta::rigid_body::detail {

// Boost's Carlson integrals, computed in the argument type itself (no promotion of double to
// long double, which would cost a factor of several in speed for digits we do not use).
using CarlsonPolicy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;

template <class Real>
Real carlson_rf(Real x, Real y, Real z) {
  return boost::math::ellint_rf(x, y, z, CarlsonPolicy());
}

template <class Real>
Real carlson_rj(Real x, Real y, Real z, Real p) {
  return boost::math::ellint_rj(x, y, z, p, CarlsonPolicy());
}

/// The arithmetic–geometric mean table of A&S 16.4 for parameter m: a0 = 1, b0 = √mc, c0 = √m;
/// a_{n+1} = (a_n + b_n)/2, b_{n+1} = √(a_n b_n), c_{n+1} = c_n²/(4 a_{n+1}) (the cancellation-free
/// form of (a_n − b_n)/2). am(u) follows by descending from φ_N = 2^N a_N u.
template <class Real>
struct AgmTable {
  static constexpr int kMaxSteps = 24;  // quadratic convergence: 12 steps reach mc = 1e-300
  int steps = 0;
  Real scale = 1;                            ///< 2^N a_N
  Real quarter_period = 0;                   ///< K(m) = π / (2 a_N)
  std::array<Real, kMaxSteps> ratio{};       ///< c_n / a_n for n = 1 .. N (index n − 1)
  std::array<Real, kMaxSteps> complement{};  ///< 1 − (c_n/a_n)² = (b_n/a_n)², no cancellation
};

/// Precondition: 0 <= m < 1, mc = 1 − m > 0 (checked by the callers).
template <class Real>
AgmTable<Real> make_agm_table(Real m, Real mc) {
  AgmTable<Real> table;
  Real a = 1, b = std::sqrt(mc), c = std::sqrt(m);
  const Real tiny = std::numeric_limits<Real>::epsilon() / 4;
  Real power = 1;
  while (c > tiny * a && table.steps < AgmTable<Real>::kMaxSteps) {
    const Real a_next = (a + b) / 2;
    const Real b_next = std::sqrt(a * b);
    c = c * c / (4 * a_next);
    a = a_next;
    b = b_next;
    power *= 2;
    table.ratio[table.steps] = c / a;
    table.complement[table.steps++] = (b / a) * (b / a);
  }
  table.scale = power * a;
  table.quarter_period = std::numbers::pi_v<Real> / (2 * a);
  return table;
}

/// One descending Landen step φ_{n−1} = (φ_n + asin(r sin φ_n))/2 with r = c_n/a_n. The arcsine
/// is taken as atan2(r s, √(c² + (1 − r²) s²)) with 1 − r² = (b_n/a_n)² from the table: near
/// m = 1 the first ratio is 1 − 2√mc and asin(x) near x = 1 would amplify the rounding of
/// r sin φ by 1/√(1 − x²).
template <class Real>
Real landen_descent_step(Real phi, Real ratio, Real complement) {
  const Real s = std::sin(phi), c = std::cos(phi);
  return (phi + std::atan2(ratio * s, std::sqrt(c * c + complement * s * s))) / 2;
}

/// The amplitude am(u|m) by descending Landen steps from φ_N = 2^N a_N u (A&S 16.4.3). Valid for
/// any real u; the absolute error is a few ulps of max(|u|, 1) (each step halves the error
/// carried down).
template <class Real>
Real jacobi_amplitude(const AgmTable<Real>& table, Real u) {
  Real phi = table.scale * u;
  for (int n = table.steps; n > 0; --n) {
    phi = landen_descent_step(phi, table.ratio[n - 1], table.complement[n - 1]);
  }
  return phi;
}

/// The descending Landen sequence for sn, cn, dn without transcendental functions per level
/// (DLMF 22.7.1–3): k_{i} = (1 − k'_{i−1})/(1 + k'_{i−1}), formed as k²_{i−1}/(1 + k'_{i−1})², and
/// k'_i = 2√k'_{i−1}/(1 + k'_{i−1}), until m_N = k_N² < 1e-8, where sn ≈ sin z − (m/4)(z − sin z
/// cos z) cos z to O(m²) (A&S 16.13). Then, level by level back up, with t = k_i sn²:
///   sn ← (1 + k_i) sn/(1 + t),  cn ← cn dn/(1 + t),  dn ← (1 − t)/(1 + t),
/// the last being DLMF 22.7.3 rewritten with dn² = 1 − k_i² sn² so that it has no cancellation.
template <class Real>
struct LandenTable {
  static constexpr int kMaxLevels = 24;
  int levels = 0;
  Real scale = 1;                    ///< z_N = scale · u, scale = 1/∏(1 + k_i)
  Real m_bottom = 0;                 ///< k_N²
  std::array<Real, kMaxLevels> k{};  ///< k_1 .. k_N (index i − 1)
};

template <class Real>
LandenTable<Real> make_landen_table(Real m, Real mc) {
  LandenTable<Real> table;
  Real k2 = m, kc = std::sqrt(mc);
  while (k2 >= Real(1e-8) && table.levels < LandenTable<Real>::kMaxLevels) {
    const Real k_next = k2 / ((1 + kc) * (1 + kc));
    kc = 2 * std::sqrt(kc) / (1 + kc);
    k2 = k_next * k_next;
    table.k[table.levels++] = k_next;
    table.scale /= 1 + k_next;
  }
  table.m_bottom = k2;
  return table;
}

/// sn, cn, dn at u (|u| <= K for the stated accuracy: absolute errors of a few ulps); dn is
/// returned as √(cn² + mc sn²) so that it keeps its relative precision where it is small.
template <class Real, class Table>
void jacobi_sn_cn_dn(const Table& table, Real mc, Real u, Real& sn, Real& cn, Real& dn) {
  const Real z = table.scale * u;
  const Real s = std::sin(z), c = std::cos(z);
  const Real correction = table.m_bottom / 4 * (z - s * c);
  sn = s - correction * c;
  cn = c + correction * s;
  dn = 1 - table.m_bottom / 2 * s * s;
  for (int i = table.levels; i > 0; --i) {
    const Real k = table.k[i - 1];
    const Real t = k * sn * sn;
    const Real inverse = 1 / (1 + t);
    sn = (1 + k) * sn * inverse;
    cn = cn * dn * inverse;
    dn = (1 - t) * inverse;
  }
  dn = std::sqrt(cn * cn + mc * sn * sn);
}

/// Δ(φ)² = 1 − m sin²φ, formed as cos²φ + mc sin²φ so that it keeps its digits near m = 1.
template <class Real>
Real delta_squared(Real s, Real c, Real mc) {
  return c * c + mc * s * s;
}

/// F(φ|m) for |φ| <= π/2 (Carlson: F = s R_F(c², Δ², 1)).
template <class Real>
Real elliptic_f_reduced(Real phi, Real mc) {
  const Real s = std::sin(phi), c = std::cos(phi);
  if (s == 0) return phi;
  return s * carlson_rf(c * c, delta_squared(s, c, mc), Real(1));
}

/// Π(n; φ|m) = ∫₀^φ dθ / ((1 − n sin²θ) Δ(θ)) for |φ| <= π/2 and n < 1, from s = sin φ and
/// c = cos φ >= 0 (Carlson: s R_F(c², Δ², 1) + (n/3) s³ R_J(c², Δ², 1, 1 − n s²)). Taking s and
/// c rather than φ lets a caller that knows them to full relative precision keep it (near
/// φ = π/2, cos φ from a rounded φ would not). `one_minus_n` is 1 − n given separately, so that
/// for n close to 1 the last argument, formed as c² + (1 − n) s², keeps its digits.
template <class Real>
Real elliptic_pi_sc(Real n, Real one_minus_n, Real s, Real c, Real mc) {
  if (s == 0) return 0;
  const Real c2 = c * c, d2 = delta_squared(s, c, mc), s2 = s * s;
  Real value = s * carlson_rf(c2, d2, Real(1));
  if (n != 0) value += n / 3 * s * s2 * carlson_rj(c2, d2, Real(1), c2 + one_minus_n * s2);
  return value;
}

/// G(n; φ|m) = (Π(n; φ|m) − F(φ|m)) / n = ∫₀^φ sin²θ dθ / ((1 − n sin²θ) Δ(θ))
///           = (s³/3) R_J(c², Δ², 1, 1 − n s²)   for |φ| <= π/2, from s = sin φ, c = cos φ >= 0.
/// The part of Π beyond F, without the cancellation of forming Π − F when n is small.
template <class Real>
Real elliptic_g_sc(Real one_minus_n, Real s, Real c, Real mc) {
  if (s == 0) return 0;
  const Real c2 = c * c, s2 = s * s;
  return s * s2 / 3 * carlson_rj(c2, delta_squared(s, c, mc), Real(1), c2 + one_minus_n * s2);
}

/// Complete G(n|m) = (Π(n|m) − K(m)) / n = R_J(0, mc, 1, 1 − n) / 3.
template <class Real>
Real elliptic_g_complete(Real one_minus_n, Real mc) {
  return carlson_rj(Real(0), mc, Real(1), one_minus_n) / 3;
}

template <class Real>
Real elliptic_pi_reduced(Real n, Real one_minus_n, Real phi, Real mc) {
  if (std::sin(phi) == 0) return phi;
  return elliptic_pi_sc(n, one_minus_n, std::sin(phi), std::cos(phi), mc);
}

template <class Real>
Real elliptic_pi_reduced(Real n, Real phi, Real mc) {
  return elliptic_pi_reduced(n, 1 - n, phi, mc);
}

/// Complete Π(n|m) = Π(n; π/2|m) = R_F(0, mc, 1) + (n/3) R_J(0, mc, 1, 1 − n).
template <class Real>
Real elliptic_pi_complete(Real n, Real mc) {
  Real value = carlson_rf(Real(0), mc, Real(1));
  if (n != 0) value += n / 3 * carlson_rj(Real(0), mc, Real(1), 1 - n);
  return value;
}

/// Splits φ = φ_r + jπ with |φ_r| <= π/2.
template <class Real>
Real reduce_amplitude(Real phi, Real& j) {
  j = std::nearbyint(phi / std::numbers::pi_v<Real>);
  return phi - j * std::numbers::pi_v<Real>;
}

/// F(φ|m) for any real φ: F(φ_r + jπ) = F(φ_r) + 2jK.
template <class Real>
Real elliptic_f(Real phi, Real mc, Real quarter_period) {
  Real j;
  const Real phi_r = reduce_amplitude(phi, j);
  return elliptic_f_reduced(phi_r, mc) + 2 * j * quarter_period;
}

/// Π(n; φ|m) for any real φ: Π(φ_r + jπ) = Π(φ_r) + 2jΠ(n|m).
template <class Real>
Real elliptic_pi(Real n, Real phi, Real mc, Real complete_pi) {
  Real j;
  const Real phi_r = reduce_amplitude(phi, j);
  return elliptic_pi_reduced(n, phi_r, mc) + 2 * j * complete_pi;
}

}  // namespace momenta::rigid_body::detail
