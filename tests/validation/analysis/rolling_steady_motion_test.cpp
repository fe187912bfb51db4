// Steady motions of rolling bodies (analysis/rolling_steady_motion.hpp) against closed forms:
// the coin on a steady circle (the moment equation about G with rolling), Beer & Johnston's
// Sample Problem 18.2 (a disk rolling at the end of a pivoted axle), the upright disk's wobble
// and its critical speed (Routh), and the nonlinear simulation of a perturbed steady motion.

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/analysis/rolling_steady_motion.hpp"
#include "momenta/common/error.hpp"
#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

io::ModelFile rolling_example(const std::string& name) {
  return io::read_model_file(test::source_dir() + "/examples/" + name + ".yaml");
}

// The coin of examples/constraints/rolling_coin.yaml: m = 1 kg, R = 0.1 m, I₃ = ½mR², I₁ = ¼mR².
constexpr double kMass = 1.0, kRadius = 0.1, kGravity = 9.81;
constexpr double kI3 = 0.5 * kMass * kRadius * kRadius, kI1 = 0.25 * kMass * kRadius * kRadius;

// Rolling (ω·e = ρΩ/R) and the moment about G of a steady circle of G's radius ρ at lean φ:
//   Ω² cos φ (m R ρ + I₃ ρ/R + I₁ sin φ) = m g R sin φ.
double coin_precession(double lean, double radius) {
  return std::sqrt(kMass * kGravity * kRadius * std::sin(lean) /
                   (std::cos(lean) *
                    (kMass * kRadius * radius + kI3 * radius / kRadius + kI1 * std::sin(lean))));
}

TEST(RollingSteadyMotion, CoinOnACircleOfAGivenRadius) {
  const io::ModelFile coin = rolling_example("constraints/rolling_coin");
  const double lean = 20 * kDeg, rho = 0.5, W = coin_precession(lean, rho);
  const std::vector<RollingSteadyMotion> found =
      find_rolling_steady_motions(coin.model, lean, RollingCondition::radius, rho);
  // One circle, rolling forwards (its reverse in time is left out).
  ASSERT_EQ(found.size(), 1u);
  {
    const RollingSteadyMotion& m = found[0];
    const double sign = 1.0;
    // The quadratic's roots from three evaluations: round-off of the closed form.
    EXPECT_TRUE(test::relatively_near(m.precession, sign * W, 1e-13)) << m.precession;
    EXPECT_TRUE(test::relatively_near(m.spin, sign * rho * W / kRadius, 1e-13)) << m.spin;
    // σ = ω·e − Ω n·e, with n·e = −sin φ for the disk leaning towards the centre.
    EXPECT_TRUE(
        test::relatively_near(m.relative_spin, m.spin + m.precession * std::sin(lean), 1e-13));
    EXPECT_TRUE(test::relatively_near(m.speed, sign * rho * W, 1e-13));
    EXPECT_TRUE(test::relatively_near(m.radius, rho, 1e-13));
    EXPECT_TRUE(test::relatively_near(m.lean, lean, 1e-14));
    // The contact is R sin φ further out than G (G leans in).
    EXPECT_TRUE(test::relatively_near(m.contact_radius, rho + kRadius * std::sin(lean), 1e-13));
    // The floor carries the weight and pushes towards the centre with m ρ Ω².
    EXPECT_TRUE(test::relatively_near(m.contact_force[0], kMass * kGravity, 1e-13));
    EXPECT_LT(std::abs(m.contact_force[1]), 1e-12);
    EXPECT_TRUE(test::relatively_near(m.contact_force[2], kMass * rho * W * W, 1e-12));
    EXPECT_LT(m.residual, 1e-15);
    // Placed with the turn's centre on the world's z axis: G at ρ from it, and the state is the
    // example's own (which is that motion) up to where it starts on the circle.
    const Vec3 p_G(m.point.q[0], m.point.q[1], 0.0);
    EXPECT_NEAR(p_G.norm(), rho, 1e-14);
  }
}

