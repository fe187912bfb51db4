#include "momenta/dynamics/reactions.hpp"

#include "argument_checks.hpp"

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/rnea.hpp"

namespace momenta::dynamics {

void joint_reactions(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot,
                     std::span<const Vec6> f_ext) {
  detail::check_inverse_dynamics("joint_reactions", model, data, q, v, vdot, f_ext);
  // The backward pass of RNEA leaves in F_B the wrench each joint transmits to its subtree
  // (Newton–Euler of the subtree: Σ of I a + v ×* I v − f_ext over it).
  rnea(model, data, q, v, vdot, f_ext);
  for (const auto& c : model.joint_constants()) {
    data.X_WB[c.child] = data.X_WB[c.parent] * data.X_PB[c.child];
  }
}

JointReaction joint_reaction(const Model& model, const Data& data, int j, ReactionFrame frame) {
  if (j < 0 || j >= model.num_joints()) {
    throw InvalidArgument(
        fmt::format("joint_reaction: joint index {} outside [0, {})", j, model.num_joints()));
  }
  const auto& c = model.joint_constants()[j];
  const int b = c.child;
  // Wrench in C about Co → about J'o (p_CoJ'o_C = X_CJ.p = −R_JCᵀ p_JC).
  const Vec6& F = data.F_B[b];
  const Transform X_CJ = c.X_JC.inverse();
  const Vec3 f_C = F.tail<3>();
  const Vec3 n_C = F.head<3>() - X_CJ.p.cross(f_C);
  Mat3 R = Mat3::Identity();  // R_AC for the frame A asked for.
  switch (frame) {
    case ReactionFrame::joint:
      R = X_CJ.R.transpose();
      break;
    case ReactionFrame::child:
      R = Mat3::Identity();
      break;
    case ReactionFrame::parent:
      R = data.X_PB[b].R;
      break;
    case ReactionFrame::world:
      R = data.X_WB[b].R;
      break;
  }
  return {R * f_C, R * n_C};
}

}  // namespace momenta::dynamics
