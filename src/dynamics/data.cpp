#include "momenta/dynamics/data.hpp"

#include "momenta/model/joint.hpp"

namespace momenta::dynamics {
namespace {

// Appends a joint's velocity coordinates to ascending runs, merged into the last run where they
// continue it (nothing for a joint without coordinates).
void add_joint_range(std::vector<std::pair<int, int>>& ranges, const model::Joint& joint) {
  if (joint.nv() == 0) return;
  if (!ranges.empty() && ranges.back().first + ranges.back().second == joint.v_index) {
    ranges.back().second += joint.nv();
  } else {
    ranges.emplace_back(joint.v_index, joint.nv());
  }
}

// Buffers handed out and taken back in the order the sweeps visit the joints, reusing the
// lowest free one: how many a sweep needs is how many sums are alive at once.
class BufferPool {
 public:
  int take() {
    if (free_.empty()) return count_++;
    const int buffer = free_.back();
    free_.pop_back();
    return buffer;
  }
  void give_back(int buffer) { free_.push_back(buffer); }
  int count() const { return count_; }

 private:
  std::vector<int> free_;
  int count_ = 0;
};

// aba_derivatives' subtree sums, visited leaves to root: a joint takes over its last child's
// buffer and adds its other children's, which are freed; a leaf takes a free one. A root joint's
// sum is nobody's child's, so its buffer is freed once it is done.
int assign_subtree_sums(const std::vector<std::vector<int>>& child_joints,
                        const std::vector<int>& parent_joint, std::vector<int>& slot) {
  BufferPool pool;
  const auto nj = static_cast<int>(child_joints.size());
  slot.assign(child_joints.size(), -1);
  for (int j = nj - 1; j >= 0; --j) {
    const auto& children = child_joints[j];
    if (children.empty()) {
      slot[j] = pool.take();
    } else {
      slot[j] = slot[children.back()];
      for (std::size_t k = 0; k + 1 < children.size(); ++k) pool.give_back(slot[children[k]]);
    }
    if (parent_joint[j] < 0) pool.give_back(slot[j]);
  }
  return pool.count();
}

// Its sums over the ancestors, visited root to leaves: a joint takes over its parent's buffer
// if it is the parent's last child, otherwise a free one (a copy); a leaf's is freed once done.
int assign_path_sums(const std::vector<std::vector<int>>& child_joints,
                     const std::vector<int>& parent_joint, std::vector<int>& slot) {
  BufferPool pool;
  slot.assign(child_joints.size(), -1);
  for (std::size_t j = 0; j < child_joints.size(); ++j) {
    const int p = parent_joint[j];
    const bool last_child = p >= 0 && child_joints[p].back() == static_cast<int>(j);
    slot[j] = last_child ? slot[p] : pool.take();
    if (child_joints[j].empty()) pool.give_back(slot[j]);
  }
  return pool.count();
}

}  // namespace

Data::Data(const Model& model) {
  const auto nb = static_cast<std::size_t>(model.num_bodies());
  const auto nj = static_cast<std::size_t>(model.num_joints());
  const int nv = model.nv();
  X_PB.assign(nb, Transform());
  X_WB.assign(nb, Transform());
  S.assign(nj, Mat6::Zero());
  V_WB_B.assign(nb, Vec6::Zero());
  c_B.assign(nb, Vec6::Zero());
  A_WB_B.assign(nb, Vec6::Zero());
  A_bias_B.assign(nb, Vec6::Zero());
  F_B.assign(nb, Vec6::Zero());
  A_gf.assign(nb, Vec6::Zero());
  IA.assign(nb, Mat6::Zero());
  pA.assign(nb, Vec6::Zero());
  U.assign(nj, Mat6::Zero());
  Dinv.assign(nj, Mat6::Zero());
  u.assign(nj, Vec6::Zero());
  solve_f.assign(nb, SolveColumns::Zero());
  solve_a.assign(nb, SolveColumns::Zero());
  solve_U_parent.assign(nj, Vec6::Zero());
  I_composite.assign(nb, SpatialInertia());
  S_W = MatX::Zero(nv, 6);
  tau = VecX::Zero(nv);
  vdot = VecX::Zero(nv);
  nle = VecX::Zero(nv);
  axis_cos = VecX::Zero(static_cast<Eigen::Index>(model.joint_constants().size()));
  axis_sin = VecX::Zero(static_cast<Eigen::Index>(model.joint_constants().size()));
  g = VecX::Zero(nv);
  M = MatX::Zero(nv, nv);
  dV_W.assign(nb, Vec6::Zero());
  dA_W.assign(nb, Vec6::Zero());
  dF_W.assign(nb, Vec6::Zero());
  dIc_W.assign(nb, SpatialInertia());
  dB_W.assign(nb, CoriolisInertia());
  dS_W = Mat6X::Zero(6, nv);
  dDeltaV_W = Mat6X::Zero(6, nv);
  dX_W = Mat6X::Zero(6, nv);
  dW_W = Mat6X::Zero(6, nv);
  minv_U_W = Mat6X::Zero(6, nv);
  minv_F_W = Mat6X::Zero(6, nv);
  minv_A_W.assign(nb, Mat6X::Zero(6, nv));
  dtau_lower_W.setZero(9, nv);
  dtau_upper_q_W = Mat6X::Zero(6, nv);
  dtau_upper_v_W = Mat6X::Zero(6, nv);
  dtau_dq = MatX::Zero(nv, nv);
  dtau_dv = MatX::Zero(nv, nv);
  dvdot_dq = MatX::Zero(nv, nv);
  dvdot_dv = MatX::Zero(nv, nv);
  Minv = MatX::Zero(nv, nv);
  dQ_dq = MatX::Zero(nv, nv);
  dQ_dv = MatX::Zero(nv, nv);
  dLoad_W.assign(nb, Vec6::Zero());
  scratch_nv = VecX::Zero(nv);
  prescribed_mask.resize(nj);
  for (std::size_t j = 0; j < nj; ++j) {
    prescribed_mask[j] = model.joint(static_cast<int>(j)).is_prescribed() ? 1 : 0;
  }

  // Motion subspaces in the child frame: the constant ones are set here once for all; the
  // q-dependent ones (universal, planar, free) are refreshed by every algorithm.
  const VecX q = model::neutral(model);
  for (std::size_t j = 0; j < nj; ++j) {
    const model::Joint& joint = model.joint(static_cast<int>(j));
    const model::JointConstants& c = model.joint_constants()[j];
    const Mat6 S_J = model::joint_motion_subspace(joint, q.data() + joint.q_index);
    for (int k = 0; k < joint.nv(); ++k) S[j].col(k) = c.X_JC.act_motion_inverse(S_J.col(k));
  }

  // Ancestor velocity ranges per joint, merged into contiguous runs, ascending.
  support_ranges.resize(nj);
  std::vector<int> joints_on_path;
  for (std::size_t j = 0; j < nj; ++j) {
    joints_on_path.clear();
    for (int b = static_cast<int>(j) + 1; b > 0; b = model.parent(b)) {
      joints_on_path.push_back(b - 1);
    }
    auto& ranges = support_ranges[j];
    for (auto it = joints_on_path.rbegin(); it != joints_on_path.rend(); ++it) {
      add_joint_range(ranges, model.joint(*it));
    }
  }
  // Descendant velocity ranges per joint: each joint's own range added to its own and every
  // ancestor's list (parents come before children, so the lists grow in ascending order), merged.
  subtree_ranges.resize(nj);
  for (std::size_t j = 0; j < nj; ++j) {
    const model::Joint& joint = model.joint(static_cast<int>(j));
    if (joint.nv() == 0) continue;
    for (int b = static_cast<int>(j) + 1; b > 0; b = model.parent(b)) {
      add_joint_range(subtree_ranges[static_cast<std::size_t>(b - 1)], joint);
    }
  }
  // M has structural zeros unless the joints with degrees of freedom form one chain, where
  // the support of each holds every earlier degree of freedom.
  all_dofs_related = true;
  for (std::size_t j = 0; j < nj; ++j) {
    const model::Joint& joint = model.joint(static_cast<int>(j));
    if (joint.nv() == 0) continue;
    const auto& r = support_ranges[j];
    if (r.size() != 1 || r[0].first != 0 || r[0].second != joint.v_index + joint.nv()) {
      all_dofs_related = false;
    }
  }

  // The joints' children, and the buffers of aba_derivatives' running sums.
  std::vector<int> parent_joint(nj);
  child_joints.assign(nj, {});
  for (std::size_t j = 0; j < nj; ++j) {
    parent_joint[j] = model.parent(static_cast<int>(j) + 1) - 1;
    if (parent_joint[j] >= 0) child_joints[parent_joint[j]].push_back(static_cast<int>(j));
  }
  const int lower_buffers = assign_subtree_sums(child_joints, parent_joint, minv_lower_slot);
  const int upper_buffers = assign_path_sums(child_joints, parent_joint, minv_upper_slot);
  minv_lower_sums.assign(lower_buffers, MatX::Zero(nv, 9));
  minv_upper_sums.assign(upper_buffers, MatX::Zero(nv, 6));
}

}  // namespace momenta::dynamics
