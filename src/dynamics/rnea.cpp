#include "momenta/dynamics/rnea.hpp"

#include "joint_kernels.hpp"

namespace momenta::dynamics {

const VecX& rnea(const Model& model, Data& data, const VecX& q, const VecX& v, const VecX& vdot,
                 std::span<const Vec6> f_ext) {
  const auto& joints = model.joint_constants();
  const int nj = static_cast<int>(joints.size());
  // Gravity enters as a fictitious upward acceleration of the base (Featherstone 2008, §5.3).
  const Vec6 a_base = spatial(Vec3::Zero(), -model.gravity());
  const bool has_fext = !f_ext.empty();

  // Forward pass: velocities, accelerations and the net force each body needs.
  for (int j = 0; j < nj; ++j) {
    const auto& c = joints[j];
    const int i = c.child;
    const int p = c.parent;
    const double* qj = q.data() + c.q_index;
    const double* vj = v.data() + c.v_index;
    Transform& X = data.X_PB[i];
    detail::joint_position(c, qj, X, data.S[j]);
    const Vec6 vJ = detail::joint_velocity(c, data.S[j], vj);
    Vec6& V = data.V_WB_B[i];
    Vec6& A = data.A_gf[i];
    if (p == 0) {
      V = vJ;
      A = X.act_motion_inverse(a_base);
    } else {
      V = X.act_motion_inverse(data.V_WB_B[p]) + vJ;
      A = X.act_motion_inverse(data.A_gf[p]) + cross_motion(V, vJ);
    }
    A += detail::joint_velocity(c, data.S[j], vdot.data() + c.v_index);
    Vec6 cJ;
    if (detail::joint_bias(c, qj, vj, cJ)) A += cJ;
    const SpatialInertia& I = model.spatial_inertia(i);
    Vec6& F = data.F_B[i];
    F = I * A + cross_force(V, I * V);
    if (has_fext) F -= f_ext[i];
  }

  // Backward pass: project onto the joint axes and pass the rest to the parent.
  for (int j = nj - 1; j >= 0; --j) {
    const auto& c = joints[j];
    const int i = c.child;
    const Vec6& F = data.F_B[i];
    if (c.nv == 1) {
      data.tau[c.v_index] = c.S_basis >= 0 ? F[c.S_basis] : data.S[j].col(0).dot(F);
    } else {
      for (int k = 0; k < c.nv; ++k) data.tau[c.v_index + k] = data.S[j].col(k).dot(F);
    }
    if (c.parent != 0) data.F_B[c.parent] += data.X_PB[i].act_force(F);
  }
  return data.tau;
}

VecX inverse_dynamics(const Model& model, const VecX& q, const VecX& v, const VecX& vdot,
                      std::span<const Vec6> f_ext) {
  Data data(model);
  return rnea(model, data, q, v, vdot, f_ext);
}

const VecX& nonlinear_effects(const Model& model, Data& data, const VecX& q, const VecX& v) {
  data.scratch_nv.setZero();
  data.nle = rnea(model, data, q, v, data.scratch_nv);
  return data.nle;
}

const VecX& generalized_gravity(const Model& model, Data& data, const VecX& q) {
  data.scratch_nv.setZero();
  data.g = rnea(model, data, q, data.scratch_nv, data.scratch_nv);
  return data.g;
}

}  // namespace momenta::dynamics
