#pragma once
// Data: the preallocated workspace and results of the dynamics algorithms for one Model.
//
// Build one Data per Model (and per thread); every algorithm then runs without allocating.
// Per-body arrays have num_bodies() entries indexed by body (entry 0, the world, stays at rest);
// per-joint arrays have num_joints() entries. Spatial vectors are rotation first; "in B" means
// expressed in body frame B about its origin Bo (Featherstone's body coordinates).
//
// Which algorithm sets which field is listed with each field. Fields not listed for an
// algorithm are left untouched by it.
//
// Every algorithm checks its arguments at the door, always: q of size nq, v, vdot and tau of
// size nv, f_ext empty or one wrench per body, and a Data built for a model of this size; a
// mismatch throws InvalidArgument naming the algorithm, the argument and both sizes
// ("aba: q has size 3; the model needs 7 (nq)").

#include <utility>
#include <vector>

#include <Eigen/Cholesky>

#include "momenta/math/spatial.hpp"
#include "momenta/model/model.hpp"

namespace momenta::dynamics {

using model::Model;

/// The Coriolis inertia of rigid bodies moving with spatial velocities Vᵢ, Σ Bᵢ with
/// Bᵢ = crf(Vᵢ) Iᵢ − Iᵢ crm(Vᵢ) + (· ×* Iᵢ Vᵢ): how their momenta's rate changes with a
/// perturbation x of their velocities, beyond I ẋ. For a rigid body's inertia [I_O [h]×; [h]×ᵀ m 1]
/// its matrix is [B_ω 0; −2 [p]× 0], p = m v − h × ω the body's linear momentum and
/// B_ω = −(I_O [ω]× + [h]× [v]×) − (…)ᵀ − [n]×, n its angular momentum about the origin: its
/// right-hand blocks vanish (rnea_derivatives.cpp), and so do a sum's.
struct CoriolisInertia {
  Mat3 angular = Mat3::Zero();   ///< B_ω, the upper-left block.
  Vec3 momentum = Vec3::Zero();  ///< p: the lower-left block is −2 [p]×.
};

struct Data {
  /// Sizes every array for `model`.
  explicit Data(const Model& model);

  // --- Position: forward_kinematics(q) (X_PB and S also by rnea, aba, crba, hybrid_dynamics) ----
  std::vector<Transform> X_PB;  ///< Pose of body B in its parent body frame P.
  std::vector<Transform> X_WB;  ///< Pose of body B in the world. Also set by crba and
                                ///< joint_reactions; not by rnea/aba.
  /// Motion subspace of joint j in its child body frame (6 × nv_j, leading columns; constant
  /// for 1-dof joints and the spherical joint).
  std::vector<Mat6> S;

  // --- Velocity: forward_kinematics(q, v) (also rnea, aba, hybrid_dynamics) ---------------------
  std::vector<Vec6> V_WB_B;  ///< Spatial velocity of B in W, in B: [w_WB_B; v_WBo_B].
  /// Velocity-product acceleration of joint j's child B, in B: V_WB × S v + Ṡ v.
  std::vector<Vec6> c_B;

  // --- Acceleration: forward_kinematics(q, v, vdot) -------------------------------------------
  /// Spatial acceleration of B in W, in B (Featherstone: the rate of the components of V_WB_B,
  /// so the classical acceleration of Bo is linear(A) + w × v; see body_acceleration_in_world).
  std::vector<Vec6> A_WB_B;
  /// The part of A_WB_B present with vdot = 0 (velocity products: Coriolis and centripetal).
  std::vector<Vec6> A_bias_B;

  // --- Forces: rnea, joint_reactions ----------------------------------------------------------
  /// Wrench transmitted by the joint carrying B, from its parent onto B, in B (about Bo).
  std::vector<Vec6> F_B;

