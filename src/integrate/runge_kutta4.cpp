#include "momenta/integrate/runge_kutta.hpp"

namespace momenta::integrate {

namespace {
// Butcher tableau of the classic method (rows of a, then c and b).
constexpr double kRk4A[4][3] = {{0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}, {0, 0, 1}};
constexpr double kRk4C[4] = {0, 0.5, 0.5, 1};
constexpr double kRk4B[4] = {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6};
}  // namespace

void RungeKutta4::initialize(SecondOrderSystem& system, const State& state) {
  (void)state;
  stages_.resize(system.nq(), system.nv(), 4);
  delta_ = VecX::Zero(system.nv());
  statistics_ = {};
}

double RungeKutta4::step(SecondOrderSystem& system, State& state, double h) {
  system.begin_step(state.t, state.t + h);
  // Stage 0 at the start, where δ = 0 and dexp⁻¹ is the identity.
  stages_.kq[0] = state.v;
  system.acceleration(state.t, state.q, state.v, stages_.kv[0]);
  ++statistics_.evaluations;
  for (int i = 1; i < 4; ++i) {
    stages_.evaluate(system, state, h, i, kRk4A[i], kRk4C[i], statistics_.evaluations);
  }
  // Combine in local coordinates, then map back onto the manifold.
  stages_.combine(state, h, kRk4B, 4, delta_, stages_.v);
  system.integrate(state.q, delta_, stages_.q);
  state.q.swap(stages_.q);
  state.v.swap(stages_.v);
  state.t += h;
  ++statistics_.steps;
  return h;
}

}  // namespace momenta::integrate
