// MJCF's geoms on the world's plane (io/mjcf/mjcf_contacts.cpp) run as the textbook's rigid
// contacts: a MuJoCo ball launched skidding starts rolling at the closed form's instant and speed
// (Beer & Johnston ch. 16). And the redundant contacts MJCF's boxes would bring: a box sliding on
// its four bottom corners stops where Coulomb's μ g deceleration says, standing level throughout.

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/io/mjcf_file.hpp"
#include "unilateral_runs.hpp"

namespace momenta::simulate {
namespace mjcf_contacts {
namespace {

using namespace unilateral_test;

// A free body on a floor of friction `floor_friction`, starting at rest on it with velocity
// qvel (MuJoCo's order: linear, then angular); `geom` is the body's geom.
model::Model on_the_floor(const std::string& geom, double height, double floor_friction,
                          double vx) {
  return io::parse_mjcf(fmt::format(R"(<mujoco model="on_the_floor">
  <option gravity="0 0 -9.81"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1" friction="{}"/>
    <body name="thing" pos="0 0 {}">
      <freejoint name="free"/>
      {}
    </body>
  </worldbody>
  <keyframe><key name="initial" qpos="0 0 {} 1 0 0 0" qvel="{} 0 0 0 0 0"/></keyframe>
</mujoco>)",
                                    floor_friction, height, geom, height, vx),
                        "on_the_floor.xml")
      .model;
}

// MuJoCo takes the larger of the two geoms' friction (0.3, the ball's): sliding from v₀ with no
// spin, friction μ m g slows the centre and spins the ball up until v = r ω at
// t = 2 v₀ / (7 μ g), v = 5 v₀ / 7, then it rolls with no friction at all.
TEST(MjcfContacts, AMuJoCoBallStartsRollingAtTheClosedFormsInstant) {
  const double r = 0.1, m = 1.0, mu = 0.3, v0 = 3.0;
  const model::Model ball = on_the_floor(
      fmt::format(R"(<geom name="ball" type="sphere" size="{}" mass="{}" friction="{}"/>)", r, m,
                  mu),
      r, 0.2, v0);
  ASSERT_EQ(ball.constraints().size(), 1u);
  const UnilateralRun run = run_unilaterals(ball, "dopri5", 1e-2, 0.6);
  const std::vector<StopEvent>& events = run.summary.stop_events;
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].kind, StopEventKind::rest);
  EXPECT_EQ(events[0].friction, FrictionState::sliding);
  EXPECT_EQ(events[1].kind, StopEventKind::stick);
  EXPECT_EQ(events[1].contact, "ball_floor");
  const double t_roll = 2.0 * v0 / (7.0 * mu * kG);
  // The slip falls linearly and dopri5 is exact on it: the locator's 1e-12 relative in time.
  EXPECT_NEAR(events[1].time, t_roll, 1e-12 * t_roll);
  const auto& last = run.table.rows.back();
  const double vx = last[static_cast<std::size_t>(run.table.column("free.vx"))];
  const double wy = last[static_cast<std::size_t>(run.table.column("free.wy"))];
  EXPECT_NEAR(vx, 5.0 * v0 / 7.0, 1e-12 * v0);
  EXPECT_NEAR(wy * r, vx, 1e-12 * v0);  // rolling: no slip at the floor
  EXPECT_NEAR(last[static_cast<std::size_t>(run.table.column("free.z"))], r, 1e-14);
}

// A box (0.4 × 0.2 × 0.1 m, m kg) on the floor, moving at v₀ along x, on contacts at its four
// bottom corners (μs = μk = μ).
std::string box_on_its_corners(double m, double mu, double v0) {
  const double c = 0.05;
  std::string text = fmt::format(
      "gravity: [0, 0, -9.81]\n"
      "bodies: [{{name: block, shape: box, mass: {m}, size: [0.4, 0.2, {h}]}}]\n"
      "joints:\n"
      "  - {{name: free, type: free, parent: world, child: block,\n"
      "     q0: {{position: [0, 0, {c}]}}, v0: [0, 0, 0, {v0}, 0, 0]}}\n"
      "constraints:\n",
      fmt::arg("m", m), fmt::arg("h", 2.0 * c), fmt::arg("c", c), fmt::arg("v0", v0));
  for (int k = 0; k < 4; ++k) {
    text += fmt::format(
        "  - {{name: block_corner{}_floor, type: contact, body: block, point: [{}, {}, {}],\n"
        "     friction: {{static: {mu}, kinetic: {mu}}}}}\n",
        k + 1, (k & 1) ? 0.2 : -0.2, (k & 2) ? 0.1 : -0.1, -c, fmt::arg("mu", mu));
  }
  return text;
}