  // --- Workspace of rnea / aba / hybrid_dynamics ---------------------------------------------
  /// Acceleration shifted by −g (Featherstone's a₀ = −g trick), in B; rnea sets entry 0, the
  /// world's, to [0; −g].
  std::vector<Vec6> A_gf;
  std::vector<Mat6> IA;    ///< Articulated-body inertia, in B.
  std::vector<Vec6> pA;    ///< Articulated-body bias force, in B.
  std::vector<Mat6> U;     ///< IA S per joint (leading nv columns).
  std::vector<Mat6> Dinv;  ///< (Sᵀ IA S)⁻¹ per joint (leading nv × nv block).
  std::vector<Vec6> u;     ///< τ − Sᵀ pA per joint (leading nv entries).

  // --- Workspace of articulated_solve (kSolveColumns columns at a time) ------------------------
  static constexpr int kSolveColumns = 4;
  using SolveColumns = Eigen::Matrix<double, 6, kSolveColumns>;
  /// Per body: the forces its subtree passes to its joint, in B (zero between calls).
  std::vector<SolveColumns> solve_f;
  std::vector<SolveColumns> solve_a;  ///< Per body: its spatial accelerations, in B.
  /// Per 1-dof joint: ᵖX_i* U_j D_j⁻¹, its articulated factor carried to the parent (the first
  /// pass sets it, the second reads it).
  std::vector<Vec6> solve_U_parent;

  // --- Workspace of crba -----------------------------------------------------------------------
  std::vector<SpatialInertia> I_composite;  ///< Composite inertia of B's subtree, in B about Bo.
  /// nv × 6: row k is velocity coordinate k's motion-subspace column in W about Wo, transposed
  /// (so the products of crba run along contiguous memory).
  MatX S_W;
  /// Per joint: the velocity-coordinate ranges [start, start + size) of the joint and all its
  /// ancestors, merged into contiguous runs (one run for a serial chain). Fixed by the model.
  std::vector<std::vector<std::pair<int, int>>> support_ranges;
  bool all_dofs_related = true;  ///< Every pair of joints is ancestor-related (M has no zeros).

  // --- Workspace of rnea_derivatives / aba_derivatives (world frame, about Wo) --------------
  std::vector<Vec6> dV_W;  ///< Per body: spatial velocity V_WB in W.
  std::vector<Vec6> dA_W;  ///< Per body: spatial acceleration shifted by −g, in W.
  std::vector<Vec6> dF_W;  ///< Per body: net force of B's subtree, in W (after the pass).
  std::vector<SpatialInertia> dIc_W;  ///< Per body: composite inertia of B's subtree, in W.
  /// Per body: Σ over B's subtree of the bodies' Coriolis inertias Bᵢ x = −Iᵢ(Vᵢ × x) +
  /// x ×* Iᵢ Vᵢ + Vᵢ ×* Iᵢ x, in W.
  std::vector<CoriolisInertia> dB_W;
  /// 6 × nv per velocity coordinate k, in W: its motion-subspace column S_k, and the terms its
  /// derivatives need (rnea_derivatives.cpp): ΔV_k = V_p × S_k, x_k = A_p × S_k − ΔV_k × V_p,
  /// W_k = (V_s + V_p) × S_k, with V_p, A_p the velocity and acceleration of the frame before
  /// the coordinate's stage of its joint and V_s after it.
  Mat6X dS_W, dDeltaV_W, dX_W, dW_W;

  // --- Workspace of aba_derivatives' M⁻¹ (Carpentier 2018; aba_derivatives.cpp), in W ----------
  Mat6X minv_U_W;  ///< 6 × nv: U = IA S of each velocity coordinate's joint, column by column.
  /// 6 × nv: column k, the force that a unit generalized force at coordinate k passes up through
  /// the bodies below the joint being visited (the backward pass).
  Mat6X minv_F_W;
  /// Per body, 6 × nv: column k (for k at or after the body's joint), its acceleration under a
  /// unit generalized force at coordinate k (the forward pass; the world's stays zero). With
  /// 6 nv doubles a body, the largest of Data's arrays (as many as six nv × nv matrices for a
  /// chain of 1-dof joints: 0.8 MB at 128 bodies), as Pinocchio's per-joint Fcrb.
  std::vector<Mat6X> minv_A_W;
  /// Per joint: the velocity-coordinate ranges [start, start + size) of the joint and all its
  /// descendants, merged into contiguous runs, ascending (the joint's own first). Fixed by the
  /// model.
  std::vector<std::vector<std::pair<int, int>>> subtree_ranges;

