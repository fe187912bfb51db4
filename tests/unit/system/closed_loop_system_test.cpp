// ClosedLoopSystem (system/closed_loop_system.hpp) and the `controllers:` section of model files:
// the kinds against each other (a transfer function that is a PI runs as the pid does), the
// sensor and actuator, no allocation on the hot path, and every bad input a clear error.

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/simulate/simulation.hpp"
#include "momenta/system/closed_loop_system.hpp"
#include "momenta_test/allocation_counter.hpp"

namespace momenta {
namespace {

// A 2 kg block on a track, pushed by `push`, with `controllers` (YAML) closing the loop.
std::string block_model(const std::string& controllers, const std::string& inputs = "") {
  return R"(name: block
gravity: [0, 0, 0]
)" + (inputs.empty() ? std::string() : "inputs:\n" + inputs) +
         (controllers.empty() ? std::string() : "controllers:\n" + controllers) + R"(
bodies:
  - {name: block, mass: 2.0}
joints:
  - {name: x, type: prismatic, parent: world, child: block, axis: [1, 0, 0], q0: 1.0}
forces:
  - {name: drive, type: force, body: block, vector: [1, 0, 0], signal: push}
)";
}

io::ModelFile parse_block(const std::string& text) {
  return io::parse_model_file(text, "block.yaml", ".");
}

simulate::TableSink run_block(const io::ModelFile& file, double duration, double step,
                              const std::string& integrator = "rk4") {
  simulate::SimulationOptions o;
  o.duration = duration;
  o.step = step;
  o.integrator = integrator;
  o.tolerances = {1e-11, 1e-12};
  simulate::Simulation simulation(file.model, file.outputs, o);
  simulate::TableSink sink;
  simulation.run(sink);
  return sink;
}

