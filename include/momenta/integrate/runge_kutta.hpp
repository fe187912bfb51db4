#pragma once
// Explicit Runge–Kutta methods on the configuration manifold: fixed-step RK4 and adaptive
// Dormand–Prince 5(4).
//
// Stages live in local coordinates about the step's start, q = q0 ⊕ δ, with δ̇ = dexp⁻¹_δ(v)
// (Runge–Kutta–Munthe-Kaas, Munthe-Kaas 1998): quaternions advance by the exponential map, never
// by adding to the quaternion and renormalizing, and the methods keep their classical order.

#include <optional>
#include <string>
#include <vector>

#include "momenta/integrate/integrator.hpp"
#include "momenta/integrate/second_order_system.hpp"

namespace momenta::integrate {

namespace detail {
/// Workspace and stage evaluation shared by the explicit methods.
class LocalStages {
 public:
  void resize(int nq, int nv, int stages);
  /// Stage i: δ = h Σ_j<i a_ij kq_j, v = v0 + h Σ_j<i a_ij kv_j, q = q0 ⊕ δ; then
  /// kq_i = dexp⁻¹_δ(v) and kv_i = a(t0 + c_i h, q, v). Stage 0 needs kv_0 set by the caller.
  void evaluate(SecondOrderSystem& system, const State& start, double h, int i, const double* a,
                double c, long& evaluations);
  /// δ = h Σ b_j kq_j and v = v0 + h Σ b_j kv_j over `stages` stages.
  void combine(const State& start, double h, const double* b, int stages, VecX& delta,
               VecX& v) const;

  std::vector<VecX> kq, kv;  // stage rates of δ and v
  VecX delta, v, q;          // the stage point being evaluated
};
}  // namespace detail

/// Classic fourth-order Runge–Kutta with a fixed step (4 evaluations per step).
class RungeKutta4 final : public Integrator {
 public:
  std::string_view name() const override { return "rk4"; }
  int order() const override { return 4; }
  void initialize(SecondOrderSystem& system, const State& state) override;
  double step(SecondOrderSystem& system, State& state, double h) override;

 private:
  detail::LocalStages stages_;
  VecX delta_;
};

/// Dormand–Prince 5(4) (Dormand & Prince 1980; Hairer, Nørsett & Wanner, Solving ODEs I, §II.5)
/// with PI step-size control, first-same-as-last, and a fourth-order dense output.
/// The error of each step is measured in the root-mean-square norm of e_i / (atol + rtol·|x_i|)
/// over δ and v (|x| of rotation coordinates counts as 1 rad) and kept ≤ 1.
class DormandPrince5 final : public Integrator {
 public:
  explicit DormandPrince5(const Tolerances& tolerances = {});

  std::string_view name() const override { return "dopri5"; }
  int order() const override { return 5; }
  bool adaptive() const override { return true; }
  void initialize(SecondOrderSystem& system, const State& state) override;
  double step(SecondOrderSystem& system, State& state, double h_max) override;
  void state_changed() override { have_last_acceleration_ = false; }

  /// The state at time t within the last accepted step [t_prev, t] from the dense output (fourth
  /// order); `out` must be sized like the state. Throws InvalidArgument outside that interval.
  bool has_dense_output() const override { return true; }
  void interpolate(const SecondOrderSystem& system, double t, State& out) const override;

  /// The step size the controller proposes next.
  double proposed_step() const { return h_; }

 private:
  double initial_step(SecondOrderSystem& system, const State& state);
  // Stages 1..6 of a step of h from `state`; false where one met a point where the acceleration
  // has no value (kept in undefined_).
  bool evaluate_stages(SecondOrderSystem& system, const State& state, double h);
  double error_norm(const State& start, const VecX& v1) const;
  void estimate_stiffness(double h, double t);
  // The coordinate whose last error estimate is largest, "name = value", for messages.
  std::string largest_error_coordinate(const SecondOrderSystem& system, const State& state) const;

  Tolerances tolerances_;
  detail::LocalStages stages_;
  VecX delta1_, v1_, error_delta_, error_v_, scale_q0_, scale_q1_;
  VecX q_prev_, v_prev_;                 // start of the last accepted step
  VecX delta6_, v6_;                     // the sixth stage's point, for the stiffness estimate
  int stiff_streak_ = 0;                 // stability-limited steps in a row
  VecX dense_[5];                        // dense-output coefficients over (δ, v), size 2 nv each
  double t_prev_ = 0.0, h_prev_ = 0.0;   // the last accepted step
  double h_ = 0.0;                       // proposed next step
  double previous_error_ = 1e-4;         // for the PI controller
  bool have_last_acceleration_ = false;  // first-same-as-last
  bool last_rejected_ = false;
  // What a stage of the steps rejected since the last accepted one met (UndefinedAcceleration).
  std::optional<UndefinedAcceleration> undefined_;
  int controlled_ = 0;  // SecondOrderSystem::error_controlled()
};

}  // namespace momenta::integrate
