#include "momenta/rigid_body/analytic_references.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/rigid_body/free_rigid_body.hpp"

namespace momenta::rigid_body {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void check_top(const SymmetricTop& top) {
  const bool ok = top.transverse_moment > 0 && top.axial_moment > 0 && top.mass > 0 &&
                  std::isfinite(top.transverse_moment) && std::isfinite(top.axial_moment) &&
                  std::isfinite(top.mass) && std::isfinite(top.com_distance) &&
                  std::isfinite(top.gravity);
  if (!ok) {
    throw InvalidArgument(fmt::format(
        "symmetric top: need positive finite moments and mass and finite l, g; got I1 = {} "
        "kg·m², I3 = {} kg·m², m = {} kg, l = {} m, g = {} m/s²",
        top.transverse_moment, top.axial_moment, top.mass, top.com_distance, top.gravity));
  }
}

void check_angle(double theta) {
  if (!(theta > 0 && theta < std::numbers::pi)) {
    throw InvalidArgument(
        fmt::format("symmetric top: nutation angle θ = {} rad must lie in "
                    "(0, π)",
                    theta));
  }
}

// Roots of a x² + b x + c = 0 without cancellation (q = −(b + sign(b)√disc)/2; q/a and c/q),
// ordered slow (smaller magnitude) then fast. a = 0 gives the linear root and ±∞.
SteadyPrecession precession_roots(double a, double b, double c, const char* what) {
  if (a == 0) {
    if (b == 0) {
      throw InvalidArgument(fmt::format("{}: no steady precession without spin at θ = π/2", what));
    }
    return {-c / b, b > 0 ? -kInf : kInf};
  }
  const double disc = b * b - 4 * a * c;
  if (!(disc >= 0)) {
    throw InvalidArgument(fmt::format(
        "{}: no steady precession: discriminant (I3 ω3)² − 4 I1 m g l cos θ = {:.6g} < 0 (spin "
        "too slow for this angle)",
        what, disc));
  }
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  if (q == 0) return {0.0, 0.0};
  const double r1 = q / a, r2 = c / q;
  return std::abs(r1) < std::abs(r2) ? SteadyPrecession{r1, r2} : SteadyPrecession{r2, r1};
}

}  // namespace

AxisymmetricPrecession axisymmetric_precession(double transverse_moment, double axial_moment,
                                               double axial_rate, double transverse_rate) {
  if (!(transverse_moment > 0 && axial_moment > 0) || !(transverse_rate >= 0) ||
      !std::isfinite(axial_rate) || !std::isfinite(transverse_rate) ||
      (axial_rate == 0 && transverse_rate == 0)) {
    throw InvalidArgument(
        fmt::format("axisymmetric precession: need positive moments (I_t = {}, I_a = {} kg·m²), a "
                    "non-negative transverse rate and ω ≠ 0 (ω_a = {}, |ω_⊥| = {} rad/s)",
                    transverse_moment, axial_moment, axial_rate, transverse_rate));
  }
  AxisymmetricPrecession p;
  p.body_rate = (axial_moment - transverse_moment) * axial_rate / transverse_moment;
  const double H_axial = axial_moment * axial_rate,
               H_transverse = transverse_moment * transverse_rate;
  p.space_rate = std::hypot(H_axial, H_transverse) / transverse_moment;
  // The symmetry axis, ω and H are coplanar (H = I_t ω + (I_a − I_t) ω_a e_a).
  p.nutation_angle = std::atan2(H_transverse, H_axial);
  p.body_cone_half_angle = std::atan2(transverse_rate, axial_rate);
  p.space_cone_half_angle = std::abs(p.nutation_angle - p.body_cone_half_angle);
  return p;
}

AsymmetricRotation asymmetric_rotation(const Vec3& I, const Vec3& w) {
  if (!(I[0] > 0 && I[0] < I[1] && I[1] < I[2]) || !I.allFinite() || !w.allFinite()) {
    throw InvalidArgument(fmt::format(
        "asymmetric rotation: need principal moments 0 < I1 < I2 < I3 and a finite ω; got {}, "
        "{}, {} kg·m², ω = [{}, {}, {}] rad/s",
        I[0], I[1], I[2], w[0], w[1], w[2]));
  }
  if ((w.array() != 0.0).count() <= 1) {
    throw InvalidArgument(
        fmt::format("asymmetric rotation: ω = [{}, {}, {}] rad/s lies along a "
                    "principal axis: a steady rotation, with no period",
                    w[0], w[1], w[2]));
  }
  // The constants of the exact solution itself (long double, S in binary128).
  const FreeRigidBodySolution solution(I.asDiagonal().toDenseMatrix(), Mat3::Identity(), w);
  AsymmetricRotation r;
  r.about_major_axis = solution.regime() == FreeRotationRegime::kMajorAxis;
  r.parameter = solution.parameter();
  r.complement = solution.complementary_parameter();
  r.argument_rate = solution.argument_rate();
  r.period = solution.angular_velocity_period();
  r.flip_interval = r.period / 2;
  return r;
}

