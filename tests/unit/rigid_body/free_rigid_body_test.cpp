#include "momenta/rigid_body/free_rigid_body.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta_test/rotation_reference.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::rigid_body {
namespace {

using test::TaylorRotation;

constexpr long double kLongDoubleEps = 1.0842021724855044340e-19L;

struct Case {
  std::string name;
  Mat3 inertia;
  Vec3 w0;
  FreeRotationRegime regime;
};

Mat3 diag(double a, double b, double c) { return Vec3(a, b, c).asDiagonal(); }

// An inertia with principal moments (a, b, c) about axes rotated away from B's, symmetrized:
// R D Rᵀ in double is symmetric only to an ulp, and a non-symmetric "inertia" is a different
// (unphysical) body to the reference, which uses the matrix as given. Nearly degenerate moments
// make the motion sensitive to that ulp (5e-15 at t = 12 s).
Mat3 rotated(double a, double b, double c) {
  const Mat3 R = rotation_from_euler("ZYX", Vec3(0.4, -1.1, 2.3));
  const Mat3 I = R * diag(a, b, c) * R.transpose();
  return 0.5 * (I + I.transpose());
}

// Every closed form: both sides of the separatrix, close to it, exactly on it, near-axisymmetric
// bodies (the asymmetric formulas in their limit), axisymmetric ones, spheres and steady spins.
std::vector<Case> cases() {
  return {
      {"major_axis", diag(1, 2, 3), {0.5, 0.3, 1.0}, FreeRotationRegime::kMajorAxis},
      {"minor_axis", diag(1, 2, 3), {1.0, 0.3, 0.2}, FreeRotationRegime::kMinorAxis},
      {"minor_axis_negative", diag(1, 2, 3), {-1.0, -0.3, 0.2}, FreeRotationRegime::kMinorAxis},
      {"benchmark_flip", diag(1, 2, 3), {0.01, 2.0, 0.01}, FreeRotationRegime::kMajorAxis},
      {"near_separatrix_major",
       diag(1, 2, 3),
       {0.1, 2.0, std::sqrt((0.01 + 4e-6) / 3)},
       FreeRotationRegime::kMajorAxis},
      {"near_separatrix_minor",
       diag(1, 2, 3),
       {std::sqrt(0.03 + 4e-6), 2.0, -0.1},
       FreeRotationRegime::kMinorAxis},
      // I = (3, 4, 6), ω = (1/2, 1, 1/4): H² − 2T I2 = 3(−1)/4 + 6·2/16 = 0 in exact arithmetic.
      {"separatrix", diag(3, 4, 6), {0.5, 1.0, 0.25}, FreeRotationRegime::kSeparatrix},
      {"separatrix_mirrored", diag(3, 4, 6), {-0.5, 1.0, -0.25}, FreeRotationRegime::kSeparatrix},
      {"nearly_oblate", diag(1, 1 + 1e-9, 3), {0.5, 0.3, -1.0}, FreeRotationRegime::kMajorAxis},
      {"nearly_prolate", diag(1, 3 - 1e-9, 3), {0.5, 0.3, -1.0}, FreeRotationRegime::kMinorAxis},
      {"rotated_tensor", rotated(1.3, 2.1, 2.9), {0.7, -0.4, 0.9}, FreeRotationRegime::kMinorAxis},
      {"oblate", diag(1, 1, 3), {0.5, 0.3, 1.0}, FreeRotationRegime::kAxisymmetric},
      {"prolate", diag(1, 3, 3), {0.5, 0.3, 1.0}, FreeRotationRegime::kAxisymmetric},
      // Rotated, the tensor is axisymmetric only to round-off: the asymmetric forms in their limit.
      {"rotated_prolate", rotated(2, 2, 0.5), {0.5, 0.3, 1.0}, FreeRotationRegime::kMinorAxis},
      {"sphere", diag(2, 2, 2), {0.5, 0.3, 1.0}, FreeRotationRegime::kSteady},
      {"steady_minor", diag(1, 2, 3), {1.5, 0, 0}, FreeRotationRegime::kSteady},
      {"steady_intermediate", diag(1, 2, 3), {0, -1.5, 0}, FreeRotationRegime::kSteady},
      {"at_rest", diag(1, 2, 3), {0, 0, 0}, FreeRotationRegime::kSteady},
  };
}

const Mat3 kR0 = rotation_from_euler("ZYX", Vec3(0.3, -0.7, 1.1));

TEST(FreeRigidBody, MatchesIndependentTaylorIntegration) {
  // Reference: Euler's equations and Ṙ = R ω̂ integrated by an adaptive-order Taylor method in
  // long double (tests/support/momenta_test/rotation_reference.hpp). Up to t = 12 s its error is
  // ~1e-18 in every case here, including the separatrix, whose instability grows a 1e-19
  // perturbation by e^{λt} = e^{8} at most. So the difference measures the closed form: its
  // round-off is a few ulps of |ω| per evaluation for ω (2e-15 |ω|; observed ≤ 1e-15 |ω|). The
  // attitude angle ψ sums terms of size up to |γ| (G(K) + K/(1 − n)) ≈ 30 near the separatrix,
  // whose ulps (3.6e-15) bound R's error there (5e-15; observed ≤ 2.5e-15, and ≤ 1e-15 away from
  // the separatrix).
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const FreeRigidBodySolution solution(c.inertia, kR0, c.w0);
    EXPECT_EQ(solution.regime(), c.regime);
    TaylorRotation<long double> reference(c.inertia, kR0, c.w0, kLongDoubleEps);
    const double scale = std::max(1.0, c.w0.norm());
    for (const double t : {0.0, 0.37, 3.0, 12.0}) {
      reference.advance_to(t, 0.05L);
      ASSERT_LT(reference.max_order_used(), reference.kMaxOrder);
      const RotationState s = solution(t);
      EXPECT_MATRIX_NEAR(s.w_WB_B, reference.w_double(), 2e-15 * scale) << "t = " << t;
      EXPECT_MATRIX_NEAR(s.R_WB, reference.R_double(), 5e-15) << "t = " << t;
    }
  }
}

