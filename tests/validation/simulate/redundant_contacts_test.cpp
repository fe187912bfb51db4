// Redundant contacts: a box (0.4 × 0.2 × 0.1 m) on contacts at its four bottom corners, whose
// normal rows depend on one another (three fix its height, roll and pitch; the fourth adds
// nothing). Statics alone cannot split the load among them; momenta takes the least-norm split
// (docs/contacts.md, "Redundant contacts"), which a symmetric box shares symmetrically. The
// proofs: the split that balance and symmetry give in closed form, Coulomb's μ g deceleration,
// and a drop onto its face whose four corners strike at one instant and bounce it level, by
// Newton's restitution, to the heights e^{2k} h, resting at t₁ (1 + e) / (1 − e); dropped tilted,
// it lands on an edge and pivots about it, its moment of momentum about the edge conserved.

#include <algorithm>
#include <cmath>
#include <string>

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
