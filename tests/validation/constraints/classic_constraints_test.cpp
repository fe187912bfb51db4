// The bundled constrained examples (examples/constraints/) simulated through momenta::simulate
// and compared with their closed forms: Beer & Johnston 18.3 and 18.2, the four-bar against
// Freudenstein, the slider-crank, the rolling coin, the Chaplygin sleigh and a geared pair; and
// constraint forces against the same system built as a tree.
//
// Tolerances. Positions and velocities of the 0-dof mechanisms (driven four-bar, slider-crank,
// rod held by its wire) are fixed by the constraints alone: the projection solves them to
// round-off, so they match to 1e-10 whatever the integrator's error. Motions that integrate
// (coin, sleigh, disk, gears) carry RK4's global error, ~1e-12 here (h = 1 ms; the energy audits
// below read it).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <numbers>
#include <string>

#include "momenta/common/error.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/model/model_builder.hpp"
#include "momenta/simulate/simulation.hpp"
#include "momenta/system/multibody_system.hpp"

namespace momenta {
namespace {

constexpr double kG = 9.81;

struct ExampleRun {
  simulate::TableSink table;
  simulate::SimulationSummary summary;
  double at(std::size_t row, const std::string& column) const {
    return table.rows[row][table.column(column)];
  }
  std::size_t rows() const { return table.rows.size(); }
};

ExampleRun simulate_example(const std::string& name, double duration = 0.0,
                            bool reactions = false) {
  static std::map<std::string, io::ModelFile> files;  // the Model must outlive the Simulation
  auto it = files.find(name);
  if (it == files.end())
    it = files.emplace(name, io::read_model_file("examples/constraints/" + name + ".yaml")).first;
  const io::ModelFile& file = it->second;
  simulate::SimulationOptions options;
  options.duration = duration > 0 ? duration : *file.simulation.duration;
  options.step = *file.simulation.step;
  options.reactions = reactions;
  simulate::Simulation simulation(file.model, file.outputs, options);
  ExampleRun run;
  run.summary = simulation.run(run.table);
  return run;
}

double relative(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

// Beer & Johnston SP 18.3: T = m ω² L sin β / 3 + m g tan β / 2, A = (T − m ω² (L/2) sin β, 0, mg).
TEST(ClassicConstraints, RodOnRotatingShaftWireTensionAndPinReaction) {
  const double m = 20, L = 2, w = 15, beta = std::numbers::pi / 6;
  const double T = m * w * w * L * std::sin(beta) / 3 + m * kG * std::tan(beta) / 2;
  const double Ax = T - m * w * w * L / 2 * std::sin(beta);
  const ExampleRun run = simulate_example("rod_on_rotating_shaft");
  ASSERT_EQ(run.rows(), 1001u);
  for (std::size_t r = 0; r < run.rows(); ++r) {
    EXPECT_LT(relative(run.at(r, "tension"), T), 1e-10) << r;
    EXPECT_LT(relative(run.at(r, "reaction_A.x"), Ax), 1e-10) << r;
    EXPECT_LT(std::abs(run.at(r, "reaction_A.y")), 1e-10 * T) << r;
    EXPECT_LT(relative(run.at(r, "reaction_A.z"), m * kG), 1e-10) << r;
    EXPECT_LT(std::abs(run.at(r, "beta") - beta), 1e-12) << r;
  }
}

// Beer & Johnston SP 18.2: Ω = −r ω1 / L, H_O = (½mr²ω1, 0, (¼mr² + mL²)Ω), T = ½ ω·H_O,
// N = mg + ½ m r³ ω1² / L².
TEST(ClassicConstraints, RollingDiskOnPivotedAxle) {
  const double m = 4, r = 0.15, L = 0.45, w1 = 20, W = -r * w1 / L;
  const double T = 0.5 * (w1 * 0.5 * m * r * r * w1 + W * (0.25 * m * r * r + m * L * L) * W);
  const double N = m * kG + 0.5 * m * r * r * r * w1 * w1 / (L * L);
  const ExampleRun run = simulate_example("rolling_disk_on_axle");
  EXPECT_EQ(run.summary.redundant_constraint_rows, std::vector<std::string>{"floor.lateral"});
  for (std::size_t i = 0; i < run.rows(); ++i) {
    EXPECT_LT(relative(run.at(i, "contact.normal"), N), 1e-10) << i;
    EXPECT_LT(std::abs(run.at(i, "contact.longitudinal")), 1e-10 * N) << i;
    EXPECT_EQ(run.at(i, "contact.lateral"), 0.0) << i;  // redundant: no force
    EXPECT_LT(relative(run.at(i, "energy_kinetic"), T), 1e-10) << i;
    // The axle precesses at Ω about the vertical: ω_z = Ω, |ω_horizontal| = ω1.
    EXPECT_LT(relative(run.at(i, "omega.z"), W), 1e-10) << i;
    EXPECT_LT(relative(std::hypot(run.at(i, "omega.x"), run.at(i, "omega.y")), w1), 1e-10) << i;
    // H about G's... about O: its vertical component (¼mr² + mL²)Ω; the axle's ½mr²ω1 turns.
  }
  EXPECT_GT(run.rows(), 4000u);
}

// Freudenstein: K1 cos θ4 − K2 cos θ2 + K3 = cos(θ2 − θ4), solved for the open branch.
double freudenstein_theta4(double a, double b, double c, double d, double t2) {
  const double K1 = d / a, K2 = d / c, K3 = (a * a - b * b + c * c + d * d) / (2 * a * c);
  const double A = std::cos(t2) - K1 - K2 * std::cos(t2) + K3;
  const double B = -2 * std::sin(t2);
  const double C = K1 - (K2 + 1) * std::cos(t2) + K3;
  return 2 * std::atan2(-B - std::sqrt(B * B - 4 * A * C), 2 * A);  // the open branch
}

TEST(ClassicConstraints, FourBarFollowsFreudenstein) {
  const double a = 0.10, b = 0.30, c = 0.25, d = 0.30, w2 = 2 * std::numbers::pi;
  const ExampleRun run = simulate_example("four_bar");
  EXPECT_EQ(run.summary.redundant_constraint_rows,
            (std::vector<std::string>{"closure.z", "closure.rx", "closure.ry"}));
  ASSERT_EQ(run.rows(), 1001u);
  double worst_angle = 0, worst_rate = 0;
  for (std::size_t i = 0; i < run.rows(); ++i) {
    const double t2 = run.at(i, "crank_pin.angle");
    const double t4 = freudenstein_theta4(a, b, c, d, t2);
    // θ3 (absolute) from the crank and coupler angles; ω4 = a ω2 sin(θ2 − θ3) / (c sin(θ4 − θ3)).
    const double t3 = t2 + run.at(i, "coupler_pin.angle");
    const double w4 = a * w2 * std::sin(t2 - t3) / (c * std::sin(t4 - t3));
    worst_angle = std::max(
        worst_angle, std::abs(std::remainder(run.at(i, "theta4") - t4, 2 * std::numbers::pi)));
    worst_rate = std::max(worst_rate, std::abs(run.at(i, "omega4") - w4) / w2);
  }
  EXPECT_LT(worst_angle, 1e-10);
  EXPECT_LT(worst_rate, 1e-10);
  EXPECT_LT(run.summary.audit.back().max_drift, 1e-10);  // constraint velocity
}

TEST(ClassicConstraints, SliderCrankPistonPositionAndAcceleration) {
  const double r = 0.05, l = 0.20, w = 100;
  const ExampleRun run = simulate_example("slider_crank");
  double worst_x = 0, worst_a = 0;
  for (std::size_t i = 0; i < run.rows(); ++i) {
    const double th = w * run.at(i, "time");
    const double S = std::sqrt(l * l - r * r * std::sin(th) * std::sin(th));
    const double x = r * std::cos(th) + S;
    const double s = std::sin(th), co = std::cos(th);
    const double acc =
        w * w *
        (-r * co - r * r * std::cos(2 * th) / S - std::pow(r, 4) * s * s * co * co / (S * S * S));
    worst_x = std::max(worst_x, std::abs(run.at(i, "piston_x") - x) / r);
    worst_a = std::max(worst_a, std::abs(run.at(i, "piston_a") - acc) / (r * w * w));
  }
  EXPECT_LT(worst_x, 1e-10);
  EXPECT_LT(worst_a, 1e-10);
}

// Steady circular rolling: ω = Ω z + s e3 with ω3 = ρΩ/R, so ω_z = Ω + s sin φ and |ω_h| =
// s cos φ; the floor pushes m g up and m ρ Ω² towards the centre. Held for 100 s.
TEST(ClassicConstraints, RollingCoinHoldsItsSteadyCircle) {
  const double m = 1, R = 0.1, rho = 0.5, phi = -20 * std::numbers::pi / 180;
  const double W =
      std::sqrt(-kG * std::sin(phi) / (std::cos(phi) * (1.5 * rho - 0.25 * R * std::sin(phi))));
  const double s = rho * W / R - W * std::sin(phi);
  const ExampleRun run = simulate_example("rolling_coin", 100.0);
  double worst = 0, worst_force = 0;
  for (std::size_t i = 0; i < run.rows(); i += 10) {
    worst = std::max(
        {worst, relative(run.at(i, "omega.z"), W + s * std::sin(phi)),
         relative(std::hypot(run.at(i, "omega.x"), run.at(i, "omega.y")), s * std::cos(phi)),
         relative(run.at(i, "free.z"), R * std::cos(phi))});
    worst_force = std::max({worst_force, relative(run.at(i, "contact.normal"), m * kG),
                            relative(std::abs(run.at(i, "contact.lateral")), m * rho * W * W)});
  }
  EXPECT_LT(worst, 1e-8);  // RK4 over 10⁵ steps
  EXPECT_LT(worst_force, 1e-8);
  for (const simulate::AuditEntry& e : run.summary.audit) {
    if (e.name == "energy") {
      EXPECT_LT(std::abs(e.max_drift), 1e-10);
    }
    if (e.name.rfind("constraint", 0) == 0) {
      EXPECT_LT(e.max_drift, 1e-10) << e.name;
    }
  }
}

// u(t) = U tanh(k t), ω(t) = ω0 / cosh(k t).
TEST(ClassicConstraints, ChaplyginSleighClosedForm) {
  const double m = 2, a = 0.2, IG = m * (0.25 + 0.04) / 12, w0 = 2;
  const double E = 0.5 * (IG + m * a * a) * w0 * w0;
  const double U = std::sqrt(2 * E / m), k = m * a * U / (IG + m * a * a);
  const ExampleRun run = simulate_example("chaplygin_sleigh", 100.0);
  double worst = 0;
  for (std::size_t i = 0; i < run.rows(); i += 10) {
    const double t = run.at(i, "time"), th = run.at(i, "floor_plane.angle");
    const double u = run.at(i, "floor_plane.x_rate") * std::cos(th) +
                     run.at(i, "floor_plane.y_rate") * std::sin(th);
    worst = std::max({worst, std::abs(u - U * std::tanh(k * t)) / U,
                      std::abs(run.at(i, "floor_plane.angle_rate") - w0 / std::cosh(k * t)) / w0});
  }
  EXPECT_LT(worst, 1e-10);
  for (const simulate::AuditEntry& e : run.summary.audit) {
    if (e.name.rfind("constraint", 0) == 0) {
      EXPECT_LT(e.max_drift, 1e-10) << e.name;
    }
  }
}

TEST(ClassicConstraints, GearedPairAccelerationsAndMeshEffort) {
  const ExampleRun run = simulate_example("geared_pair");
  const std::size_t last = run.rows() - 1;
  EXPECT_NEAR(run.at(last, "wheel_axle.angle_rate"), 40.0, 40.0 * 1e-12);
  EXPECT_NEAR(run.at(last, "pinion_axle.angle_rate"), -80.0, 80.0 * 1e-12);
  for (std::size_t i = 0; i < run.rows(); ++i) {
    EXPECT_NEAR(run.at(i, "mesh_effort.effort_a"), -0.1, 1e-13);
    EXPECT_NEAR(run.at(i, "mesh_effort.effort_b"), -0.2, 1e-13);
  }
}

// A pendulum as a free body held at its pivot by a `point` constraint moves as the same
// pendulum on a ball joint, and the constraint's force is that joint's reaction.
TEST(ClassicConstraints, PointConstraintEqualsBallJointTree) {
  const auto build = [](bool as_loop) {
    model::ModelBuilder builder;
    builder.add_body("bob", inertia::box(inertia::Amount::mass(2.0), Vec3(0.05, 0.08, 0.8))
                                .transformed(Mat3::Identity(), Vec3(0, 0, -0.4)));
    model::Joint j;
    j.name = "hold";
    j.parent = "world";
    j.child = "bob";
    const Mat3 R = (Eigen::AngleAxisd(0.7, Vec3::UnitX()) * Eigen::AngleAxisd(0.3, Vec3::UnitY()))
                       .toRotationMatrix();
    const Quat qr(R);
    if (as_loop) {
      j.type = model::JointType::free;
      j.q0 = (VecX(7) << 0, 0, 0, qr.w(), qr.x(), qr.y(), qr.z()).finished();
      j.v0 = (VecX(6) << 1.0, -0.5, 2.0, 0, 0, 0).finished();
      j.v0.tail<3>() = Vec3::Zero();
      builder.add_constraint(
          model::LoopClosure{"pivot", model::LoopType::point, {"world", {}}, {"bob", {}}});
    } else {
      j.type = model::JointType::spherical;
      j.q0 = (VecX(4) << qr.w(), qr.x(), qr.y(), qr.z()).finished();
      j.v0 = (VecX(3) << 1.0, -0.5, 2.0).finished();
    }
    builder.add_joint(j);
    return builder.build();
  };
  const model::Model loop = build(true), tree = build(false);
  simulate::SimulationOptions options;
  options.duration = 2.0;
  options.step = 1e-3;
  options.reactions = true;
  simulate::TableSink a, b;
  simulate::Simulation(loop, {}, options).run(a);
  simulate::Simulation(tree, {}, options).run(b);
  ASSERT_EQ(a.rows.size(), b.rows.size());
  double worst_q = 0, worst_f = 0;
  for (std::size_t i = 0; i < a.rows.size(); ++i) {
    // The free joint's quaternion and the ball joint's share their names.
    for (const char* c : {"hold.qw", "hold.qx", "hold.qy", "hold.qz"})
      worst_q = std::max(worst_q, std::abs(a.rows[i][a.column(c)] - b.rows[i][b.column(c)]));
    for (const char* f : {"Fx", "Fy", "Fz"}) {
      worst_f = std::max(worst_f, std::abs(a.rows[i][a.column(std::string("pivot.reaction.") + f)] -
                                           b.rows[i][b.column(std::string("hold.reaction.") + f)]));
    }
  }
  EXPECT_LT(worst_q, 1e-10);
  EXPECT_LT(worst_f, 1e-8);  // N, of forces ~50 N
}

}  // namespace
}  // namespace momenta

namespace momenta {
namespace {

// Every bundled constrained example run for 100 s at its own step: the projection after each
// step keeps the position and velocity residuals (audited after every step) at round-off.
// 10 × 10⁵ steps, 20 s in Release; skipped under AddressSanitizer (10× slower), where the shorter
// runs above go through the same code.
TEST(ClassicConstraints, EveryExampleStaysOnItsConstraintsFor100Seconds) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "10⁵ steps per example: Release only";
#endif
  int examples = 0;
  for (const auto& entry : std::filesystem::directory_iterator("examples/constraints")) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    ++examples;
    const io::ModelFile file = io::read_model_file(entry.path());
    simulate::SimulationOptions options;
    options.duration = 100.0;
    options.step = *file.simulation.step;
    options.every = 1000000;  // the audit sees every step; the table only the ends
    if (file.simulation.integrator) options.integrator = *file.simulation.integrator;
    simulate::Simulation simulation(file.model, {}, options);
    simulate::TableSink table;
    const simulate::SimulationSummary summary = simulation.run(table);
    ASSERT_TRUE(summary.constraints_audited);
    EXPECT_NEAR(summary.t_end, 100.0, 1e-9);
    for (const simulate::AuditEntry& audited : summary.audit) {
      if (audited.name.starts_with("constraint")) {
        EXPECT_LE(audited.max_drift, 1e-10) << audited.name;
      }
    }
  }
  EXPECT_EQ(examples, 10);
}

// IFToMM A02's N-four-bar (N = 4) started with every link horizontal, at 1 rad/s on the
// parallelogram branch. There each loop's row along the links depends on the others (rank 4 of
// the 8 its 20 rows have nearby); the rows do not fix the accelerations, and the Gauss solution of
// the singular rows left rk4 an O(h²) error (1.48e-7 rad at h = 1 ms, 1.48e-9 at 0.1 ms: measured
// before the fix). The run must say so and take the limit along the motion: the mechanism moves
// as one body, θ̈ = −C cos θ / I with I = (N + 1) m L² / 3 + N m L² and C = m g L ((N + 1) / 2
// + N), integrated here independently (classic RK4 at 1e-5 s: error < 1e-15).
TEST(ConstraintSingularities, AStartWithEveryLinkAlignedIsReportedAndIntegratedThrough) {
  const io::ModelFile file = io::read_model_file("tests/data/models/n_four_bar_horizontal.yaml");
  simulate::SimulationOptions options;
  options.duration = 0.5;
  options.step = 1e-3;
  simulate::Simulation simulation(file.model, {}, options);
  simulate::TableSink table;
  const simulate::SimulationSummary summary = simulation.run(table);
  const system::ConsistentState& start = summary.initial_state;
  EXPECT_EQ(start.singular_rows,
            (std::vector<std::string>{"loop0.x", "loop1.x", "loop2.x", "loop3.x"}));
  EXPECT_EQ(start.rank_at_start, 4);  // of the 20 rows, x and y of each loop are independent
  EXPECT_EQ(start.rank_nearby, 8);    // nearby; at the start only y
  // Redundant: only the out-of-plane rows, as at every regular configuration.
  for (const std::string& row : summary.redundant_constraint_rows)
    EXPECT_FALSE(row.ends_with(".x") || row.ends_with(".y")) << row;
  const std::string text = simulate::format_summary(summary);
  EXPECT_NE(text.find("constraints  the initial configuration is singular: rows loop0.x, "
                      "loop1.x, loop2.x, loop3.x depend on the others there but not at assembled "
                      "configurations nearby (4 independent rows there, 8 nearby)"),
            std::string::npos)
      << text;

  const int N = 4;
  const double I = (N + 1) / 3.0 + N, C = 9.81 * ((N + 1) / 2.0 + N);
  double theta = 0.0, rate = 1.0;
  const auto f = [&](double th) { return -C * std::cos(th) / I; };
  const double h = 1e-5;
  for (int k = 0; k < 50000; ++k) {
    const double a1 = f(theta), v1 = rate;
    const double a2 = f(theta + h / 2 * v1), v2 = rate + h / 2 * a1;
    const double a3 = f(theta + h / 2 * v2), v3 = rate + h / 2 * a2;
    const double a4 = f(theta + h * v3), v4 = rate + h * a3;
    theta += h / 6 * (v1 + 2 * v2 + 2 * v3 + v4);
    rate += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
  }
  const std::vector<double>& last = table.rows.back();
  EXPECT_EQ(last[table.column("time")], 0.5);
  // Measured 5.2e-12 rad and 1e-11 rad/s: rk4's own O(h⁴), where the singular rows cost 1.5e-7.
  EXPECT_NEAR(last[table.column("pivot0.angle")], theta, 2e-11);
  EXPECT_NEAR(last[table.column("pivot0.angle_rate")], rate, 1e-10);
  EXPECT_NEAR(last[table.column("pivot4.angle")], theta, 2e-11);  // the cranks turn together
  EXPECT_NEAR(last[table.column("pin0.angle")], -theta, 2e-11);   // the couplers stay level
  for (const simulate::AuditEntry& audited : summary.audit) {
    if (audited.name == "energy") {
      EXPECT_LT(std::abs(audited.max_drift), 1e-12);  // was 7.4e-9
    }
  }
}

// At rest in that configuration no motion says which branch the mechanism takes: the run stops
// at once and says why.
TEST(ConstraintSingularities, AtRestAtASingularConfigurationTheRunStopsAndSaysWhy) {
  std::ifstream in("tests/data/models/n_four_bar_horizontal.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const std::string moving : {"v0: 1}", "v0: -1}"}) {
    for (auto at = text.find(moving); at != std::string::npos; at = text.find(moving))
      text.replace(at, moving.size(), "v0: 0}");
  }
  const io::ModelFile file = io::parse_model_file(text, "at_rest.yaml", ".");
  simulate::SimulationOptions options;
  options.duration = 0.01;
  simulate::Simulation simulation(file.model, {}, options);
  simulate::TableSink table;
  try {
    simulation.run(table);
    FAIL() << "ran";
  } catch (const NumericalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("singular configuration at t = 0 s, at rest: constraint row 'loop0.x' "
                        "became dependent on the others (4 independent rows, 8 at assembled "
                        "configurations nearby)"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("Give a velocity along the branch"), std::string::npos) << what;
  }
}

