#pragma once
// The forward (root-to-leaves) kinematics pass every dynamics algorithm shares, one joint at a
// time (private to src/dynamics). forward_kinematics, rnea, aba, hybrid_dynamics and crba call
// these steps in their own first loop, where each adds what it needs (accelerations, inertias,
// bias forces) while the joint's quantities are still in registers.
//
// Featherstone 2008, Table 7.1, in the child body frame B of joint j (parent body λ):
//   X_PB = X_PJ · X_JJ'(q) · X_JC,   V_B = ᴮX_λ V_λ + S v̄,   c_B = V_B ×m S v̄ + Ṡ v̄.
// The world (body 0) stays at rest in Data, so a root joint's parent velocity is zero there.

#include "joint_kernels.hpp"
#include "momenta/math/spatial_kernels.hpp"

namespace momenta::dynamics::detail {

/// Position step of joint j: data.X_PB[child] and data.S[j] from q.
inline void position_step(const JointConstants& c, int j, const double* q, Data& data) {
  joint_position(c, q + c.q_index, data.X_PB[c.child], data.S[j]);
}

/// Velocity step of joint j after its position step: V_WB_B and c_B of its child from v.
[[gnu::always_inline]] inline void velocity_after_position(const JointConstants& c, int j,
                                                           const double* q, const double* v,
                                                           Data& data) {
  const int i = c.child;
  const Transform& X = data.X_PB[i];
  const double* vj = v + c.v_index;
  double V[6];
  double cB[6] = {0, 0, 0, 0, 0, 0};
  kernel::motion_inverse(X.R, X.p, data.V_WB_B[c.parent].data(), V);
  if (c.S_basis >= 0) {
    // Axis along a coordinate axis of B: S v̄ = v̄ e_k, and (V_λ + S v̄) ×m S v̄ = V_λ ×m S v̄.
    kernel::add_cross_motion_basis(V, c.S_basis, vj[0], cB);
    kernel::add_basis(c.S_basis, vj[0], V);
  } else {
    const Vec6 vJ = joint_velocity(c, data.S[j], vj);
    kernel::add_cross_motion(V, vJ.data(), cB);
    for (int r = 0; r < 6; ++r) V[r] += vJ[r];
    Vec6 cJ;
    if (joint_bias(c, q + c.q_index, vj, cJ)) {
      for (int r = 0; r < 6; ++r) cB[r] += cJ[r];
    }
  }
  for (int r = 0; r < 6; ++r) {
    data.V_WB_B[i][r] = V[r];
    data.c_B[i][r] = cB[r];
  }
}

/// Position and velocity step of joint j: X_PB, S, then V_WB_B and c_B of its child from v.
[[gnu::always_inline]] inline void velocity_step(const JointConstants& c, int j, const double* q,
                                                 const double* v, Data& data) {
  position_step(c, j, q, data);
  velocity_after_position(c, j, q, v, data);
}

}  // namespace momenta::dynamics::detail
