#pragma once
// The interface every integrator advances: a mechanical system with configuration q (size nq,
// possibly on a Lie group: quaternions of ball and free joints) and velocity v (size nv, in the
// tangent space), obeying q̇ = "v" and v̇ = a(t, q, v).

#include <limits>
#include <string>

#include "momenta/common/error.hpp"
#include "momenta/math/types.hpp"

namespace momenta::integrate {

/// The acceleration has no value at the state asked about: a point past a singular one, such as
/// a sliding contact whose normal force has no solution there (Painlevé's paradox). An adaptive
/// integrator that meets it at a trial point of a step it has not accepted retries smaller steps
/// (the true motion may leave that way before it gets there: a slip that stops), and throws it on
/// where its step falls below the resolution of time; a fixed-step one, and any at the start of a
/// step, throws it on.
class UndefinedAcceleration : public NumericalError {
 public:
  using NumericalError::NumericalError;
};

class SecondOrderSystem {
 public:
  virtual ~SecondOrderSystem() = default;

  /// Number of configuration coordinates (quaternions count 4).
  virtual int nq() const = 0;
  /// Number of velocity coordinates (the tangent-space dimension; rotations count 3).
  virtual int nv() const = 0;

  /// Writes v̇ = a(t, q, v) into vdot (size nv, already sized). Non-const because implementations
  /// keep a preallocated workspace; must not allocate.
  virtual void acceleration(double t, const VecX& q, const VecX& v, VecX& vdot) = 0;

  /// q_out = q ⊕ dq: moves q along the tangent vector dq (size nv) — the exponential map on
  /// rotation coordinates, plain addition on the others. q_out may not alias q.
  virtual void integrate(const VecX& q, const VecX& dq, VecX& q_out) const = 0;

  /// dq with q1 = q0 ⊕ dq (the inverse of integrate(); on rotations the shortest turn, |dq| ≤ π).
  /// The default, q1 − q0, holds where every coordinate is a vector (nq == nv).
  virtual void difference(const VecX& q0, const VecX& q1, VecX& dq) const { dq = q1 - q0; }

  /// Rate of local coordinates δ (size nv) about a base point, q = q0 ⊕ δ, when the velocity is v:
  /// δ̇ = dexp⁻¹_δ(v). On vector-space coordinates it is v itself (the default); on rotations
  /// with body-frame angular velocity it is J_r(δ)⁻¹ ω. Runge–Kutta methods need it to keep
  /// their order on the group (Munthe-Kaas 1998).
  virtual void local_coordinate_rate(const VecX& delta, const VecX& v, VecX& delta_rate) const {
    (void)delta;
    delta_rate = v;
  }

  /// Magnitude of each tangent coordinate of q (size nv) against which adaptive methods scale
  /// the relative tolerance: |q_i| on vector-space coordinates (the default only knows those
  /// when nq == nv), 1 rad on rotations.
  virtual void configuration_scale(const VecX& q, VecX& scale) const { scale = q.cwiseAbs(); }

  /// How many leading tangent coordinates (of q's tangent and of v alike) the adaptive methods'
  /// error control weighs: all by default. A system that carries derivatives of its state along
  /// with it (identify/trajectory_sensitivities.hpp) controls the state's own, and its extra
  /// coordinates follow the steps the state's accuracy chooses — as CVODES does with its
  /// sensitivities left out of the error test.
  virtual int error_controlled() const { return nv(); }

  /// The first time strictly after t where a(t, q, v) is not smooth in t — an input steps, a
  /// table has a corner. integrate::run ends a step there so that no step straddles it (a step
  /// across a jump would cut the method to first order). +infinity (the default): none.
  virtual double next_discontinuity(double t) const {
    (void)t;
    return std::numeric_limits<double>::infinity();
  }

  /// Announces the step [t0, t1] an integrator is about to take (each attempt of an adaptive
  /// one). Evaluations at t1 then take time-dependent inputs as their limits from the left, so
  /// that a step ending on a discontinuity integrates the inputs it lay over. The default does
  /// nothing (systems without inputs).
  virtual void begin_step(double t0, double t1) {
    (void)t0;
    (void)t1;
  }

  /// Moves a state that has just been stepped to back onto the system's invariant manifold (the
  /// constraints of a constrained model) and returns true when it changed it; integrate::run
  /// calls it after every step and then tells the integrator (Integrator::state_changed). The
  /// default does nothing.
  virtual bool project(double t, VecX& q, VecX& v) {
    (void)t;
    (void)q;
    (void)v;
    return false;
  }

  /// A name for configuration coordinate i (velocity coordinate i when `velocity`), used in
  /// error messages: "hinge.angle". The default is "q[i]" / "v[i]".
  virtual std::string coordinate_name(int i, bool velocity) const {
    return (velocity ? "v[" : "q[") + std::to_string(i) + "]";
  }
};

}  // namespace momenta::integrate