std::string error_of(const std::string& text) {
  try {
    parse_block(text);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

// A PID with a filtered derivative, kp + ki/s + kd s/(Tf s + 1), written as the one transfer
// function [(kp Tf + kd) s² + (kp + ki Tf) s + ki] / (Tf s² + s), runs as the pid does: the same
// closed loop by a second realization. Both start at rest (the reference steps at 0.5 s), and
// the two realizations differ by a change of state coordinates, to which Runge–Kutta methods are
// equivariant: only round-off separates the runs.
TEST(ClosedLoopSystem, TransferFunctionPidRunsAsThePid) {
  const auto model = [](const std::string& law) {
    std::string text = block_model("  - name: c\n" + law +
                                       "    measure: x.position\n    reference: target\n"
                                       "    drives: push\n",
                                   "  - {name: target, type: step, start: 0.5, final: 1}\n");
    text.replace(text.find("q0: 1.0"), 7, "q0: 0.0");
    return parse_block(text);
  };
  const io::ModelFile pid =
      model("    type: pid\n    kp: 8\n    ki: 3\n    kd: 4\n    derivative_filter: 0.05\n");
  const io::ModelFile tf = model(
      "    type: transfer_function\n    numerator: [4.4, 8.15, 3]\n    denominator: [0.05, 1, "
      "0]\n");
  const simulate::TableSink a = run_block(pid, 15.0, 0.001), b = run_block(tf, 15.0, 0.001);
  const int x = a.column("x.position"), u = a.column("c.push");
  ASSERT_EQ(a.rows.size(), b.rows.size());
  double worst_x = 0.0, worst_u = 0.0;
  for (std::size_t i = 0; i < a.rows.size(); ++i) {
    worst_x = std::max(worst_x, std::abs(a.rows[i][x] - b.rows[i][x]));
    worst_u = std::max(worst_u, std::abs(a.rows[i][u] - b.rows[i][u]));
  }
  EXPECT_LT(worst_x, 1e-12);
  EXPECT_LT(worst_u, 1e-10);  // u reaches kd/Tf = 80 N at the step
  // The loop 0.1 s⁴ + 2 s³ + 4.4 s² + 8.15 s + 3 is stable (Routh; its slowest pole −0.458 1/s):
  // 14.5 s after the step the block is at 1 m to e^{−6.6} of the swing.
  EXPECT_NEAR(a.rows.back()[x], 1.0, 1e-3);
}

// The continuous PD's derivative on a position is the coordinate's own rate: u = −kp x − kd ẋ,
// the spring-damper m ẍ + kd ẋ + kp x = 0 (ω = 2, ζ = 0.5): x = e^{−t}(cos √3 t + sin(√3 t)/√3).
TEST(ClosedLoopSystem, ContinuousPdIsTheSpringDamperItStandsFor) {
  const io::ModelFile file = parse_block(block_model(R"(  - name: c
    type: pid
    measure: x.position
    kp: 8
    kd: 4
    drives: push
)"));
  const simulate::TableSink table = run_block(file, 5.0, 0.001);
  const int t = table.column("time"), x = table.column("x.position");
  const double w = std::sqrt(3.0);
  for (const auto& row : table.rows) {
    const double exact = std::exp(-row[t]) * (std::cos(w * row[t]) + std::sin(w * row[t]) / w);
    EXPECT_NEAR(row[x], exact, 1e-12);
  }
}

// An external law (the program's function: Python's controller=fn) u = −8 x − 4 ẋ added to the
// open block with Model::with_controller is the same spring–damper: the closed form to 1e-12,
// sampled at 0.1 s it is called once per sample at t = kT exactly, and a non-finite output
// stops the run naming the controller, input and time.
TEST(ClosedLoopSystem, AnExternalLawClosesTheLoopAsItsCode) {
  const io::ModelFile open =
      parse_block(block_model("", "  - {name: push, type: constant, value: 0}\n"));
  std::vector<double> calls;
  model::Controller c;
  c.name = "law";
  c.kind = model::ControllerKind::external;
  c.drives = {"push"};
  c.law = std::make_shared<const model::ControlLaw>(
      [&calls](double t, const VecX& q, const VecX& v, std::span<double> u) {
        calls.push_back(t);
        u[0] = -8.0 * q[0] - 4.0 * v[0];
      });
  io::ModelFile closed = open;
  closed.model = open.model.with_controller(c);
  ASSERT_TRUE(closed.model.is_driven(0));
  EXPECT_FALSE(open.model.has_controllers());  // the model it came from is as it was
  const simulate::TableSink table = run_block(closed, 5.0, 0.001);
  const int t = table.column("time"), x = table.column("x.position"), u = table.column("law.push");
  const double w = std::sqrt(3.0);
  for (const auto& row : table.rows) {
    EXPECT_NEAR(row[x], std::exp(-row[t]) * (std::cos(w * row[t]) + std::sin(w * row[t]) / w),
                1e-12);
  }
  EXPECT_DOUBLE_EQ(table.rows.front()[u], -8.0);

  // Sampled: one call per sample, at 0, 0.1, ..., 1.
  calls.clear();
  c.sample_time = 0.1;
  closed.model = open.model.with_controller(c);
  run_block(closed, 1.0, 0.01);
  ASSERT_EQ(calls.size(), 11u);
  for (std::size_t k = 0; k < calls.size(); ++k) EXPECT_NEAR(calls[k], 0.1 * k, 1e-15);

  // Bad laws and bad fits.
  c.sample_time = 0.0;
  c.law = std::make_shared<const model::ControlLaw>(
      [](double time, const VecX&, const VecX&, std::span<double> out) {
        out[0] = time > 0.5 ? std::nan("") : 0.0;
      });
  closed.model = open.model.with_controller(c);
  try {
    run_block(closed, 1.0, 0.01);
    ADD_FAILURE() << "a NaN output ran on";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("controller 'law' gave push = nan at t = 0.5"),
              std::string::npos)
        << e.what();
  }
  model::Controller twice = c;
  EXPECT_THROW(closed.model.with_controller(twice), InvalidArgument);  // same name
  twice.name = "other";
  try {
    closed.model.with_controller(twice);
    ADD_FAILURE() << "a signal driven twice";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("drives 'push', which controller 'law' drives too"),
              std::string::npos);
  }
  model::Controller lawless = c;
  lawless.law = nullptr;
  EXPECT_THROW(open.model.with_controller(lawless), InvalidArgument);
  model::Controller measuring = c;
  measuring.measured = {"x.position"};
  EXPECT_THROW(open.model.with_controller(measuring), InvalidArgument);
}

// A controller measuring a model output: a filtered PID on the position of the block's point
// 0.5 m ahead of its origin (a body point's x, `outputs:`) following 2 m runs exactly as the same
// PID on the joint coordinate following 1.5 m; sampled at 20 Hz, the same.
TEST(ClosedLoopSystem, AControllerMeasuresAModelOutput) {
  const auto with_output = [](const std::string& controllers) {
    return block_model(controllers) + R"(outputs:
  - {name: nose, body: block, quantity: position, point: [0.5, 0, 0], component: x}
)";
  };
  for (const std::string sampled : {"", ", sample_time: 0.05"}) {
    const std::string pid =
        "  - {name: c, type: pid, kp: 8, ki: 3, kd: 4, derivative_filter: 0.01, drives: push, ";
    const io::ModelFile on_output =
        parse_block(with_output(pid + "measure: nose, reference: 2.0" + sampled + "}\n"));
    const io::ModelFile on_coordinate =
        parse_block(with_output(pid + "measure: x.position, reference: 1.5" + sampled + "}\n"));
    ASSERT_EQ(on_output.model.controllers()[0].spec.measured_outputs.size(), 1u);
    const simulate::TableSink a = run_block(on_output, 12.0, 0.001);
    const simulate::TableSink b = run_block(on_coordinate, 12.0, 0.001);
    const int x = a.column("x.position"), u = a.column("c.push"), e = a.column("c.error");
    ASSERT_EQ(a.rows.size(), b.rows.size());
    for (std::size_t k = 0; k < a.rows.size(); ++k) {
      EXPECT_NEAR(a.rows[k][x], b.rows[k][x], 1e-12) << sampled << k;
      EXPECT_NEAR(a.rows[k][u], b.rows[k][u], 1e-10) << sampled << k;
      EXPECT_NEAR(a.rows[k][e], b.rows[k][e], 1e-12) << sampled << k;
    }
    // Settled: the nose at 2 m.
    EXPECT_NEAR(a.rows.back()[a.column("nose")], 2.0, 1e-3);
  }
  // A misspelled output is suggested; what cannot be measured is said at the controller's line.
  const std::string misspelled = error_of(with_output(
      "  - {name: c, type: pid, kp: 8, ki: 3, kd: 4, derivative_filter: 0.01, drives: push, "
      "measure: nse}\n"));
  EXPECT_NE(misspelled.find("measures 'nse', which is no coordinate or output of the model (did "
                            "you mean 'nose'?)"),
            std::string::npos)
      << misspelled;
  const auto refused = [&](const std::string& output, const std::string& words) {
    const std::string text =
        block_model("  - {name: c, type: pid, kp: 8, drives: push, measure: o}\n") +
        "outputs:\n  - " + output + "\n";
    const std::string message = error_of(text);
    EXPECT_NE(message.find(words), std::string::npos) << message;
    EXPECT_NE(message.find("block.yaml:"), std::string::npos) << message;
  };
  refused("{name: o, body: block, quantity: acceleration, component: x}",
          "measures output 'o', which depends on the accelerations or the inputs");
  refused("{name: o, body: block, quantity: position}",
          "measures output 'o', which has three values: choose one with 'component'");
  refused("{name: o, joint: x, quantity: effort}", "an algebraic loop");
}