TEST(FreeRigidBody, InvariantsHoldToRoundOffAtLongTimes) {
  // Energy, |H| and H in W are constants of the exact motion; the closed form builds them in
  // (h = H/|H| on the orbit, R_WA fixed), so at t = 1000 s they must hold to round-off: a few
  // ulps of each quantity (observed ≤ 2e-15 relative).
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const FreeRigidBodySolution solution(c.inertia, kR0, c.w0);
    const double T0 = 0.5 * c.w0.dot(c.inertia * c.w0);
    const Vec3 H0 = kR0 * c.inertia * c.w0;
    for (const double t : {1000.0, -731.3}) {
      const RotationState s = solution(t);
      const double T = 0.5 * s.w_WB_B.dot(c.inertia * s.w_WB_B);
      const Vec3 H = s.R_WB * c.inertia * s.w_WB_B;
      EXPECT_NEAR(T, T0, 4e-15 * std::max(T0, 1.0));
      EXPECT_MATRIX_NEAR(H, H0, 4e-15 * std::max(H0.norm(), 1.0));
      EXPECT_MATRIX_NEAR(s.R_WB.transpose() * s.R_WB, Mat3::Identity(), 2e-15);
      EXPECT_GT(s.R_WB.determinant(), 0.0);
    }
    EXPECT_NEAR(solution.kinetic_energy(), T0, 4 * test::kEps * std::max(T0, 1.0));
    EXPECT_MATRIX_NEAR(solution.angular_momentum_W(), H0,
                       4 * test::kEps * std::max(H0.norm(), 1.0));
  }
}

