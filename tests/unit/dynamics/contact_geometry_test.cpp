// dynamics::contact_geometry against the geometry worked by hand: a ball above a tilted plane,
// two balls on rotated bodies, a ball on a turned body's plane, a tilted disk on the ground and a
// disk against a ball over its face and by its rim — gap, normal, contact point and tangents —
// and the errors where two centres coincide or a ball's centre is in a disk's face.

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
// in a); contact 2 is b's sphere on a plane of a's (normal [0, 0.6, 0.8] through [0, 0, 0.5] in
// a), with friction.
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
    "other_point: [0, 0, 0.5], other_radius: 0.3}\n"
    "  - {name: on_a, type: contact, body: b, point: [0.2, 0, 0], radius: 0.1, other_body: a, "
    "normal: [0, 0.6, 0.8], plane_point: [0, 0, 0.5], friction: 0.3}\n";

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

  // a's plane: a turned 90° about z carries its normal [0, 0.6, 0.8] to [−0.6, 0, 0.8] and its
  // point to [1, 2, 3.5]; t₁ is a's x axis ([0, 1, 0] in W) projected on the plane, already on it.
  const auto& on_a = std::get<model::Contact>(model.constraints()[2]);
  const ContactGeometry p = contact_geometry(on_a, data);
  const Vec3 m(-0.6, 0, 0.8);
  EXPECT_NEAR(p.gap, m.dot(centre - Vec3(1, 2, 3.5)) - 0.1, 1e-15);
  EXPECT_LT((p.normal_W - m).norm(), 1e-15);
  EXPECT_LT((p.point_W - (centre - 0.1 * m)).norm(), 1e-15);
  EXPECT_LT((p.tangent_1_W - Vec3(0, 1, 0)).norm(), 1e-15);
  EXPECT_LT((p.tangent_2_W - m.cross(Vec3(0, 1, 0))).norm(), 1e-15);
  // The ground's tangents: the world's x on the tilted plane, and n × t₁.
  EXPECT_LT((g.tangent_1_W - Vec3::UnitX()).norm(), 1e-15);
  EXPECT_LT((g.tangent_2_W - n.cross(Vec3::UnitX())).norm(), 1e-15);

  // The centres on each other: no line of centres.
  q.segment<3>(7) = Vec3(1.0, 1.8, 3.5);  // b's sphere centre then at a's, [1, 2, 3.5]
  forward_kinematics(model, data, q);
  EXPECT_THROW(contact_geometry(balls, data), NumericalError);
}

// A disk of radius 0.1 m, its axis (the coin's z) turned about y by β = 60° — a = (cos φ, 0,
// sin φ) with φ = 30° above the floor —, its centre at [0, 0, 1]: its rim point nearest the floor
// is c + r (sin φ, 0, −cos φ) (w = n − (n · a) a = cos φ (−sin φ, 0, cos φ)), the gap
// 1 − r cos φ. Turned flat (β = 0), every rim point is as low: the rim point along the coin's x.
TEST(ContactGeometry, ADiskTouchesAtItsRimPointNearestThePlane) {
  const model::Model model =
      io::parse_model_file(
          "bodies: [{name: coin, shape: thin_disk, mass: 1, radius: 0.1}]\n"
          "joints: [{name: f, type: free, parent: world, child: coin}]\n"
          "constraints: [{name: floor, type: contact, shape: disk, body: coin, radius: 0.1}]\n",
          "disk.yaml", ".")
          .model;
  const auto& floor = std::get<model::Contact>(model.constraints()[0]);
  const double phi = std::acos(-1.0) / 6, beta = std::acos(-1.0) / 3;
  VecX q = model.initial_q();
  q.segment<7>(0) << 0, 0, 1, std::cos(beta / 2), 0, std::sin(beta / 2), 0;
  Data data(model);
  forward_kinematics(model, data, q);
  const ContactGeometry g = contact_geometry(floor, data);
  EXPECT_NEAR(g.gap, 1 - 0.1 * std::cos(phi), 1e-15);
  EXPECT_LT((g.point_W - Vec3(0.1 * std::sin(phi), 0, 1 - 0.1 * std::cos(phi))).norm(), 1e-15);
  EXPECT_LT((g.normal_W - Vec3::UnitZ()).norm(), 1e-15);
  EXPECT_FALSE(disk_lies_flat(floor, data, 1e-6));

  q.segment<4>(3) << 1, 0, 0, 0;  // flat
  forward_kinematics(model, data, q);
  const ContactGeometry flat = contact_geometry(floor, data);
  EXPECT_NEAR(flat.gap, 1.0, 1e-15);
  EXPECT_LT((flat.point_W - Vec3(0.1, 0, 1)).norm(), 1e-15);
  EXPECT_TRUE(disk_lies_flat(floor, data, 1e-6));
}

