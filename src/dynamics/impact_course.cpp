#include "impact_course.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include <fmt/format.h>
#include <Eigen/LU>
#include <Eigen/QR>
#include <boost/math/tools/toms748_solve.hpp>
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>

#include "momenta/common/error.hpp"

namespace momenta::dynamics::detail {
namespace {

namespace odeint = boost::numeric::odeint;

// The course is followed in scaled units: velocities in |u⁻|, the normal impulse in the
// frictionless compression's p₀ = |u⁻| / W_nn, so that W_nn = 1 and every state entry is of
// order one. The state: u (3, contact basis), the impulse P (3), and the normal impulse's work
// ∫ u_n dp.
using State = std::array<double, 7>;
constexpr int kWork = 6;

Vec3 velocity_of(const State& y) { return {y[0], y[1], y[2]}; }
Vec2 slip_of(const State& y) { return {y[0], y[1]}; }

// A slip this small (in |u⁻|) has come to rest.
constexpr double kSlipAtRest = 1e-13;
// Past this normal impulse (in p₀) the impact is taken not to end.
constexpr double kJammed = 1e6;
constexpr int kMostSteps = 100000;
// A slip this slow (in |u⁻|) approaching rest lands on it straight, turning or not: halving a
// turning approach's steps there only chases the integration's round-off (the turn over the last
// piece moves the impulse by ~speed², below it).
constexpr double kLandingSpeed = 1e-9;
// A tangential response this small (in W_nn) is round-off: the slip is held still.
constexpr double kHeldStill = 1e-12;

// The state's rate per unit normal impulse for the friction impulse f_t per unit normal impulse.
void advance_rate(const Mat3& W, const Vec2& f_t, const State& y, State& dy) {
  const Vec3 f(f_t.x(), f_t.y(), 1.0);
  const Vec3 du = W * f;
  for (int k = 0; k < 3; ++k) {
    dy[k] = du[k];
    dy[3 + k] = f[k];
  }
  dy[kWork] = y[2];
}

// Sliding: μk against the slip, or along `at_rest` where the slip is zero (a slip resuming).
struct Sliding {
  const Mat3* W;
  double mu_k;
  Vec2 at_rest;
  Vec2 direction(const State& y) const {
    const Vec2 slip = slip_of(y);
    const double speed = slip.norm();
    return speed > 0.0 ? Vec2(slip / speed) : at_rest;
  }
  void operator()(const State& y, State& dy, double /*p*/) const {
    advance_rate(*W, -mu_k * direction(y), y, dy);
  }
};

class Course {
 public:
  Course(const Mat3& W, double e, double mu_s, double mu_k)
      : W_(W), e_(e), mu_s_(mu_s), mu_k_(mu_k), hold_(sticking_friction(W)) {}

  // f* = −W_tt⁺ W_tn; zero where the mechanism's other constraints hold the slip still (W_tt and
  // W_tn round-off of W_nn = 1: a contact struck while another beside it sticks).
  static Vec2 sticking_friction(const Mat3& W) {
    const Eigen::Matrix2d W_tt = W.topLeftCorner<2, 2>();
    const Vec2 W_tn = W.topRightCorner<2, 1>();
    if (W_tt.norm() <= kHeldStill && W_tn.norm() <= kHeldStill) return Vec2::Zero();
    return -W_tt.completeOrthogonalDecomposition().solve(W_tn);
  }

  ImpactCourse run(const Vec3& u_before) {
    State y{};
    for (int k = 0; k < 3; ++k) y[k] = u_before[k];
    course_.course = SlipCourse::slides;
    if (slip_of(y).norm() <= kSlipAtRest) {
      y[0] = y[1] = 0.0;
      if (holds()) return stick(y, SlipCourse::sticks);
      resume(SlipCourse::slides_again);
      return slide_straight(y);
    }
    return slide(y);
  }

 private:
  // Sticking needs the friction f* = −W_tt⁺ W_tn per unit normal impulse; the cone holds it
  // within μs.
  bool holds() const { return hold_.norm() <= mu_s_ * (1.0 + 1e-12); }

