#include "momenta/dynamics/contact_geometry.hpp"

#include <cassert>
#include <cmath>

#include <fmt/format.h>

#include "constraint_row_formulas.hpp"
#include "momenta/common/error.hpp"
#include "momenta/math/rotation.hpp"

namespace momenta::dynamics {

namespace {

ContactGeometry with_tangents(ContactGeometry g) {
  g.tangent_1_W = plane_tangent(g.normal_W);
  g.tangent_2_W = g.normal_W.cross(g.tangent_1_W);
  return g;
}

// The velocity in W of body's material point at point_W (the ground's is zero).
Vec3 material_velocity(const Data& data, int body, const Vec3& point_W) {
  if (body == 0) return Vec3::Zero();
  const Transform& X = data.X_WB[body];
  const Vec6& V = data.V_WB_B[body];
  const Vec3 p_B = X.R.transpose() * (point_W - X.p);
  return X.R * (V.tail<3>() + V.head<3>().cross(p_B));
}

// The motion of the frame X_BF of body (the ground's where body is 0) at data's poses, and, with
// motion, its velocity and acceleration — spatial, in W about Wo (dynamics/constraints.hpp's rows).
detail::FrameMotionOf<double> frame_motion(const Data& data, int body, const Transform& X_BF,
                                           bool motion) {
  detail::FrameMotionOf<double> m = detail::frame_pose_and_velocity(data, body, X_BF, motion);
  if (motion && body != 0) m.A = data.X_WB[body].act_motion(data.A_WB_B[body]);
  return m;
}

// Body b's surface point nearest a plane of normal n: the sphere's lowest point or the disk's.
Vec3 nearest_point(const model::Contact& contact, const Data& data, const Vec3& normal_W) {
  const detail::FrameMotionOf<double> mb =
      frame_motion(data, contact.frame.body_index, contact.frame.X_BF, false);
  return mb.p + detail::surface_offset<double>(contact, mb, normal_W, Vec3::Zero()).offset;
}

// The gap to a plane through plane_point: from a sphere's centre less its radius (as the rows
// write it), from a disk's rim point.
double plane_gap(const model::Contact& contact, const ContactGeometry& g, const Vec3& centre_W,
                 const Vec3& plane_point_W) {
  if (contact.shape == model::ContactShape::sphere) {
    return g.normal_W.dot(centre_W - plane_point_W) - contact.radius;
  }
  return g.normal_W.dot(g.point_W - plane_point_W);
}

}  // namespace

Vec3 contact_point_velocity(const model::Contact& contact, const Data& data, const Vec3& point_W) {
  return material_velocity(data, contact.frame.body_index, point_W) -
         material_velocity(data, contact.other.body_index, point_W);
}

ContactGeometry contact_geometry(const model::Contact& contact, const Data& data) {
  ContactGeometry g;
  const Vec3 centre_b = data.X_WB[contact.frame.body_index].apply(contact.frame.X_BF.p);
  if (contact.on_ground()) {
    g.normal_W = contact.plane_normal;
    g.point_W = nearest_point(contact, data, g.normal_W);
    g.gap = plane_gap(contact, g, centre_b, contact.plane_point);
    return with_tangents(g);
  }
  if (contact.other_plane) {  // the plane's frame: z its normal, x and y its tangents
    const Transform X_WF = data.X_WB[contact.other.body_index] * contact.other.X_BF;
    g.normal_W = X_WF.R.col(2);
    g.tangent_1_W = X_WF.R.col(0);
    g.tangent_2_W = X_WF.R.col(1);
    g.point_W = nearest_point(contact, data, g.normal_W);
    g.gap = plane_gap(contact, g, centre_b, X_WF.p);
    return g;
  }
  // Another body's sphere: the line of centres, or the disk's point nearest the sphere's centre.
  const detail::FrameMotionOf<double> ma =
      frame_motion(data, contact.other.body_index, contact.other.X_BF, false);
  const detail::FrameMotionOf<double> mb =
      frame_motion(data, contact.frame.body_index, contact.frame.X_BF, false);
  const detail::SphereTouchOf<double> touch =
      contact.shape == model::ContactShape::disk
          ? detail::disk_against_sphere<double>(contact, ma, mb)
          : detail::sphere_against_sphere<double>(contact, ma, mb);
  g.normal_W = touch.normal;
  g.gap = touch.gap;
  g.point_W = touch.contact;
  return with_tangents(g);
}

double contact_gap_acceleration(const model::Contact& contact, const Data& data) {
  const detail::FrameMotionOf<double> ma =
      frame_motion(data, contact.other.body_index, contact.other.X_BF, true);
  const detail::FrameMotionOf<double> mb =
      frame_motion(data, contact.frame.body_index, contact.frame.X_BF, true);
  // The gap's row comes first: its second rate is ẇ · (V_b − V_a) + w · (A_b − A_a).
  double gap_acceleration = 0.0;
  bool first = true;
  detail::contact_rows<double>(contact, ma, mb,
                               [&](double, bool, const Vec6& w, const Vec6& w_rate) {
                                 if (!first) return;
                                 gap_acceleration = w_rate.dot(mb.V - ma.V) + w.dot(mb.A - ma.A);
                                 first = false;
                               });
  return gap_acceleration;
}

Vec2 contact_slip_acceleration(const model::Contact& contact, const Data& data) {
  assert(contact.has_friction());
  const detail::FrameMotionOf<double> ma =
      frame_motion(data, contact.other.body_index, contact.other.X_BF, true);
  const detail::FrameMotionOf<double> mb =
      frame_motion(data, contact.frame.body_index, contact.frame.X_BF, true);
  // The gap's row, then the tangents' two.
  Vec2 slip = Vec2::Zero();
  int row = 0;
  detail::contact_rows<double>(contact, ma, mb,
                               [&](double, bool, const Vec6& w, const Vec6& w_rate) {
                                 if (row > 0)
                                   slip[row - 1] = w_rate.dot(mb.V - ma.V) + w.dot(mb.A - ma.A);
                                 ++row;
                               });
  return slip;
}

bool disk_lies_flat(const model::Contact& contact, const Data& data, double tolerance) {
  if (contact.shape != model::ContactShape::disk || !contact.on_plane()) return false;
  const Vec3 axis_W = (data.X_WB[contact.frame.body_index] * contact.frame.X_BF).R.col(2);
  return axis_W.cross(contact_geometry(contact, data).normal_W).norm() < tolerance;
}

}  // namespace momenta::dynamics