TEST(ConstraintErrors, RigidBodyIntegratorsAreRefused) {
  const io::ModelFile file = io::read_model_file("examples/constraints/rolling_coin.yaml");
  simulate::SimulationOptions options;
  options.integrator = "splitting";
  try {
    simulate::Simulation simulation(file.model, {}, options);
    FAIL() << "splitting accepted on a constrained model";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("cannot keep the model's constraints"), std::string::npos)
        << e.what();
  }
}

TEST(ConstraintErrors, ADrivenRockerStopsAtItsDeadPointWithTheTimeAndRow) {
  // The four-bar of four_bar.yaml driven by its rocker (c = 0.25 m) at 1 rad/s from 100°. The
  // rocker can only swing while crank (a = 0.10) and coupler (b = 0.30) reach it: its limits are
  // where they line up, |O2 B| = a + b or b − a, cos θ4 = (|O2 B|² − d² − c²) / (2 d c):
  // 87.13° and 138.59°. Driven past 138.59° (t = 0.6735 s) the loop cannot close: the run stops
  // there naming the time and the closure's row.
  const std::string text = R"(name: driven rocker
gravity: [0, -9.81, 0]
inputs:
  - {name: rocker_angle, type: ramp, start: 0.0, offset: 1.7453292519943295, slope: 1.0}
bodies:
  - {name: crank, shape: slender_rod, mass: 1.0, length: 0.10, position: [0.05, 0, 0],
     euler: {sequence: XYZ, angles_deg: [0, 90, 0]}}
  - {name: coupler, shape: slender_rod, mass: 2.0, length: 0.30, position: [0.15, 0, 0],
     euler: {sequence: XYZ, angles_deg: [0, 90, 0]}}
  - {name: rocker, shape: slender_rod, mass: 1.5, length: 0.25, position: [0.125, 0, 0],
     euler: {sequence: XYZ, angles_deg: [0, 90, 0]}}
joints:
  - {name: crank_pin, type: revolute, parent: world, child: crank, axis: [0, 0, 1], q0_deg: 60}
  - {name: coupler_pin, type: revolute, parent: crank, child: coupler, axis: [0, 0, 1],
     in_parent: {position: [0.10, 0, 0]}, q0_deg: 50}
  - {name: rocker_pin, type: revolute, parent: world, child: rocker, axis: [0, 0, 1],
     in_parent: {position: [0.30, 0, 0]}, prescribed: rocker_angle}
constraints:
  - {name: closure, type: hinge, body_a: rocker, point_a: [0.25, 0, 0],
     body_b: coupler, point_b: [0.30, 0, 0]}
)";
  const io::ModelFile file = io::parse_model_file(text, "driven_rocker.yaml", ".");
  simulate::SimulationOptions options;
  options.duration = 1.0;
  options.step = 1e-3;
  simulate::Simulation simulation(file.model, {}, options);
  simulate::TableSink table;
  const double limit = std::acos(-0.75) - 100 * std::numbers::pi / 180;  // 0.67352 s
  try {
    simulation.run(table);
    FAIL() << "driven past the dead point without an error";
  } catch (const NumericalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("closure."), std::string::npos) << what;
    const std::size_t at = what.find("t = ");
    ASSERT_NE(at, std::string::npos) << what;
    const double t = std::stod(what.substr(at + 4));
    EXPECT_GE(t, limit - 2e-3) << what;  // within two steps of the limit
    EXPECT_LE(t, limit + 2e-3) << what;
  }
  // The rows before the stop are whole and on the constraint.
  ASSERT_FALSE(table.rows.empty());
  EXPECT_LT(table.rows.back()[0], limit + 1e-3);
}

