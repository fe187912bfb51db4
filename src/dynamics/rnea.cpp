#include "momenta/dynamics/rnea.hpp"

#include "argument_checks.hpp"

#include "joint_kernels.hpp"
#include "scalar_kernels.hpp"

namespace momenta::dynamics {

const VecX& rnea(const Model& model, Data& data, const VecX& q, const VecX& v, const VecX& vdot,
                 std::span<const Vec6> f_ext) {
  detail::check_data_and_q("rnea", model, data, q);
  detail::check_nv("rnea", "v", model, v);
  detail::check_nv("rnea", "vdot", model, vdot);
  detail::check_f_ext("rnea", model, f_ext);
  const auto& joints = model.joint_constants();
  const int nj = static_cast<int>(joints.size());
  // Gravity enters as a fictitious upward acceleration of the base (Featherstone 2008, §5.3).
  const Vec6 a_base = spatial(Vec3::Zero(), -model.gravity());
  const bool has_fext = !f_ext.empty();

  // Forward pass: velocities, accelerations and the net force each body needs:
  // V_i = ⁱX_λ V_λ + S v̄,  A_i = ⁱX_λ A_λ + S v̇ + V_i × S v̄ + Ṡ v̄,
  // F_i = I_i A_i + V_i ×* I_i V_i − f_ext,i.
  for (int j = 0; j < nj; ++j) {
    const auto& c = joints[j];
    const int i = c.child;
    const int p = c.parent;
    const double* qj = q.data() + c.q_index;
    const double* vj = v.data() + c.v_index;
    Transform& X = data.X_PB[i];
    detail::joint_position(c, qj, X, data.S[j]);
    double* V = data.V_WB_B[i].data();
    double* A = data.A_gf[i].data();
    if (p == 0) {
      for (int r = 0; r < 6; ++r) V[r] = 0.0;
      detail::motion_inverse(X, a_base.data(), A);
    } else {
      detail::motion_inverse(X, data.V_WB_B[p].data(), V);
      detail::motion_inverse(X, data.A_gf[p].data(), A);
    }
    if (c.S_basis >= 0) {
      // V ×m (S v̄) before adding S v̄ to V: (V_λ + S v̄) × S v̄ = V_λ × S v̄.
      detail::add_cross_motion_basis(V, c.S_basis, vj[0], A);
      V[c.S_basis] += vj[0];
      A[c.S_basis] += vdot[c.v_index];
    } else {
      const Vec6 vJ = detail::joint_velocity(c, data.S[j], vj);
      detail::add_cross_motion(V, vJ.data(), A);
      for (int r = 0; r < 6; ++r) V[r] += vJ[r];
      const Vec6 aJ = detail::joint_velocity(c, data.S[j], vdot.data() + c.v_index);
      for (int r = 0; r < 6; ++r) A[r] += aJ[r];
      Vec6 cJ;
      if (detail::joint_bias(c, qj, vj, cJ)) {
        for (int r = 0; r < 6; ++r) A[r] += cJ[r];
      }
    }
    const SpatialInertia& I = model.spatial_inertia(i);
    double IV[6];
    double* F = data.F_B[i].data();
    detail::inertia_times(I, V, IV);
    detail::inertia_times(I, A, F);
    detail::add_cross_force(V, IV, F);
    if (has_fext) {
      for (int r = 0; r < 6; ++r) F[r] -= f_ext[i][r];
    }
  }

  // Backward pass: project onto the joint axes and pass the rest to the parent.
  for (int j = nj - 1; j >= 0; --j) {
    const auto& c = joints[j];
    const int i = c.child;
    const double* F = data.F_B[i].data();
    if (c.S_basis >= 0) {
      data.tau[c.v_index] = F[c.S_basis];
    } else {
      for (int k = 0; k < c.nv; ++k) data.tau[c.v_index + k] = data.S[j].col(k).dot(data.F_B[i]);
    }
    if (c.parent != 0) detail::add_force(data.X_PB[i], F, data.F_B[c.parent].data());
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
