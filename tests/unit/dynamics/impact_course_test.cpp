// dynamics::frictional_impact where the mechanism couples the normal and the slip: a free slender
// rod striking the ground by one end, tilted. In its plane the course is piecewise linear in the
// normal impulse, and Routh's construction (Stronge, Impact Mechanics, 2000, §4.3) — written here
// for two dimensions from the rod's closed-form inverse inertia at its end — gives the impulse and
// the velocities after to round-off: slip that stops and sticks, that reverses, that slides
// throughout, restitution by Stronge's energetic coefficient. Out of the plane (a slip with a
// sideways part, which turns) the course keeps its mirror symmetry, takes energy (Kelvin's
// T⁺ − T⁻ = ½ P·(u⁻ + u⁺) no more than zero), and tends to the planar course as the sideways slip
// vanishes (where μs = μk).

#include <cmath>
#include <random>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "dynamics/impact_course.hpp"
#include "momenta/common/error.hpp"
#include "momenta/dynamics/impulse.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/point_kinematics.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics::impact_course_test {
namespace {

using model::JointType;

// Routh's construction in a plane: the slip u_t and the normal speed u_n, linear in the normal
// impulse p between the instants where the slip stops, compression ends, or the impact ends.
// W = [[a, b], [b, c]] in (t, n).
struct PlanarCourse {
  double P_t = 0, P_n = 0, u_t = 0, u_n = 0;
  double compression_impulse = 0;
  int slip_stops = 0;
};

PlanarCourse routh(double a, double b, double c, double u_t, double u_n, double e, double mu_s,
                   double mu_k) {
  PlanarCourse r;
  r.u_t = u_t;
  r.u_n = u_n;
  bool compressed = false, stuck = false;
  double work = 0, target = 0, resumed = 0;
  for (int phase = 0; phase < 8; ++phase) {
    if (!stuck && r.u_t == 0 && resumed == 0) {
      if (std::abs(b / a) <= mu_s) {
        stuck = true;
      } else {
        resumed = b > 0 ? 1 : -1;  // a slip from rest grows where a f + b points: |b| > μk a
      }
    }
    const double sign = r.u_t != 0 ? (r.u_t > 0 ? 1 : -1) : resumed;
    const double f = stuck ? -b / a : -mu_k * sign;
    const double du_t = stuck ? 0.0 : a * f + b, du_n = b * f + c;
    const double to_rest = !stuck && r.u_t * du_t < 0 ? -r.u_t / du_t : INFINITY;
    double to_event = INFINITY;
    if (!compressed) {
      if (du_n > 0) to_event = -r.u_n / du_n;
    } else {  // u_n h + du_n h² / 2 = what the work still lacks
      const double lacking = target - work;
      const double discriminant = r.u_n * r.u_n + 2 * du_n * lacking;
      if (du_n == 0)
        to_event = lacking / r.u_n;
      else if (discriminant >= 0)
        to_event = (-r.u_n + std::sqrt(discriminant)) / du_n;
    }
    const double h = std::min(to_rest, to_event);
    if (!std::isfinite(h)) {
      if (stuck && !compressed) return r;  // held still: no normal motion left
      ADD_FAILURE() << "the planar course does not end";
      return r;
    }
    work += r.u_n * h + 0.5 * du_n * h * h;
    r.u_t += du_t * h;
    r.u_n += du_n * h;
    r.P_t += f * h;
    r.P_n += h;
    if (to_rest < to_event) {
      r.u_t = 0;
      ++r.slip_stops;
      continue;
    }
    if (compressed) return r;
    r.u_n = 0;
    compressed = true;
    r.compression_impulse = r.P_n;
    target = (1 - e * e) * work;
    if (e == 0) return r;
  }
  ADD_FAILURE() << "more phases than a planar course has";
  return r;
}

// A free slender rod (m = 1 kg, L = 1 m, I = m L² / 12 about its centre) tilted by θ about y with
// its lower end on the ground at the origin.
struct TiltedRod {
  double m = 1.0, L = 1.0, theta = 0.5;
  Model model = build();
  explicit TiltedRod(double tilt) : theta(tilt) {}
  Model build() const {
    model::ModelBuilder b;
    b.add_body("rod",
               inertia::MassProperties(m, Vec3::Zero(),
                                       Vec3(m * L * L / 12, m * L * L / 12, 1e-4).asDiagonal()));
    b.add_joint(test::make_joint("free", JointType::free, "world", "rod", Vec3::UnitZ()));
    return b.build();
  }
  double I() const { return m * L * L / 12; }
  Vec3 end_B() const { return Vec3(0, 0, -L / 2); }
  Vec3 end_from_centre_W() const {
    return Vec3(-L / 2 * std::sin(theta), 0, -L / 2 * std::cos(theta));
  }
  VecX q() const {
    VecX q = model.initial_q();
    const Quat R(Eigen::AngleAxisd(theta, Vec3::UnitY()));
    q.head<3>() = -end_from_centre_W();
    q.segment<4>(3) << R.w(), R.x(), R.y(), R.z();
    return q;
  }
  // v = [ω (body axes), ṗ (world)]; the rod turns about y at ω and its centre moves at V.
  static VecX v(double omega, const Vec3& V) {
    VecX v = VecX::Zero(6);
    v[1] = omega;
    v.tail<3>() = V;
    return v;
  }
  // The end's velocity, V + ω × r.
  Vec3 end_velocity(double omega, const Vec3& V) const {
    return V + Vec3(0, omega, 0).cross(end_from_centre_W());
  }
  PointContact contact() const { return {0, Vec3::Zero(), 1, end_B(), Vec3::UnitZ()}; }
};

// In the rod's plane: Routh's construction from W = 1/m + (r × ·)ᵀ I⁻¹ (r × ·) at its end, to
// round-off, over random tilts, speeds and coefficients, every course met.
TEST(ImpactCourse, ARodStrikingByOneEndFollowsRouthsConstruction) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  int stops = 0, again = 0, slides = 0, sticks = 0, with_other_speed = 0;
  for (int trial = 0; trial < 400; ++trial) {
    SCOPED_TRACE(fmt::format("trial {}", trial));
    const TiltedRod rod(0.1 + 1.3 * u(rng));
    const double omega = 6 * (u(rng) - 0.5);
    Vec3 V(4 * (u(rng) - 0.5), 0, -0.5 - 3 * u(rng));
    const Vec3 r = rod.end_from_centre_W();
    if (trial % 8 == 0) V.x() = -Vec3(0, omega, 0).cross(r).x();  // no slip before
    const Vec3 u_before = rod.end_velocity(omega, V);
    if (u_before.z() >= 0) continue;
    const double e = u(rng), mu_s = 1.2 * u(rng), mu_k = mu_s * u(rng);
    const double a = 1 / rod.m + r.z() * r.z() / rod.I(), b = -r.x() * r.z() / rod.I(),
                 c = 1 / rod.m + r.x() * r.x() / rod.I();
    const PlanarCourse expected = routh(a, b, c, u_before.x(), u_before.z(), e, mu_s, mu_k);
    const FrictionalImpact impact =
        frictional_impact(rod.model, rod.q(), TiltedRod::v(omega, V), rod.contact(), e, mu_s, mu_k);
    const double speed = u_before.norm(), impulse = speed / c;
    EXPECT_NEAR(impact.approach_speed, u_before.z(), 1e-15 * speed);
    EXPECT_NEAR(impact.slip_before_W.x(), u_before.x(), 1e-15 * speed);
    EXPECT_NEAR(impact.impulse_W.x(), expected.P_t, 1e-12 * impulse);
    EXPECT_NEAR(impact.impulse_W.y(), 0.0, 1e-15 * impulse);
    EXPECT_NEAR(impact.normal_impulse, expected.P_n, 1e-12 * impulse);
    EXPECT_NEAR(impact.compression_impulse, expected.compression_impulse, 1e-12 * impulse);
    EXPECT_NEAR(impact.slip_after_W.x(), expected.u_t, 1e-12 * speed);
    EXPECT_NEAR(impact.separation_speed, expected.u_n, 1e-12 * speed);
    // The rod's own response: ΔV = P / m, Δω = (r × P)_y / I.
    const Vec3 P = impact.impulse_W;
    EXPECT_NEAR(impact.motion.v_after[1], omega + r.cross(P).y() / rod.I(), 1e-12 * speed);
    EXPECT_MATRIX_NEAR(impact.motion.v_after.tail<3>(), Vec3(V + P / rod.m), 1e-12 * speed);
    EXPECT_LE(impact.motion.kinetic_after, impact.motion.kinetic_before);
    if (std::abs(expected.u_n + e * u_before.z()) > 1e-6 * speed) ++with_other_speed;
    switch (impact.course) {
      case SlipCourse::sticks:
        ++sticks;
        EXPECT_EQ(expected.slip_stops, 0);
        EXPECT_LE(std::abs(P.x()), mu_s * P.z() * (1 + 1e-12));
        break;
      case SlipCourse::stops:
        ++stops;
        EXPECT_EQ(expected.slip_stops, 1);
        EXPECT_NEAR(impact.slip_after_W.norm(), 0.0, 1e-13 * speed);
        break;
      case SlipCourse::slides_again:
        ++again;
        break;
      case SlipCourse::slides:
        ++slides;
        EXPECT_EQ(expected.slip_stops, 0);
        EXPECT_NEAR(std::abs(P.x()), mu_k * P.z(), 1e-12 * impulse);
        break;
    }
  }
  EXPECT_GT(stops, 20);
  EXPECT_GT(again, 20);
  EXPECT_GT(slides, 20);
  EXPECT_GT(sticks, 5);
  EXPECT_GT(with_other_speed, 50);  // the separation speed is not Newton's −e v_n⁻
}