// A discrete state feedback with quantization, a delay of two samples and a rate limit: the
// output steps only at samples, by at most rate_limit · T, and reads the quantized value of two
// samples before.
TEST(ClosedLoopSystem, SensorAndActuatorShapeTheDiscreteLaw) {
  const io::ModelFile file = parse_block(block_model(R"(  - name: c
    type: state_feedback
    measure: [x.position, x.position_rate]
    gain: [[4, 4]]
    sample_time: 0.05
    sensor: {quantization: 0.01, delay: 2}
    actuator: {min: -3, max: 3, rate_limit: 20}
    drives: push
)"));
  const simulate::TableSink table = run_block(file, 3.0, 0.01);
  const int t = table.column("time"), u = table.column("c.push");
  const int x = table.column("x.position"), v = table.column("x.position_rate");
  // Rows at the samples, in order.
  std::vector<std::size_t> samples;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const double k = table.rows[i][t] / 0.05;
    if (std::abs(k - std::round(k)) < 1e-9) samples.push_back(i);
  }
  ASSERT_EQ(samples.size(), 61u);
  const auto quantized = [](double y) { return 0.01 * std::round(y / 0.01); };
  double previous = 0.0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const auto& row = table.rows[samples[k]];
    // The reading used at sample k was taken at sample k − 2 (the first one, before that).
    const auto& read = table.rows[samples[k >= 2 ? k - 2 : 0]];
    double law = std::clamp(-4.0 * quantized(read[x]) - 4.0 * quantized(read[v]), -3.0, 3.0);
    if (k > 0) law = std::clamp(law, previous - 1.0, previous + 1.0);
    EXPECT_NEAR(row[u], law, 1e-15) << "sample " << k;
    previous = row[u];
  }
  EXPECT_EQ(table.rows[samples[0]][u], -3.0);  // −4 · 1 saturates
  EXPECT_EQ(table.rows[samples[1]][u], -3.0);  // the rate limit allows −3 ± 1
}

