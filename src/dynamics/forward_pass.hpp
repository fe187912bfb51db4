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

/// out = ᴮX_λ m: a motion vector of joint c's parent carried into its child, by the joint's
/// current X_PB (the half-cost form for a joint turning about a coordinate axis).
[[gnu::always_inline]] inline void to_child(const JointConstants& c, const Transform& X,
                                            const double* m, double* out) {
  if (c.turns_about_axis) {
    return with_axis_rotation(c.S_basis, X.R, [&](auto k, double cq, double sq) {
      kernel::motion_inverse_about_axis<decltype(k)::value>(cq, sq, X.p, m, out);
    });
  }
  kernel::motion_inverse(X.R, X.p, m, out);
}

/// out = ᴾX_B* f: a force on joint c's child carried to its parent (`out` may alias `f`).
[[gnu::always_inline]] inline void to_parent(const JointConstants& c, const Transform& X,
                                             const double* f, double* out) {
  if (c.turns_about_axis) {
    return with_axis_rotation(c.S_basis, X.R, [&](auto k, double cq, double sq) {
      kernel::force_about_axis<decltype(k)::value>(cq, sq, X.p, f, out);
    });
  }
  kernel::force(X.R, X.p, f, out);
}

/// Position step of joint j: data.X_PB[child] and data.S[j] from q.
inline void position_step(const JointConstants& c, int j, const double* q, Data& data) {
  joint_position(c, q + c.q_index, data.X_PB[c.child], data.S[j]);
}

/// The velocity step of a joint turning about coordinate axis K of its child
/// (c.turns_about_axis): X_PB = (Rot_K(q), p_PJ), then V and c_B, every index known at compile
/// time.
template <int K>
[[gnu::always_inline]] inline void velocity_step_about_axis(const JointConstants& c,
                                                            const double* q, const double* v,
                                                            Data& data) {
  const int i = c.child;
  Transform& X = data.X_PB[i];
  const auto [sq, cq] = math::sin_cos(q[c.q_index]);
  set_axis_rotation<K>(cq, sq, c.X_PJ.p, X);
  const double w = v[c.v_index];
  double V[6];
  double cB[6] = {0, 0, 0, 0, 0, 0};
  kernel::motion_inverse_about_axis<K>(cq, sq, X.p, data.V_WB_B[c.parent].data(), V);
  // S v̄ = v̄ e_K, and (V_λ + S v̄) ×m S v̄ = V_λ ×m S v̄.
  kernel::add_cross_motion_axis<K>(V, w, cB);
  V[K] += w;
  for (int r = 0; r < 6; ++r) {
    data.V_WB_B[i][r] = V[r];
    data.c_B[i][r] = cB[r];
  }
}

/// Position and velocity step of joint j: X_PB, S, then V_WB_B and c_B of its child from v.
[[gnu::always_inline]] inline void velocity_step(const JointConstants& c, int j, const double* q,
                                                 const double* v, Data& data) {
  if (c.turns_about_axis) {
    switch (c.S_basis) {
      case 0:
        return velocity_step_about_axis<0>(c, q, v, data);
      case 1:
        return velocity_step_about_axis<1>(c, q, v, data);
      default:
        return velocity_step_about_axis<2>(c, q, v, data);
    }
  }
  position_step(c, j, q, data);
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

}  // namespace momenta::dynamics::detail