TEST(RollingSteadyMotion, CoinAtAGivenSpeedHasTwoCircles) {
  // With ρ = v/Ω the moment equation is a quadratic in Ω:
  //   I₁ sin φ cos φ Ω² + (m R + I₃/R) v cos φ Ω − m g R sin φ = 0.
  const io::ModelFile coin = rolling_example("constraints/rolling_coin");
  const double lean = 20 * kDeg, v = 1.0847887974793695;  // the example's speed: ρ = 0.5
  const double a = kI1 * std::sin(lean) * std::cos(lean);
  const double b = (kMass * kRadius + kI3 / kRadius) * v * std::cos(lean);
  const double c = -kMass * kGravity * kRadius * std::sin(lean);
  const double disc = std::sqrt(b * b - 4 * a * c);
  const double roots[] = {2 * c / (-b - disc), (-b - disc) / (2 * a)};  // slow, then fast
  const std::vector<RollingSteadyMotion> found =
      find_rolling_steady_motions(coin.model, lean, RollingCondition::speed, v);
  ASSERT_EQ(found.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_TRUE(test::relatively_near(found[k].precession, roots[k], 1e-12)) << k;
    EXPECT_TRUE(test::relatively_near(found[k].speed, v, 1e-14)) << k;
    EXPECT_TRUE(test::relatively_near(found[k].radius, v / roots[k], 1e-12)) << k;
    EXPECT_LT(found[k].residual, 1e-14) << k;
  }
  // The slow root is the example's circle; the fast one turns the other way round a small circle
  // on the far side (the gyroscopic moment holds the lean).
  EXPECT_TRUE(test::relatively_near(found[0].radius, 0.5, 1e-12));
  EXPECT_LT(found[1].radius, 0.0);
  // By the precession and by the spin: the same circle.
  for (RollingCondition condition : {RollingCondition::precession, RollingCondition::spin}) {
    const double value =
        condition == RollingCondition::precession ? found[0].precession : found[0].spin;
    const std::vector<RollingSteadyMotion> again =
        find_rolling_steady_motions(coin.model, lean, condition, value);
    ASSERT_FALSE(again.empty());
    bool matched = false;
    for (const RollingSteadyMotion& m : again) {
      matched = matched || test::relatively_near(m.radius, 0.5, 1e-11);
    }
    EXPECT_TRUE(matched) << rolling_condition_name(condition);
  }
}

// Euler's disk: at speed 0 the coin rolls round on the spot, G still, ω·e = 0, its contact
// circling at R sin φ; the moment about G gives Ω² = m g R/(I₁ cos φ) = 4 g/(R cos φ).
TEST(RollingSteadyMotion, EulersDiskTurnsOnTheSpot) {
  const io::ModelFile coin = rolling_example("constraints/rolling_coin");
  for (double lean_deg : {5.0, 20.0, 60.0}) {
    const double lean = lean_deg * kDeg;
    const double W = std::sqrt(4 * kGravity / (kRadius * std::cos(lean)));
    const std::vector<RollingSteadyMotion> found =
        find_rolling_steady_motions(coin.model, lean, RollingCondition::speed, 0.0);
    ASSERT_EQ(found.size(), 2u) << lean_deg;  // both ways round
    for (const RollingSteadyMotion& m : found) {
      EXPECT_TRUE(test::relatively_near(std::abs(m.precession), W, 1e-13)) << lean_deg;
      EXPECT_EQ(m.speed, 0.0);
      EXPECT_EQ(m.spin, 0.0);
      EXPECT_EQ(m.radius, 0.0);
      EXPECT_TRUE(
          test::relatively_near(std::abs(m.contact_radius), kRadius * std::sin(lean), 1e-12));
      EXPECT_LT(m.residual, 1e-14);
    }
  }
}

TEST(RollingSteadyMotion, TheExamplesStateIsItsSteadyCircle) {
  const io::ModelFile coin = rolling_example("constraints/rolling_coin");
  const RollingSteadyMotion m =
      rolling_steady_motion(coin.model, initial_operating_point(coin.model));
  EXPECT_TRUE(test::relatively_near(m.precession, coin_precession(20 * kDeg, 0.5), 1e-12));
  EXPECT_TRUE(test::relatively_near(m.radius, 0.5, 1e-12));
  EXPECT_LT(m.residual, 1e-12);
  // Perturbed, the state is no steady motion, and the error says which part moves.
  OperatingPoint wobbling = initial_operating_point(coin.model);
  wobbling.v[0] += 0.01;
  EXPECT_THROW(rolling_steady_motion(coin.model, wobbling), InvalidArgument);
}