// Out of the plane the slip turns: mirror symmetry, energy taken, and the planar course where the
// sideways slip is 1e-9 of the rest.
TEST(ImpactCourse, ASlipThatTurnsKeepsItsSymmetryAndTakesEnergy) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 100; ++trial) {
    SCOPED_TRACE(fmt::format("trial {}", trial));
    const TiltedRod rod(0.1 + 1.3 * u(rng));
    const double omega = 6 * (u(rng) - 0.5);
    const Vec3 V(4 * (u(rng) - 0.5), 4 * (u(rng) - 0.5), -0.5 - 3 * u(rng));
    if (rod.end_velocity(omega, V).z() >= 0) continue;
    const double e = u(rng), mu_s = 1.2 * u(rng), mu_k = mu_s * u(rng);
    const auto strike = [&](const Vec3& velocity, double static_friction) {
      return frictional_impact(rod.model, rod.q(), TiltedRod::v(omega, velocity), rod.contact(), e,
                               static_friction, mu_k);
    };
    const FrictionalImpact impact = strike(V, mu_s);
    const FrictionalImpact mirrored = strike(Vec3(V.x(), -V.y(), V.z()), mu_s);
    const double speed = rod.end_velocity(omega, V).norm(), impulse = speed * rod.m;
    EXPECT_NEAR(mirrored.impulse_W.x(), impact.impulse_W.x(), 1e-10 * impulse);
    EXPECT_NEAR(mirrored.impulse_W.y(), -impact.impulse_W.y(), 1e-10 * impulse);
    EXPECT_NEAR(mirrored.impulse_W.z(), impact.impulse_W.z(), 1e-10 * impulse);
    EXPECT_LE(impact.motion.kinetic_after, impact.motion.kinetic_before);
    EXPECT_NEAR(impact.motion.kinetic_after - impact.motion.kinetic_before,
                impact.motion.impulse_work, 1e-12 * impulse * speed);
    // Nearly planar: the planar course, where μs = μk. (Where μs > μk a slip that stops in the
    // plane may stick, while one with a sideways part passes by zero at μk and does not.)
    if (mu_k == 0) continue;
    const FrictionalImpact planar = strike(Vec3(V.x(), 0, V.z()), mu_k);
    const FrictionalImpact near = strike(Vec3(V.x(), 1e-9 * speed, V.z()), mu_k);
    EXPECT_NEAR(near.normal_impulse, planar.normal_impulse, 1e-7 * impulse);
    EXPECT_NEAR(near.impulse_W.x(), planar.impulse_W.x(), 1e-7 * impulse);
  }
}

