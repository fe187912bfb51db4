#pragma once
// Internal to momenta::analysis: a model's equations of motion as the generalized-force residual
// of its free coordinates, and the difference formulas linearize() and find_equilibrium() share.

#include <string>
#include <vector>

#include "momenta/dynamics/constraint_derivatives.hpp"
#include "momenta/dynamics/data.hpp"
#include "momenta/math/types.hpp"
#include "momenta/model/model.hpp"
#include "momenta/system/multibody_system.hpp"

namespace momenta::analysis::detail {

/// r_f(t, q, v, v̇_f) = [ID(q, v, v̇) − τ_elements(q, v)]_f over the free (not prescribed)
/// coordinates: rnea with the force elements' body wrenches, minus their joint forces. The
/// prescribed coordinates' q, v and v̇ come from their signals (plus the offsets set here), so the
/// motion of the model obeys r_f(t, q, v, a_f(t, q, v)) = 0 with ∂r_f/∂v̇_f = M_ff.
class ModelResidual {
 public:
  explicit ModelResidual(const model::Model& model);

  const model::Model& model() const { return model_; }
  system::MultibodySystem& system() { return system_; }

  /// Velocity indices of the free coordinates, ascending.
  const std::vector<int>& free() const { return free_; }
  int nf() const { return static_cast<int>(free_.size()); }

  /// Offsets of one signal (value, rate, acceleration); every other signal's are zero.
  void set_offset(int signal, double value, double rate, double acceleration);
  void clear_offsets();

  /// r_f (size nf) at (t, q, v) with the free coordinates' accelerations a_free (size nf).
  void residual(double t, const VecX& q, const VecX& v, const VecX& a_free, VecX& r);

  /// As residual(), and also the generalized-force scale of r: max |g_f| + max |(τ_elements +
  /// Jᵀ f_ext)_f| (the magnitudes r sums), for convergence tests.
  void residual_and_scale(double t, const VecX& q, const VecX& v, const VecX& a_free, VecX& r,
                          double& scale);

  /// ∂r_f/∂δq_f and ∂r_f/∂v_f (nf × nf) at (t, q, v) with the free accelerations a_free, analytic:
  /// rnea_derivatives less force_element_derivatives (dynamics/), on the free rows and columns.
  void derivatives(double t, const VecX& q, const VecX& v, const VecX& a_free, MatX& dr_dq,
                   MatX& dr_dv);
  /// ∂r_f/∂δq_i (nf × nv) for every velocity coordinate i, the prescribed ones included, from the
  /// last derivatives(): how r moves when a prescribed coordinate's value does.
  const MatX& dr_dq_all() const { return dr_dq_all_; }

  /// The constraint rows' derivatives (dynamics/constraint_derivatives.hpp) at the state of the
  /// last derivatives() — its prescribed coordinates from their signals, its accelerations —
  /// with multipliers lambda.
  void constraint_derivatives(const VecX& lambda, dynamics::ConstraintDerivatives& out);

  /// M_ff (nf × nf) at q with the prescribed coordinates from their signals at t.
  MatX free_mass(double t, const VecX& q);

 private:
  const model::Model& model_;
  system::MultibodySystem system_;
  dynamics::Data data_;
  std::vector<int> free_;
  std::vector<double> offset_value_, offset_rate_, offset_acceleration_;
  VecX q_, v_, vdot_, r_;
  MatX dr_dq_all_;
  std::vector<double> signal_values_;  // the signals' values at the last residual()
};

/// True when velocity coordinate i of the model is an angle (revolute, a cylindrical or planar
/// joint's angle, universal angles, the rotation of ball and free joints).
bool is_angle_coordinate(const model::Model& model, int i);

/// q_out = q ⊕ s e_i: q moved by s along tangent coordinate i (size nv). `tangent` is a work
/// vector.
void displace(const model::Model& model, const VecX& q, int i, double s, VecX& tangent,
              VecX& q_out);

/// Throws InvalidArgument unless q has size nq, v size nv and every quaternion is unit to 1e-6
/// (`what` names the state in the message); returns q with its quaternions normalized.
VecX checked_configuration(const model::Model& model, const VecX& q, const VecX& v,
                           const std::string& what);

/// Derivative by the central difference d = [f(h) − f(−h)] / 2h of f(s, out); exact for a
/// quadratic f (the odd part of a quadratic is linear).
template <class F>
void central_difference(F&& f, double h, VecX& plus, VecX& minus, VecX& d) {
  f(h, plus);
  f(-h, minus);
  d = (plus - minus) / (2.0 * h);
}

/// Central differences with one Richardson extrapolation, (4 D(h/2) − D(h)) / 3 = f'(0) + O(h⁴).
template <class F>
void richardson_difference(F&& f, double h, VecX& plus, VecX& minus, VecX& coarse, VecX& d) {
  central_difference(f, h, plus, minus, coarse);
  central_difference(f, 0.5 * h, plus, minus, d);
  d = (4.0 * d - coarse) / 3.0;
}

}  // namespace momenta::analysis::detail