  // --- Workspace of aba_derivatives' products −M⁻¹ ∂τ (aba_derivatives.cpp), in W -------------
  /// 9 × nv: per velocity coordinate m, [Ic S_m; (Bᵀ S_m)_ω] (Ic, B of its joint's subtree;
  /// (Bᵀ S_m)_v is zero): the entries (m, k) of ∂τ where k moves m (k ≤ m in a chain) are its
  /// dot products with [x_k; (ΔV_k)_ω] (∂/∂q) and [W_k; (S_k)_ω] (∂/∂v).
  Eigen::Matrix<double, 9, Eigen::Dynamic> dtau_lower_W;
  /// 6 × nv each: per velocity coordinate m, G_m and H_m: the entries (k, m) of ∂τ/∂q and ∂τ/∂v
  /// where k is above m (k < m in a chain) are S_kᵀ G_m and S_kᵀ H_m.
  Mat6X dtau_upper_q_W, dtau_upper_v_W;
  /// Running sums of M⁻¹'s columns times those factors, nv × 9 (Σ M⁻¹ₘ (dtau_lower_W)ₘᵀ over
  /// a joint's subtree) and nv × 6 (Σ M⁻¹ₖ S_kᵀ over a joint's ancestors), in a few buffers
  /// that the joints share: one each for a chain, one more per branch still open for a tree.
  std::vector<MatX> minv_lower_sums, minv_upper_sums;
  std::vector<int> minv_lower_slot;  ///< Per joint: which of minv_lower_sums holds its sum.
  std::vector<int> minv_upper_slot;  ///< Per joint: which of minv_upper_sums holds its sum.
  /// Per joint: the joints whose parent body is its child body, ascending. Fixed by the model.
  std::vector<std::vector<int>> child_joints;

  // --- Results of rnea_derivatives / aba_derivatives -----------------------------------------
  MatX dtau_dq;   ///< nv × nv: ∂τ/∂q on the tangent space (rnea_derivatives).
  MatX dtau_dv;   ///< nv × nv: ∂τ/∂v (rnea_derivatives).
  MatX dvdot_dq;  ///< nv × nv: ∂v̇/∂q on the tangent space (aba_derivatives).
  MatX dvdot_dv;  ///< nv × nv: ∂v̇/∂v (aba_derivatives).
  MatX Minv;      ///< nv × nv: M(q)⁻¹ = ∂v̇/∂τ (aba_derivatives; both triangles filled).
  MatX dQ_dq;     ///< nv × nv: ∂Q/∂q of the force elements (force_element_derivatives).
  MatX dQ_dv;     ///< nv × nv: ∂Q/∂v of the force elements (force_element_derivatives).
  std::vector<Vec6> dLoad_W;  ///< Per body: the force elements' wrench on B's subtree, in W.

  // --- Results -------------------------------------------------------------------------------
  VecX tau;   ///< nv: rnea's inverse dynamics; hybrid_dynamics' full generalized forces.
  VecX vdot;  ///< nv: aba's and hybrid_dynamics' accelerations.
  VecX nle;   ///< nv: nonlinear_effects, C(q, v) v + g(q).
  /// Per joint: cos q and sin q of a joint turning about an axis (crba takes them all first,
  /// where their computations overlap).
  VecX axis_cos, axis_sin;
  VecX g;  ///< nv: generalized_gravity, g(q).
  MatX M;  ///< nv × nv: crba's mass matrix (both triangles filled).

  // --- Scratch sized nv for the convenience paths (not results) ------------------------------
  VecX scratch_nv;
  /// The model's prescribed joints (num_joints() entries, 1 = prescribed), for hybrid_dynamics.
  std::vector<char> prescribed_mask;
};

}  // namespace momenta::dynamics
