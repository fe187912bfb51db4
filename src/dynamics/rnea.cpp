#include "momenta/dynamics/rnea.hpp"

#include "argument_checks.hpp"

#include "forward_pass.hpp"

namespace momenta::dynamics {

const VecX& rnea(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot,
                 std::span<const Vec6> f_ext) {
  detail::check_inverse_dynamics("rnea", model, data, q, v, vdot, f_ext);
  const auto& joints = model.joint_constants();
  const int nj = static_cast<int>(joints.size());
  // Gravity enters as a fictitious upward acceleration of the base (Featherstone 2008, §5.3).
  const Vec6 a_base = spatial(Vec3::Zero(), -model.gravity());
  const bool has_fext = !f_ext.empty();

  // Forward pass: velocities (the shared kinematics step), accelerations and the net force
  // each body needs: A_i = ⁱX_λ A_λ + S v̇ + c_i,  F_i = I_i A_i + V_i ×* I_i V_i − f_ext,i.
  data.A_gf[0] = a_base;
  for (int j = 0; j < nj; ++j) {
    const auto& c = joints[j];
    const int i = c.child;
    detail::velocity_step(c, j, q.data(), v.data(), data);
    const double* V = data.V_WB_B[i].data();
    const double* cB = data.c_B[i].data();
    const Transform& X = data.X_PB[i];
    double A[6];
    detail::to_child(c, X, data.A_gf[c.parent].data(), A);
    for (int r = 0; r < 6; ++r) A[r] += cB[r];
    if (c.S_basis >= 0) {
      kernel::add_basis(c.S_basis, vdot[c.v_index], A);
    } else {
      const Vec6 aJ = detail::joint_velocity(c, data.S[j], vdot.data() + c.v_index);
      for (int r = 0; r < 6; ++r) A[r] += aJ[r];
    }
    const SpatialInertia& I = model.spatial_inertia(i);
    double IV[6], F[6];
    kernel::inertia_times(I.mass, I.h, I.I_O, V, IV);
    kernel::inertia_times(I.mass, I.h, I.I_O, A, F);
    kernel::add_cross_force(V, IV, F);
    if (has_fext) {
      for (int r = 0; r < 6; ++r) F[r] -= f_ext[i][r];
    }
    for (int r = 0; r < 6; ++r) {
      data.A_gf[i][r] = A[r];
      data.F_B[i][r] = F[r];
    }
  }

  // Backward pass: project onto the joint axes and pass the rest to the parent. The force a
  // body passes to its parent stays in `carried` while the next joint processed is the parent's
  // own (always so along a chain), so it is not stored and reloaded at once.
  double carried[6] = {0, 0, 0, 0, 0, 0};
  int carried_to = 0;
  for (int j = nj - 1; j >= 0; --j) {
    const auto& c = joints[j];
    const int i = c.child;
    if (carried_to != i && carried_to != 0) {
      for (int r = 0; r < 6; ++r) data.F_B[carried_to][r] += carried[r];
    }
    double F[6];
    for (int r = 0; r < 6; ++r) F[r] = data.F_B[i][r] + (carried_to == i ? carried[r] : 0.0);
    for (int r = 0; r < 6; ++r) data.F_B[i][r] = F[r];
    if (c.S_basis >= 0) {
      data.tau[c.v_index] = F[c.S_basis];
    } else {
      for (int k = 0; k < c.nv; ++k) data.tau[c.v_index + k] = data.S[j].col(k).dot(data.F_B[i]);
    }
    // The rotor's reflected inertia (armature) on the joint's own coordinates.
    for (int k = 0; k < c.nv && c.armature != 0.0; ++k)
      data.tau[c.v_index + k] += c.armature * vdot[c.v_index + k];
    carried_to = c.parent;
    detail::to_parent(c, data.X_PB[i], F, carried);
  }
  return data.tau;
}

VecX inverse_dynamics(const Model& model, VecRef q, VecRef v, VecRef vdot,
                      std::span<const Vec6> f_ext) {
  Data data(model);
  return rnea(model, data, q, v, vdot, f_ext);
}

const VecX& nonlinear_effects(const Model& model, Data& data, VecRef q, VecRef v) {
  data.scratch_nv.setZero();
  data.nle = rnea(model, data, q, v, data.scratch_nv);
  return data.nle;
}

const VecX& generalized_gravity(const Model& model, Data& data, VecRef q) {
  data.scratch_nv.setZero();
  data.g = rnea(model, data, q, data.scratch_nv, data.scratch_nv);
  return data.g;
}

}  // namespace momenta::dynamics