SteadyPrecession steady_precession(const SymmetricTop& top, double theta, double spin) {
  check_top(top);
  check_angle(theta);
  return precession_roots(top.transverse_moment * std::cos(theta), -top.axial_moment * spin,
                          top.mass * top.gravity * top.com_distance, "steady precession");
}

SteadyPrecession steady_precession_for_relative_spin(const SymmetricTop& top, double theta,
                                                     double relative_spin) {
  check_top(top);
  check_angle(theta);
  const double cos_theta = std::cos(theta);
  return precession_roots(
      (top.transverse_moment - top.axial_moment) * cos_theta, -top.axial_moment * relative_spin,
      top.mass * top.gravity * top.com_distance, "steady precession (relative spin)");
}

double gyroscopic_precession_rate(const SymmetricTop& top, double spin) {
  check_top(top);
  if (spin == 0) {
    throw InvalidArgument("gyroscopic precession: the spin ω3 must not be zero");
  }
  return top.mass * top.gravity * top.com_distance / (top.axial_moment * spin);
}

double sleeping_top_critical_spin(const SymmetricTop& top) {
  check_top(top);
  const double mgl = top.mass * top.gravity * top.com_distance;
  return mgl <= 0 ? 0.0 : std::sqrt(4 * mgl * top.transverse_moment) / top.axial_moment;
}

NutationBounds nutation_bounds(const SymmetricTop& top, double theta, double theta_dot,
                               double phi_dot, double spin) {
  check_top(top);
  check_angle(theta);
  if (!std::isfinite(theta_dot) || !std::isfinite(phi_dot) || !std::isfinite(spin)) {
    throw InvalidArgument(
        fmt::format("nutation bounds: rates must be finite (θ̇ = {}, φ̇ = {}, "
                    "ω3 = {} rad/s)",
                    theta_dot, phi_dot, spin));
  }
  // Goldstein eqs. 5.63–5.70: a = p_ψ/I1, b = p_φ/I1, α = 2E'/I1, β = 2 m g l/I1.
  const double I1 = top.transverse_moment, I3 = top.axial_moment;
  const double u0 = std::cos(theta), s2 = std::pow(std::sin(theta), 2);
  const double a = I3 * spin / I1;
  const double b = phi_dot * s2 + a * u0;
  const double beta = 2 * top.mass * top.gravity * top.com_distance / I1;
  const double alpha = theta_dot * theta_dot + phi_dot * phi_dot * s2 + beta * u0;
  const auto f = [&](double u) {
    return (1 - u * u) * (alpha - beta * u) - std::pow(b - a * u, 2);
  };
  // Bisection for the sign change of f on [lo, hi] (f(lo) and f(hi) of opposite signs).
  const auto bisect = [&](double lo, double hi) {
    double f_lo = f(lo);
    for (int i = 0; i < 200 && hi - lo > 0; ++i) {
      const double mid = 0.5 * (lo + hi);
      if (mid == lo || mid == hi) break;
      const double f_mid = f(mid);
      if ((f_mid > 0) == (f_lo > 0)) {
        lo = mid;
        f_lo = f_mid;
      } else {
        hi = mid;
      }
    }
    return 0.5 * (lo + hi);
  };
  double u1 = u0, u2 = u0;
  if (theta_dot != 0) {
    // f(u0) = sin²θ θ̇² > 0 and f(±1) = −(b ∓ a)² <= 0: one root on each side.
    u1 = f(-1.0) == 0 ? -1.0 : bisect(-1.0, u0);
    u2 = f(1.0) == 0 ? 1.0 : bisect(u0, 1.0);
  } else {
    // u0 is a turning point; deflate f = (u − u0) q(u) with q quadratic and take q's root on the
    // side where f' sends the motion.
    const double c3 = beta, c2 = -(alpha + a * a), c1 = 2 * a * b - beta;
    const double q2 = c3, q1 = c2 + u0 * q2, q0 = c1 + u0 * q1;
    const double slope = q2 * u0 * u0 + q1 * u0 + q0;  // f'(u0) = q(u0)
    if (slope != 0) {
      double r1, r2;
      if (q2 == 0) {
        r1 = r2 = -q0 / q1;
      } else {
        const double disc = std::max(0.0, q1 * q1 - 4 * q2 * q0);
        const double q = -0.5 * (q1 + std::copysign(std::sqrt(disc), q1));
        r1 = q / q2;
        r2 = q == 0 ? r1 : q0 / q;
      }
      const auto pick = [&](bool above) {
        double best = above ? 1.0 : -1.0;
        for (const double r : {r1, r2}) {
          if (above && r > u0 && r < best) best = r;
          if (!above && r < u0 && r > best) best = r;
        }
        return best;
      };
      if (slope > 0) {
        u2 = pick(true);
      } else {
        u1 = pick(false);
      }
    }
  }
  return {std::acos(u2), std::acos(u1), u1, u2};
}

}  // namespace momenta::rigid_body