  // The slip resumes along ŝ with W_tn − μk W_tt ŝ = λ ŝ, λ > 0: ŝ(λ) = (λ + μk W_tt)⁻¹ W_tn, of
  // length |f*|/μk > 1 as λ → 0 and at most 1 at λ = |W_tn|.
  void resume(SlipCourse course) {
    course_.course = course;
    const Vec2 W_tn = W_.topRightCorner<2, 1>();
    const Eigen::Matrix2d W_tt = W_.topLeftCorner<2, 2>();
    const auto along = [&](double lambda) {
      // W_tt is not symmetric where other contacts slide through the impact (their friction
      // rides on their normal rows): a general solve.
      return Vec2((lambda * Eigen::Matrix2d::Identity() + mu_k_ * W_tt).partialPivLu().solve(W_tn));
    };
    const double high = W_tn.norm();
    double lambda = high;
    if (mu_k_ > 0.0) {
      const auto excess = [&](double l) { return along(l).norm() - 1.0; };
      double low = high;
      while (excess(low) <= 0.0 && low > 1e-300) low *= 0.5;
      std::uintmax_t iterations = 200;
      const auto close = [](double a, double b) {
        return std::abs(a - b) <= 1e-15 * std::max(std::abs(a), std::abs(b));
      };
      if (low < high) {  // else no bracket: already beyond at `high` (round-off)
        const auto [lo, hi] = boost::math::tools::toms748_solve(excess, low, high, excess(low),
                                                                excess(high), close, iterations);
        lambda = 0.5 * (lo + hi);
      }
    }
    const Vec2 s = along(lambda);
    resume_direction_ = s / s.norm();
  }

  // While sticking the state moves along a = W (f*, 1): u_t stays zero, u_n grows at k = a_n ≥ 0
  // (the Schur complement of W_tt): closed form to the end of compression and of restitution.
  ImpactCourse stick(State y, SlipCourse course) {
    course_.course = course;
    return straight(y, Vec3(hold_.x(), hold_.y(), 1.0), false);
  }

  // A slip resumed from rest along ŝ stays along it to the end: its rate W_tn − μk W_tt ŝ is λ ŝ
  // (resume), so the friction −μk ŝ, and every rate, are constant.
  ImpactCourse slide_straight(State y) {
    return straight(y, Vec3(-mu_k_ * resume_direction_.x(), -mu_k_ * resume_direction_.y(), 1.0),
                    true);
  }

  // With a constant friction f per unit normal impulse the state moves along a = W (f_t, 1): u_n
  // grows at k = a_n (≥ 0 while sticking: the Schur complement of W_tt), the slip at a_t where it
  // `slips` (sticking, it stays zero): closed form to the end of compression and of restitution.
  ImpactCourse straight(State y, const Vec3& f, bool slips) {
    const Vec3 a = W_ * f;
    const double k = a.z();
    const auto advance = [&](double dp) {
      const double u_n = y[2];
      y[kWork] += u_n * dp + 0.5 * k * dp * dp;
      y[2] += k * dp;
      if (slips) {
        y[0] += a.x() * dp;
        y[1] += a.y() * dp;
      }
      for (int j = 0; j < 3; ++j) y[3 + j] += f[j] * dp;
    };
    if (!compressed_) {
      if (k > 1e-14 && y[2] < 0.0) {
        advance(-y[2] / k);
        y[2] = 0.0;  // compression's end
      } else if (slips && y[2] < 0.0) {
        jammed(0.0);
      }
      y[2] = std::max(y[2], 0.0);  // where k = 0 it is held still: the impact ends, u = 0
      end_compression(y);
    }
    const double remaining = target_ - y[kWork];
    if (remaining > 0.0 && k > 1e-14) {  // u_n s + k s² / 2 = remaining, s > 0
      advance(2.0 * remaining / (y[2] + std::sqrt(y[2] * y[2] + 2.0 * k * remaining)));
    }
    if (!slips) y[0] = y[1] = 0.0;
    return finish(y);
  }

  [[noreturn]] void jammed(double p) const {
    throw NumericalError(fmt::format(
        "the impact does not end: friction (μk = {}) keeps the contact from separating (the "
        "normal impulse has passed {:g} times the frictionless one's; Painlevé's jam)",
        mu_k_, p));
  }

  // From the end of compression the work is counted afresh, towards e² of compression's (so the
  // end is found to round-off where e is small and the work's rate with it).
  void end_compression(State& y) {
    compressed_ = true;
    course_.compression_impulse = y[5];
    target_ = -e_ * e_ * y[kWork];
    y[kWork] = 0.0;
  }

  ImpactCourse finish(const State& y) {
    course_.u_after = velocity_of(y);
    course_.impulse = Vec3(y[3], y[4], y[5]);
    return course_;
  }

  // The event this state has passed: compression's end (u_n ≥ 0), then the impact's (the work in
  // restitution e² of compression's).
  double event_value(const State& y) const { return compressed_ ? y[kWork] - target_ : y[2]; }

