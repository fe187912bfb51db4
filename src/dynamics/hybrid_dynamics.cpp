#include "momenta/dynamics/hybrid_dynamics.hpp"

#include "argument_checks.hpp"

#include <Eigen/Cholesky>

#include "forward_pass.hpp"
#include "spatial_inertia_ops.hpp"

namespace momenta::dynamics {
namespace {
using MatN = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
using VecN = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;
}  // namespace

// The articulated-body algorithm where prescribed joints pass their whole articulated inertia
// to the parent with a known acceleration S v̇ (Featherstone 2008, §9.2): in pass 2 a prescribed
// joint contributes Ia = IA and pa = pA + IA (c + S v̇); in pass 3 its force is
// τ = Sᵀ (IA a + pA), the force across the joint onto the articulated body it carries.
const VecX& hybrid_dynamics(const Model& model, Data& data, const std::vector<char>& prescribed,
                            VecRef q, VecRef v, VecRef vdot_in, VecRef tau_in,
                            std::span<const Vec6> f_ext) {
  detail::check_data_and_q("hybrid_dynamics", model, data, q);
  detail::check_nv("hybrid_dynamics", "v", model, v);
  detail::check_nv("hybrid_dynamics", "vdot", model, vdot_in);
  detail::check_nv("hybrid_dynamics", "tau", model, tau_in);
  detail::check_size("hybrid_dynamics", "prescribed", static_cast<long>(prescribed.size()),
                     model.num_joints(), "one flag per joint");
  detail::check_f_ext("hybrid_dynamics", model, f_ext);
  const auto& joints = model.joint_constants();
  const int nj = static_cast<int>(joints.size());
  const bool has_fext = !f_ext.empty();

  // Pass 1: kinematics, rigid inertias and bias forces.
  for (int j = 0; j < nj; ++j) {
    const auto& c = joints[j];
    const int i = c.child;
    detail::velocity_step(c, j, q.data(), v.data(), data);
    const SpatialInertia& I = model.spatial_inertia(i);
    detail::set_inertia_matrix(I, data.IA[i]);
    const Vec6& V = data.V_WB_B[i];
    data.pA[i] = cross_force(V, I * V);
    if (has_fext) data.pA[i] -= f_ext[i];
  }

  // Pass 2: articulated inertias; prescribed joints pass everything on.
  for (int j = nj - 1; j >= 0; --j) {
    const auto& c = joints[j];
    const int i = c.child;
    const int p = c.parent;
    const int n = c.nv;
    Mat6& IA = data.IA[i];
    const auto S = data.S[j].leftCols(n);
    Vec6 a_known = data.c_B[i];
    Vec6 pa = data.pA[i];
    if (prescribed[j] && n > 0) {
      a_known.noalias() += S * vdot_in.segment(c.v_index, n);
    } else if (n > 0) {
      auto U = data.U[j].leftCols(n);
      U.noalias() = IA * S;
      MatN D = S.transpose() * U;
      D.diagonal().array() += c.armature;  // the rotor's reflected inertia
      auto Dinv = data.Dinv[j].topLeftCorner(n, n);
      Dinv = Eigen::LLT<MatN>(D).solve(MatN::Identity(n, n));
      auto u = data.u[j].head(n);
      u = tau_in.segment(c.v_index, n);
      u.noalias() -= S.transpose() * data.pA[i];
      if (p == 0) continue;
      const Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6> U_Dinv = U * Dinv;
      IA.noalias() -= U_Dinv * U.transpose();
      pa += U_Dinv * u;
    }
    if (p == 0) continue;
    pa.noalias() += IA * a_known;
    detail::add_transformed_inertia(data.X_PB[i], IA, data.IA[p]);
    data.pA[p] += data.X_PB[i].act_force(pa);
  }

  // Pass 3: accelerations of the free joints, forces of the prescribed ones.
  const Vec6 a_base = spatial(Vec3::Zero(), -model.gravity());
  for (int j = 0; j < nj; ++j) {
    const auto& c = joints[j];
    const int i = c.child;
    const int p = c.parent;
    const int n = c.nv;
    Vec6& a = data.A_gf[i];
    a = data.X_PB[i].act_motion_inverse(p == 0 ? a_base : data.A_gf[p]) + data.c_B[i];
    if (n == 0) continue;
    const auto S = data.S[j].leftCols(n);
    if (prescribed[j]) {
      // IA here is still the full articulated inertia of the subtree (pass 2 left it whole).
      data.vdot.segment(c.v_index, n) = vdot_in.segment(c.v_index, n);
      a.noalias() += S * vdot_in.segment(c.v_index, n);
      const Vec6 f = data.IA[i] * a + data.pA[i];
      data.tau.segment(c.v_index, n).noalias() = S.transpose() * f;
      data.tau.segment(c.v_index, n) += c.armature * vdot_in.segment(c.v_index, n);
    } else {
      const VecN qdd = data.Dinv[j].topLeftCorner(n, n) *
                       (data.u[j].head(n) - data.U[j].leftCols(n).transpose() * a);
      data.vdot.segment(c.v_index, n) = qdd;
      data.tau.segment(c.v_index, n) = tau_in.segment(c.v_index, n);
      a.noalias() += S * qdd;
    }
  }
  return data.vdot;
}

const VecX& hybrid_dynamics(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot_in,
                            VecRef tau_in, std::span<const Vec6> f_ext) {
  return hybrid_dynamics(model, data, data.prescribed_mask, q, v, vdot_in, tau_in, f_ext);
}

std::vector<char> prescribed_joint_mask(const Model& model) {
  std::vector<char> mask(static_cast<std::size_t>(model.num_joints()));
  for (std::size_t j = 0; j < mask.size(); ++j) {
    mask[j] = model.joint(static_cast<int>(j)).is_prescribed();
  }
  return mask;
}

}  // namespace momenta::dynamics
