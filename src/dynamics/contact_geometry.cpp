#include "momenta/dynamics/contact_geometry.hpp"

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::dynamics {

ContactGeometry contact_geometry(const model::Contact& contact, const Data& data) {
  ContactGeometry g;
  const Vec3 centre_b = data.X_WB[contact.frame.body_index].apply(contact.frame.X_BF.p);
  if (contact.on_ground()) {
    g.normal_W = contact.plane_normal;
    g.gap = g.normal_W.dot(centre_b - contact.plane_point) - contact.radius;
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
  return g;
}

}  // namespace momenta::dynamics
