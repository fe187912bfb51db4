#include "momenta/rigid_body/elliptic.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "momenta/common/error.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::rigid_body {
namespace {

// The reference: Boost.Math's own algorithms (modulus k = √m, Landen/Carlson) run in 50 decimal
// digits. m and 1 − m are exact binary numbers here, so 50 digits leave 40 after the worst loss
// near m = 1 — far below double round-off.
using Big = boost::multiprecision::cpp_bin_float_50;

struct BigJacobi {
  double sn, cn, dn;
};

BigJacobi reference_jacobi(double u, double m) {
  Big cn, dn;
  const Big k = boost::multiprecision::sqrt(Big(m));
  const Big sn = boost::math::jacobi_elliptic(k, Big(u), &cn, &dn);
  return {static_cast<double>(sn), static_cast<double>(cn), static_cast<double>(dn)};
}

double reference_k(double m) {
  return static_cast<double>(boost::math::ellint_1(boost::multiprecision::sqrt(Big(m))));
}

// The parameters tested: ordinary, and near the separatrix 1 − m ≈ 1e-6 and 1e-12, where double
// functions of k = √m lose 6 and 12 digits. Powers of two, so that m = 1 − mc is exact and the
// reference (which sees only m) solves the same problem.
const double kComplements[] = {1.0, 0.75, 0.125, 0x1p-10, 0x1p-20, 0x1p-40};

TEST(EllipticParameter, JacobiFunctionsMatchFiftyDigitReference) {
  for (const double mc : kComplements) {
    const double m = 1.0 - mc;  // exact: mc is a power-of-two multiple representable beside 1
    const EllipticParameter p(m, mc);
    const double K = p.quarter_period();
    for (int i = -40; i <= 40; ++i) {
      const double u = 3.1 * K * i / 40.0;
      const JacobiValues v = p.jacobi(u);
      const BigJacobi r = reference_jacobi(u, m);
      // Absolute error: the reduction u − 2jK and the Landen descent each add an ulp of
      // max(|u|, 1); 8 ulps of that bounds them (observed: ≤ 3).
      const double tol = 8 * test::kEps * std::max(1.0, std::abs(u));
      EXPECT_NEAR(v.sn, r.sn, tol) << "mc " << mc << " u " << u;
      EXPECT_NEAR(v.cn, r.cn, tol) << "mc " << mc << " u " << u;
      EXPECT_NEAR(v.dn, r.dn, tol) << "mc " << mc << " u " << u;
      EXPECT_NEAR(std::sin(v.am), v.sn, 4 * test::kEps);
    }
  }
}

TEST(EllipticParameter, DnKeepsItsDigitsNearTheSeparatrix) {
  // At u = K, dn = √mc exactly. From k = √m it would be √(1 − m sn²) with 1 − m sn² ≈ 1e-12
  // carrying an absolute error of 1e-16, i.e. dn wrong in the 5th digit; here it keeps ~15.
  for (const double mc : {0x1p-20, 0x1p-40}) {
    const EllipticParameter p(1.0 - mc, mc);
    const JacobiValues v = p.jacobi(p.quarter_period());
    EXPECT_REL_NEAR(v.dn, std::sqrt(mc), 1e-13);
    EXPECT_NEAR(v.cn, 0.0, 8 * test::kEps * p.quarter_period());
    EXPECT_NEAR(v.sn, 1.0, 4 * test::kEps);
  }
}

TEST(EllipticParameter, QuarterPeriodMatchesReference) {
  for (const double mc : kComplements) {
    const EllipticParameter p(1.0 - mc, mc);
    EXPECT_REL_NEAR(p.quarter_period(), reference_k(1.0 - mc), 4 * test::kEps) << mc;
  }
  EXPECT_DOUBLE_EQ(EllipticParameter(0.0, 1.0).quarter_period(), std::numbers::pi / 2);
}

TEST(EllipticParameter, IntegralsMatchReference) {
  for (const double mc : kComplements) {
    const double m = 1.0 - mc;
    const EllipticParameter p(m, mc);
    const Big k = boost::multiprecision::sqrt(Big(m));
    for (const double phi : {0.3, 1.2, 1.5, 1.5707, 2.9, -4.0}) {
      // Beyond π/2 the reference uses the same quasi-periodicity F(φ + jπ) = F(φ) + 2jK that is
      // being tested, but on Boost's own values.
      const double j = std::nearbyint(phi / std::numbers::pi);
      const Big phi_r = Big(phi) - j * boost::math::constants::pi<Big>();
      const Big f = boost::math::ellint_1(k, phi_r) + 2 * j * boost::math::ellint_1(k);
      // Relative 8 ulps, and an absolute 8 ulps of φ/Δ(φ) for the amplitude's own rounding.
      const double delta = std::sqrt(std::pow(std::cos(phi), 2) + mc * std::pow(std::sin(phi), 2));
      const double slack = 8 * test::kEps * std::abs(phi) / delta;
      EXPECT_NEAR(p.first_kind(phi), static_cast<double>(f),
                  8 * test::kEps * std::abs(static_cast<double>(f)) + slack)
          << "mc " << mc << " phi " << phi;
      for (const double n : {-3.0, -0.4, 0.5}) {
        const Big pi =
            boost::math::ellint_3(k, Big(n), phi_r) + 2 * j * boost::math::ellint_3(k, Big(n));
        EXPECT_NEAR(p.third_kind(n, phi), static_cast<double>(pi),
                    8 * test::kEps * std::abs(static_cast<double>(pi)) + slack / (1.0 - n))
            << "mc " << mc << " n " << n << " phi " << phi;
      }
    }
  }
}

TEST(EllipticParameter, SeparatrixLimitIsHyperbolic) {
  const EllipticParameter p(1.0, 0.0);
  EXPECT_TRUE(std::isinf(p.quarter_period()));
  for (const double u : {-3.0, 0.2, 1.7, 30.0}) {
    const JacobiValues v = p.jacobi(u);
    EXPECT_DOUBLE_EQ(v.sn, std::tanh(u));
    EXPECT_DOUBLE_EQ(v.cn, 1.0 / std::cosh(u));
    EXPECT_DOUBLE_EQ(v.dn, v.cn);
  }
  // Π(n; φ|1) in closed form against Boost at k = 1 (50 digits), both signs of n.
  for (const double phi : {0.4, 1.3, -1.5}) {
    EXPECT_NEAR(p.first_kind(phi), std::atanh(std::sin(phi)), 4 * test::kEps);
    for (const double n : {-3.0, -0.5, 0.6}) {
      const Big pi = boost::math::ellint_3(Big(1), Big(n), Big(phi));
      EXPECT_NEAR(p.third_kind(n, phi), static_cast<double>(pi),
                  8 * test::kEps * std::abs(static_cast<double>(pi)))
          << "n " << n << " phi " << phi;
    }
  }
}

TEST(EllipticParameter, RejectsInconsistentArguments) {
  EXPECT_THROW(EllipticParameter(0.5, 0.4), InvalidArgument);
  EXPECT_THROW(EllipticParameter(1.2, -0.2), InvalidArgument);
  EXPECT_THROW(EllipticParameter(std::nan(""), 1.0), InvalidArgument);
  const EllipticParameter p(0.5, 0.5);
  EXPECT_THROW(p.third_kind(1.0, 0.3), InvalidArgument);
  EXPECT_THROW(EllipticParameter(1.0, 0.0).first_kind(2.0), InvalidArgument);
}

}  // namespace
}  // namespace momenta::rigid_body
