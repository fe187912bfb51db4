#pragma once
// Loading the bundled examples (examples/*.yaml) and simulating them, for their validation tests.
// Tests run from the source tree (tests/CMakeLists.txt), so examples/ is a relative path.

#include <filesystem>
#include <functional>
#include <string>

#include "momenta/integrate/run.hpp"
#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/system/multibody_system.hpp"

namespace momenta::test {

inline io::ModelFile load_example(const std::string& name) {
  return io::read_model_file(std::filesystem::path("examples") / (name + ".yaml"));
}

/// The model's initial state at t = 0, prescribed coordinates applied.
inline integrate::State initial_state(system::MultibodySystem& system) {
  integrate::State state{0.0, system.model().initial_q(), system.model().initial_v()};
  system.apply_prescribed_motion(state.t, state.q, state.v);
  return state;
}

/// Simulates `system` from its initial state to t_end with classic RK4 steps of h, calling
/// observe(state) at the start and after every step (prescribed coordinates applied).
inline integrate::State simulate_rk4(system::MultibodySystem& system, double t_end, double h,
                                     const std::function<void(const integrate::State&)>& observe) {
  integrate::State state = initial_state(system);
  integrate::RungeKutta4 rk4;
  integrate::run(system, rk4, state, {t_end, h, 1}, [&](const integrate::State& s) {
    integrate::State exact = s;
    system.apply_prescribed_motion(exact.t, exact.q, exact.v);
    observe(exact);
  });
  return state;
}

/// Times where x(t) crosses zero downwards (from positive to non-positive), located on each step
/// [t0, t1] by the cubic Hermite interpolant of (x, ẋ) at its ends — O(h⁴) accurate like the
/// RK4 solution it reads — and bisection.
class DownwardCrossings {
 public:
  void add(double t, double x, double x_dot) {
    if (has_last_ && last_x_ > 0 && x <= 0) {
      const double h = t - last_t_;
      const auto p = [&](double s) {
        const double s2 = s * s, s3 = s2 * s;
        return (2 * s3 - 3 * s2 + 1) * last_x_ + (s3 - 2 * s2 + s) * h * last_x_dot_ +
               (-2 * s3 + 3 * s2) * x + (s3 - s2) * h * x_dot;
      };
      double lo = 0, hi = 1;
      for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (p(mid) > 0 ? lo : hi) = mid;
      }
      times.push_back(last_t_ + 0.5 * (lo + hi) * h);
    }
    last_t_ = t;
    last_x_ = x;
    last_x_dot_ = x_dot;
    has_last_ = true;
  }
  std::vector<double> times;

 private:
  bool has_last_ = false;
  double last_t_ = 0, last_x_ = 0, last_x_dot_ = 0;
};

}  // namespace momenta::test