// A coin (R = 0.1 m) at the origin, turned 90° about x — its axis a = (0, −1, 0) —, against a
// ball (r = 0.05 m) whose centre s is moved about. Over the face (s = (0.03, −0.2, 0.04): d · a =
// 0.2 > 0, w = (0.03, 0, 0.04), |w| = 0.05 < R) the nearest point is (0.03, 0, 0.04), n = −a, the
// gap 0.2 − r. Beside the rim (s = (0.3, −0.3, 0.4): w = (0.3, 0, 0.4), |w| = 0.5 > R) it is
// p = R (0.6, 0, 0.8) = (0.06, 0, 0.08), s − p = (0.24, −0.3, 0.32), |s − p| = 0.5, the gap
// 0.5 − r, n = (p − s) / 0.5.
TEST(ContactGeometry, ADiskMeetsABallWithItsFaceOrItsRim) {
  const model::Model model =
      io::parse_model_file(
          "bodies: [{name: coin, shape: thin_disk, mass: 1, radius: 0.1},\n"
          "         {name: ball, shape: sphere, mass: 1, radius: 0.05}]\n"
          "joints: [{name: f, type: free, parent: world, child: coin},\n"
          "         {name: g, type: free, parent: world, child: ball}]\n"
          "constraints: [{name: c, type: contact, shape: disk, body: coin, radius: 0.1,\n"
          "               other_body: ball, other_radius: 0.05, friction: 0.3}]\n",
          "disk_ball.yaml", ".")
          .model;
  const auto& c = std::get<model::Contact>(model.constraints()[0]);
  const double h = std::sqrt(0.5);
  VecX q = model.initial_q();
  q.segment<7>(0) << 0, 0, 0, h, h, 0, 0;  // 90° about x: the coin's z along −y
  Data data(model);
  const auto at = [&](const Vec3& s) {
    q.segment<3>(7) = s;
    forward_kinematics(model, data, q);
    return contact_geometry(c, data);
  };
  const ContactGeometry face = at(Vec3(0.03, -0.2, 0.04));
  EXPECT_NEAR(face.gap, 0.2 - 0.05, 1e-15);
  EXPECT_LT((face.normal_W - Vec3(0, 1, 0)).norm(), 1e-15);
  EXPECT_LT((face.point_W - Vec3(0.03, -0.15, 0.04)).norm(), 1e-15);  // s + r n
  // The tangents turn with n as between two balls: the world's x across it, and n × t₁.
  EXPECT_LT((face.tangent_1_W - Vec3::UnitX()).norm(), 1e-15);
  EXPECT_LT((face.tangent_2_W - Vec3(0, 1, 0).cross(Vec3::UnitX())).norm(), 1e-15);
  EXPECT_FALSE(disk_lies_flat(c, data, 1e-6));  // a face against a ball is modelled

  const ContactGeometry rim = at(Vec3(0.3, -0.3, 0.4));
  const Vec3 n = Vec3(-0.24, 0.3, -0.32) / 0.5;
  EXPECT_NEAR(rim.gap, 0.5 - 0.05, 1e-15);
  EXPECT_LT((rim.normal_W - n).norm(), 1e-15);
  EXPECT_LT((rim.point_W - (Vec3(0.3, -0.3, 0.4) + 0.05 * n)).norm(), 1e-15);

  // The face's and the rim's formulas meet at the face's edge: just inside and just outside.
  const ContactGeometry inside = at(Vec3(0.06, -0.2, 0.08 - 1e-12));
  const ContactGeometry outside = at(Vec3(0.06, -0.2, 0.08 + 1e-12));
  EXPECT_NEAR(inside.gap, outside.gap, 1e-15);
  EXPECT_LT((inside.normal_W - outside.normal_W).norm(), 1e-10);

  // The ball's centre in the face, or on the rim: no side of the disk to push it to.
  EXPECT_THROW(at(Vec3(0.03, 0, 0.04)), NumericalError);
  EXPECT_THROW(at(Vec3(0.06, 0, 0.08)), NumericalError);
}

}  // namespace
}  // namespace momenta::dynamics