TEST(FreeRigidBody, FlowIsAGroup) {
  // φ_{t+s} = φ_t ∘ φ_s, and φ_{−t} undoes φ_t: a solution restarted from the state at s and
  // evaluated at t must agree with the first one at s + t (ulps of round-off, ≤ 3e-15). The
  // restart sees the state at s rounded to double; near the separatrix that rounding moves 1 − m
  // by ε|ω|²/|H² − 2T I2| relatively (1e-10 for 1 − m = 1e-6), and the period with it, so those
  // orbits are left to the tests that start both solutions from the same numbers.
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const FreeRigidBodySolution first(c.inertia, kR0, c.w0);
    if (first.regime() == FreeRotationRegime::kSeparatrix ||
        ((first.regime() == FreeRotationRegime::kMajorAxis ||
          first.regime() == FreeRotationRegime::kMinorAxis) &&
         first.complementary_parameter() < 0.01)) {
      continue;
    }
    const RotationState at_s = first(7.25);
    const FreeRigidBodySolution second(c.inertia, at_s.R_WB, at_s.w_WB_B);
    const double scale = std::max(1.0, c.w0.norm());
    EXPECT_MATRIX_NEAR(second(5.5).R_WB, first(12.75).R_WB, 3e-15);
    EXPECT_MATRIX_NEAR(second(5.5).w_WB_B, first(12.75).w_WB_B, 3e-15 * scale);
    EXPECT_MATRIX_NEAR(second(-7.25).R_WB, kR0, 3e-15);
    EXPECT_MATRIX_NEAR(second(-7.25).w_WB_B, c.w0, 3e-15 * scale);
    EXPECT_MATRIX_NEAR(first.angular_velocity(3.3), first(3.3).w_WB_B, 0.0);
  }
}

TEST(FreeRigidBody, MassPropertiesUseTheInertiaAboutTheCentreOfMass) {
  const Mat3 I = rotated(0.8, 1.5, 2.0);
  const inertia::MassProperties body(4.0, Vec3(0.3, -0.2, 0.1), I);
  const Vec3 w0(0.4, 1.2, -0.3);
  const RotationState a = free_rigid_body_motion(body, kR0, w0, 4.2);
  const RotationState b = free_rigid_body_motion(I, kR0, w0, 4.2);
  EXPECT_MATRIX_NEAR(a.R_WB, b.R_WB, 0.0);
  EXPECT_MATRIX_NEAR(a.w_WB_B, b.w_WB_B, 0.0);
}

TEST(FreeRigidBody, ExactStepperFollowsTheSolution) {
  // While the state is handed back unchanged, n steps of h equal the solution at n h (the
  // accumulated time is long double); a changed state starts a new solution from it.
  const Mat3 I = diag(1, 2, 3);
  const Vec3 w0(0.01, 2.0, 0.01);
  ExactFreeRigidBodyStepper stepper(I);
  Mat3 R = kR0;
  Vec3 w = w0;
  for (int i = 0; i < 10000; ++i) stepper.step(R, w, 1e-3);
  const RotationState expected = FreeRigidBodySolution(I, kR0, w0)(10.0);
  EXPECT_MATRIX_NEAR(R, expected.R_WB, 1e-15);
  EXPECT_MATRIX_NEAR(w, expected.w_WB_B, 2e-15);
  // A kick: the stepper restarts from the kicked state.
  w.x() += 0.1;
  const Vec3 kicked = w;
  const Mat3 R_kicked = R;
  stepper.step(R, w, 0.5);
  const RotationState after = FreeRigidBodySolution(I, R_kicked, kicked)(0.5);
  EXPECT_MATRIX_NEAR(R, after.R_WB, 0.0);
  EXPECT_MATRIX_NEAR(w, after.w_WB_B, 0.0);
}

