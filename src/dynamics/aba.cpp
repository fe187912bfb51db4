#include "momenta/dynamics/aba.hpp"

#include "argument_checks.hpp"

#include <cmath>

#include "forward_pass.hpp"
#include "spatial_inertia_ops.hpp"

namespace momenta::dynamics {

namespace detail {

// A multi-dof joint's n × n blocks: fixed N (2, 3, 6) or Eigen::Dynamic with at most 6 (on the
// stack either way: no allocation).
template <int N>
using MatNN =
    Eigen::Matrix<double, N, N, 0, (N == Eigen::Dynamic ? 6 : N), (N == Eigen::Dynamic ? 6 : N)>;
template <int N>
using VecNd = Eigen::Matrix<double, N, 1, 0, (N == Eigen::Dynamic ? 6 : N), 1>;

// Leading n columns / n × n corner / n entries, as fixed-size blocks when N is fixed.
template <int N, class M>
auto left_cols(M& m, int n) {
  if constexpr (N == Eigen::Dynamic) {
    return m.leftCols(n);
  } else {
    (void)n;
    return m.template leftCols<N>();
  }
}
template <int N, class M>
auto corner(M& m, int n) {
  if constexpr (N == Eigen::Dynamic) {
    return m.topLeftCorner(n, n);
  } else {
    (void)n;
    return m.template topLeftCorner<N, N>();
  }
}
template <int N, class V>
auto segment(V& v, int start, int n) {
  if constexpr (N == Eigen::Dynamic) {
    return v.segment(start, n);
  } else {
    (void)n;
    return v.template segment<N>(start);
  }
}

// D⁻¹ of the joint's symmetric positive-definite n × n matrix D = Sᵀ IA S by Cholesky, written
// out so that fixed N unrolls: Eigen's LLT::solve(Identity) dispatches to its blocked triangular
// solvers, which cost more than the whole rest of the articulated-body pass at these sizes.
// D = L Lᵀ, W = L⁻¹ (lower), D⁻¹ = Wᵀ W.
template <int N>
MatNN<N> spd_inverse(const MatNN<N>& D, int n) {
  const int m = N == Eigen::Dynamic ? n : N;
  MatNN<N> L = MatNN<N>::Zero(m, m);
  for (int j = 0; j < m; ++j) {
    double d = D(j, j);
    for (int k = 0; k < j; ++k) d -= L(j, k) * L(j, k);
    L(j, j) = std::sqrt(d);
    const double inv = 1.0 / L(j, j);
    for (int i = j + 1; i < m; ++i) {
      double x = D(i, j);
      for (int k = 0; k < j; ++k) x -= L(i, k) * L(j, k);
      L(i, j) = x * inv;
    }
  }
  MatNN<N> W = MatNN<N>::Zero(m, m);
  for (int j = 0; j < m; ++j) {
    W(j, j) = 1.0 / L(j, j);
    for (int i = j + 1; i < m; ++i) {
      double x = 0.0;
      for (int k = j; k < i; ++k) x += L(i, k) * W(k, j);
      W(i, j) = -x / L(i, i);
    }
  }
  MatNN<N> Dinv(m, m);
  for (int c = 0; c < m; ++c) {
    for (int r = c; r < m; ++r) {
      double x = 0.0;
      for (int k = r; k < m; ++k) x += W(k, r) * W(k, c);
      Dinv(r, c) = x;
      Dinv(c, r) = x;
    }
  }
  return Dinv;
}

// Pass 2 for joint j with N degrees of freedom: U = IA S, D⁻¹ = (Sᵀ U + armature)⁻¹, u = τ − Sᵀ pA;
// and,
// unless it is a root joint, Ia = IA − U D⁻¹ Uᵀ into IA and pa += U D⁻¹ u.
template <int N>
void articulate(Data& data, int j, const double* tau, bool root, Vec6& pa, double armature,
                int n = N) {
  const int i = j + 1;
  Mat6& IA = data.IA[i];
  const auto S = left_cols<N>(data.S[j], n);
  const Eigen::Matrix<double, 6, N, 0, 6, (N == Eigen::Dynamic ? 6 : N)> U = IA * S;
  MatNN<N> D = S.transpose() * U;
  D.diagonal().array() += armature;  // the rotor's reflected inertia (Joint::armature)
  const MatNN<N> Dinv = spd_inverse<N>(D, n);
  const VecNd<N> u = Eigen::Map<const VecNd<N>>(tau, n) - S.transpose() * data.pA[i];
  left_cols<N>(data.U[j], n) = U;
  corner<N>(data.Dinv[j], n) = Dinv;
  segment<N>(data.u[j], 0, n) = u;
  if (root) return;
  const Eigen::Matrix<double, 6, N, 0, 6, (N == Eigen::Dynamic ? 6 : N)> U_Dinv = U * Dinv;
  IA.noalias() -= U_Dinv * U.transpose();
  pa.noalias() += U_Dinv * u;
}

// Pass 3 for joint j: v̇_j = D⁻¹ (u + du − Uᵀ a) and a += S v̇_j (du: the joint's entries of
// aba_accelerate's, or null).
template <int N>
void accelerate(Data& data, int j, int v_index, const double* du, Vec6& a, int n = N) {
  VecNd<N> u = segment<N>(data.u[j], 0, n);
  if (du != nullptr) u += Eigen::Map<const VecNd<N>>(du + v_index, n);
  const VecNd<N> qdd =
      corner<N>(data.Dinv[j], n) * (u - left_cols<N>(data.U[j], n).transpose() * a);
  segment<N>(data.vdot, v_index, n) = qdd;
  a.noalias() += left_cols<N>(data.S[j], n) * qdd;
}

}  // namespace detail

void aba_articulate(const Model& model, Data& data, VecRef q, VecRef v, VecRef tau,
                    std::span<const Vec6> f_ext) {
  detail::check_data_and_q("aba", model, data, q);
  detail::check_nv("aba", "v", model, v);
  detail::check_nv("aba", "tau", model, tau);
  detail::check_f_ext("aba", model, f_ext);
  const auto& joints = model.joint_constants();
  const int nj = static_cast<int>(joints.size());
  const bool has_fext = !f_ext.empty();

  // Pass 1 (root to leaves): poses, velocities, velocity products, rigid-body inertias and
  // bias forces (Featherstone 2008, Table 7.1).
  for (int j = 0; j < nj; ++j) {
    const auto& c = joints[j];
    const int i = c.child;
    detail::velocity_step(c, j, q.data(), v.data(), data);
    const SpatialInertia& I = model.spatial_inertia(i);
    detail::set_inertia_matrix(I, data.IA[i]);
    const double* V = data.V_WB_B[i].data();
    double IV[6];
    double pA[6] = {0, 0, 0, 0, 0, 0};
    kernel::inertia_times(I.mass, I.h, I.I_O, V, IV);
    kernel::add_cross_force(V, IV, pA);
    if (has_fext) {
      for (int r = 0; r < 6; ++r) pA[r] -= f_ext[i][r];
    }
    for (int r = 0; r < 6; ++r) data.pA[i][r] = pA[r];
  }

  // Pass 2 (leaves to root): articulated inertias and bias forces.
  for (int j = nj - 1; j >= 0; --j) {
    const auto& c = joints[j];
    const int i = c.child;
    const int p = c.parent;
    Mat6& IA = data.IA[i];
    const Vec6& pA = data.pA[i];
    if (c.nv == 1) {
      Vec6 U;
      double u_j;
      if (c.S_basis >= 0) {
        U = IA.col(c.S_basis);
        u_j = tau[c.v_index] - pA[c.S_basis];
      } else {
        U.noalias() = IA * data.S[j].col(0);
        u_j = tau[c.v_index] - data.S[j].col(0).dot(pA);
      }
      const double D_inv =
          1.0 / ((c.S_basis >= 0 ? U[c.S_basis] : data.S[j].col(0).dot(U)) + c.armature);
      data.U[j].col(0) = U;
      data.Dinv[j](0, 0) = D_inv;
      data.u[j][0] = u_j;
      if (p == 0) continue;
      // Ia = IA − U D⁻¹ Uᵀ;  pa = pA + Ia c + U D⁻¹ u.
      double Ud[6];
      for (int r = 0; r < 6; ++r) Ud[r] = U[r] * D_inv;
      for (int col = 0; col < 6; ++col) {
        for (int r = 0; r < 6; ++r) IA(r, col) -= Ud[r] * U[col];
      }
      double pa[6];
      const double* cB = data.c_B[i].data();
      for (int r = 0; r < 6; ++r) pa[r] = pA[r] + Ud[r] * u_j;
      for (int col = 0; col < 6; ++col) {
        for (int r = 0; r < 6; ++r) pa[r] += IA(r, col) * cB[col];
      }
      detail::add_transformed_inertia(data.X_PB[i], IA, data.IA[p]);
      detail::to_parent(c, data.X_PB[i], pa, pa);
      for (int r = 0; r < 6; ++r) data.pA[p][r] += pa[r];
      continue;
    }
    Vec6 pa = pA;
    if (c.nv > 0) {
      // Fixed sizes for the common multi-dof joints (Eigen unrolls and vectorizes them).
      switch (c.nv) {
        case 2:
          detail::articulate<2>(data, j, tau.data() + c.v_index, p == 0, pa, c.armature);
          break;
        case 3:
          detail::articulate<3>(data, j, tau.data() + c.v_index, p == 0, pa, c.armature);
          break;
        case 6:
          detail::articulate<6>(data, j, tau.data() + c.v_index, p == 0, pa, c.armature);
          break;
        default:
          detail::articulate<Eigen::Dynamic>(data, j, tau.data() + c.v_index, p == 0, pa,
                                             c.armature, c.nv);
          break;
      }
      if (p == 0) continue;
    } else if (p == 0) {
      continue;
    }
    pa.noalias() += IA * data.c_B[i];
    detail::add_transformed_inertia(data.X_PB[i], IA, data.IA[p]);
    data.pA[p] += data.X_PB[i].act_force(pa);
  }
}

const VecX& aba_accelerate(const Model& model, Data& data, VecRef du) {
  const auto& joints = model.joint_constants();
  const int nj = static_cast<int>(joints.size());
  const double* extra = du.size() > 0 ? du.data() : nullptr;  // the joints' du, if any
  if (extra != nullptr) detail::check_nv("aba_accelerate", "du", model, du);

  // Pass 3 (root to leaves): accelerations; gravity as an upward acceleration of the base.
  const Vec6 a_base = spatial(Vec3::Zero(), -model.gravity());
  for (int j = 0; j < nj; ++j) {
    const auto& c = joints[j];
    const int i = c.child;
    const int p = c.parent;
    Vec6& a = data.A_gf[i];
    detail::to_child(c, data.X_PB[i], p == 0 ? a_base.data() : data.A_gf[p].data(), a.data());
    for (int r = 0; r < 6; ++r) a[r] += data.c_B[i][r];
    if (c.nv == 1) {
      const double* U = data.U[j].data();
      double Ua = 0.0;
      for (int r = 0; r < 6; ++r) Ua += U[r] * a[r];
      const double u = extra != nullptr ? data.u[j][0] + extra[c.v_index] : data.u[j][0];
      const double qdd = data.Dinv[j](0, 0) * (u - Ua);
      data.vdot[c.v_index] = qdd;
      if (c.S_basis >= 0) {
        a[c.S_basis] += qdd;
      } else {
        a += data.S[j].col(0) * qdd;
      }
    } else if (c.nv > 0) {
      switch (c.nv) {
        case 2:
          detail::accelerate<2>(data, j, c.v_index, extra, a);
          break;
        case 3:
          detail::accelerate<3>(data, j, c.v_index, extra, a);
          break;
        case 6:
          detail::accelerate<6>(data, j, c.v_index, extra, a);
          break;
        default:
          detail::accelerate<Eigen::Dynamic>(data, j, c.v_index, extra, a, c.nv);
          break;
      }
    }
  }
  return data.vdot;
}

const VecX& aba(const Model& model, Data& data, VecRef q, VecRef v, VecRef tau,
                std::span<const Vec6> f_ext) {
  aba_articulate(model, data, q, v, tau, f_ext);
  return aba_accelerate(model, data);
}

VecX forward_dynamics(const Model& model, VecRef q, VecRef v, VecRef tau,
                      std::span<const Vec6> f_ext) {
  Data data(model);
  return aba(model, data, q, v, tau, f_ext);
}

}  // namespace momenta::dynamics