// Noise is seeded: two runs agree, a different seed differs, and the noise has the standard
// deviation asked. The controller drives an input nothing uses, so the block rests at x = 1 and
// its output is −(1 + n_k): over 400 samples the mean of n within 4 standard errors (σ/√400) of
// 0, its variance within 4 (σ²√(2/400)) of σ².
TEST(ClosedLoopSystem, SensorNoiseIsSeededAndHasItsDeviation) {
  const auto model = [](int seed) {
    return parse_block(block_model(R"(  - name: c
    type: state_feedback
    measure: [x.position]
    gain: [[1.0]]
    sample_time: 0.01
    sensor: {noise: 0.5, seed: )" + std::to_string(seed) +
                                       R"(}
    drives: spare
)",
                                   "  - {name: push, type: constant, value: 0}\n"));
  };
  const simulate::TableSink a = run_block(model(7), 3.99, 0.01),
                            b = run_block(model(7), 3.99, 0.01);
  const simulate::TableSink c = run_block(model(8), 3.99, 0.01);
  EXPECT_EQ(a.rows, b.rows);
  const int u = a.column("c.spare"), x = a.column("x.position");
  ASSERT_EQ(a.rows.size(), 400u);
  double mean = 0.0, square = 0.0, differ = 0.0;
  for (std::size_t i = 0; i < a.rows.size(); ++i) {
    EXPECT_EQ(a.rows[i][x], 1.0);
    const double n = -a.rows[i][u] - 1.0;
    mean += n / 400.0;
    square += n * n / 400.0;
    differ = std::max(differ, std::abs(a.rows[i][u] - c.rows[i][u]));
  }
  EXPECT_LT(std::abs(mean), 4.0 * 0.5 / 20.0);
  EXPECT_LT(std::abs(square - 0.25), 4.0 * 0.25 * std::sqrt(2.0 / 400.0));
  EXPECT_GT(differ, 0.1);
}

