// dynamics::simultaneous_impact: contacts struck at one instant, by Poisson's hypothesis over the
// group. Against closed forms: a box landing flat on four corner contacts (each a quarter of
// m (1 + e) V, the box leaving level at e V); one frictionless contact is Newton's impact
// (restitution_impact); a group whose compression would pull one contact names it; landing while
// sliding, it sticks, slides, or slides and then sticks, as its cones say.

#include "momenta/dynamics/simultaneous_impact.hpp"

#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/dynamics/constraints.hpp"
#include "momenta/io/model_file.hpp"

namespace momenta::dynamics::simultaneous_impact_test {
namespace {

constexpr double kMass = 2.0, kHalfLength = 0.2, kHalfWidth = 0.1, kHalfHeight = 0.05;

// A free box (0.4 × 0.2 × 0.1 m) with contacts at `points` (in the box) on the ground plane.
Model box_with_contacts(const std::vector<Vec3>& points) {
  std::string text = fmt::format(
      "bodies: [{{name: block, shape: box, mass: {}, size: [{}, {}, {}]}}]\n"
      "joints: [{{name: free, type: free, parent: world, child: block}}]\n"
      "constraints:\n",
      kMass, 2 * kHalfLength, 2 * kHalfWidth, 2 * kHalfHeight);
  for (std::size_t k = 0; k < points.size(); ++k) {
    text += fmt::format(
        "  - {{name: c{}, type: contact, body: block, point: [{}, {}, {}], friction: {{static: "
        "1, kinetic: 1}}}}\n",
        k, points[k].x(), points[k].y(), points[k].z());
  }
  return io::parse_model_file(text, "box.yaml", ".").model;
}

std::vector<Vec3> corners() {
  std::vector<Vec3> points;
  for (int k = 0; k < 4; ++k) {
    points.emplace_back((k & 1) ? kHalfLength : -kHalfLength, (k & 2) ? kHalfWidth : -kHalfWidth,
                        -kHalfHeight);
  }
  return points;
}

// The group: every contact of the model, on the ground (body 0) at its point, normal +z.
std::vector<GroupContact> ground_group(const Model& model, const std::vector<Vec3>& points,
                                       double e, double mu) {
  const ConstraintRows rows(model);
  std::vector<GroupContact> group;
  for (std::size_t k = 0; k < points.size(); ++k) {
    PointContact touch{0, Vec3(points[k].x(), points[k].y(), 0.0), 1, points[k], Vec3::UnitZ()};
    group.push_back({touch, rows.first_row[k], e, mu});
  }
  return group;
}

// Every row off: the contacts open, as a run has them before it strikes.
std::vector<char> no_rows(const Model& model) {
  return std::vector<char>(static_cast<std::size_t>(ConstraintRows(model).count), 0);
}

// At rest on the ground (centre kHalfHeight up), v = (ω; v) rotation first.
VecX resting_q(const Model& model) {
  VecX q = VecX::Zero(model.nq());
  q[2] = kHalfHeight;  // position x, y, z, then the quaternion w, x, y, z
  q[3] = 1.0;
  return q;
}

TEST(SimultaneousImpact, ABoxLandingFlatOnItsFourCornersLeavesLevelAtEV) {
  const std::vector<Vec3> points = corners();
  const Model model = box_with_contacts(points);
  const double V = 2.0;
  const VecX q = resting_q(model), v = (VecX(6) << 0, 0, 0, 0, 0, -V).finished();
  for (const double e : {0.0, 0.5, 1.0}) {
    SCOPED_TRACE(e);
    const auto impact =
        simultaneous_impact(model, q, v, ground_group(model, points, e, 1.0), no_rows(model));
    ASSERT_TRUE(impact.has_value());
    EXPECT_EQ(impact->pulling, -1);
    ASSERT_EQ(impact->normal_impulses.size(), 4u);
    // Products and sums of O(1) numbers through two solves: round-off ~1e-15.
    for (const double P : impact->normal_impulses) {
      EXPECT_NEAR(P, kMass * (1.0 + e) * V / 4.0, 1e-14);
    }
    const VecX expected = (VecX(6) << 0, 0, 0, 0, 0, e * V).finished();
    EXPECT_LT((impact->motion.v_after - expected).norm(), 1e-14);
    EXPECT_NEAR(impact->motion.kinetic_before - impact->motion.kinetic_after,
                0.5 * kMass * V * V * (1.0 - e * e), 1e-14);
  }
}

// One frictionless contact, the box struck by a corner while it spins: Poisson's and Newton's
// laws agree (for one contact and no friction they are one law).
TEST(SimultaneousImpact, OneFrictionlessContactIsNewtonsImpact) {
  const std::vector<Vec3> points{corners()[0]};
  const Model model = box_with_contacts(points);
  const VecX q = resting_q(model), v = (VecX(6) << 0.3, -1.1, 0.7, 0.4, -0.2, -1.5).finished();
  const double e = 0.6;
  const auto impact =
      simultaneous_impact(model, q, v, ground_group(model, points, e, 0.0), no_rows(model));
  ASSERT_TRUE(impact.has_value());
  const std::vector<GroupContact> group = ground_group(model, points, e, 0.0);
  const Impact newton = restitution_impact(model, q, v, group[0].touch, e, no_rows(model));
  EXPECT_LT((impact->motion.v_after - newton.motion.v_after).norm(),
            1e-13 * newton.motion.v_after.norm());
  EXPECT_NEAR(impact->normal_impulses[0], newton.normal_impulse, 1e-13 * newton.normal_impulse);
}

// A corner (x = −a) and the bottom's centre, the box falling at V and pitching at ω_y: the
// corner approaches at v_z + a ω_y = −0.6 m/s (v_z = −1, ω_y = 2). Holding both still, the corner's
// impulse must take out the pitch: a P_A = −I ω_y < 0 — it would pull, and is named.
TEST(SimultaneousImpact, AContactItsCompressionWouldPullIsNamed) {
  const std::vector<Vec3> points{corners()[0], Vec3(0.0, 0.0, -kHalfHeight)};
  const Model model = box_with_contacts(points);
  const VecX q = resting_q(model), v = (VecX(6) << 0, 2.0, 0, 0, 0, -1.0).finished();
  const auto impact =
      simultaneous_impact(model, q, v, ground_group(model, points, 0.5, 1.0), no_rows(model));
  ASSERT_TRUE(impact.has_value());
  EXPECT_EQ(impact->pulling, 0);
}

// Landing flat at V while sliding at u along x (e = 0.5, μs = 0.25, μk = 0.2): where the cone
// holds what sticking needs in compression (u ≤ μs V), it sticks — the corners' compression
// impulses balance the friction's moment m u c, and restitution's e times them, unbalanced by
// friction, pitch the box, the corners held along x: (I_y + m c²) ω_y = −e m u c, v_x = c ω_y.
// Beyond it, each corner slides, its friction μk P_n against the slip in both phases: all four
// normal rows hold the box level through compression, so the friction's moment about the centre
// (c below it) is taken by the leading corners' larger share, P_c = m V (1 ± μk c / a) / 4, and
// restitution's e P_c in the same proportion leaves it level, at u − μk (1 + e) V. Where that
// would turn the slip back (u < μk (1 + e) V) the corners slide through compression only and stick
// through restitution: after compression at u_c = u − μk V, restitution's normal impulses
// e P_c (the same shares) pitch the box by their moment −e μk c m V, and the corners holding
// still along x make v_x = c ω_y: (I_y + m c²) ω_y = m c (u_c − e μk V).
TEST(SimultaneousImpact, ABoxLandingFlatWhileSlidingSticksSlidesOrSlidesThenSticks) {
  const std::vector<Vec3> points = corners();
  const Model model = box_with_contacts(points);
  const VecX q = resting_q(model);
  const double V = 1.0, e = 0.5, mu_s = 0.25, mu_k = 0.2, m = kMass, a = kHalfLength,
               c = kHalfHeight;
  const double I_y = m * (4 * a * a + 4 * c * c) / 12.0;
  std::vector<GroupContact> group = ground_group(model, points, e, mu_s);
  for (GroupContact& contact : group) contact.kinetic_friction = mu_k;
  struct Case {
    double u;
    GroupFriction state;
  };
  for (const Case& x : {Case{0.2, GroupFriction::sticking}, Case{0.4, GroupFriction::sliding},
                        Case{0.28, GroupFriction::sliding_then_sticking}}) {
    SCOPED_TRACE(x.u);
    const VecX v = (VecX(6) << 0, 0, 0, x.u, 0, -V).finished();
    const auto impact = simultaneous_impact(model, q, v, group, no_rows(model));
    ASSERT_TRUE(impact.has_value());
    ASSERT_EQ(impact->friction.size(), 4u);
    for (const GroupContactFriction& f : impact->friction) {
      EXPECT_EQ(f.state, x.state) << group_friction_name(f.state);
      EXPECT_NEAR(f.slip_before, x.u, 1e-15);
    }
    VecX expected(6);
    if (x.state == GroupFriction::sticking) {
      const double w_y = -e * m * x.u * c / (I_y + m * c * c);
      expected << 0, w_y, 0, c * w_y, 0, e * V;
      EXPECT_LT((impact->motion.v_after - expected).norm(), 1e-14);
      continue;
    }
    for (int k = 0; k < 4; ++k) {
      const double leading = (k % 2 == 1) ? 1.0 : -1.0;
      EXPECT_NEAR(impact->normal_impulses[static_cast<std::size_t>(k)],
                  (1.0 + e) * m * V * (1.0 + leading * mu_k * c / a) / 4.0, 1e-14)
          << "corner " << k;
      // Sliding from a slip of u along x: sticking needed more than the cone held.
      const GroupContactFriction& f = impact->friction[static_cast<std::size_t>(k)];
      EXPECT_GT(f.needed, f.limit);
    }
    if (x.state == GroupFriction::sliding) {
      expected << 0, 0, 0, x.u - mu_k * (1.0 + e) * V, 0, e * V;
    } else {
      const double u_c = x.u - mu_k * V;
      const double w_y = m * c * (u_c - e * mu_k * V) / (I_y + m * c * c);
      expected << 0, w_y, 0, c * w_y, 0, e * V;
    }
    EXPECT_LT((impact->motion.v_after - expected).norm(), 1e-14);
    EXPECT_LT(impact->motion.kinetic_after, impact->motion.kinetic_before);
  }
}

// Landing flat at V = 1 while sliding at u = 0.5 (e = 0, μs = 0.2, μk = 0): the cone of μs P
// cannot hold it, and sliding without kinetic friction the box keeps its slip.
TEST(SimultaneousImpact, ACornerSlidingWithoutKineticFrictionKeepsItsSlip) {
  const std::vector<Vec3> points = corners();
  const Model model = box_with_contacts(points);
  const VecX q = resting_q(model);
  const VecX v = (VecX(6) << 0, 0, 0, 0.5, 0, -1.0).finished();
  const auto impact =
      simultaneous_impact(model, q, v, ground_group(model, points, 0.0, 0.2), no_rows(model));
  ASSERT_TRUE(impact.has_value());
  const VecX expected = (VecX(6) << 0, 0, 0, 0.5, 0, 0).finished();
  EXPECT_LT((impact->motion.v_after - expected).norm(), 1e-14);
}

// normal_mobility: a corner of the box resting on the other three held along their normals is
// held still along its own (the four are coplanar: its row is the others' combination), so it
// has no impact of its own. On corners 1 and 2 (y = −b) the box tips about their edge: a unit
// pair at corner 3 (y = +b) has the lever 2 b about it, the box's inertia about the edge for
// that turn is I_x + m b² (its centre free along y, no friction), and the corner rises at
// w = (2 b)² / (I_x + m b²).
TEST(SimultaneousImpact, ACornerHeldStillByTheOthersHasNoMobility) {
  const std::vector<Vec3> points = corners();
  const Model model = box_with_contacts(points);
  const VecX q = resting_q(model);
  const std::vector<GroupContact> group = ground_group(model, points, 0.0, 1.0);
  std::vector<char> rows = no_rows(model);
  for (int k = 0; k < 2; ++k) rows[static_cast<std::size_t>(group[k].first_row)] = 1;
  const double tipping = normal_mobility(model, q, group[2].touch, rows);
  const double b = kHalfWidth, c = kHalfHeight;
  const double I_x = kMass * (4 * b * b + 4 * c * c) / 12.0;
  EXPECT_NEAR(tipping, 4 * b * b / (I_x + kMass * b * b), 1e-13);
  EXPECT_FALSE(held_still(tipping));
  rows[static_cast<std::size_t>(group[2].first_row)] = 1;
  const double fourth = normal_mobility(model, q, group[3].touch, rows);
  EXPECT_TRUE(held_still(fourth)) << fourth;
  EXPECT_LT(std::abs(fourth), 1e-13);
}

}  // namespace
}  // namespace momenta::dynamics::simultaneous_impact_test