// The course itself (detail::follow_impact) at two W's a box's corner met in a run (MJCF boxes
// dropped tilted, with μ = 1), each of which ran the course out of steps before.
//
// A contact struck beside one that sticks: the mechanism cannot move its slip (W_tt, W_tn round-off
// of W_nn): it sticks, and the impact stops its normal speed (e = 0) with the normal impulse alone.
TEST(ImpactCourse, AContactWhoseSlipTheOthersHoldSticks) {
  Mat3 W;
  W << -3.5527140715964842e-16, -6.8502552054212496e-17, -4.1078251911130792e-14,
      7.0704368677926855e-17, -3.330665239131346e-17, -2.0317081350640251e-14,
      -4.0786158729439894e-14, -2.0376635444426946e-14, 1.846153846153846;
  const Vec3 u(3.4472424914611111e-14, 1.7236212457305461e-14, -1.5523903796068681);
  const detail::ImpactCourse course = detail::follow_impact(W, u, 0.0, 1.0, 1.0);
  EXPECT_EQ(course.course, SlipCourse::sticks);
  EXPECT_LT(course.u_after.norm(), 1e-13 * u.norm());
  EXPECT_NEAR(course.impulse.z(), -u.z() / W(2, 2), 1e-15 * u.norm());
  EXPECT_EQ(course.impulse.head<2>(), Vec2::Zero());
}

