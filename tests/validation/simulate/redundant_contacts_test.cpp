// Redundant contacts: a box (0.4 × 0.2 × 0.1 m) on contacts at its four bottom corners, whose
// normal rows depend on one another (three fix its height, roll and pitch; the fourth adds
// nothing). Statics alone cannot split the load among them; momenta takes the least-norm split
// (docs/contacts.md, "Redundant contacts"), which a symmetric box shares symmetrically. The
// proofs: the split that balance and symmetry give in closed form, Coulomb's μ g deceleration,
// and a drop onto its face whose four corners strike at one instant and bounce it level, by
// Newton's restitution, to the heights e^{2k} h, resting at t₁ (1 + e) / (1 − e); dropped tilted,
// it lands on an edge and pivots about it, its moment of momentum about the edge conserved; dropped
// flat while it slides, its four corners slide through the impact together and it lands level.

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "unilateral_runs.hpp"

namespace momenta::simulate {
namespace redundant_contacts {
namespace {

using namespace unilateral_test;

constexpr double kHalfLength = 0.2, kHalfWidth = 0.1, kHalfHeight = 0.05;

// The box (m kg) with its bottom `lift` m above the floor, moving at v₀ along x, on contacts at
// its four bottom corners (μs = μk = μ, restitution e) at (±0.2, ±0.1, −0.05) in the box:
// corners 2 and 4 lead (x = +0.2), 1 and 3 trail.
std::string box_on_its_corners(double m, double mu, double v0, double lift = 0.0, double e = 0.0) {
  std::string text = fmt::format(
      "gravity: [0, 0, -9.81]\n"
      "bodies: [{{name: block, shape: box, mass: {m}, size: [{l}, {w}, {h}]}}]\n"
      "joints:\n"
      "  - {{name: free, type: free, parent: world, child: block,\n"
      "     q0: {{position: [0, 0, {z}]}}, v0: [0, 0, 0, {v0}, 0, 0]}}\n"
      "constraints:\n",
      fmt::arg("m", m), fmt::arg("l", 2 * kHalfLength), fmt::arg("w", 2 * kHalfWidth),
      fmt::arg("h", 2 * kHalfHeight), fmt::arg("z", kHalfHeight + lift), fmt::arg("v0", v0));
  for (int k = 0; k < 4; ++k) {
    text += fmt::format(
        "  - {{name: block_corner{}_floor, type: contact, body: block, point: [{}, {}, {}],\n"
        "     restitution: {e}, friction: {{static: {mu}, kinetic: {mu}}}}}\n",
        k + 1, (k & 1) ? kHalfLength : -kHalfLength, (k & 2) ? kHalfWidth : -kHalfWidth,
        -kHalfHeight, fmt::arg("mu", mu), fmt::arg("e", e));
  }
  return text;
}

double column(const UnilateralRun& run, const std::vector<double>& row, const std::string& name) {
  return row[static_cast<std::size_t>(run.table.column(name))];
}

std::string normal(int corner) { return fmt::format("block_corner{}_floor.normal", corner); }

// At rest the box stays put, each corner carrying a quarter of its weight, sticking — whatever
// μ (before, the order the corners closed in decided: at μ = 0.4 the first corner, closed alone,
// slid as if the box would tip, and at μ ≥ 1 a corner of no share toggled until the run
// stopped).
TEST(RedundantContacts, ABoxRestsOnItsCornersEachCarryingAQuarterOfItsWeight) {
  const double m = 2.0;
  for (const double mu : {0.4, 1.0, 2.0}) {
    for (const std::string integrator : {"rk4", "dopri5"}) {
      SCOPED_TRACE(fmt::format("mu {} {}", mu, integrator));
      const model::Model box = load(box_on_its_corners(m, mu, 0.0));
      const UnilateralRun run = run_unilaterals(box, integrator, 1e-2, 1.0, true);
      EXPECT_EQ(run.summary.t_end, 1.0);
      ASSERT_EQ(run.summary.stop_events.size(), 4u);
      for (const StopEvent& event : run.summary.stop_events) {
        EXPECT_EQ(event.kind, StopEventKind::rest);
        EXPECT_EQ(event.friction, FrictionState::sticking);
        EXPECT_EQ(event.time, 0.0);
      }
      for (const auto& row : run.table.rows) {
        EXPECT_NEAR(column(run, row, "free.x"), 0.0, 1e-15) << row[0];
        EXPECT_NEAR(column(run, row, "free.z"), kHalfHeight, 1e-15) << row[0];
        for (int k = 1; k <= 4; ++k) {
          EXPECT_NEAR(column(run, row, normal(k)), m * kG / 4.0, 1e-13 * m * kG) << row[0];
        }
      }
    }
  }
}

// Launched at v₀ it slides on all four corners, the friction μ N of each against the slip: the
// box slows at μ g and stops at t = v₀ / (μ g), x = v₀² / (2 μ g), level and at its height. The
// friction μ m g, a height c below the centre, pitches it forward: the moment balance about the
// centre, μ c m g = 2 a (N_lead − N_trail), and the weight, 2 (N_lead + N_trail) = m g, with the
// least-norm split's symmetry (each side's two corners equal), give N = m g / 4 ± μ c m g / (4 a).
// Stopped, the four stick, a quarter each.
TEST(RedundantContacts, ABoxSlidesToAStopOnItsCornersLoadingTheLeadingOnesMore) {
  const double m = 2.0, mu = 0.4, v0 = 2.0, c = kHalfHeight, a = kHalfLength;
  const model::Model box = load(box_on_its_corners(m, mu, v0));
  const double t_stop = v0 / (mu * kG), x_stop = v0 * v0 / (2.0 * mu * kG);
  const UnilateralRun run = run_unilaterals(box, "dopri5", 1e-2, 1.5 * t_stop, true);
  const double quarter = m * kG / 4.0, shift = mu * c * m * kG / (4.0 * a);
  double worst_height = 0.0, worst_tilt = 0.0;
  for (const auto& row : run.table.rows) {
    worst_height = std::max(worst_height, std::abs(column(run, row, "free.z") - c));
    worst_tilt = std::max(worst_tilt, std::abs(column(run, row, "free.qw") - 1.0));
    const bool sliding = row[0] < t_stop * (1.0 - 1e-12);
    for (int k = 1; k <= 4; ++k) {
      const double leading = (k % 2 == 0) ? 1.0 : -1.0;
      const double expected = sliding ? quarter + leading * shift : quarter;
      if (std::abs(row[0] - t_stop) < 1e-9) continue;  // the instant itself: either
      EXPECT_NEAR(column(run, row, normal(k)), expected, 1e-12 * m * kG)
          << "corner " << k << " at t = " << row[0];
    }
  }
  EXPECT_LT(worst_height, 1e-14);
  EXPECT_LT(worst_tilt, 1e-14);
  const auto first_stick =
      std::find_if(run.summary.stop_events.begin(), run.summary.stop_events.end(),
                   [](const StopEvent& e) { return e.kind == StopEventKind::stick; });
  ASSERT_NE(first_stick, run.summary.stop_events.end());
  EXPECT_NEAR(first_stick->time, t_stop, 1e-12 * t_stop);
  const auto& last = run.table.rows.back();
  EXPECT_NEAR(column(run, last, "free.x"), x_stop, 1e-12 * x_stop);
  EXPECT_NEAR(column(run, last, "free.vx"), 0.0, 1e-12 * v0);
}

// Dropped flat from h onto its four corners (e = 0.5, μ = 1): they strike at one instant, as one
// impact (Poisson's law over the group, docs/contacts.md): each corner's impulse is a quarter of
// m (1 + e) v, the box leaves level at e v — no corner struck before another, so nothing tips it
// — and bounces to e^{2k} h, the k-th impact at t₁ (1 + 2 e (1 − e^{k−1}) / (1 − e)) with
// t₁ = √(2 h / g), until it rests at t₁ (1 + e) / (1 − e) having lost all of m g h. Before, the
// corners struck one after another: the first alone, with friction, jammed (Painlevé) and
// stopped the run.
TEST(RedundantContacts, ABoxDroppedFlatStrikesOnItsFourCornersAtOnceAndBouncesLevel) {
  const double m = 2.0, mu = 1.0, h = 0.2, e = 0.5;
  const model::Model box = load(box_on_its_corners(m, mu, 0.0, h, e));
  const UnilateralRun run = run_unilaterals(box, "dopri5", 1e-2, 1.0, true);
  const double t1 = std::sqrt(2.0 * h / kG), v1 = kG * t1;
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_GE(events.size(), 12u);
  for (int bounce = 0; bounce < 3; ++bounce) {
    SCOPED_TRACE(bounce);
    const double v = v1 * std::pow(e, bounce);
    const double t = t1 * (1.0 + 2.0 * e * (1.0 - std::pow(e, bounce)) / (1.0 - e));
    for (int k = 0; k < 4; ++k) {
      const StopEvent& s = events[static_cast<std::size_t>(4 * bounce + k)];
      EXPECT_EQ(s.kind, StopEventKind::impact);
      EXPECT_EQ(s.contact, fmt::format("block_corner{}_floor", k + 1));
      EXPECT_NEAR(s.time, t, 1e-12 * t);
      EXPECT_EQ(s.time, events[static_cast<std::size_t>(4 * bounce)].time);  // one instant
      EXPECT_NEAR(s.rate_before, -v, 1e-10 * v);
      EXPECT_NEAR(s.rate_after, e * v, 1e-10 * v);
      EXPECT_NEAR(s.impulse, m * (1.0 + e) * v / 4.0, 1e-10 * m * v);
      // The group's energy said once, with its first corner.
      const double lost = k == 0 ? 0.5 * m * v * v * (1.0 - e * e) : 0.0;
      EXPECT_NEAR(s.energy_lost, lost, 1e-10 * m * v1 * v1);
    }
  }
  // Level throughout; the apex after the k-th bounce at e^{2k} h.
  double worst_tilt = 0.0, apex = 0.0;
  for (const auto& row : run.table.rows) {
    worst_tilt = std::max(worst_tilt, std::abs(column(run, row, "free.qw") - 1.0));
    if (row[0] > t1 && row[0] < t1 * (1.0 + 2.0 * e)) {
      apex = std::max(apex, column(run, row, "free.z") - kHalfHeight);
    }
  }
  EXPECT_LT(worst_tilt, 1e-14);
  EXPECT_NEAR(apex, e * e * h, 1e-3 * h);  // the rows' sampling of the apex (dopri5's steps)
  // At rest, all four held, at the Zeno limit.
  const double t_rest = t1 * (1.0 + e) / (1.0 - e);
  double lost = 0.0;
  int resting = 0;
  for (const StopEvent& s : events) {
    lost += s.energy_lost;
    if (s.kind == StopEventKind::rest) {
      ++resting;
      EXPECT_NEAR(s.rest_time, t_rest, 1e-9 * t_rest);
    }
  }
  EXPECT_EQ(resting, 4);
  EXPECT_NEAR(lost, m * kG * h, 1e-9 * m * kG * h);
  const auto& last = run.table.rows.back();
  EXPECT_NEAR(column(run, last, "free.z"), kHalfHeight, 1e-14);
  for (int k = 1; k <= 4; ++k)
    EXPECT_NEAR(column(run, last, normal(k)), m * kG / 4.0, 1e-12 * m * kG);
}

// The corners' share of a group impact's normal impulse P on a box sliding along x with friction
// μ P against it (c below the centre): the leading ones (x = +a: corners 2 and 4) take more, so
// that nothing pitches it, P (1 ± μ c / a) / 4.
double corner_share(int corner, double P, double mu) {
  const double leading = (corner % 2 == 0) ? 1.0 : -1.0;
  return P * (1.0 + leading * mu * kHalfHeight / kHalfLength) / 4.0;
}

// Dropped flat from h while it slides at v₀ along x (e = 0, μs = μk = μ): sticking at once would
// need a friction impulse m v₀ against μ m V of normal impulse — beyond the cone — so the four
// corners slide through the impact together (Poisson's law over the group with sliding friction,
// docs/contacts.md): the box lands level, each corner's normal impulse its share of m V, and
// leaves the impact sliding at u = v₀ − μ V; it then slows at μ g and sticks at t₁ + u / (μ g),
// having come to x = v₀ t₁ + u² / (2 μ g). Before, the corners struck one after another and the
// box rattled through 342 impacts.
TEST(RedundantContacts, ABoxDroppedFlatWhileSlidingLandsLevelAndSlidesOn) {
  const double m = 2.0, mu = 0.4, v0 = 2.0, h = 0.2;
  const model::Model box = load(box_on_its_corners(m, mu, v0, h, 0.0));
  const UnilateralRun run = run_unilaterals(box, "dopri5", 1e-2, 0.6, true);
  const double t1 = std::sqrt(2.0 * h / kG), V = kG * t1, u = v0 - mu * V;
  const double t_stop = t1 + u / (mu * kG), x_stop = v0 * t1 + u * u / (2.0 * mu * kG);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_GE(events.size(), 8u);
  for (int k = 0; k < 4; ++k) {
    SCOPED_TRACE(k);
    const StopEvent& landing = events[static_cast<std::size_t>(k)];
    EXPECT_EQ(landing.contact, fmt::format("block_corner{}_floor", k + 1));
    EXPECT_EQ(landing.kind, StopEventKind::rest);
    EXPECT_EQ(landing.friction, FrictionState::sliding);
    EXPECT_NEAR(landing.time, t1, 1e-12 * t1);
    EXPECT_NEAR(landing.impulse, corner_share(k + 1, m * V, mu), 1e-10 * m * V);
    const double lost = k == 0 ? 0.5 * m * (V * V + v0 * v0 - u * u) : 0.0;
    EXPECT_NEAR(landing.energy_lost, lost, 1e-10 * m * v0 * v0);
    const StopEvent& slip = events[static_cast<std::size_t>(4 + k)];
    EXPECT_EQ(slip.contact, landing.contact);
    EXPECT_EQ(slip.kind, StopEventKind::slip);
    EXPECT_TRUE(slip.in_impact);
    EXPECT_EQ(slip.time, landing.time);
    EXPECT_GT(slip.friction_needed, slip.friction_limit);
  }
  const auto first_stick = std::find_if(events.begin(), events.end(), [](const StopEvent& e) {
    return e.kind == StopEventKind::stick;
  });
  ASSERT_NE(first_stick, events.end());
  EXPECT_NEAR(first_stick->time, t_stop, 1e-12 * t_stop);
  double worst_tilt = 0.0;
  for (const auto& row : run.table.rows) {
    worst_tilt = std::max(worst_tilt, std::abs(column(run, row, "free.qw") - 1.0));
    if (row[0] > t1 * (1.0 + 1e-9) && row[0] < t_stop) {
      EXPECT_NEAR(column(run, row, "free.vx"), u - mu * kG * (row[0] - t1), 1e-12 * v0) << row[0];
    }
  }
  EXPECT_LT(worst_tilt, 1e-14);
  const auto& last = run.table.rows.back();
  EXPECT_NEAR(column(run, last, "free.x"), x_stop, 1e-12 * x_stop);
  EXPECT_NEAR(column(run, last, "free.z"), kHalfHeight, 1e-14);
}

// The same with e = 0.5: each landing's corners slide through compression and restitution, the
// friction μ (1 + e) m V_k taking μ (1 + e) V_k from the slide, V_k = eᵏ⁻¹ V; the box bounces
// level, sliding at u₁ = v₀ − μ (1 + e) V, then u₂ = u₁ − μ (1 + e) e V (to 0.45 s, before its
// third landing, where the slip its friction would turn back sticks through restitution and
// restitution's unequal shares pitch it: SimultaneousImpact.* has that closed form).
TEST(RedundantContacts, ABoxBouncingWhileSlidingLosesMuOnePlusETimesItsFallAtEachLanding) {
  const double m = 2.0, mu = 0.4, v0 = 2.0, h = 0.2, e = 0.5;
  const model::Model box = load(box_on_its_corners(m, mu, v0, h, e));
  const UnilateralRun run = run_unilaterals(box, "dopri5", 1e-2, 0.45, true);
  const double t1 = std::sqrt(2.0 * h / kG), V = kG * t1, t2 = t1 * (1.0 + 2.0 * e);
  const double u1 = v0 - mu * (1.0 + e) * V, u2 = u1 - mu * (1.0 + e) * e * V;
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_EQ(events.size(), 16u);
  for (int landing = 0; landing < 2; ++landing) {
    SCOPED_TRACE(landing);
    const double V_k = V * std::pow(e, landing), t = landing == 0 ? t1 : t2;
    const double u_before = landing == 0 ? v0 : u1, u_after = landing == 0 ? u1 : u2;
    for (int k = 0; k < 4; ++k) {
      // The corner the run reached first, then the others in the file's order.
      const StopEvent& impact = events[static_cast<std::size_t>(8 * landing + k)];
      const int corner = impact.contact.at(std::string_view("block_corner").size()) - '0';
      EXPECT_EQ(impact.kind, StopEventKind::impact);
      EXPECT_NEAR(impact.time, t, 1e-12 * t);
      EXPECT_NEAR(impact.rate_before, -V_k, 1e-10 * V);
      EXPECT_NEAR(impact.rate_after, e * V_k, 1e-10 * V);
      EXPECT_NEAR(impact.impulse, corner_share(corner, (1.0 + e) * m * V_k, mu), 1e-10 * m * V);
      const double lost =
          k == 0 ? 0.5 * m * ((1.0 - e * e) * V_k * V_k + u_before * u_before - u_after * u_after)
                 : 0.0;
      EXPECT_NEAR(impact.energy_lost, lost, 1e-10 * m * v0 * v0);
      const StopEvent& slip = events[static_cast<std::size_t>(8 * landing + 4 + k)];
      EXPECT_EQ(slip.kind, StopEventKind::slip);
      EXPECT_TRUE(slip.in_impact);
    }
  }
  double worst_tilt = 0.0;
  for (const auto& row : run.table.rows) {
    worst_tilt = std::max(worst_tilt, std::abs(column(run, row, "free.qw") - 1.0));
    const double vx = column(run, row, "free.vx");
    // Between the landings (a landing's instant has a row before it and one after).
    if (row[0] > t1 * (1.0 + 1e-9) && std::abs(row[0] - t2) > 1e-9 * t2) {
      EXPECT_NEAR(vx, row[0] < t2 ? u1 : u2, 1e-12 * v0) << row[0];
    }
  }
  EXPECT_LT(worst_tilt, 1e-14);
  const double x_end = v0 * t1 + u1 * (t2 - t1) + u2 * (0.45 - t2);
  EXPECT_NEAR(column(run, run.table.rows.back(), "free.x"), x_end, 1e-12 * x_end);
}

// Run on to 1 s, the same box pitches at its third landing, rocks through its corners' impacts and
// comes to rest on all four, turned a little about the vertical by the rocking. Resting, two
// corners sticking and two held along the normal: their rows, nearly parallel at that small turn,
// were once counted one more than the box has freedoms, and the run stopped at 0.587 s as at a
// singular configuration (naming a probe's time, 1.6e14 s).
TEST(RedundantContacts, ABoxBouncingWhileSlidingComesToRestOnItsFourCorners) {
  const double m = 2.0;
  const model::Model box = load(box_on_its_corners(m, 0.4, 2.0, 0.2, 0.5));
  // The command line's tolerances (integrate::Tolerances' defaults), where it stopped.
  const UnilateralRun run = run_unilaterals(box, "dopri5", 1e-2, 1.0, true, {});
  EXPECT_EQ(run.summary.t_end, 1.0);
  const auto& last = run.table.rows.back();
  EXPECT_NEAR(column(run, last, "free.z"), kHalfHeight, 1e-12);
  double weight = 0.0;
  for (int k = 1; k <= 4; ++k) weight += column(run, last, normal(k));
  EXPECT_NEAR(weight, m * kG, 1e-12 * m * kG);
  for (const std::string speed : {"free.vx", "free.vy", "free.vz", "free.wx", "free.wy"}) {
    EXPECT_NEAR(column(run, last, speed), 0.0, 1e-12) << speed;
  }
}

// Dropped tilted by θ about its length (x), it lands on the edge of corners 1 and 2 (y = −b,
// z = −c in the box) — both at one instant, one impact (e = 0, μ = 1: sticking, Beer & Johnston
// ch. 17, eccentric impact). The impulses act on the edge, so the box's angular momentum about it
// is conserved: m v p_y = I_E ω⁺ with p_y the edge's horizontal offset from the centre and
// I_E = m (b² + c²) / 3 + m (b² + c²) the moment about the edge; the edge stays still after.
TEST(RedundantContacts, ABoxLandingOnAnEdgePivotsAboutIt) {
  const double m = 2.0, theta = 0.5, drop = 0.1, b = kHalfWidth, c = kHalfHeight;
  // The edge's offset from the centre, turned by θ about x; the centre placed `drop` above where
  // the edge touches.
  const double p_y = -b * std::cos(theta) + c * std::sin(theta);
  const double p_z = -b * std::sin(theta) - c * std::cos(theta);
  std::string text = box_on_its_corners(m, 1.0, 0.0, 0.0, 0.0);
  text.replace(
      text.find("q0: {position: [0, 0, 0.05]}"), 28,
      fmt::format("q0: {{position: [0, 0, {:.17g}], euler: {{sequence: XYZ, angles: [{:.17g}, "
                  "0, 0]}}}}",
                  drop - p_z, theta));
  const model::Model box = load(text);
  // To just after the landing (t₁ = 0.143 s): pivoting on the edge it slides at 0.19 s, and there
  // the two sliding corners are near Painlevé's paradox (a linearization |λ| ~ 1e15 1/s) where
  // dopri5 crawls — docs/contacts.md, "Not yet".
  const UnilateralRun run = run_unilaterals(box, "dopri5", 1e-2, 0.15, true);
  const double t1 = std::sqrt(2.0 * drop / kG), v = kG * t1;
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_GE(events.size(), 2u);
  EXPECT_EQ(events[0].contact, "block_corner1_floor");
  EXPECT_EQ(events[1].contact, "block_corner2_floor");
  EXPECT_NEAR(events[0].time, t1, 1e-12 * t1);
  EXPECT_EQ(events[1].time, events[0].time);
  const double I_E = 4.0 * m * (b * b + c * c) / 3.0;
  const double omega = m * v * p_y / I_E;
  EXPECT_NEAR(events[0].energy_lost, 0.5 * m * v * v - 0.5 * I_E * omega * omega,
              1e-10 * m * v * v);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(events[std::size_t(k)].rate_before, -v, 1e-10 * v);
    EXPECT_NEAR(events[std::size_t(k)].rate_after, 0.0, 1e-12 * v);
  }
  // The row just after the impact.
  const auto after =
      std::find_if(run.table.rows.begin(), run.table.rows.end(), [&](const std::vector<double>& r) {
        return r[0] == events[0].time && std::abs(column(run, r, "free.wx")) > 0.0;
      });
  ASSERT_NE(after, run.table.rows.end());
  EXPECT_NEAR(column(run, *after, "free.wx"), omega, 1e-10 * std::abs(omega));
  // The centre turns about the edge: v_G = ω × (−p), the edge point still.
  EXPECT_NEAR(column(run, *after, "free.vy"), omega * p_z, 1e-10 * v);
  EXPECT_NEAR(column(run, *after, "free.vz"), -omega * p_y, 1e-10 * v);
}

}  // namespace
}  // namespace redundant_contacts
}  // namespace momenta::simulate
