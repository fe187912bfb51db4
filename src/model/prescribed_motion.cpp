#include "momenta/model/prescribed_motion.hpp"

#include "momenta/math/lie_group.hpp"
#include "momenta/math/rotation.hpp"

namespace momenta::model {
namespace {

// The rotation vector's samples at `first`, `first + 1`, `first + 2` of the joint's signals:
// writes the quaternion (w, x, y, z) at q, ω at v and ω̇ at vdot (when not null).
void prescribed_rotation(const Joint& joint, std::span<const SignalSample> samples, int first,
                         double* q, double* v, double* vdot) {
  Vec3 phi, phi_rate, phi_acceleration;
  for (int k = 0; k < 3; ++k) {
    const SignalSample& s = samples[joint.prescribed_signal_indices[first + k]];
    phi[k] = s.value;
    phi_rate[k] = s.rate;
    phi_acceleration[k] = s.acceleration;
  }
  const Quat r = quaternion_exp(phi);
  q[0] = r.w();
  q[1] = r.x();
  q[2] = r.y();
  q[3] = r.z();
  const Mat3 J = so3_right_jacobian(phi);
  Eigen::Map<Vec3> w(v);
  w = J * phi_rate;
  if (vdot != nullptr) {
    Eigen::Map<Vec3> w_dot(vdot);
    w_dot = J * phi_acceleration + so3_right_jacobian_rate(phi, phi_rate) * phi_rate;
  }
}

}  // namespace

void prescribed_joint_motion(const Joint& joint, std::span<const SignalSample> signal_samples,
                             double* q, double* v, double* vdot) {
  switch (joint.type) {
    case JointType::spherical:
      prescribed_rotation(joint, signal_samples, 0, q, v, vdot);
      return;
    case JointType::free:
      prescribed_rotation(joint, signal_samples, 0, q + 3, v, vdot);
      for (int k = 0; k < 3; ++k) {
        const SignalSample& s = signal_samples[joint.prescribed_signal_indices[3 + k]];
        q[k] = s.value;
        v[3 + k] = s.rate;
        if (vdot != nullptr) vdot[3 + k] = s.acceleration;
      }
      return;
    case JointType::fixed:
    case JointType::revolute:
    case JointType::prismatic:
    case JointType::cylindrical:
    case JointType::universal:
    case JointType::planar:
      for (int k = 0; k < joint.nv(); ++k) {
        const SignalSample& s = signal_samples[joint.prescribed_signal_indices[k]];
        q[k] = s.value;
        v[k] = s.rate;
        if (vdot != nullptr) vdot[k] = s.acceleration;
      }
  }
}

}  // namespace momenta::model
