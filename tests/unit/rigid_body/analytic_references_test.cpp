#include "momenta/rigid_body/analytic_references.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::rigid_body {
namespace {

const SymmetricTop kTop{1e-3, 2e-4, 0.5, 0.04, 9.81};

TEST(AnalyticReferences, SteadyPrecessionRootsSolveTheQuadratic) {
  for (const double theta : {0.3, 1.2, 2.5}) {
    for (const double spin : {150.0, -150.0}) {
      const SteadyPrecession p = steady_precession(kTop, theta, spin);
      const double a = kTop.transverse_moment * std::cos(theta), b = -kTop.axial_moment * spin,
                   c = kTop.mass * kTop.gravity * kTop.com_distance;
      for (const double x : {p.slow, p.fast}) {
        // Residual relative to the largest term: a few ulps (no cancellation in the roots).
        const double scale = std::max({std::abs(a * x * x), std::abs(b * x), std::abs(c)});
        EXPECT_NEAR(a * x * x + b * x + c, 0.0, 8 * test::kEps * scale) << theta << " " << spin;
      }
      EXPECT_LE(std::abs(p.slow), std::abs(p.fast));
    }
  }
  // Horizontal axle (θ the double nearest π/2, cos θ = 6.1e-17, no special case): the slow
  // root is m g l/(I3 ω3) (1 + ε + …) with ε = I1 m g l cos θ/(I3 ω3)² ~ 1e-18, so equal to it
  // to an ulp; the fast root is I3 ω3/(I1 cos θ) − slow, ~1e17 rad/s.
  const double spin = 150.0, cos_half_pi = std::cos(std::numbers::pi / 2);
  ASSERT_GT(cos_half_pi, 0.0);
  const SteadyPrecession h = steady_precession(kTop, std::numbers::pi / 2, spin);
  const double gyroscopic =
      kTop.mass * kTop.gravity * kTop.com_distance / (kTop.axial_moment * spin);
  EXPECT_REL_NEAR(h.slow, gyroscopic, test::kEps);
  EXPECT_REL_NEAR(h.fast, kTop.axial_moment * spin / (kTop.transverse_moment * cos_half_pi),
                  4 * test::kEps);
  // Just past π/2 (cos θ ≈ −1e-9) the fast root changes sign; the slow one keeps its first
  // correction, 1 + ε (ε² ~ 1e-20 below round-off).
  const double theta = std::numbers::pi / 2 + 1e-9;
  const double H3 = kTop.axial_moment * spin;
  const double epsilon = kTop.transverse_moment * kTop.mass * kTop.gravity * kTop.com_distance *
                         std::cos(theta) / (H3 * H3);
  const SteadyPrecession past = steady_precession(kTop, theta, spin);
  EXPECT_REL_NEAR(past.slow, gyroscopic * (1 + epsilon), 2 * test::kEps);
  EXPECT_LT(past.fast, 0.0);
  // Too slow a spin for the angle: no steady precession.
  EXPECT_THROW(steady_precession(kTop, 0.3, 10.0), InvalidArgument);
  EXPECT_THROW(steady_precession(kTop, 0.0, 150.0), InvalidArgument);
}

TEST(AnalyticReferences, RelativeSpinIsTheSameSteadyMotion) {
  // With ψ̇ given, ω3 = ψ̇ + φ̇ cos θ must make φ̇ a root of the ω3 form.
  const double theta = 0.8, psi_dot = 120.0;
  const SteadyPrecession p = steady_precession_for_relative_spin(kTop, theta, psi_dot);
  for (const double x : {p.slow, p.fast}) {
    const SteadyPrecession q = steady_precession(kTop, theta, psi_dot + x * std::cos(theta));
    EXPECT_TRUE(test::relatively_near(
        x, std::abs(q.slow - x) < std::abs(q.fast - x) ? q.slow : q.fast, 1e-12));
  }
}

TEST(AnalyticReferences, NutationBoundsOfASteadyPrecessionCollapse) {
  // At a steady root the two turning points merge at θ0; the cubic's double root is found to
  // √ε (≈ 1e-8 rad).
  const double theta = 0.6, spin = 150.0;
  const SteadyPrecession p = steady_precession(kTop, theta, spin);
  const NutationBounds b = nutation_bounds(kTop, theta, 0.0, p.slow, spin);
  EXPECT_NEAR(b.theta_min, theta, 1e-7);
  EXPECT_NEAR(b.theta_max, theta, 1e-7);
  EXPECT_THROW(nutation_bounds(kTop, 4.0, 0, 0, 1), InvalidArgument);
}

TEST(AnalyticReferences, AxisymmetricPrecessionGeometry) {
  // A sphere does not precess in the body; ω, H and the axis coincide in direction.
  const AxisymmetricPrecession sphere = axisymmetric_precession(2.0, 2.0, 1.0, 0.5);
  EXPECT_EQ(sphere.body_rate, 0.0);
  EXPECT_NEAR(sphere.space_cone_half_angle, 0.0, 1e-16);
  EXPECT_NEAR(sphere.space_rate, std::hypot(1.0, 0.5), 1e-15);
  // Oblate (I_a > I_t): H lies between the axis and ω, θ_H < θ_ω; prolate: the reverse
  // (Landau & Lifshitz §33, fig. 47).
  const AxisymmetricPrecession oblate = axisymmetric_precession(1.0, 3.0, 1.0, 0.5);
  EXPECT_LT(oblate.nutation_angle, oblate.body_cone_half_angle);
  EXPECT_NEAR(oblate.body_rate, 2.0, 1e-15);
  const AxisymmetricPrecession prolate = axisymmetric_precession(3.0, 1.0, 1.0, 0.5);
  EXPECT_GT(prolate.nutation_angle, prolate.body_cone_half_angle);
  EXPECT_THROW(axisymmetric_precession(1.0, 1.0, 0.0, 0.0), InvalidArgument);
}

TEST(AnalyticReferences, AsymmetricRotationNeedsDistinctMomentsAndAPeriod) {
  const AsymmetricRotation r = asymmetric_rotation(Vec3(1, 2, 3), Vec3(0.01, 2, 0.01));
  EXPECT_TRUE(r.about_major_axis);
  EXPECT_NEAR(r.flip_interval, r.period / 2, 0.0);
  EXPECT_NEAR(r.parameter + r.complement, 1.0, 2 * test::kEps);
  EXPECT_THROW(asymmetric_rotation(Vec3(1, 1, 3), Vec3(0.1, 0.2, 0.3)), InvalidArgument);
  EXPECT_THROW(asymmetric_rotation(Vec3(1, 2, 3), Vec3(0, 2, 0)), InvalidArgument);
  EXPECT_FALSE(asymmetric_rotation(Vec3(1, 2, 3), Vec3(1.0, 0.3, 0.2)).about_major_axis);
  EXPECT_EQ(sleeping_top_critical_spin({1e-3, 2e-4, 0.5, -0.04, 9.81}), 0.0);  // hanging: stable
}

}  // namespace
}  // namespace momenta::rigid_body