TEST(FreeRigidBody, ExactStepperQuadratureKeepsRoundOffAccuracy) {
  // The stepper advances G by Gauss–Legendre over each step (re-anchored every 128 steps) for a
  // repeated h; it must agree with direct evaluation to round-off in every elliptic regime and
  // for steps short and long (long steps use more nodes or fall back to direct evaluation).
  for (const Case& c : cases()) {
    if (c.regime != FreeRotationRegime::kMajorAxis && c.regime != FreeRotationRegime::kMinorAxis) {
      continue;
    }
    SCOPED_TRACE(c.name);
    for (const double h : {1e-3, 0.05, 0.7}) {
      ExactFreeRigidBodyStepper stepper(c.inertia);
      const FreeRigidBodySolution solution(c.inertia, kR0, c.w0);
      Mat3 R = kR0;
      Vec3 w = c.w0;
      const int steps = static_cast<int>(std::lround(20.0 / h));
      double worst_R = 0, worst_w = 0;
      long double t = 0;  // summed as the stepper sums it
      for (int i = 1; i <= steps; ++i) {
        stepper.step(R, w, h);
        t += h;
        if (i % 97 == 0 || i == steps) {
          Mat3 R_direct;
          Vec3 w_direct;
          solution.evaluate(t, R_direct, w_direct);
          worst_R = std::max(worst_R, (R - R_direct).cwiseAbs().maxCoeff());
          worst_w = std::max(worst_w, (w - w_direct).cwiseAbs().maxCoeff());
        }
      }
      // Same times, so only the quadrature and the Kahan-summed G differ from Carlson's R_J
      // (itself good to a few ulps): a few ulps of γ G (≤ 30, ulp 3.6e-15) in ψ; 2e-14 allowed
      // (observed ≤ 7e-15, near the separatrix). ω does not depend on G.
      EXPECT_LT(worst_R, 2e-14) << "h = " << h;
      EXPECT_LT(worst_w, 4 * test::kEps * std::max(1.0, c.w0.norm())) << "h = " << h;
    }
  }
}

TEST(FreeRigidBody, ReportsItsConstants) {
  const FreeRigidBodySolution s(diag(1, 2, 3), kR0, Vec3(0.01, 2.0, 0.01));
  // 1 − m = (H² − 2T I2) / (I3 (I3 − I2) a_z²), a_z² = ω3² + I2(I2 − I1)/(I3(I3 − I1)) ω2².
  const double az2 = 1e-4 + 2.0 / 6.0 * 4.0;
  const double S = -1e-4 + 3 * 1e-4;
  EXPECT_REL_NEAR(s.complementary_parameter(), S / (3 * az2), 4 * test::kEps);
  EXPECT_REL_NEAR(s.parameter(), 1.0 - S / (3 * az2), 4 * test::kEps);
  EXPECT_REL_NEAR(s.argument_rate(), std::sqrt(az2), 4 * test::kEps);
  EXPECT_TRUE(s.principal_moments().isApprox(Vec3(1, 2, 3)));
  EXPECT_TRUE(std::isinf(
      FreeRigidBodySolution(diag(3, 4, 6), kR0, Vec3(0.5, 1, 0.25)).angular_velocity_period()));
}

TEST(FreeRigidBody, RejectsInvalidArguments) {
  const Vec3 w(0.1, 0.2, 0.3);
  EXPECT_THROW(FreeRigidBodySolution(diag(0, 1, 1), kR0, w), InvalidInertia);
  Mat3 asymmetric = diag(1, 2, 3);
  asymmetric(0, 1) = 0.1;
  EXPECT_THROW(FreeRigidBodySolution(asymmetric, kR0, w), InvalidInertia);
  EXPECT_THROW(FreeRigidBodySolution(diag(1, 2, 3), 1.01 * kR0, w), InvalidArgument);
  EXPECT_THROW(FreeRigidBodySolution(diag(1, 2, 3), kR0, Vec3(0, std::nan(""), 0)),
               InvalidArgument);
  EXPECT_THROW(ExactFreeRigidBodyStepper(diag(-1, 2, 3)).solution(), InvalidInertia);
}

}  // namespace
}  // namespace momenta::rigid_body