TEST(ConstraintErrors, ModelFileNamesTheLineAndSuggests) {
  const std::string text = R"(bodies:
  - {name: arm, shape: box, mass: 1, size: [0.1, 0.1, 1]}
joints:
  - {name: pin, type: revolute, parent: world, child: arm}
constraints:
  - {name: tie, type: distance, body_a: world, body_b: amr, length: 1.0}
)";
  try {
    io::parse_model_file(text, "m.yaml", ".");
    FAIL() << "accepted";
  } catch (const ParseError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("m.yaml:6:"), std::string::npos) << what;
    EXPECT_NE(what.find("did you mean 'arm'"), std::string::npos) << what;
  }
  try {
    io::parse_model_file(R"(bodies:
  - {name: arm, shape: box, mass: 1, size: [0.1, 0.1, 1]}
joints:
  - {name: pin, type: revolute, parent: world, child: arm}
constraints:
  - {name: tie, type: distnce, body_a: world, body_b: arm, length: 1.0}
)",
                         "m.yaml", ".");
    FAIL() << "accepted";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'distance'"), std::string::npos) << e.what();
  }
}

// Two wires of different lengths from the same point to the same body point cannot both hold.
TEST(ConstraintErrors, ConflictingConstraintsAreRefusedWithTheResidual) {
  const std::string text = R"(bodies:
  - {name: arm, shape: box, mass: 1, size: [0.1, 0.1, 1], position: [0, 0, -0.5]}
joints:
  - {name: pin, type: ball, parent: world, child: arm}
constraints:
  - {name: short, type: distance, body_a: world, point_a: [0, 0, -2], body_b: arm, point_b: [0, 0, -1], length: 1.0}
  - {name: long, type: distance, body_a: world, point_a: [0, 0, -2], body_b: arm, point_b: [0, 0, -1], length: 1.5}
)";
  const io::ModelFile file = io::parse_model_file(text, "m.yaml", ".");
  simulate::SimulationOptions options;
  options.duration = 0.1;
  simulate::Simulation simulation(file.model, {}, options);
  simulate::TableSink table;
  try {
    simulation.run(table);
    FAIL() << "conflicting constraints accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("no consistent initial state"), std::string::npos)
        << e.what();
  }
}