// The coin's wobble about its steady circle (the linearization seen from the turning frame)
// against the nonlinear motion of a slightly disturbed coin: its lean oscillates at that frequency.
TEST(RollingSteadyMotion, CoinsWobbleIsTheDisturbedMotionsFrequency) {
  const io::ModelFile coin = rolling_example("constraints/rolling_coin");
  const std::vector<RollingSteadyMotion> found =
      find_rolling_steady_motions(coin.model, 20 * kDeg, RollingCondition::radius, 0.5);
  ASSERT_EQ(found.size(), 1u);
  const RollingSteadyMotion& steady = found[0];
  const RollingSteadyModes modes = rolling_steady_modes(coin.model, steady);
  EXPECT_TRUE(modes.stable);
  ASSERT_EQ(modes.eigenvalues.size(), 1u);
  EXPECT_LT(std::abs(modes.eigenvalues[0].real()), 1e-9);
  const double wobble = modes.eigenvalues[0].imag();
  // The displaced circle turns at Ω in the turning frame.
  ASSERT_EQ(modes.circle_shift.size(), 1u);
  EXPECT_TRUE(test::relatively_near(modes.circle_shift[0].imag(), steady.precession, 1e-9));

  // Disturbed by a lean rate of 1e-4 rad/s about the heading (the coin's joint frame is its body
  // frame), simulated by RK4 at 0.5 ms for 3 s: the lean's peaks, refined by parabolas.
  system::MultibodySystem system(coin.model);
  integrate::State state{0.0, steady.point.q, steady.point.v};
  system.evaluate(0.0, state.q, state.v);
  const Mat3 R_WB = system.data().X_WB[1].R;
  state.v.head<3>() += R_WB.transpose() * (1e-4 * steady.heading_W);
  system.make_consistent(0.0, state.q, state.v);
  integrate::RungeKutta4 rk4;
  rk4.initialize(system, state);
  const double h = 5e-4;
  std::vector<double> lean;
  for (int k = 0; k <= 6000; ++k) {
    if (k > 0) {
      rk4.step(system, state, h);
      system.project(state.t, state.q, state.v);
    }
    system.evaluate(state.t, state.q, state.v);
    const Vec3 e_W = system.data().X_WB[1].R.col(2);
    lean.push_back(std::asin(-e_W.z()));
  }
  std::vector<double> peaks;
  for (std::size_t k = 1; k + 1 < lean.size(); ++k) {
    if (lean[k] > lean[k - 1] && lean[k] >= lean[k + 1]) {
      const double curvature = lean[k - 1] - 2 * lean[k] + lean[k + 1];
      peaks.push_back(h * (static_cast<double>(k) + 0.5 * (lean[k - 1] - lean[k + 1]) / curvature));
    }
  }
  ASSERT_GE(peaks.size(), 5u);
  const double period = (peaks.back() - peaks.front()) / static_cast<double>(peaks.size() - 1);
  // Measured 1.5e-10 apart: the disturbance (a lean of ~7e-6 rad) shifts the frequency by its
  // square, RK4 by (hω)⁴/120 ≈ 3e-11 (hω = 0.0076), the parabolas. peaks less.
  EXPECT_TRUE(test::relatively_near(2 * std::numbers::pi / period, wobble, 1e-8))
      << 2 * std::numbers::pi / period << " vs " << wobble;
}

