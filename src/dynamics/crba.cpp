#include "momenta/dynamics/crba.hpp"

#include "joint_kernels.hpp"

namespace momenta::dynamics {

// The composite-rigid-body algorithm in world coordinates (Featherstone 2008, §6.2, with the
// quantities expressed in the fixed frame as in Pinocchio's crba): with composite inertias I_c
// and motion subspaces J in W, M(λ, i) = J_λᵀ (I_c,i J_i) for every ancestor λ of joint i.
// In W each entry is one dot product (no per-ancestor transform), so a column costs O(depth).
const MatX& crba(const Model& model, Data& data, const VecX& q) {
  const auto& joints = model.joint_constants();
  const int nj = static_cast<int>(joints.size());

  // Poses, motion subspaces and body inertias in W.
  for (int j = 0; j < nj; ++j) {
    const auto& c = joints[j];
    const int i = c.child;
    detail::joint_position(c, q.data() + c.q_index, data.X_PB[i], data.S[j]);
    data.X_WB[i] = data.X_WB[c.parent] * data.X_PB[i];
    for (int k = 0; k < c.nv; ++k) {
      data.J_W.col(c.v_index + k) = data.X_WB[i].act_motion(data.S[j].col(k));
    }
    data.I_composite[i] = model.spatial_inertia(i).transformed(data.X_WB[i]);
  }

  // Composite inertias, leaves to root.
  for (int j = nj - 1; j >= 0; --j) {
    const auto& c = joints[j];
    if (c.parent != 0) data.I_composite[c.parent] += data.I_composite[c.child];
  }

  // Columns: F = I_c J for each joint, then the entries with its ancestors (and itself).
  if (!data.all_dofs_related) data.M.setZero();
  for (int j = 0; j < nj; ++j) {
    const auto& c = joints[j];
    if (c.nv == 0) continue;
    const SpatialInertia& Ic = data.I_composite[c.child];
    for (int k = 0; k < c.nv; ++k) {
      data.F_W.col(c.v_index + k) = Ic * Vec6(data.J_W.col(c.v_index + k));
    }
    const auto& ranges = data.support_ranges[j];
    for (std::size_t r = 0; r < ranges.size(); ++r) {
      const auto [start, size] = ranges[r];
      auto block = data.M.block(start, c.v_index, size, c.nv);
      block.noalias() =
          data.J_W.middleCols(start, size).transpose() * data.F_W.middleCols(c.v_index, c.nv);
      // Mirror into the lower triangle, leaving out the joint's own (symmetric) block.
      const int mirrored = r + 1 == ranges.size() ? size - c.nv : size;
      if (mirrored > 0) {
        data.M.block(c.v_index, start, c.nv, mirrored) = block.topRows(mirrored).transpose();
      }
    }
  }
  return data.M;
}

MatX mass_matrix(const Model& model, const VecX& q) {
  Data data(model);
  return crba(model, data, q);
}

}  // namespace momenta::dynamics
