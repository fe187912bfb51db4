#include "momenta/dynamics/aba_derivatives.hpp"

#include <utility>
#include <vector>

#include "joint_stages.hpp"
#include "momenta/common/error.hpp"
#include "momenta/dynamics/aba.hpp"
#include "rnea_derivatives_detail.hpp"

namespace momenta::dynamics {
namespace {

// Every joint's D⁻¹ = (Sᵀ IA S)⁻¹ from aba is finite with a positive diagonal, or M is singular.
void check_articulated_factors(const Model& model, const Data& data) {
  const auto& joints = model.joint_constants();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const int n = joints[j].nv;
    const auto Dinv = data.Dinv[j].topLeftCorner(n, n);
    if (!Dinv.allFinite() || (n > 0 && Dinv.diagonal().minCoeff() <= 0.0)) {
      throw NumericalError(
          "aba_derivatives: the mass matrix is not positive definite (a joint that carries no "
          "mass or inertia along one of its axes)");
    }
  }
}

// Run r of a joint's subtree ranges without the joint's own n coordinates (which open run 0).
std::pair<int, int> below_joint(const std::vector<std::pair<int, int>>& ranges, std::size_t r,
                                int n) {
  const auto [first, size] = ranges[r];
  return r == 0 ? std::pair{first + n, size - n} : std::pair{first, size};
}

// The two passes' steps for a joint with one coordinate k, column by column over 6-vectors (the
// general blocks' dispatch would cost more than their arithmetic at these sizes).
using ConstVec6Map = Eigen::Map<const Vec6>;
using Mat6N = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6>;  // a joint's columns, on the stack
using Vec6Map = Eigen::Map<Vec6>;

void backward_step_1dof(Data& data, const model::JointConstants& c, int j) {
  const int k = c.v_index;
  const double d = data.Dinv[j](0, 0);
  const Vec6 S_d = data.dS_W.col(k) * d;
  const Vec6 U = data.minv_U_W.col(k);
  double* M_k = data.Minv.col(k).data();  // below the diagonal: rows of the subtree
  double* F = data.minv_F_W.data();
  const bool passes_up = c.parent != 0;
  if (passes_up) Vec6Map(F + 6 * k) = U * d;
  const auto& ranges = data.subtree_ranges[j];
  for (std::size_t r = 0; r < ranges.size(); ++r) {
    const auto [first, size] = below_joint(ranges, r, 1);
    for (int col = first; col < first + size; ++col) {
      const double m = -ConstVec6Map(F + 6 * col).dot(S_d);
      M_k[col] = m;
      if (passes_up) Vec6Map(F + 6 * col) += U * m;
    }
  }
}

void forward_step_1dof(Data& data, const model::JointConstants& c, int j, int nv) {
  const int k = c.v_index;
  const double d = data.Dinv[j](0, 0);
  const Vec6 S = data.dS_W.col(k);
  const Vec6 U_d = data.minv_U_W.col(k) * d;
  double* M_k = data.Minv.col(k).data();
  double* A = data.minv_A_W[c.child].data();
  if (c.parent == 0) {
    for (int col = k; col < nv; ++col) Vec6Map(A + 6 * col) = S * M_k[col];
    return;
  }
  const double* A_parent = data.minv_A_W[c.parent].data();
  for (int col = k; col < nv; ++col) {
    const ConstVec6Map a_parent(A_parent + 6 * col);
    const double m = M_k[col] - a_parent.dot(U_d);
    M_k[col] = m;
    Vec6Map(A + 6 * col) = a_parent + S * m;
  }
}

// M⁻¹ from the articulated-body factors U = IA S and D⁻¹ that aba left (Carpentier, "Analytical
// inverse of the joint space inertia matrix", 2018: the algorithm of Pinocchio's computeMinverse),
// in W so that no transform is needed between bodies, and written into the lower triangle (the
// columns of a joint's coordinates are contiguous there), then mirrored. With J a joint's
// coordinates, U, S and D⁻¹ its factors, F its subtree's test forces and A its parent's test
// accelerations:
//   leaves to root:  M⁻¹(J, J) = D⁻¹,  M⁻¹(k, J) = −(F_kᵀ S) D⁻¹ for k below J,
//                    F_k += U M⁻¹(k, J)ᵀ for k in J's subtree (passed up unchanged in W);
//   root to leaves:  M⁻¹(k, J) −= (A_kᵀ U) D⁻¹ for k ≥ J,  A_k ← A_k + S M⁻¹(k, J)ᵀ.
// The entries below the diagonal outside J's subtree (none in a chain) start at zero and take
// only the second pass's term. O(n d) per coordinate for a tree of depth d.
void inverse_mass_matrix(const Model& model, Data& data) {
  const auto& joints = model.joint_constants();
  const int nj = static_cast<int>(joints.size());
  const int nv = model.nv();
  MatX& Minv = data.Minv;
  if (!data.all_dofs_related) Minv.setZero();  // otherwise the first pass writes every entry
  for (int j = 0; j < nj; ++j) {
    const auto& c = joints[j];
    for (int k = 0; k < c.nv; ++k) {
      data.minv_U_W.col(c.v_index + k) = data.X_WB[c.child].act_force(data.U[j].col(k));
    }
  }

  for (int j = nj - 1; j >= 0; --j) {
    const auto& c = joints[j];
    const int n = c.nv;
    if (n == 0) continue;  // the forces pass through a body welded to its parent unchanged
    const auto S = data.dS_W.middleCols(c.v_index, n);
    const auto U = data.minv_U_W.middleCols(c.v_index, n);
    const auto Dinv = data.Dinv[j].topLeftCorner(n, n);
    Minv.block(c.v_index, c.v_index, n, n) = Dinv;
    if (n == 1) {
      backward_step_1dof(data, c, j);
      continue;
    }
    const bool passes_up = c.parent != 0;
    Mat6N minus_S_Dinv(6, n);  // the sign here: Eigen would copy a negated F or S to the heap
    minus_S_Dinv.noalias() = S * Dinv;
    minus_S_Dinv = -minus_S_Dinv;
    if (passes_up) data.minv_F_W.middleCols(c.v_index, n).noalias() = U * Dinv;
    const auto& ranges = data.subtree_ranges[j];
    for (std::size_t r = 0; r < ranges.size(); ++r) {
      const auto [start, size] = below_joint(ranges, r, n);
      auto F = data.minv_F_W.middleCols(start, size);
      auto below = Minv.block(start, c.v_index, size, n);
      below.noalias() = F.transpose() * minus_S_Dinv;
      if (!passes_up) continue;
      for (int col = 0; col < size; ++col) {  // a column at a time: Eigen would copy below
        F.col(col).noalias() += U * below.row(col).transpose();
      }
    }
  }

  for (int j = 0; j < nj; ++j) {
    const auto& c = joints[j];
    const int n = c.nv;
    const int tail = nv - c.v_index;
    const auto A_parent = data.minv_A_W[c.parent].rightCols(tail);
    auto A = data.minv_A_W[c.child].rightCols(tail);
    if (n == 0) {
      A = A_parent;
      continue;
    }
    if (n == 1) {
      forward_step_1dof(data, c, j, nv);
      continue;
    }
    const auto S = data.dS_W.middleCols(c.v_index, n);
    const auto U = data.minv_U_W.middleCols(c.v_index, n);
    const auto Dinv = data.Dinv[j].topLeftCorner(n, n);
    auto after = Minv.block(c.v_index, c.v_index, tail, n);
    if (c.parent != 0) {
      const Mat6N U_Dinv = U * Dinv;
      after.noalias() -= A_parent.transpose() * U_Dinv;
      A = A_parent;
      A.noalias() += S * after.transpose();
    } else {
      A.noalias() = S * after.transpose();
    }
  }

  for (int col = 1; col < nv; ++col) {
    Minv.col(col).head(col) = Minv.row(col).head(col).transpose();
  }
}

// −M⁻¹ ∂τ/∂q and −M⁻¹ ∂τ/∂v in O(n²) from the factors of ∂τ's entries (data.hpp), never forming
// ∂τ. Column k of ∂τ/∂q holds p_mᵀ y_k, p_m = [Ic S_m; (Bᵀ S_m)_ω] and y_k = [x_k; (ΔV_k)_ω],
// in each row m that k moves (the subtree below k's stage: D(k)), and S_mᵀ G_k in each row m
// above k (the ancestors' and earlier stages' coordinates: A(k)), so with M⁻¹ₘ column m of M⁻¹
//   M⁻¹ ∂τ/∂q e_k = (Σ_{m ∈ D(k)} M⁻¹ₘ p_mᵀ) y_k + (Σ_{m ∈ A(k)} M⁻¹ₘ S_mᵀ) G_k,
// and the same sums times [W_k; (S_k)_ω] and H_k for ∂τ/∂v. The first sum is a subtree's, built
// leaves to root; the second a path's, built root to leaves: 45 n multiply-adds per coordinate
// where the dense products take 2 n² (4 n³ flops).
using Vec9 = Eigen::Matrix<double, 9, 1>;

// Coordinate k's column factors of ∂τ's entries where k moves m: y_k = [x_k; (ΔV_k)_ω] (∂/∂q)
// and [W_k; (S_k)_ω] (∂/∂v).
Vec9 lower_column_factor_q(const Data& data, int k) {
  Vec9 y;
  y << data.dX_W.col(k), data.dDeltaV_W.col(k).head<3>();
  return y;
}

Vec9 lower_column_factor_v(const Data& data, int k) {
  Vec9 z;
  z << data.dW_W.col(k), data.dS_W.col(k).head<3>();
  return z;
}

// A 1-dof joint's coordinate k in one pass over a sum Σ (n × K, column-major): its two columns
// out_q = base + Σ a − M⁻¹ₖ α_q and out_v = base + Σ b − M⁻¹ₖ α_v with Σ as it was, base their
// own old values or zero, and then Σ −= M⁻¹ₖ wᵀ (a rank-one update). Rows::RowsAtCompileTime
// rows from row i, each of Σ's entries loaded and stored once.
template <class Rows, int K, bool kAccumulate>
void apply_and_update_rows(int i, double* sum, int n, const double* Minv_k, const double* a,
                           const double* b, double alpha_q, double alpha_v, const double* w,
                           double* out_q, double* out_v) {
  const Rows m = Eigen::Map<const Rows>(Minv_k + i);
  Rows sum_a = -alpha_q * m;
  Rows sum_b = -alpha_v * m;
  for (int col = 0; col < K; ++col) {
    Eigen::Map<Rows> entries(sum + col * n + i);
    const Rows old = entries;
    sum_a += old * a[col];
    sum_b += old * b[col];
    entries = old - m * w[col];
  }
  Eigen::Map<Rows> q(out_q + i);
  Eigen::Map<Rows> v(out_v + i);
  if constexpr (kAccumulate) {
    q += sum_a;
    v += sum_b;
  } else {
    q = sum_a;
    v = sum_b;
  }
}

// The rows eight at a time (four vector registers each: the K broadcasts of a, b and w are
// loaded once for the eight), then four, two and one.
template <int K, bool kAccumulate>
void apply_and_update(double* sum, int n, const double* Minv_k, const double* a, const double* b,
                      double alpha_q, double alpha_v, const double* w, double* out_q,
                      double* out_v) {
  int i = 0;
  for (; i + 8 <= n; i += 8) {
    apply_and_update_rows<Eigen::Array<double, 8, 1>, K, kAccumulate>(
        i, sum, n, Minv_k, a, b, alpha_q, alpha_v, w, out_q, out_v);
  }
  if (i + 4 <= n) {
    apply_and_update_rows<Eigen::Array4d, K, kAccumulate>(i, sum, n, Minv_k, a, b, alpha_q, alpha_v,
                                                          w, out_q, out_v);
    i += 4;
  }
  if (i + 2 <= n) {
    apply_and_update_rows<Eigen::Array2d, K, kAccumulate>(i, sum, n, Minv_k, a, b, alpha_q, alpha_v,
                                                          w, out_q, out_v);
    i += 2;
  }
  if (i < n) {
    apply_and_update_rows<Eigen::Array<double, 1, 1>, K, kAccumulate>(
        i, sum, n, Minv_k, a, b, alpha_q, alpha_v, w, out_q, out_v);
  }
}

void path_sums_step(const Model& model, Data& data, int j) {
  const auto& c = model.joint_constants()[j];
  MatX& T = data.minv_upper_sums[data.minv_upper_slot[j]];  // Σ M⁻¹ₘ S_mᵀ over A
  const int p = c.parent - 1;
  if (p < 0) {
    T.setZero();
  } else if (data.minv_upper_slot[p] != data.minv_upper_slot[j]) {
    T = data.minv_upper_sums[data.minv_upper_slot[p]];
  }
  if (c.nv == 1 && p < 0) {  // T = 0: no columns above; the update is the children's
    const int k = c.v_index;
    data.dvdot_dq.col(k).setZero();
    data.dvdot_dv.col(k).setZero();
    if (!data.child_joints[j].empty()) {
      T.noalias() -= data.Minv.col(k) * data.dS_W.col(k).transpose();
    }
    return;
  }
  if (c.nv == 1) {  // the columns from T as it was; the update is the children's
    const int k = c.v_index;
    apply_and_update<6, false>(T.data(), static_cast<int>(T.rows()), data.Minv.col(k).data(),
                               data.dtau_upper_q_W.col(k).data(), data.dtau_upper_v_W.col(k).data(),
                               0.0, 0.0, data.dS_W.col(k).data(), data.dvdot_dq.col(k).data(),
                               data.dvdot_dv.col(k).data());
    return;
  }
  for (int s = 0; s < detail::joint_stage_count(c.type) && c.nv > 0; ++s) {
    for (int k = 0; k < c.nv; ++k) {
      if (detail::joint_stage(c.type, k) != s) continue;
      const int vk = c.v_index + k;
      data.dvdot_dq.col(vk).noalias() = T * Vec6(data.dtau_upper_q_W.col(vk));
      data.dvdot_dv.col(vk).noalias() = T * Vec6(data.dtau_upper_v_W.col(vk));
    }
    for (int k = 0; k < c.nv; ++k) {
      if (detail::joint_stage(c.type, k) != s) continue;
      const int vk = c.v_index + k;
      T.noalias() -= data.Minv.col(vk) * data.dS_W.col(vk).transpose();
    }
  }
}

void subtree_sums_step(const Model& model, Data& data, int j) {
  const auto& c = model.joint_constants()[j];
  MatX& R = data.minv_lower_sums[data.minv_lower_slot[j]];  // Σ M⁻¹ₘ p_mᵀ over D
  const auto& children = data.child_joints[j];
  if (children.empty()) R.setZero();
  for (const int child : children) {
    const int slot = data.minv_lower_slot[child];
    if (slot != data.minv_lower_slot[j]) R += data.minv_lower_sums[slot];
  }
  if (c.nv == 1) {  // R after the update, applied as R before it minus M⁻¹ₖ (pᵀ y)
    const int k = c.v_index;
    const Vec9 along_q = lower_column_factor_q(data, k);
    const Vec9 along_v = lower_column_factor_v(data, k);
    const Vec9 p_k = data.dtau_lower_W.col(k);
    apply_and_update<9, true>(R.data(), static_cast<int>(R.rows()), data.Minv.col(k).data(),
                              along_q.data(), along_v.data(), p_k.dot(along_q), p_k.dot(along_v),
                              p_k.data(), data.dvdot_dq.col(k).data(), data.dvdot_dv.col(k).data());
    return;
  }
  for (int s = detail::joint_stage_count(c.type) - 1; s >= 0 && c.nv > 0; --s) {
    for (int k = 0; k < c.nv; ++k) {
      if (detail::joint_stage(c.type, k) != s) continue;
      const int vk = c.v_index + k;
      R.noalias() -= data.Minv.col(vk) * data.dtau_lower_W.col(vk).transpose();
    }
    for (int k = 0; k < c.nv; ++k) {
      if (detail::joint_stage(c.type, k) != s) continue;
      const int vk = c.v_index + k;
      data.dvdot_dq.col(vk).noalias() += R * lower_column_factor_q(data, vk);
      data.dvdot_dv.col(vk).noalias() += R * lower_column_factor_v(data, vk);
    }
  }
}

void minus_inverse_mass_matrix_products(const Model& model, Data& data) {
  const int nj = model.num_joints();
  for (int j = 0; j < nj; ++j) path_sums_step(model, data, j);
  for (int j = nj - 1; j >= 0; --j) subtree_sums_step(model, data, j);
}

}  // namespace

void aba_derivatives(const Model& model, Data& data, VecRef q, VecRef v, VecRef tau,
                     std::span<const Vec6> f_ext) {
  // v̇ and the articulated-body factors first (aba checks the arguments), then the factors of
  // ∂τ/∂(q, v) at that v̇ (with the bodies' poses and the coordinates' columns in W), then M⁻¹
  // from the articulated-body factors, then the products.
  aba(model, data, q, v, tau, f_ext);
  check_articulated_factors(model, data);
  detail::rnea_derivative_factors_at_current_positions(model, data, q, v, data.vdot, f_ext);
  inverse_mass_matrix(model, data);
  minus_inverse_mass_matrix_products(model, data);
}

}  // namespace momenta::dynamics
