#include "momenta/dynamics/kinematics.hpp"

#include "argument_checks.hpp"

#include "joint_kernels.hpp"

namespace momenta::dynamics {

void forward_kinematics(const Model& model, Data& data, const VecX& q) {
  detail::check_data_and_q("forward_kinematics", model, data, q);
  const auto& joints = model.joint_constants();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const auto& c = joints[j];
    detail::joint_position(c, q.data() + c.q_index, data.X_PB[c.child], data.S[j]);
    data.X_WB[c.child] = data.X_WB[c.parent] * data.X_PB[c.child];
  }
}

void forward_kinematics(const Model& model, Data& data, const VecX& q, const VecX& v) {
  detail::check_data_and_q("forward_kinematics", model, data, q);
  detail::check_nv("forward_kinematics", "v", model, v);
  const auto& joints = model.joint_constants();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const auto& c = joints[j];
    const int i = c.child;
    detail::joint_position(c, q.data() + c.q_index, data.X_PB[i], data.S[j]);
    data.X_WB[i] = data.X_WB[c.parent] * data.X_PB[i];
    // V_i = ⁱX_λ V_λ + S v̄;  c_i = V_i × S v̄ + Ṡ v̄ (Featherstone 2008, Table 7.1).
    const Vec6 vJ = detail::joint_velocity(c, data.S[j], v.data() + c.v_index);
    data.V_WB_B[i] = data.X_PB[i].act_motion_inverse(data.V_WB_B[c.parent]) + vJ;
    data.c_B[i] = cross_motion(data.V_WB_B[i], vJ);
    Vec6 cJ;
    if (detail::joint_bias(c, q.data() + c.q_index, v.data() + c.v_index, cJ)) data.c_B[i] += cJ;
  }
}

void forward_kinematics(const Model& model, Data& data, const VecX& q, const VecX& v,
                        const VecX& vdot) {
  detail::check_nv("forward_kinematics", "vdot", model, vdot);
  forward_kinematics(model, data, q, v);
  const auto& joints = model.joint_constants();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const auto& c = joints[j];
    const int i = c.child;
    // A_i = ⁱX_λ A_λ + S v̇ + c_i; the bias part leaves out S v̇.
    data.A_bias_B[i] = data.X_PB[i].act_motion_inverse(data.A_bias_B[c.parent]) + data.c_B[i];
    data.A_WB_B[i] = data.X_PB[i].act_motion_inverse(data.A_WB_B[c.parent]) + data.c_B[i] +
                     detail::joint_velocity(c, data.S[j], vdot.data() + c.v_index);
  }
}

}  // namespace momenta::dynamics
