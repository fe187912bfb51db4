#include "momenta/dynamics/rnea_derivatives.hpp"

#include "argument_checks.hpp"

#include "forward_pass.hpp"
#include "joint_stages.hpp"
#include "rnea_derivatives_detail.hpp"

namespace momenta::dynamics {
namespace {

using detail::joint_stage;
using detail::joint_stage_count;

// The matrix of x ↦ x ×* h for a fixed force h = [n; f]: [x_ω × n + x_v × f; x_ω × f].
Mat6 force_cross_of_motion(const Vec6& h) {
  const Mat3 n = skew(h.head<3>());
  const Mat3 f = skew(h.tail<3>());
  Mat6 out;
  out.topLeftCorner<3, 3>() = -n;
  out.topRightCorner<3, 3>() = -f;
  out.bottomLeftCorner<3, 3>() = -f;
  out.bottomRightCorner<3, 3>().setZero();
  return out;
}

// Forward pass in W: each body's V, A (shifted by −g), own net force f = I A + V ×* I V − f_ext,
// inertia I and Coriolis inertia B, and each velocity coordinate's column and derivative terms.
void forward_pass(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot,
                  std::span<const Vec6> f_ext, bool positions_current) {
  const auto& joints = model.joint_constants();
  data.dV_W[0].setZero();
  data.dA_W[0] = spatial(Vec3::Zero(), -model.gravity());
  data.dF_W[0].setZero();  // the world's sums are not used; kept from growing
  data.dIc_W[0].setZero();
  data.dB_W[0].setZero();
  for (int j = 0; j < static_cast<int>(joints.size()); ++j) {
    const auto& c = joints[j];
    const int i = c.child;
    if (!positions_current) detail::position_step(c, j, q.data(), data);
    const Transform X_WB = data.X_WB[c.parent] * data.X_PB[i];
    data.X_WB[i] = X_WB;

    // Stage by stage: V_s = V_p + Σ S_k v_k, A_s = A_p + Σ (S_k v̇_k + (V_s × S_k) v_k).
    Vec6 V = data.dV_W[c.parent];
    Vec6 A = data.dA_W[c.parent];
    for (int s = 0; s < joint_stage_count(c.type) && c.nv > 0; ++s) {
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
    const Mat6 I = model.spatial_inertia(i).transformed(X_WB).matrix();
    const Vec6 h = I * V;
    Vec6 f = I * A + cross_force(V, h);
    if (!f_ext.empty()) f -= X_WB.act_force(f_ext[i]);
    data.dF_W[i] = f;
    data.dIc_W[i] = I;
    // B = crf(V) I − I crm(V) + (· ×* h); with crf(V) = −crm(V)ᵀ and I symmetric the first term is
    // −(I crm(V))ᵀ: one product.
    const Mat6 P = I * crm(V);
    data.dB_W[i] = force_cross_of_motion(h) - P - P.transpose();
  }
}

void derivative_passes(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot,
                       std::span<const Vec6> f_ext, bool positions_current) {
  forward_pass(model, data, q, v, vdot, f_ext, positions_current);

  if (!data.all_dofs_related) {  // otherwise the pass below writes every entry
    data.dtau_dq.setZero();
    data.dtau_dv.setZero();
    data.M.setZero();
  }
  const auto& joints = model.joint_constants();
  for (int j = static_cast<int>(joints.size()) - 1; j >= 0; --j) {
    const auto& c = joints[j];
    const int i = c.child;
    const Mat6& Ic = data.dIc_W[i];
    const Mat6& B = data.dB_W[i];
    const Vec6& F = data.dF_W[i];
    for (int m = 0; m < c.nv; ++m) {
      const int vm = c.v_index + m;
      const int stage_m = joint_stage(c.type, m);
      const Vec6 S_m = data.dS_W.col(vm);
      data.tau[vm] = S_m.dot(F);
      const Vec6 IS_m = Ic * S_m;  // Ic is symmetric: S_mᵀ Ic = (Ic S_m)ᵀ
      const Vec6 BtS_m = B.transpose() * S_m;
      // Entries (m, k) where coordinate k moves S_m (k in an ancestor joint, or in this joint at
      // m's stage or an earlier one): S_mᵀ (Ic x_k + B ΔV_k), the S_k ×* terms cancelling with
      // S_m's own turn. Entries (k, m) where coordinate m moves the subtree under a still S_k (k
      // in an ancestor joint or an earlier stage): S_kᵀ (S_m ×* F + Ic x_m + B ΔV_m). The same
      // for ∂/∂v with W and S in place of x and ΔV, and M from Ic.
      const Vec6 G = cross_force(S_m, F) + Ic * data.dX_W.col(vm) + B * data.dDeltaV_W.col(vm);
      const Vec6 H = Ic * data.dW_W.col(vm) + B * S_m;
      for (const auto& [start, length] : data.support_ranges[j]) {
        for (int k = start; k < start + length; ++k) {
          const int stage_k = detail::support_stage(c, k);
          if (stage_k <= stage_m) {  // k moves m
            data.dtau_dq(vm, k) = IS_m.dot(data.dX_W.col(k)) + BtS_m.dot(data.dDeltaV_W.col(k));
            data.dtau_dv(vm, k) = IS_m.dot(data.dW_W.col(k)) + BtS_m.dot(data.dS_W.col(k));
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
    }
    // The subtree's sums pass to the parent.
    data.dIc_W[c.parent] += Ic;
    data.dB_W[c.parent] += B;
    data.dF_W[c.parent] += F;
  }
}

}  // namespace

void rnea_derivatives(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot,
                      std::span<const Vec6> f_ext) {
  detail::check_inverse_dynamics("rnea_derivatives", model, data, q, v, vdot, f_ext);
  derivative_passes(model, data, q, v, vdot, f_ext, false);
}

void detail::rnea_derivatives_at_current_positions(const Model& model, Data& data, VecRef q,
                                                   VecRef v, VecRef vdot,
                                                   std::span<const Vec6> f_ext) {
  derivative_passes(model, data, q, v, vdot, f_ext, true);
}

}  // namespace momenta::dynamics
