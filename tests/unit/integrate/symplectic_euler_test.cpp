#include "momenta/integrate/symplectic_euler.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/model/integrators.hpp"
#include "test_systems.hpp"

namespace momenta::integrate {
namespace {

using test::HarmonicOscillator;

TEST(SymplecticEuler, ConvergesAtFirstOrder) {
  const auto error = [](double h) {
    HarmonicOscillator system(2.0);
    SymplecticEuler euler;
    State state{0.0, VecX::Constant(1, 1.0), VecX::Zero(1)};
    euler.initialize(system, state);
    const int n = static_cast<int>(std::lround(2.0 / h));
    for (int i = 0; i < n; ++i) euler.step(system, state, h);
    return std::hypot(state.q[0] - std::cos(4.0), state.v[0] + 2.0 * std::sin(4.0));
  };
  EXPECT_NEAR(std::log2(error(1e-3) / error(5e-4)), 1.0, 0.02);
}

TEST(SymplecticEuler, EnergyErrorStaysBoundedWithoutDrift) {
  // Symplectic Euler conserves a modified energy H̃ = H + O(h) exactly on the linear oscillator,
  // so the energy error oscillates with amplitude ~ h ω E and never grows (Hairer, Lubich &
  // Wanner, Geometric Numerical Integration, §IX.8). An explicit Euler step would grow it by
  // (1 + h²ω²) per step.
  const double omega = 2.0, h = 0.01;
  HarmonicOscillator system(omega);
  SymplecticEuler euler;
  State state{0.0, VecX::Constant(1, 1.0), VecX::Zero(1)};
  const double E0 = system.energy(state.q, state.v);
  euler.initialize(system, state);
  double worst_first = 0.0, worst_last = 0.0;
  const int n = 1'000'000;  // ~3000 periods
  for (int i = 0; i < n; ++i) {
    euler.step(system, state, h);
    const double error = std::abs(system.energy(state.q, state.v) - E0) / E0;
    (i < n / 10 ? worst_first : worst_last) =
        std::max(i < n / 10 ? worst_first : worst_last, error);
  }
  EXPECT_LT(worst_first, 1.5 * h * omega);
  // No secular growth: the last 90 % of the run reaches the same envelope as the first 10 %.
  EXPECT_LT(worst_last, 1.001 * worst_first);
}

TEST(SymplecticEuler, KeepsQuaternionsOnTheUnitSphere) {
  test::FreeRigidBody system(Vec3(1.0, 2.0, 3.0));
  SymplecticEuler euler;
  State state{0.0, VecX(4), VecX(Vec3(0.01, 2.0, 0.01))};
  state.q << 1.0, 0.0, 0.0, 0.0;
  euler.initialize(system, state);
  for (int i = 0; i < 100'000; ++i) euler.step(system, state, 1e-3);
  // 1e5 exponential updates: round-off drift ~ √n ε ≈ 1e-13, nothing like renormalization error.
  EXPECT_NEAR(state.q.norm(), 1.0, 1e-12);
}

// Every integrator of the general family in the registry (model/integrators.hpp, the one list of
// names) is made here; another name is refused (the registry suggests for typos:
// IntegratorRegistry.*).
TEST(MakeIntegrator, MakesTheRegistrysGeneralFamily) {
  int made = 0;
  for (const model::IntegratorInfo& info : model::integrators()) {
    if (info.family != model::IntegratorFamily::general) continue;
    EXPECT_EQ(make_integrator(info.name)->name(), info.name);
    ++made;
  }
  EXPECT_EQ(made, 5);
  EXPECT_THROW(make_integrator("rk5"), InvalidArgument);
  EXPECT_THROW(make_integrator("splitting"), InvalidArgument);  // system::make_integrator's
}

}  // namespace
}  // namespace momenta::integrate
