#include "momenta/dynamics/aba.hpp"

#include <Eigen/Cholesky>

#include "joint_kernels.hpp"
#include "scalar_kernels.hpp"
#include "spatial_inertia_ops.hpp"

namespace momenta::dynamics {

namespace detail {
// Matrices of at most 6×6 on the stack (no allocation) for multi-dof joints.
using MatN = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
using VecN = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;
}  // namespace detail

const VecX& aba(const Model& model, Data& data, const VecX& q, const VecX& v, const VecX& tau,
                std::span<const Vec6> f_ext) {
  const auto& joints = model.joint_constants();
  const int nj = static_cast<int>(joints.size());
  const bool has_fext = !f_ext.empty();

  // Pass 1 (root to leaves): poses, velocities, velocity products, rigid-body inertias and
  // bias forces (Featherstone 2008, Table 7.1).
  for (int j = 0; j < nj; ++j) {
    const auto& c = joints[j];
    const int i = c.child;
    const int p = c.parent;
    const double* qj = q.data() + c.q_index;
    const double* vj = v.data() + c.v_index;
    Transform& X = data.X_PB[i];
    detail::joint_position(c, qj, X, data.S[j]);
    double* V = data.V_WB_B[i].data();
    double* cB = data.c_B[i].data();
    if (p == 0) {
      for (int r = 0; r < 6; ++r) V[r] = 0.0;
    } else {
      detail::motion_inverse(X, data.V_WB_B[p].data(), V);
    }
    for (int r = 0; r < 6; ++r) cB[r] = 0.0;
    if (c.S_basis >= 0) {
      // c = (V_λ + S v̄) × S v̄ = V_λ × S v̄, with V_λ in the child frame.
      detail::add_cross_motion_basis(V, c.S_basis, vj[0], cB);
      V[c.S_basis] += vj[0];
    } else {
      const Vec6 vJ = detail::joint_velocity(c, data.S[j], vj);
      detail::add_cross_motion(V, vJ.data(), cB);
      for (int r = 0; r < 6; ++r) V[r] += vJ[r];
      Vec6 cJ;
      if (detail::joint_bias(c, qj, vj, cJ)) data.c_B[i] += cJ;
    }
    const SpatialInertia& I = model.spatial_inertia(i);
    detail::set_inertia_matrix(I, data.IA[i]);
    double IV[6];
    detail::inertia_times(I, V, IV);
    double* pA = data.pA[i].data();
    for (int r = 0; r < 6; ++r) pA[r] = 0.0;
    detail::add_cross_force(V, IV, pA);
    if (has_fext) {
      for (int r = 0; r < 6; ++r) pA[r] -= f_ext[i][r];
    }
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
      const double D_inv = 1.0 / (c.S_basis >= 0 ? U[c.S_basis] : data.S[j].col(0).dot(U));
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
      detail::add_force(data.X_PB[i], pa, data.pA[p].data());
      continue;
    }
    Vec6 pa = pA;
    if (c.nv > 0) {
      const int n = c.nv;
      const auto S = data.S[j].leftCols(n);
      auto U = data.U[j].leftCols(n);
      U.noalias() = IA * S;
      const detail::MatN D = S.transpose() * U;
      const Eigen::LLT<detail::MatN> llt(D);
      auto Dinv = data.Dinv[j].topLeftCorner(n, n);
      Dinv = llt.solve(detail::MatN::Identity(n, n));
      auto u = data.u[j].head(n);
      u = tau.segment(c.v_index, n) - S.transpose() * pA;
      if (p == 0) continue;
      const Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6> U_Dinv = U * Dinv;
      IA.noalias() -= U_Dinv * U.transpose();
      pa += U_Dinv * u;
    } else if (p == 0) {
      continue;
    }
    pa.noalias() += IA * data.c_B[i];
    detail::add_transformed_inertia(data.X_PB[i], IA, data.IA[p]);
    data.pA[p] += data.X_PB[i].act_force(pa);
  }

  // Pass 3 (root to leaves): accelerations; gravity as an upward acceleration of the base.
  const Vec6 a_base = spatial(Vec3::Zero(), -model.gravity());
  for (int j = 0; j < nj; ++j) {
    const auto& c = joints[j];
    const int i = c.child;
    const int p = c.parent;
    Vec6& a = data.A_gf[i];
    detail::motion_inverse(data.X_PB[i], p == 0 ? a_base.data() : data.A_gf[p].data(), a.data());
    for (int r = 0; r < 6; ++r) a[r] += data.c_B[i][r];
    if (c.nv == 1) {
      const double* U = data.U[j].data();
      double Ua = 0.0;
      for (int r = 0; r < 6; ++r) Ua += U[r] * a[r];
      const double qdd = data.Dinv[j](0, 0) * (data.u[j][0] - Ua);
      data.vdot[c.v_index] = qdd;
      if (c.S_basis >= 0) {
        a[c.S_basis] += qdd;
      } else {
        a += data.S[j].col(0) * qdd;
      }
    } else if (c.nv > 0) {
      const int n = c.nv;
      const detail::VecN qdd = data.Dinv[j].topLeftCorner(n, n) *
                               (data.u[j].head(n) - data.U[j].leftCols(n).transpose() * a);
      data.vdot.segment(c.v_index, n) = qdd;
      a += data.S[j].leftCols(n) * qdd;
    }
  }
  return data.vdot;
}

VecX forward_dynamics(const Model& model, const VecX& q, const VecX& v, const VecX& tau,
                      std::span<const Vec6> f_ext) {
  Data data(model);
  return aba(model, data, q, v, tau, f_ext);
}

}  // namespace momenta::dynamics