// The hot path does not allocate: the closed loop's acceleration, and a sample.
TEST(ClosedLoopSystem, AccelerationAndSamplesDoNotAllocate) {
  const io::ModelFile file = parse_block(block_model(R"(  - name: c
    type: pid
    measure: x.position
    kp: 8
    ki: 1
    kd: 2
    derivative_filter: 0.01
    drives: push
  - name: d
    type: state_space
    measure: x.position
    A: [[0.5]]
    B: [1]
    C: [[0.1]]
    D: 0.2
    sample_time: 0.1
    drives: pull
)") + "  - {name: pulling, type: force, body: block, vector: [-1, 0, 0], signal: pull}\n");
  system::MultibodySystem plant(file.model);
  system::ClosedLoopSystem loop(plant);
  ASSERT_EQ(loop.num_controller_states(), 2);  // the pid's integral and filter
  integrate::State s = loop.start(0.0, file.model.initial_q(), file.model.initial_v());
  VecX vdot = VecX::Zero(loop.nv());
  loop.begin_step(0.0, 0.1);
  const long before = test::allocation_count();
  loop.acceleration(0.05, s.q, s.v, vdot);
  EXPECT_TRUE(loop.project(0.1, s.q, s.v));   // the sample at 0.1 s
  EXPECT_FALSE(loop.project(0.1, s.q, s.v));  // taken once
  EXPECT_EQ(test::allocation_count(), before);
  EXPECT_TRUE(vdot.allFinite());
  EXPECT_NEAR(loop.next_discontinuity(0.1), 0.2, 1e-15);
  EXPECT_NEAR(loop.next_discontinuity(0.30000000000000004), 0.4, 1e-15);
}

// --- bad input ---------------------------------------------------------------------------------

TEST(ClosedLoopSystem, BadControllersAreNamedAtTheirLine) {
  const std::string pid = "  - name: c\n    type: pid\n    kp: 1\n    drives: push\n";
  EXPECT_NE(
      error_of(block_model(pid + "    measure: x.postion\n"))
          .find("measures 'x.postion', which is no coordinate or output of the model (did you mean "
                "'x.position'?)"),
      std::string::npos)
      << error_of(block_model(pid + "    measure: x.postion\n"));
  EXPECT_EQ(error_of(block_model(pid + "    measure: x.position\n")), "(no error)");
  EXPECT_NE(error_of(block_model(pid + "    measure: x.position\n    sample_time: 0\n"))
                .find("sample_time"),
            std::string::npos);
  EXPECT_NE(error_of(block_model(R"(  - name: c
    type: state_feedback
    measure: [x.position, x.position_rate]
    gain: [1, 2, 3]
    drives: push
)"))
                .find("K is 1×3; it must be 1×2"),
            std::string::npos);
  EXPECT_NE(error_of(block_model(pid + "    measure: x.position\n",
                                 "  - {name: push, type: constant, value: 1}\n"))
                .find("'push' is already an input of time"),
            std::string::npos);
  EXPECT_NE(error_of(block_model(pid + "    measure: x.position\n    actuator: {rate_limit: 2}\n"))
                .find("a rate limit needs a sample_time"),
            std::string::npos);
  EXPECT_NE(error_of(block_model("  - name: c\n    type: pid\n    kd: 1\n    drives: push\n"
                                 "    measure: x.position_rate\n"))
                .find("needs a derivative_filter"),
            std::string::npos);
  EXPECT_NE(error_of(block_model(R"(  - name: c
    type: transfer_function
    measure: x.position
    numerator: [1, 0, 0]
    denominator: [1, 1]
    drives: push
)"))
                .find("improper"),
            std::string::npos);
  EXPECT_NE(error_of(block_model(pid + "    measure: x.position\n    reference: target\n"))
                .find("unknown signal 'target'"),
            std::string::npos);
  EXPECT_NE(error_of(block_model("  - name: c\n    type: pdi\n")).find("unknown controller type"),
            std::string::npos);
  // The error names the file and the controller's line.
  const std::string e =
      error_of(block_model(pid + "    measure: x.position\n    sample_time: -1\n"));
  EXPECT_EQ(e.rfind("block.yaml:", 0), 0u) << e;
}

}  // namespace
}  // namespace momenta

namespace momenta {
namespace {

// A loop on a ball joint (quaternion coordinates: the closed loop's steps go through the plant's
// exponential map): a sphere-like body, I = 1 kg·m² about every axis, spun up about x by a PI on
// its rate, u = 3 (r − ω) + 2 ∫(r − ω). About a fixed axis, I ω̇ = u: Ω/R = (3 s + 2)/((s + 1)
// (s + 2)), so ω = r (1 + e^{−t} − 2 e^{−2t}), and the angle turned is ∫ω.
TEST(ClosedLoopSystem, PiOnABallJointSpinsUpAsItsClosedForm) {
  const io::ModelFile file = parse_block(R"(name: spinner
gravity: [0, 0, 0]
controllers:
  - {name: spin, type: pid, measure: ball.wx, reference: 2.0, kp: 3, ki: 2, drives: torque_x}
bodies:
  - {name: body, mass: 1.0, inertia: [1, 1, 1]}
joints:
  - {name: ball, type: spherical, parent: world, child: body}
forces:
  - {name: drive, type: torque, body: body, vector: [1, 0, 0], signal: torque_x}
)");
  const simulate::TableSink table = run_block(file, 4.0, 0.001);
  const int t = table.column("time"), w = table.column("ball.wx");
  const int qw = table.column("ball.qw"), qx = table.column("ball.qx");
  double worst = 0.0, worst_angle = 0.0;
  for (const auto& row : table.rows) {
    const double s = row[t];
    worst =
        std::max(worst, std::abs(row[w] - 2.0 * (1.0 + std::exp(-s) - 2.0 * std::exp(-2.0 * s))));
    // θ = ∫ω = 2 (s + 1 − e^{−s} − 1 + e^{−2s}) = 2 (s − e^{−s} + e^{−2s}); q = (cos θ/2, sin θ/2,
    // 0, 0).
    const double theta = 2.0 * (s - std::exp(-s) + std::exp(-2.0 * s));
    const double turned = 2.0 * std::atan2(row[qx], row[qw]);
    worst_angle =
        std::max(worst_angle, std::abs(std::remainder(turned - theta, 2.0 * std::acos(-1.0))));
  }
  // RK4 at h = 1 ms on rates of 1 and 2 1/s: ~(2h)⁴ relative, far below 1e-10.
  EXPECT_LT(worst, 1e-10);
  EXPECT_LT(worst_angle, 1e-9);
}

// A controller driving the signal that prescribes a joint commands its acceleration: a PD servo on
// a 2 kg link swinging in gravity, q̈ = 16 (1 − q) − 4 q̇, whatever the link's weight — ωn = 4,
// ζ = ½, from its q0 (0.2 rad, at rest): 1 − q = 0.8 e^{−2t} (cos ωd t +
// (2/ωd) sin ωd t), ωd = √12. The drive's effort is what moves the link so: about the pivot,
// J q̈ − m g r cos q with J = I_yy + m r² = 0.7 kg·m², r = 0.5 m (the gravity moment of the centre
// R_y(q) [r, 0, 0] is m g r cos q about +y).
TEST(ClosedLoopSystem, AServoCommandsItsJointsAcceleration) {
  const io::ModelFile file = parse_block(R"(name: servo
gravity: [0, 0, -9.81]
controllers:
  - {name: servo, type: pid, measure: arm.angle, reference: 1.0, kp: 16, kd: 4, drives: arm_drive}
bodies:
  - {name: link, mass: 2.0, com: [0.5, 0, 0], inertia: [0.01, 0.2, 0.2]}
joints:
  - {name: arm, type: revolute, parent: world, child: link, axis: [0, 1, 0], prescribed: arm_drive,
     q0: 0.2}
outputs:
  - {name: torque, joint: arm, quantity: effort}
)");
  EXPECT_EQ(file.model.initial_q()[0], 0.2);
  const simulate::TableSink table = run_block(file, 4.0, 0.001);
  const int t = table.column("time"), q = table.column("arm.angle");
  const int v = table.column("arm.angle_rate"), u = table.column("servo.arm_drive");
  const int torque = table.column("torque");
  const double wd = std::sqrt(12.0);
  double worst = 0.0, worst_u = 0.0, worst_torque = 0.0;
  for (const auto& row : table.rows) {
    const double s = row[t];
    const double e = 0.8 * std::exp(-2.0 * s) * (std::cos(wd * s) + 2.0 / wd * std::sin(wd * s));
    worst = std::max(worst, std::abs(row[q] - (1.0 - e)));
    const double a = 16.0 * (1.0 - row[q]) - 4.0 * row[v];
    worst_u = std::max(worst_u, std::abs(row[u] - a));
    worst_torque = std::max(
        worst_torque, std::abs(row[torque] - (0.7 * a - 2.0 * 9.81 * 0.5 * std::cos(row[q]))));
  }
  // RK4 at h = 1 ms on ωn = 4: ~(4h)⁴ a step relative, far below 1e-10 over the run.
  EXPECT_LT(worst, 1e-10);
  EXPECT_LT(worst_u, 1e-12);
  EXPECT_LT(worst_torque, 1e-11);
  // A ball joint's signals are a rotation vector: no one coordinate to command.
  const std::string ball = R"(name: ball
gravity: [0, 0, 0]
inputs:
  - {name: r2, type: constant, value: 0}
  - {name: r3, type: constant, value: 0}
controllers:
  - {name: c, type: pid, measure: ball.wx, kp: 1, drives: r1}
bodies:
  - {name: body, mass: 1.0, inertia: [1, 1, 1]}
joints:
  - {name: ball, type: spherical, parent: world, child: body, prescribed: [r1, r2, r3]}
)";
  EXPECT_NE(error_of(ball).find("drives 'r1', which prescribes the spherical joint 'ball'"),
            std::string::npos)
      << error_of(ball);
}

}  // namespace
}  // namespace momenta
