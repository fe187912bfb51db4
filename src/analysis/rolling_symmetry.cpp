#include "rolling_symmetry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "momenta/common/error.hpp"

namespace momenta::analysis::detail {
namespace {

bool is_ball_or_free(const model::Joint& joint) {
  return joint.type == model::JointType::spherical || joint.type == model::JointType::free;
}

// The one rolling disk of the model, or an error saying what the model has instead.
const model::RollingContact& the_rolling_disk(const model::Model& model) {
  if (!(model.num_joints() == 1 && model.joint(0).parent_index == 0 &&
        is_ball_or_free(model.joint(0)))) {
    throw InvalidArgument(fmt::format(
        "steady motions of a rolling body are found for one body on a free or spherical joint to "
        "the world; this model has {} joint{}{}",
        model.num_joints(), model.num_joints() == 1 ? "" : "s",
        model.num_joints() >= 1
            ? fmt::format(", the first a {} joint", model::joint_type_name(model.joint(0).type))
            : std::string()));
  }
  if (model.joint(0).is_prescribed()) {
    throw InvalidArgument(
        fmt::format("joint '{}' is prescribed: its motion is an input, not a steady motion to find",
                    model.joint(0).name));
  }
  const auto* disk = model.constraints().size() == 1
                         ? std::get_if<model::RollingContact>(&model.constraints().front())
                         : nullptr;
  if (disk == nullptr || disk->shape != model::RollingShape::disk) {
    throw InvalidArgument(fmt::format(
        "steady motions of a rolling body need exactly one constraint, a rolling disk; this model "
        "has {} constraint{}",
        model.constraints().size(), model.constraints().size() == 1 ? " of another kind" : "s"));
  }
  return *disk;
}

}  // namespace

RollingBody rolling_body(const model::Model& model) {
  const model::RollingContact& disk = the_rolling_disk(model);
  const model::Body& b = model.body(1);
  RollingBody body;
  body.joint = &model.joint(0);
  body.axis_B = disk.frame.X_BF.R.col(2).normalized();
  body.p_BoD_B = disk.frame.X_BF.p;
  body.p_BoG_B = b.mass_properties.center_of_mass();
  body.g = model.gravity().norm();
  body.up_W = disk.plane_normal.normalized();
  body.floor_height = body.up_W.dot(disk.plane_point);
  RollingBodyInfo& info = body.info;
  info.body = b.name;
  info.joint = body.joint->name;
  info.contact = disk.name;
  info.pivoted = body.joint->type == model::JointType::spherical;
  info.radius = disk.radius;
  info.mass = b.mass_properties.mass();

  // A level floor: its normal against gravity.
  if (body.g > 0.0) {
    const double c = std::clamp(body.up_W.dot(-model.gravity() / body.g), -1.0, 1.0);
    if (!(c >= 1.0 - 1e-9)) {
      throw InvalidArgument(fmt::format(
          "rolling contact '{}': the floor's normal makes {:.6g}° with the upward vertical; a "
          "steady turn needs a level floor (normal against gravity)",
          disk.name, std::acos(c) * 180.0 / std::numbers::pi));
    }
  }
  // Round about the disk's axis: e principal, the moments across it equal, G on it.
  const Vec3& e = body.axis_B;
  const Mat3& I = b.mass_properties.inertia_about_com();
  const Vec3 u1 = e.unitOrthogonal(), u2 = e.cross(u1);
  const double scale = I.norm(),
               length = std::max(disk.radius, (body.p_BoG_B - body.p_BoD_B).norm());
  info.axial_moment = e.dot(I * e);
  info.transverse_moment = u1.dot(I * u1);
  const double off_axis = (I * e - info.axial_moment * e).norm();
  const double unequal = std::abs(u1.dot(I * u1) - u2.dot(I * u2)) + std::abs(u1.dot(I * u2));
  if (!(off_axis <= 1e-9 * scale && unequal <= 1e-9 * scale)) {
    throw InvalidArgument(fmt::format(
        "body '{}' is not round about the disk's axis [{:.6g}, {:.6g}, {:.6g}] (in the body): its "
        "inertia about the centre of mass differs across it by {:.3g} kg·m² and couples it by "
        "{:.3g} kg·m²; steady motions need a body of revolution about that axis",
        b.name, e.x(), e.y(), e.z(), unequal, off_axis));
  }
  const double G_off = (body.p_BoG_B - body.p_BoD_B).cross(e).norm();
  if (!(G_off <= 1e-9 * length)) {
    throw InvalidArgument(fmt::format(
        "body '{}': its centre of mass is {:.6g} m off the disk's axis; steady motions need it on "
        "the axis",
        b.name, G_off));
  }
  if (info.pivoted) {
    const double O_off = (body.joint->X_CJ.p - body.p_BoG_B).cross(e).norm();
    if (!(O_off <= 1e-9 * std::max(length, (body.joint->X_CJ.p - body.p_BoG_B).norm()))) {
      throw InvalidArgument(fmt::format(
          "spherical joint '{}': its pivot is {:.6g} m off the disk's axis; the disk can spin "
          "steadily only about an axle through the pivot",
          body.joint->name, O_off));
    }
  }
  return body;
}

Transform body_pose(const RollingBody& body, const VecX& q) {
  const model::Joint& joint = *body.joint;
  const int k = joint.q_index;
  const bool free = joint.type == model::JointType::free;
  const int r = free ? k + 3 : k;
  const Quat quat(q[r], q[r + 1], q[r + 2], q[r + 3]);
  const Transform X_JJc(quat.normalized().toRotationMatrix(),
                        free ? Vec3(q.segment<3>(k)) : Vec3::Zero());
  return joint.X_PJ * X_JJc * joint.X_CJ.inverse();
}

VecX configuration_of_pose(const RollingBody& body, const Transform& X_WB) {
  const model::Joint& joint = *body.joint;
  const Transform X_JJc = joint.X_PJ.inverse() * X_WB * joint.X_CJ;
  const Quat quat(X_JJc.R);
  VecX q(joint.nq());
  const bool free = joint.type == model::JointType::free;
  if (free) q.head<3>() = X_JJc.p;
  q.tail<4>() << quat.w(), quat.x(), quat.y(), quat.z();
  return q;
}

SymmetryMotion::SymmetryMotion(const RollingBody& body, const TurnRates& rates, const Vec3& p_WoG_W)
    : body_(body), pivoted_(body.info.pivoted) {
  const model::Joint& joint = *body.joint;
  // The world's twist: Ω about n, G moving at v_G; in J about J's origin.
  const Vec3 a_W = rates.precession * body.up_W;
  const Vec3 b_W = rates.v_WG_W - a_W.cross(p_WoG_W);  // the velocity of the point at Wo
  a_J_ = joint.X_PJ.R.transpose() * a_W;
  b_J_ = joint.X_PJ.R.transpose() * (b_W + a_W.cross(joint.X_PJ.p));
  // The body's twist: σ about e through G; in J' about J''s origin.
  const Vec3 c_B = rates.relative_spin * body.axis_B;
  c_Jc_ = joint.X_CJ.R.transpose() * c_B;
  d_Jc_ = joint.X_CJ.R.transpose() * c_B.cross(joint.X_CJ.p - body.p_BoG_B);
}

void SymmetryMotion::velocity(const VecX& q, VecX& v) const {
  const Transform X_JJc = body_.joint->X_PJ.inverse() * body_pose(body_, q) * body_.joint->X_CJ;
  v.resize(body_.joint->nv());
  v.head<3>() = X_JJc.R.transpose() * a_J_ + c_Jc_;
  if (!pivoted_) v.tail<3>() = a_J_.cross(X_JJc.p) + b_J_ + X_JJc.R * d_Jc_;
}

void SymmetryMotion::velocity_rate(const VecX& q, const VecX& v, VecX& rate) const {
  const Vec3 w_Jc = v.head<3>();
  rate.resize(body_.joint->nv());
  rate.head<3>() = -c_Jc_.cross(w_Jc);
  if (!pivoted_) {
    const Transform X_JJc = body_.joint->X_PJ.inverse() * body_pose(body_, q) * body_.joint->X_CJ;
    rate.tail<3>() = a_J_.cross(Vec3(v.tail<3>())) + X_JJc.R * w_Jc.cross(d_Jc_);
  }
}

}  // namespace momenta::analysis::detail