// At rest on its four corners the box stays put: a step that its contacts' events have cut to no
// length (an instant acted on twice) is no bracket for the locator (it stopped the run with an
// internal error).
TEST(RedundantContacts, ABoxRestsOnItsCorners) {
  const model::Model box = load(box_on_its_corners(2.0, 0.4, 0.0));
  const UnilateralRun run = run_unilaterals(box, "rk4", 1e-3, 0.1);
  EXPECT_EQ(run.summary.t_end, 0.1);
  const int x = run.table.column("free.x"), z = run.table.column("free.z");
  for (const auto& row : run.table.rows) {
    EXPECT_NEAR(row[std::size_t(x)], 0.0, 1e-15) << row[0];
    EXPECT_NEAR(row[std::size_t(z)], 0.05, 1e-15) << row[0];
  }
}

// The box launched at v₀: the normal forces share m g (one
// corner's row depends on the other three's, and carries none), the friction μ N of each opposes
// the slip, so the box slows at μ g and stops at t = v₀ / (μ g), x = v₀² / (2 μ g), level and at
// its height throughout. One corner is let go at the start (its row's share is zero, round-off
// pulling; the start rows show it before): the step's first instant acts on the state there.
TEST(RedundantContacts, ABoxSlidesToAStopOnItsCorners) {
  const double m = 2.0, mu = 0.4, v0 = 2.0, c = 0.05;
  const std::string text = box_on_its_corners(m, mu, v0);
  const model::Model box = load(text);
  ASSERT_EQ(box.constraints().size(), 4u);
  const double t_stop = v0 / (mu * kG), x_stop = v0 * v0 / (2.0 * mu * kG);
  const UnilateralRun run = run_unilaterals(box, "dopri5", 1e-2, 1.5 * t_stop, true);
  const int x = run.table.column("free.x"), z = run.table.column("free.z"),
            vx = run.table.column("free.vx"), qw = run.table.column("free.qw");
  double worst_height = 0.0, worst_tilt = 0.0, worst_weight = 0.0;
  for (const auto& row : run.table.rows) {
    worst_height = std::max(worst_height, std::abs(row[std::size_t(z)] - c));
    worst_tilt = std::max(worst_tilt, std::abs(row[std::size_t(qw)] - 1.0));
    if (row[0] == 0.0) continue;  // the start's rows: a corner pulls there until it is let go
    double normal = 0.0;
    for (int k = 1; k <= 4; ++k) {
      const double N =
          row[std::size_t(run.table.column(fmt::format("block_corner{}_floor.normal", k)))];
      EXPECT_GE(N, -1e-12 * m * kG) << "corner " << k << " pulls at t = " << row[0];
      normal += N;
    }
    worst_weight = std::max(worst_weight, std::abs(normal - m * kG));
  }
  EXPECT_LT(worst_height, 1e-14);
  EXPECT_LT(worst_tilt, 1e-14);
  EXPECT_LT(worst_weight, 1e-12 * m * kG);
  // Where the slip ends the box sticks (the first corner to: the redundant one's slip, which
  // carries no friction, is round-off from then on and may pass zero a little later).
  const auto first_stick =
      std::find_if(run.summary.stop_events.begin(), run.summary.stop_events.end(),
                   [](const StopEvent& e) { return e.kind == StopEventKind::stick; });
  ASSERT_NE(first_stick, run.summary.stop_events.end());
  EXPECT_NEAR(first_stick->time, t_stop, 1e-12 * t_stop);
  const auto& last = run.table.rows.back();
  EXPECT_NEAR(last[std::size_t(x)], x_stop, 1e-12 * x_stop);
  EXPECT_NEAR(last[std::size_t(vx)], 0.0, 1e-12 * v0);
}

}  // namespace
}  // namespace mjcf_contacts
}  // namespace momenta::simulate
