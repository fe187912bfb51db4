#include "momenta/dynamics/rnea_derivatives.hpp"

#include "argument_checks.hpp"

#include "forward_pass.hpp"
#include "joint_stages.hpp"
#include "rnea_derivatives_detail.hpp"

namespace momenta::dynamics {
namespace {

using detail::joint_stage;
using detail::joint_stage_count;

// A rigid body's Coriolis inertia B = crf(V) I − I crm(V) + (· ×* I V) (data.hpp). With
// P = I crm(V) and crf(V) I = −Pᵀ, B = (· ×* I V) − P − Pᵀ; by blocks, with Ω = [ω]×, [h]× [v]× =
// v hᵀ − (h·v) 1 and I V = [n; p]: the upper-left −(I_O Ω + v hᵀ − (h·v) 1) − (…)ᵀ − [n]×; the
// upper-right −[h]× Ω − (−[h]× Ω + m [v]×)ᵀ − [p]× = [ω × h + m v − p]× = 0; the lower-left
// −(−[h]× Ω + m [v]×) − ([h]× Ω)ᵀ − [p]× = −[ω × h + m v]× − [p]× = −2 [p]×; the lower-right
// −m (Ω + Ωᵀ) = 0.
CoriolisInertia coriolis_inertia(const SpatialInertia& I, const Vec6& V, const Vec6& momentum) {
  const Vec3 w = V.head<3>();
  const Vec3 v = V.tail<3>();
  const Mat3 K = I.I_O * skew(w);
  CoriolisInertia B;
  B.angular =
      -K - K.transpose() - v * I.h.transpose() - I.h * v.transpose() - skew(momentum.head<3>());
  B.angular.diagonal().array() += 2.0 * I.h.dot(v);
  B.momentum = momentum.tail<3>();
  return B;
}

// B x = [B_ω x_ω; −2 p × x_ω].
Vec6 coriolis_times(const CoriolisInertia& B, const Vec6& x) {
  const Vec3 x_w = x.head<3>();
  Vec6 out;
  out << B.angular * x_w, -2.0 * B.momentum.cross(x_w);
  return out;
}

// (Bᵀ y)_ω = B_ωᵀ y_ω + 2 p × y_v; (Bᵀ y)_v is zero.
Vec3 coriolis_transpose_times(const CoriolisInertia& B, const Vec6& y) {
  return B.angular.transpose() * y.head<3>() + 2.0 * B.momentum.cross(y.tail<3>());
}

// Forward pass in W: each body's V, A (shifted by −g), own net force f = I A + V ×* I V − f_ext,
// inertia I and Coriolis inertia B, and each velocity coordinate's column and derivative terms.
void forward_pass(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot,
                  std::span<const Vec6> f_ext, bool positions_current) {
  const auto& joints = model.joint_constants();
  data.dV_W[0].setZero();
  data.dA_W[0] = spatial(Vec3::Zero(), -model.gravity());
  data.dF_W[0].setZero();  // the world's sums are not used; kept from growing
  data.dIc_W[0] = SpatialInertia();
  data.dB_W[0] = CoriolisInertia();
  for (int j = 0; j < static_cast<int>(joints.size()); ++j) {
    const auto& c = joints[j];
    const int i = c.child;
    if (!positions_current) detail::position_step(c, j, q.data(), data);
    const Transform X_WB = data.X_WB[c.parent] * data.X_PB[i];
    data.X_WB[i] = X_WB;

    // Stage by stage: V_s = V_p + Σ S_k v_k, A_s = A_p + Σ (S_k v̇_k + (V_s × S_k) v_k).
    Vec6 V = data.dV_W[c.parent];
    Vec6 A = data.dA_W[c.parent];
    if (c.nv == 1) {  // one stage of one column S: V_s × S = V_p × S = ΔV (S × S = 0), W = 2 ΔV
      const int vk = c.v_index;
      const Vec6 S = X_WB.act_motion(data.S[j].col(0));
      const Vec6 delta_V = cross_motion(V, S);
      data.dS_W.col(vk) = S;
      data.dDeltaV_W.col(vk) = delta_V;
      data.dX_W.col(vk) = cross_motion(A, S) - cross_motion(delta_V, V);
      data.dW_W.col(vk) = 2.0 * delta_V;
      V += S * v[vk];
      A += S * vdot[vk] + delta_V * v[vk];
    }
    for (int s = 0; s < joint_stage_count(c.type) && c.nv > 1; ++s) {
      const Vec6 V_p = V;
      const Vec6 A_p = A;
      for (int k = 0; k < c.nv; ++k) {
        if (joint_stage(c.type, k) != s) continue;
        const int vk = c.v_index + k;
        data.dS_W.col(vk) = X_WB.act_motion(data.S[j].col(k));
        V += data.dS_W.col(vk) * v[vk];
      }
      for (int k = 0; k < c.nv; ++k) {
        if (joint_stage(c.type, k) != s) continue;
        const int vk = c.v_index + k;
        const Vec6 S_k = data.dS_W.col(vk);
        A += S_k * vdot[vk] + cross_motion(V, S_k) * v[vk];
        const Vec6 delta_V = cross_motion(V_p, S_k);
        data.dDeltaV_W.col(vk) = delta_V;
        data.dX_W.col(vk) = cross_motion(A_p, S_k) - cross_motion(delta_V, V_p);
        data.dW_W.col(vk) = cross_motion(V + V_p, S_k);
      }
    }
    data.dV_W[i] = V;
    data.dA_W[i] = A;

    // The body's own force, inertia and Coriolis inertia, in W.
    const SpatialInertia I = model.spatial_inertia(i).transformed(X_WB);
    const Vec6 h = I * V;
    Vec6 f = I * A + cross_force(V, h);
    if (!f_ext.empty()) f -= X_WB.act_force(f_ext[i]);
    data.dF_W[i] = f;
    data.dIc_W[i] = I;
    data.dB_W[i] = coriolis_inertia(I, V, h);
  }
}

// What the backward pass leaves: the entries of ∂τ/∂q, ∂τ/∂v and M, and τ (rnea_derivatives),
// or the factors those entries are products of, per coordinate (aba_derivatives, which applies
// M⁻¹ to the factors instead of to the entries).
enum class Output { entries, factors };

void derivative_passes(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot,
                       std::span<const Vec6> f_ext, bool positions_current, Output output) {
  forward_pass(model, data, q, v, vdot, f_ext, positions_current);

  // Otherwise the pass below writes every entry.
  if (output == Output::entries && !data.all_dofs_related) {
    data.dtau_dq.setZero();
    data.dtau_dv.setZero();
    data.M.setZero();
  }
  const auto& joints = model.joint_constants();
  for (int j = static_cast<int>(joints.size()) - 1; j >= 0; --j) {
    const auto& c = joints[j];
    const int i = c.child;
    const SpatialInertia& Ic = data.dIc_W[i];
    const CoriolisInertia& B = data.dB_W[i];
    const Vec6& F = data.dF_W[i];
    for (int m = 0; m < c.nv; ++m) {
      const int vm = c.v_index + m;
      const int stage_m = joint_stage(c.type, m);
      const Vec6 S_m = data.dS_W.col(vm);
      const Vec6 IS_m = Ic * S_m;  // Ic is symmetric: S_mᵀ Ic = (Ic S_m)ᵀ
      const Vec3 BtS_m = coriolis_transpose_times(B, S_m);  // (Bᵀ S_m)_v = 0
      // Entries (m, k) where coordinate k moves S_m (k in an ancestor joint, or in this joint at
      // m's stage or an earlier one): S_mᵀ (Ic x_k + B ΔV_k), the S_k ×* terms cancelling with
      // S_m's own turn. Entries (k, m) where coordinate m moves the subtree under a still S_k (k
      // in an ancestor joint or an earlier stage): S_kᵀ (S_m ×* F + Ic x_m + B ΔV_m). The same
      // for ∂/∂v with W and S in place of x and ΔV, and M from Ic.
      const Vec6 G = cross_force(S_m, F) + Ic * Vec6(data.dX_W.col(vm)) +
                     coriolis_times(B, data.dDeltaV_W.col(vm));
      const Vec6 H = Ic * Vec6(data.dW_W.col(vm)) + coriolis_times(B, S_m);
      if (output == Output::factors) {
        data.dtau_lower_W.col(vm) << IS_m, BtS_m;
        data.dtau_upper_q_W.col(vm) = G;
        data.dtau_upper_v_W.col(vm) = H;
        continue;
      }
      data.tau[vm] = S_m.dot(F);
      for (const auto& [start, length] : data.support_ranges[j]) {
        for (int k = start; k < start + length; ++k) {
          const int stage_k = detail::support_stage(c, k);
          if (stage_k <= stage_m) {  // k moves m
            data.dtau_dq(vm, k) =
                IS_m.dot(data.dX_W.col(k)) + BtS_m.dot(data.dDeltaV_W.col(k).head<3>());
            data.dtau_dv(vm, k) =
                IS_m.dot(data.dW_W.col(k)) + BtS_m.dot(data.dS_W.col(k).head<3>());
            data.M(vm, k) = IS_m.dot(data.dS_W.col(k));
          }
          if (stage_k < stage_m) {  // k is above m
            const auto S_k = data.dS_W.col(k);
            data.dtau_dq(k, vm) = S_k.dot(G);
            data.dtau_dv(k, vm) = S_k.dot(H);
            data.M(k, vm) = S_k.dot(IS_m);
          }
        }
      }
      // The rotor's reflected inertia (armature): on M's diagonal and in τ, not in ∂τ/∂q or ∂v.
      data.M(vm, vm) += c.armature;
      data.tau[vm] += c.armature * vdot[vm];
    }
    // The subtree's sums pass to the parent.
    data.dIc_W[c.parent] += Ic;
    data.dB_W[c.parent].angular += B.angular;
    data.dB_W[c.parent].momentum += B.momentum;
    data.dF_W[c.parent] += F;
  }
}

}  // namespace

void rnea_derivatives(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot,
                      std::span<const Vec6> f_ext) {
  detail::check_inverse_dynamics("rnea_derivatives", model, data, q, v, vdot, f_ext);
  derivative_passes(model, data, q, v, vdot, f_ext, false, Output::entries);
}

void detail::rnea_derivative_factors_at_current_positions(const Model& model, Data& data, VecRef q,
                                                          VecRef v, VecRef vdot,
                                                          std::span<const Vec6> f_ext) {
  derivative_passes(model, data, q, v, vdot, f_ext, true, Output::factors);
}

}  // namespace momenta::dynamics
