#include "momenta/dynamics/kinematics.hpp"

#include "argument_checks.hpp"

#include "forward_pass.hpp"

namespace momenta::dynamics {

void forward_kinematics(const Model& model, Data& data, VecRef q) {
  detail::check_data_and_q("forward_kinematics", model, data, q);
  const auto& joints = model.joint_constants();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const auto& c = joints[j];
    detail::position_step(c, static_cast<int>(j), q.data(), data);
    data.X_WB[c.child] = data.X_WB[c.parent] * data.X_PB[c.child];
  }
}

void forward_kinematics(const Model& model, Data& data, VecRef q, VecRef v) {
  detail::check_data_and_q("forward_kinematics", model, data, q);
  detail::check_nv("forward_kinematics", "v", model, v);
  const auto& joints = model.joint_constants();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const auto& c = joints[j];
    detail::velocity_step(c, static_cast<int>(j), q.data(), v.data(), data);
    data.X_WB[c.child] = data.X_WB[c.parent] * data.X_PB[c.child];
  }
}

void forward_kinematics(const Model& model, Data& data, VecRef q, VecRef v, VecRef vdot) {
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
