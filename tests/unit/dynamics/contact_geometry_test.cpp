// dynamics::contact_geometry against the geometry worked by hand: a ball above a tilted plane and
// two balls on rotated bodies — gap, normal and contact point — and the error where two centres
// coincide.

#include "momenta/dynamics/contact_geometry.hpp"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/io/model_file.hpp"

namespace momenta::dynamics {
namespace {

// Two free balls; contact 0 is ball b's sphere (r = 0.1 at [0.2, 0, 0] in b) on a plane tilted
// 30° about x through [0, 0, -1]; contact 1 is b's sphere on a's sphere (r = 0.3 at [0, 0, 0.5]
// in a).
const char* const kModel =
    "bodies: [{name: a, shape: sphere, mass: 1, radius: 0.3}, {name: b, shape: sphere, mass: 1, "
    "radius: 0.1}]\n"
    "joints:\n"
    "  - {name: fa, type: free, parent: world, child: a}\n"
    "  - {name: fb, type: free, parent: world, child: b}\n"
    "constraints:\n"
    "  - {name: tilted, type: contact, body: b, point: [0.2, 0, 0], radius: 0.1, normal: [0, "
    "-0.5, 0.8660254037844386], plane_point: [0, 0, -1]}\n"
    "  - {name: balls, type: contact, body: b, point: [0.2, 0, 0], radius: 0.1, other_body: a, "
    "other_point: [0, 0, 0.5], other_radius: 0.3}\n";

TEST(ContactGeometry, GapNormalAndPointAsWorkedByHand) {
  const model::Model model = io::parse_model_file(kModel, "geometry.yaml", ".").model;
  VecX q = model.initial_q();
  // a at [1, 2, 3] turned 90° about z (its [0, 0, 0.5] stays at [1, 2, 3.5]); b at [1.3, 2.4, 3.5]
  // turned 90° about z (its [0.2, 0, 0] lands at [1.3, 2.6, 3.5]).
  const double h = std::sqrt(0.5);
  q.segment<7>(0) << 1, 2, 3, h, 0, 0, h;
  q.segment<7>(7) << 1.3, 2.4, 3.5, h, 0, 0, h;
  Data data(model);
  forward_kinematics(model, data, q);

  const auto& tilted = std::get<model::Contact>(model.constraints()[0]);
  const ContactGeometry g = contact_geometry(tilted, data);
  const Vec3 n(0, -0.5, std::sqrt(3.0) / 2), centre(1.3, 2.6, 3.5);
  EXPECT_NEAR(g.gap, n.dot(centre - Vec3(0, 0, -1)) - 0.1, 1e-15);
  EXPECT_LT((g.normal_W - n).norm(), 1e-15);
  EXPECT_LT((g.point_W - (centre - 0.1 * n)).norm(), 1e-15);

  const auto& balls = std::get<model::Contact>(model.constraints()[1]);
  const ContactGeometry s = contact_geometry(balls, data);
  // Centres [1, 2, 3.5] and [1.3, 2.6, 3.5]: 0.3 √5 apart along [1, 2, 0] / √5.
  const Vec3 e = Vec3(1, 2, 0) / std::sqrt(5.0);
  EXPECT_NEAR(s.gap, 0.3 * std::sqrt(5.0) - 0.4, 1e-15);
  EXPECT_LT((s.normal_W - e).norm(), 1e-15);
  EXPECT_LT((s.point_W - (Vec3(1, 2, 3.5) + 0.3 * e)).norm(), 1e-15);

  // The centres on each other: no line of centres.
  q.segment<3>(7) = Vec3(1.0, 1.8, 3.5);  // b's sphere centre then at a's, [1, 2, 3.5]
  forward_kinematics(model, data, q);
  EXPECT_THROW(contact_geometry(balls, data), NumericalError);
}

}  // namespace
}  // namespace momenta::dynamics
