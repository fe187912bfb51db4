#include "momenta/integrate/symplectic_euler.hpp"

namespace momenta::integrate {

void SymplecticEuler::initialize(SecondOrderSystem& system, const State& state) {
  (void)state;
  vdot_ = VecX::Zero(system.nv());
  dq_ = VecX::Zero(system.nv());
  q_next_ = VecX::Zero(system.nq());
  statistics_ = {};
}

double SymplecticEuler::step(SecondOrderSystem& system, State& state, double h) {
  system.begin_step(state.t, state.t + h);
  // Kick the velocity with the acceleration at the old configuration ...
  system.acceleration(state.t, state.q, state.v, vdot_);
  ++statistics_.evaluations;
  state.v.noalias() += h * vdot_;
  // ... then drift the configuration with the new velocity.
  dq_.noalias() = h * state.v;
  system.integrate(state.q, dq_, q_next_);
  state.q.swap(q_next_);
  state.t += h;
  ++statistics_.steps;
  return h;
}

}  // namespace momenta::integrate
