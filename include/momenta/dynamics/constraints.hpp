#pragma once
// The model's constraints (model/constraint.hpp) as rows of equations at one instant:
//
//   position rows      φ(q) = 0                 (holonomic rows only)
//   velocity rows      G(q) v = 0               (every row; on holonomic rows G v = φ̇ exactly)
//   acceleration rows  G(q) v̇ + k(q, v) = 0     (k = Ġ v, the velocity-product term)
//
// Every row except a coupler's is the power of a wrench: a unit multiplier λ_i applies the
// wrench w_i (expressed in W about Wo, [moment; force]) to body b and −w_i to body a, and
// G_i v = w_iᵀ (V_b − V_a) with V the bodies' spatial velocities in W about Wo. So G_iᵀ λ_i is the
// generalized force of that wrench pair, and the row's force is read off λ_i directly (a
// translation row's λ is the force along its axis on body b, a rotation row's the moment). The
// velocity-product term follows from the same form: k_i = ẇ_iᵀ (V_b − V_a) + w_iᵀ (A_b − A_a)
// with A the bodies' velocity-product (v̇ = 0) spatial accelerations in W.
//
// Rows, per constraint in model order (the row layout of every vector and matrix here):
//   weld      e_x·d, e_y·d, e_z·d, x_A·y_B, y_A·z_B, z_A·x_B   (d = p_Bo − p_Ao, e_k = A's axes)
//   point     e_x·d, e_y·d, e_z·d
//   hinge     e_x·d, e_y·d, e_z·d, x_A·z_B, y_A·z_B
//   slider    e_x·d, e_y·d, x_A·y_B, y_A·z_B, z_A·x_B
//   distance  |p_b − p_a| − length
//   rolling   height of the contact above the plane; no slip along the rolling direction;
//             no slip sideways (the last two velocity rows only)
//   knife     no velocity across the blade (a velocity row only)
//   coupler   q_a − ratio·q_b − offset (a row of G in joint space, no wrench)
//   contact   the gap n·(p_centre − p_plane) − radius, a force along n at the contact point;
//             with friction, no slip along the plane's tangents t₁, t₂ (velocity rows); each
//             zero while off (ConstraintRows::enabled)

#include <span>
#include <string>
#include <vector>

#include "momenta/dynamics/data.hpp"

namespace momenta::dynamics {

/// The constraint equations of a model at one instant. Sized once for the model; the functions
/// below then fill it without allocating.
struct ConstraintRows {
  explicit ConstraintRows(const Model& model);

  int count = 0;                ///< rows (model.num_constraint_rows())
  std::vector<int> constraint;  ///< per row: index into model.constraints()
  std::vector<int> first_row;   ///< per constraint: its first row
  std::vector<char> holonomic;  ///< per row: 1 for a position row
  /// Per row: 1 where it holds. A unilateral contact's row (model::Contact) starts at 0 (open)
  /// and is switched by whoever runs the contacts (simulate/unilaterals.hpp); constraint_equations
  /// writes a row that is off as zero (φ, G, bias, wrench): it exerts no force and restricts
  /// nothing.
  std::vector<char> enabled;
  VecX position;  ///< φ per row (m or rad); 0 on velocity-only rows
  MatX G;         ///< count × nv
  /// k = Ġ v per row (RowTerms::with_velocity_products), G v̇ + k at data's accelerations
  /// (RowTerms::with_acceleration_residual), or ẇ·(V_b − V_a) (RowTerms::with_wrench_rates).
  VecX bias;
  std::vector<Vec6> wrench_W;       ///< per row: w_i on body b, in W about Wo; zero for a coupler
  std::vector<int> body_a, body_b;  ///< per row: the bodies w_i acts on (a may be the world, 0)
  std::vector<std::string> names;   ///< per row: "<constraint>.<row>" for messages

  MatX S_world;  ///< workspace: 6 × nv, every motion-subspace column in W about Wo
};

/// Which terms constraint_equations computes.
enum class RowTerms {
  jacobian,                ///< φ, G and the wrenches: needs data's poses of q
  with_velocity_products,  ///< also k: needs data's velocities of (q, v) as well
  /// G v̇ + k in `bias` instead of k, for the v̇ of the last aba or hybrid_dynamics (data.vdot
  /// and the bodies' accelerations data.A_gf): what the constraint solver's right-hand side
  /// needs, without the velocity-product pass over the bodies or the product G v̇.
  with_acceleration_residual,
  /// ẇ·(V_b − V_a) in `bias` (0 for a coupler): the part of G v̇ + k that
  /// articulated_row_factors' accelerations leave out (dynamics/articulated_solve.hpp).
  with_wrench_rates,
};

/// φ, G and the wrenches at the configuration of `data`, whose X_PB and S must be those of q (set
/// by forward_kinematics(q), aba, rnea, crba or hybrid_dynamics); also sets data.X_WB. With
/// RowTerms::with_velocity_products, also k: data must then hold the velocities of (q, v) too
/// (V_WB_B and c_B, from forward_kinematics(q, v), aba or hybrid_dynamics), and data.A_bias_B is
/// set. With RowTerms::with_acceleration_residual, bias = G v̇ + k for the accelerations of the
/// aba or hybrid_dynamics call that set data's velocities (data.A_bias_B is not set); with
/// RowTerms::with_wrench_rates, bias = ẇ·(V_b − V_a), for data's velocities alone. Throws
/// NumericalError when a constraint has no direction there (a distance link's points coincide, a
/// rolling disk lies flat on its plane, a knife edge stands on its blade's end). No allocation.
void constraint_equations(const Model& model, Data& data, VecRef q, ConstraintRows& rows,
                          RowTerms terms = RowTerms::jacobian);

/// Adds each row's force, multiplier λ (size rows.count), to the bodies' external wrenches f_ext
/// (num_bodies() entries, in B about Bo, the rnea convention): w_i λ_i on body b, −w_i λ_i on
/// body a. A coupler's rows add G_iᵀ λ_i to tau instead (size nv). Preconditions: the rows and
/// data.X_WB of the same configuration. No allocation.
void add_constraint_forces(const Model& model, const Data& data, const ConstraintRows& rows,
                           VecRef lambda, std::span<Vec6> f_ext, VecX& tau);

/// Writes constraint k's forces (one per model::constraint_force_labels label) from the multipliers
/// λ of `rows`. Preconditions: data.X_WB of the rows' configuration. No allocation.
void constraint_forces(const Model& model, const Data& data, const ConstraintRows& rows,
                       VecRef lambda, int k, std::span<double> out);

}  // namespace momenta::dynamics