// Beer & Johnston SP 18.2: Ω = −r ω₁/L, N = m g + ½ m r³ ω₁²/L².
TEST(RollingSteadyMotion, DiskOnAPivotedAxleBeerSampleProblem18_2) {
  const io::ModelFile beer = rolling_example("constraints/rolling_disk_on_axle");
  const double m = 4, r = 0.15, L = 0.45, w1 = 20;
  const double W = -r * w1 / L, N = m * kGravity + 0.5 * m * r * r * r * w1 * w1 / (L * L);
  for (RollingCondition condition : {RollingCondition::spin, RollingCondition::precession}) {
    const std::vector<RollingSteadyMotion> found = find_rolling_steady_motions(
        beer.model, std::nullopt, condition, condition == RollingCondition::spin ? w1 : W);
    ASSERT_EQ(found.size(), 1u);
    const RollingSteadyMotion& s = found[0];
    EXPECT_TRUE(test::relatively_near(s.precession, W, 1e-14));
    EXPECT_TRUE(test::relatively_near(s.spin, w1, 1e-14));
    EXPECT_TRUE(test::relatively_near(s.relative_spin, w1, 1e-14));  // the axle is level
    EXPECT_EQ(s.lean, 0.0);
    // G circles the pivot's vertical at L; the turn's centre lies away from `lateral` (which
    // points along the axle's horizontal part, from O out to G): a negative radius.
    EXPECT_TRUE(test::relatively_near(s.radius, -L, 1e-14));
    EXPECT_TRUE(test::relatively_near(s.contact_force[0], N, 1e-13));
    EXPECT_LT(s.residual, 1e-15);
    // Every rate is steady on the pivot: the floor's normal force takes the moment. The
    // perturbed motion neither grows nor oscillates (its one speed and two angles are set by
    // the symmetry and the conserved energy).
    const RollingSteadyModes modes = rolling_steady_modes(beer.model, s);
    EXPECT_TRUE(modes.stable);
    EXPECT_TRUE(modes.eigenvalues.empty());
    EXPECT_EQ(modes.zero_eigenvalues, 3);
  }
  EXPECT_THROW(find_rolling_steady_motions(beer.model, 0.1, RollingCondition::spin, w1),
               InvalidArgument);
}

// Routh: an upright disk rolling straight at spin ω wobbles at
//   ω_w² = [C (C + m a²) ω² − m g a A] / [A (A + m a²)]   (A, C about G across and along its axis),
// stable exactly above ω² = m g a A / (C (C + m a²)), g/(3a) for a thin disk.
TEST(RollingSteadyMotion, UprightDiskWobblesAtRouthsFrequency) {
  const io::ModelFile coin = rolling_example("constraints/rolling_coin");
  const double A = kI1, C = kI3, a = kRadius, m = kMass;
  const double critical = std::sqrt(m * kGravity * a * A / (C * (C + m * a * a)));
  EXPECT_TRUE(test::relatively_near(critical, std::sqrt(kGravity / (3 * a)), 1e-15));
  for (double ratio : {0.5, 0.9, 1.1, 2.0, 5.0}) {
    const double w = ratio * critical;
    const std::vector<RollingSteadyMotion> found =
        find_rolling_steady_motions(coin.model, 0.0, RollingCondition::speed, w * a);
    ASSERT_EQ(found.size(), 1u) << ratio;
    const RollingSteadyMotion& s = found[0];
    EXPECT_EQ(s.precession, 0.0);
    EXPECT_TRUE(std::isinf(s.radius));
    EXPECT_TRUE(test::relatively_near(s.spin, w, 1e-14));
    const RollingSteadyModes modes = rolling_steady_modes(coin.model, s);
    const double w2 = (C * (C + m * a * a) * w * w - m * kGravity * a * A) / (A * (A + m * a * a));
    ASSERT_FALSE(modes.eigenvalues.empty()) << ratio;
    if (ratio > 1.0) {
      EXPECT_TRUE(modes.stable) << ratio;
      ASSERT_EQ(modes.eigenvalues.size(), 1u) << ratio;
      EXPECT_LT(std::abs(modes.eigenvalues[0].real()), 1e-9) << ratio;
      // Richardson differences: ~1e-10 relative.
      EXPECT_TRUE(test::relatively_near(modes.eigenvalues[0].imag(), std::sqrt(w2), 1e-9))
          << ratio << " " << modes.eigenvalues[0].imag();
    } else {
      EXPECT_FALSE(modes.stable) << ratio;
      EXPECT_TRUE(test::relatively_near(modes.growth_rate, std::sqrt(-w2), 1e-9))
          << ratio << " " << modes.growth_rate;
    }
  }
  // Upright and straight, every speed is steady: the radius alone picks nothing.
  EXPECT_THROW(find_rolling_steady_motions(coin.model, 0.0, RollingCondition::radius,
                                           std::numeric_limits<double>::infinity()),
               InvalidArgument);
}

}  // namespace
}  // namespace momenta::analysis
