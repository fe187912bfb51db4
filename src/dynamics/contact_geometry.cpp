#include "momenta/dynamics/contact_geometry.hpp"

#include <cmath>

#include <fmt/format.h>

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
    g.gap = g.normal_W.dot(centre_b - contact.plane_point) - contact.radius;
    g.point_W = centre_b - contact.radius * g.normal_W;
    return with_tangents(g);
  }
  if (contact.other_plane) {  // the plane's frame: z its normal, x and y its tangents
    const Transform X_WF = data.X_WB[contact.other.body_index] * contact.other.X_BF;
    g.normal_W = X_WF.R.col(2);
    g.tangent_1_W = X_WF.R.col(0);
    g.tangent_2_W = X_WF.R.col(1);
    g.gap = g.normal_W.dot(centre_b - X_WF.p) - contact.radius;
    g.point_W = centre_b - contact.radius * g.normal_W;
    return g;
  }
  const Vec3 centre_a = data.X_WB[contact.other.body_index].apply(contact.other.X_BF.p);
  const Vec3 d = centre_b - centre_a;
  const double length = d.norm();
  if (!(length > 0.0)) {
    throw NumericalError(
        fmt::format("contact '{}': the spheres' centres coincide: no line of centres to push along",
                    contact.name));
  }
  g.normal_W = d / length;
  g.gap = length - contact.radius - contact.other_radius;
  g.point_W = centre_a + contact.other_radius * g.normal_W;
  return with_tangents(g);
}

}  // namespace momenta::dynamics