  ImpactCourse slide(State y) {
    Sliding rate{&W_, mu_k_, resume_direction_};
    auto controlled = odeint::make_controlled(1e-13, 1e-13, odeint::runge_kutta_dopri5<State>());
    odeint::runge_kutta_dopri5<State> single;
    // One step from `from` (its rate given: the stepper's own would be its last step's end's).
    const auto step = [&](const State& from, double p, double h) {
      State to, from_rate, to_rate;
      rate(from, from_rate, p);
      single.do_step(rate, from, from_rate, p, to, to_rate, h);
      return to;
    };
    // A straight approach to the slip's rest keeps its rate to the end: the state is linear in p
    // and the work quadratic. (The stepper's last stage would see the slip reversed there.)
    const auto straight = [&](const State& from, const State& from_rate, double h) {
      State to;
      for (int k = 0; k < kWork; ++k) to[k] = from[k] + from_rate[k] * h;
      to[kWork] = from[kWork] + from[2] * h + 0.5 * from_rate[2] * h * h;
      return to;
    };
    double p = 0.0, dp = 1.0 / 64;
    for (int steps = 0; steps < kMostSteps; ++steps) {
      if (p > kJammed) break;
      if (!compressed_ && y[2] >= 0.0) {
        end_compression(y);
        if (e_ == 0.0) return finish(y);
      }
      const Vec2 slip = slip_of(y);
      const double speed = slip.norm();
      if (speed <= kSlipAtRest) {  // the slip has come to rest
        y[0] = y[1] = 0.0;
        if (course_.course == SlipCourse::slides && holds()) return stick(y, SlipCourse::stops);
        resume(SlipCourse::slides_again);
        return slide_straight(y);
      }
      // Never past the slip's rest: a straight approach lands on it, a turning one halves it.
      State dy;
      rate(y, dy, p);
      const Vec2 d_t(dy[0], dy[1]);
      double h = dp;
      bool lands = false;
      if (speed > kSlipAtRest && slip.dot(d_t) < 0.0) {
        const Vec2 s = slip / speed;
        const double to_rest = speed / -s.dot(d_t);
        const double across = std::abs(s.x() * d_t.y() - s.y() * d_t.x());
        if (across <= 1e-12 * d_t.norm() || speed <= kLandingSpeed) {
          if (to_rest <= h) {
            h = to_rest;
            lands = true;
          }
        } else {
          h = std::min(h, 0.5 * to_rest);
        }
      }
      State next;
      double h_next = h;
      if (lands) {
        next = straight(y, dy, h);
      } else {
        State next_rate;
        double p_next = p;
        if (controlled.try_step(rate, y, dy, p_next, next, next_rate, h_next) == odeint::fail) {
          dp = h_next;
          continue;
        }
      }
      const auto reached = [&](double s) { return lands ? straight(y, dy, s) : step(y, p, s); };
      if (event_value(next) >= 0.0) {  // an event within the step: the first instant of it
        const auto value = [&](double s) { return event_value(reached(s)); };
        std::uintmax_t iterations = 200;
        const auto close = [](double a, double b) {
          return std::abs(a - b) <=
                 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b));
        };
        const double start = event_value(y);
        double at = h;
        if (start < 0.0 && h > 0.0) {
          const auto [lo, hi] = boost::math::tools::toms748_solve(
              value, 0.0, h, start, event_value(next), close, iterations);
          at = value(lo) >= 0.0 ? lo : hi;
        }
        y = reached(at);
        p += at;
        if (compressed_) return finish(y);
        continue;  // compression's end, taken at the loop's top
      }
      y = next;
      p += h;
      if (lands) {
        y[0] = y[1] = 0.0;
      } else {
        dp = h_next;
      }
    }
    jammed(p);
  }

  Mat3 W_;
  double e_, mu_s_, mu_k_;
  Vec2 hold_;
  Vec2 resume_direction_ = Vec2::Zero();
  bool compressed_ = false;
  double target_ = 0.0;
  ImpactCourse course_;
};

}  // namespace

ImpactCourse follow_impact(const Mat3& W, const Vec3& u_before, double restitution,
                           double static_friction, double kinetic_friction) {
  const double u_scale = u_before.norm();
  const double p_scale = u_scale / W(2, 2);
  ImpactCourse course = Course(W / W(2, 2), restitution, static_friction, kinetic_friction)
                            .run(Vec3(u_before / u_scale));
  course.impulse *= p_scale;
  course.u_after *= u_scale;
  course.compression_impulse *= p_scale;
  return course;
}

}  // namespace momenta::dynamics::detail
