#pragma once
// Small systems with exact solutions, to test integrators without a multibody model.

#include <cmath>

#include "momenta/integrate/second_order_system.hpp"
#include "momenta/math/lie_group.hpp"
#include "momenta/math/rotation.hpp"

namespace momenta::integrate::test {

/// Undamped harmonic oscillator q̈ = −ω² q (one coordinate): q = A cos(ω t), v = −A ω sin(ω t).
class HarmonicOscillator final : public SecondOrderSystem {
 public:
  explicit HarmonicOscillator(double omega) : omega_(omega) {}
  int nq() const override { return 1; }
  int nv() const override { return 1; }
  void acceleration(double, const VecX& q, const VecX&, VecX& vdot) override {
    vdot[0] = -omega_ * omega_ * q[0];
  }
  void integrate(const VecX& q, const VecX& dq, VecX& q_out) const override { q_out = q + dq; }
  double energy(const VecX& q, const VecX& v) const {
    return 0.5 * v[0] * v[0] + 0.5 * omega_ * omega_ * q[0] * q[0];
  }

 private:
  double omega_;
};

/// A mass on a spring-damper, m ẍ + c ẋ + k x = u(t), with u a step of `step_force` at
/// `step_time` (announced by next_discontinuity; infinity: none). Overdamped for c² > 4 m k.
class SpringDamper final : public SecondOrderSystem {
 public:
  SpringDamper(double mass, double stiffness, double damping, double step_time = INFINITY,
               double step_force = 0.0)
      : m_(mass), k_(stiffness), c_(damping), step_time_(step_time), step_force_(step_force) {}
  int nq() const override { return 1; }
  int nv() const override { return 1; }
  void acceleration(double t, const VecX& q, const VecX& v, VecX& vdot) override {
    // At the step's time itself the force is its left limit when a step ends there.
    const bool on = t > step_time_ || (t == step_time_ && step_end_ != step_time_);
    vdot[0] = ((on ? step_force_ : 0.0) - k_ * q[0] - c_ * v[0]) / m_;
    ++evaluations;
  }
  void integrate(const VecX& q, const VecX& dq, VecX& q_out) const override { q_out = q + dq; }
  double next_discontinuity(double t) const override {
    return t < step_time_ ? step_time_ : INFINITY;
  }
  void begin_step(double, double t1) override { step_end_ = t1; }

  /// x(t) from x(0) = x0, ẋ(0) = 0 without the step (overdamped: two real exponentials).
  double exact(double t, double x0) const {
    const double d = std::sqrt(c_ * c_ - 4 * m_ * k_);
    const double l1 = (-c_ + d) / (2 * m_), l2 = (-c_ - d) / (2 * m_);
    return x0 * (l2 * std::exp(l1 * t) - l1 * std::exp(l2 * t)) / (l2 - l1);
  }
  long evaluations = 0;

 private:
  double m_, k_, c_, step_time_, step_force_;
  double step_end_ = INFINITY;
};

/// A torque-free rigid body with principal inertia diag(I): q = quaternion q_WB as [w, x, y, z],
/// v = w_WB_B. Euler's equations I ω̇ = −ω × I ω; the attitude advances by q ⊗ exp(δ).
class FreeRigidBody final : public SecondOrderSystem {
 public:
  explicit FreeRigidBody(const Vec3& principal_moments) : I_(principal_moments) {}
  int nq() const override { return 4; }
  int nv() const override { return 3; }
  void acceleration(double, const VecX&, const VecX& v, VecX& vdot) override {
    const Vec3 w = v.head<3>();
    vdot = (-w.cross(I_.cwiseProduct(w))).cwiseQuotient(I_);
  }
  void integrate(const VecX& q, const VecX& dq, VecX& q_out) const override {
    const Quat q_WB = quaternion(q) * quaternion_exp(dq.head<3>());
    q_out << q_WB.w(), q_WB.x(), q_WB.y(), q_WB.z();
  }
  void local_coordinate_rate(const VecX& delta, const VecX& v, VecX& rate) const override {
    rate = so3_right_jacobian_inverse(delta.head<3>()) * v.head<3>();
  }
  void configuration_scale(const VecX&, VecX& scale) const override { scale.setOnes(); }

  static Quat quaternion(const VecX& q) { return Quat(q[0], q[1], q[2], q[3]); }
  double energy(const VecX& v) const { return 0.5 * v.head<3>().dot(I_.cwiseProduct(v.head<3>())); }
  /// Angular momentum in the world frame.
  Vec3 momentum_world(const VecX& q, const VecX& v) const {
    return quaternion(q).toRotationMatrix() * I_.cwiseProduct(v.head<3>());
  }

 private:
  Vec3 I_;
};

/// Exact attitude of an axisymmetric body (I1 = I2): R(t) = Exp(u φ̇ t) R0 Exp(e3 ψ̇ t) with
/// u = H_W/|H|, φ̇ = |H|/I1, ψ̇ = −(I3 − I1) ω3 / I1 (derived by matching I ω_B = Rᵀ H_W).
inline Mat3 axisymmetric_attitude(double I1, double I3, const Mat3& R0, const Vec3& w0, double t,
                                  Vec3* w_out = nullptr) {
  const Vec3 H_W = R0 * Vec3(I1 * w0.x(), I1 * w0.y(), I3 * w0.z());
  const double phi_rate = H_W.norm() / I1;
  const double psi_rate = -(I3 - I1) * w0.z() / I1;
  const Mat3 R = rotation_from_axis_angle(H_W.normalized(), phi_rate * t) * R0 *
                 rotation_from_axis_angle(Vec3::UnitZ(), psi_rate * t);
  if (w_out) *w_out = phi_rate * R.transpose() * H_W.normalized() + psi_rate * Vec3::UnitZ();
  return R;
}

}  // namespace momenta::integrate::test