// The velocities a file gives are kept where the unset ones can take up the whole residual,
// even when the unset ones alone could not move every row (issue 28: the test was the rank of
// the constraint matrix, not the residual, and a rolling disk's given 1 m/s became 0.0099 m/s).
// A slider x (given 1 m/s) turns a spin joint through a coupler (given −10 rad/s, already
// consistent: ω = −10 ẋ) and drives an unset slider y through a second coupler (y = x): only ẏ
// moves, to 1 m/s.
TEST(ClassicConstraints, GivenVelocitiesAreKeptWhereTheUnsetOnesCanTakeUpTheResidual) {
  const std::string text = R"(bodies:
  - {name: cart, mass: 1, inertia: [1, 1, 1]}
  - {name: wheel, mass: 1, inertia: [1, 1, 1]}
  - {name: follower, mass: 1, inertia: [1, 1, 1]}
joints:
  - {name: x, type: prismatic, parent: world, child: cart, axis: [1, 0, 0], v0: 1.0}
  - {name: spin, type: revolute, parent: cart, child: wheel, axis: [0, 1, 0], v0: -10.0}
  - {name: y, type: prismatic, parent: world, child: follower, axis: [0, 1, 0]}
constraints:
  - {name: rolling, type: coupler, joint_a: spin, joint_b: x, ratio: -10.0}
  - {name: follow, type: coupler, joint_a: y, joint_b: x, ratio: 1.0}
)";
  const io::ModelFile file = io::parse_model_file(text, "m.yaml", ".");
  system::MultibodySystem system(file.model);
  VecX q = file.model.initial_q(), v = file.model.initial_v();
  const system::ConsistentState changed = system.make_consistent(0.0, q, v);
  ASSERT_EQ(changed.v_changes.size(), 1u);
  EXPECT_EQ(changed.v_changes[0].name, "y.position_rate");
  const auto speed = [&](const char* joint) {
    return v[file.model.joint(file.model.joint_index(joint)).v_index];
  };
  EXPECT_EQ(speed("x"), 1.0);       // given, kept
  EXPECT_EQ(speed("spin"), -10.0);  // given, kept
  EXPECT_NEAR(speed("y"), 1.0, 1e-15);
}

}  // namespace
}  // namespace momenta