// W not symmetric (another contact slides through the impact, its friction riding on its normal
// row): the slip stops before compression ends, the cone cannot hold it (|f*| = 1.017 > μs = 1),
// and it slides again along the ŝ whose rate W_tn − μk W_tt ŝ is along ŝ itself — so straight on
// to the end. The LDLᵀ solve that found ŝ read W_tt as symmetric: the slip, sent the wrong way,
// came back to rest again and again.
TEST(ImpactCourse, ASlipResumedFromRestRunsStraightAlongItsOwnRate) {
  Mat3 W;
  W << 2.1798188273355636, -0.3509585819833102, 0.52568671023406877, -0.40839520989048855,
      0.726081423299336, 0.52128069011208866, 0.71478482005212385, 0.39155757760386789,
      2.9033943855114499;
  const Vec3 u(0.040429517266060533, -0.26478169587965428, -0.66749620838389101);
  const double mu = 1.0;
  const detail::ImpactCourse course = detail::follow_impact(W, u, 0.0, mu, mu);
  EXPECT_EQ(course.course, SlipCourse::slides_again);
  const Vec2 slip = course.u_after.head<2>();
  ASSERT_GT(slip.norm(), 0.0);
  const Vec2 s = slip / slip.norm();
  const Vec2 rate = W.topRightCorner<2, 1>() - mu * W.topLeftCorner<2, 2>() * s;
  // Along ŝ to 1e-11 rad: ŝ(λ) is found to 1e-15 in λ, and here λ = |rate| is small (1.5 % of
  // |W_tn|), which magnifies its error in the direction.
  EXPECT_LT(std::abs(rate.x() * s.y() - rate.y() * s.x()), 1e-11 * rate.norm());
  EXPECT_GT(rate.dot(s), 0.0);
  EXPECT_NEAR(course.u_after.z(), 0.0, 1e-15);  // e = 0: compression's end is the impact's
  // u⁺ = u⁻ + W P, whatever the course.
  EXPECT_LT((course.u_after - (u + W * course.impulse)).norm(), 1e-14 * u.norm());
}

}  // namespace
}  // namespace momenta::dynamics::impact_course_test
