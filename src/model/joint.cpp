#include "momenta/model/joint.hpp"

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/math/rotation.hpp"

namespace momenta::model {
namespace {

// Rotation about the unit axis a by angle θ (axes are validated once by the builder).
Mat3 axis_rotation(const Vec3& a, double theta) {
  return unit_axis_rotation(a, std::cos(theta), std::sin(theta));
}

Mat3 quaternion_rotation(const double* wxyz) {
  return Quat(wxyz[0], wxyz[1], wxyz[2], wxyz[3]).normalized().toRotationMatrix();
}

}  // namespace

std::string_view joint_type_name(JointType type) { return joint_traits(type).name; }

JointType joint_type_from_name(std::string_view name) {
  std::vector<std::string_view> names, aliases;
  for (const JointTraits& t : kJointTraits) {
    if (t.name == name || (!t.alias.empty() && t.alias == name)) return t.type;
    names.push_back(t.name);
    if (!t.alias.empty()) aliases.push_back(t.alias);
  }
  std::vector<std::string_view> every = names;
  every.insert(every.end(), aliases.begin(), aliases.end());
  throw InvalidArgument(fmt::format("unknown joint type '{}'{}; expected one of {} (or {})", name,
                                    did_you_mean(name, every), fmt::join(names, ", "),
                                    fmt::join(aliases, ", ")));
}

Transform joint_transform(const Joint& joint, const double* q) {
  switch (joint.type) {
    case JointType::fixed:
      return {};
    case JointType::revolute:
      return Transform::rotation(axis_rotation(joint.axis, q[0]));
    case JointType::prismatic:
      return Transform::translation(joint.axis * q[0]);
    case JointType::cylindrical:
      return {axis_rotation(joint.axis, q[0]), joint.axis * q[1]};
    case JointType::universal:
      return Transform::rotation(axis_rotation(joint.axis, q[0]) *
                                 axis_rotation(joint.axis2, q[1]));
    case JointType::spherical:
      return Transform::rotation(quaternion_rotation(q));
    case JointType::planar:
      return {axis_rotation(Vec3::UnitZ(), q[2]), Vec3(q[0], q[1], 0.0)};
    case JointType::free:
      return {quaternion_rotation(q + 3), Vec3(q[0], q[1], q[2])};
  }
  return {};
}

Mat6 joint_motion_subspace(const Joint& joint, const double* q) {
  Mat6 S = Mat6::Zero();
  switch (joint.type) {
    case JointType::fixed:
      break;
    case JointType::revolute:
      S.block<3, 1>(0, 0) = joint.axis;
      break;
    case JointType::prismatic:
      S.block<3, 1>(3, 0) = joint.axis;
      break;
    case JointType::cylindrical:
      S.block<3, 1>(0, 0) = joint.axis;
      S.block<3, 1>(3, 1) = joint.axis;
      break;
    case JointType::universal:
      // ω in J' = R2ᵀ a1 θ̇1 + a2 θ̇2 (R2 = Rot(a2, θ2) leaves a2 unchanged).
      S.block<3, 1>(0, 0) = axis_rotation(joint.axis2, q[1]).transpose() * joint.axis;
      S.block<3, 1>(0, 1) = joint.axis2;
      break;
    case JointType::spherical:
      S.topLeftCorner<3, 3>().setIdentity();
      break;
    case JointType::planar: {
      const Mat3 Rt = axis_rotation(Vec3::UnitZ(), q[2]).transpose();
      S.block<3, 2>(3, 0) = Rt.leftCols<2>();
      S(2, 2) = 1.0;
      break;
    }
    case JointType::free:
      S.topLeftCorner<3, 3>().setIdentity();
      S.block<3, 3>(3, 3) = quaternion_rotation(q + 3).transpose();
      break;
  }
  return S;
}

}  // namespace momenta::model
