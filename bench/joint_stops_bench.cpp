// A thousand bounces (issue 56): a 0.1 kg ball dropped 1 cm on an elastic floor (a prismatic
// joint's lower stop, e = 1) bounces every 2 √(2h/g) = 90.3 ms; 90.3 s of it is 1 000 impacts,
// each located on the step's dense output (TOMS 748), the run taken back there and restarted.
// Beside it the same ball without the floor, falling for the same 90.3 s: what the stops cost over
// the steps themselves. The same again as a free body (6 speeds) on a floor that is a contact
// (model::Contact: the constraint solver's row, off while the ball flies), beside the free body
// falling. rk4 at h = 1 ms and dopri5 (rtol 1e-10, atol 1e-12, largest step 10 ms).
// Counters: the run's steps, evaluations and impacts; the wall time is the benchmark's.
//
// Stick–slip: the block on the belt of examples/belt_stick_slip.yaml for 100 cycles (80.08 s,
// 200 sticks and slips, each located, the contact's rows switched), beside the same block on its
// spring with no belt and no contact (a frictionless oscillator): what Coulomb friction costs —
// the sliding phases' normal force takes three solves an evaluation (system/multibody_system.hpp)
// — over the steps themselves. Counters: steps, evaluations, events.
//
// One impact with friction followed through its course, beside the frictionless one: see
// BM_FrictionalImpact.
//
// A stop on a loop: the four-bar of examples/constraints/four_bar_on_a_stop.yaml for 10 s (rk4,
// 1 ms) — 25 impacts through the loop's rows in its first 0.4 s, then held on its stop (the
// constraint solver with the crank held: hybrid dynamics and the loop's rows) — beside the same
// four-bar without the stop, swinging freely (the loop alone). Counters: steps, evaluations,
// events.
//
// Run (from the repository root): build/bench/joint_stops_bench --benchmark_repetitions=5
// --benchmark_report_aggregates_only and quote the medians and the ratio of each integrator's two
// rows.

#include <fstream>
#include <iterator>
#include <span>
#include <stdexcept>
#include <string>

#include <benchmark/benchmark.h>

#include "momenta/dynamics/impulse.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/simulate/simulation.hpp"

namespace {

using namespace momenta;

constexpr double kDuration = 90.3;  // s: 1 000 bounces of 90.3 ms

// A sink that keeps nothing: the benchmark times the run, not a table.
class Discard final : public simulate::RowSink {
 public:
  void begin(std::span<const std::string>) override {}
  void row(std::span<const double>) override {}
};

// Times the run of `model` with `options` and counts its steps, evaluations and stop events
// (under `events`).
void run_timed(benchmark::State& bench, const model::Model& model,
               const simulate::SimulationOptions& options, const char* events) {
  simulate::Simulation simulation(model, {}, options);
  simulate::SimulationSummary summary;
  for (auto _ : bench) {
    Discard sink;
    summary = simulation.run(sink);
    benchmark::DoNotOptimize(summary.t_end);
  }
  bench.counters["steps"] = static_cast<double>(summary.statistics.steps);
  bench.counters["evaluations"] = static_cast<double>(summary.statistics.evaluations);
  bench.counters[events] = static_cast<double>(summary.stop_events.size());
}

// The ball on a vertical slide (its floor a stop), or free (its floor a contact).
model::Model ball(bool free, bool floor) {
  std::string text =
      "gravity: [0, 0, -9.81]\n"
      "bodies: [{name: ball, shape: sphere, mass: 0.1, radius: 0.005}]\n"
      "joints:\n";
  if (!free) {
    text +=
        "  - {name: drop, type: prismatic, parent: world, child: ball, axis: [0, 0, 1], q0: "
        "0.01" +
        std::string(floor ? ", limits: {lower: 0.0, restitution: 1.0}" : "") + "}\n";
  } else {
    text +=
        "  - {name: free, type: free, parent: world, child: ball, q0: [0, 0, 0.015, 1, 0, 0, "
        "0]}\n";
    if (floor) {
      text +=
          "constraints: [{name: floor, type: contact, body: ball, radius: 0.005, restitution: "
          "1}]\n";
    }
  }
  return io::parse_model_file(text, "ball.yaml", ".").model;
}

void BM_Bounces(benchmark::State& bench, const std::string& integrator, bool free, bool floor) {
  const model::Model model = ball(free, floor);
  simulate::SimulationOptions options;
  options.duration = kDuration;
  options.integrator = integrator;
  options.step = integrator == "rk4" ? 1e-3 : 1e-2;
  options.tolerances = {1e-10, 1e-12};
  options.every = 1000;
  run_timed(bench, model, options, "impacts");
}

// The block on the belt (a contact with the belt's plane, μs = 0.6, μk = 0.4), or the same block
// on its spring alone.
model::Model belt(bool contact) {
  std::string text =
      "gravity: [0, 0, -9.81]\n"
      "inputs: [{name: belt_drive, type: ramp, slope: 0.1}]\n"
      "bodies:\n"
      "  - {name: belt, shape: box, size: [2.0, 0.3, 0.02], mass: 1.0, position: [0, 0, -0.01]}\n"
      "  - {name: carriage, mass: 0}\n"
      "  - {name: block, shape: box, size: [0.1, 0.1, 0.1], mass: 1.0}\n"
      "joints:\n"
      "  - {name: belt, type: prismatic, parent: world, child: belt, axis: [1, 0, 0], "
      "prescribed: belt_drive}\n"
      "  - {name: slide, type: prismatic, parent: world, child: carriage, axis: [1, 0, 0], q0: "
      "0.01962, v0: 0.1}\n";
  // Without the belt's contact the block would fall: it is welded to the carriage instead.
  text += contact ? "  - {name: lift, type: prismatic, parent: carriage, child: block, axis: [0, "
                    "0, 1], q0: 0.05}\n"
                  : "  - {name: lift, type: fixed, parent: carriage, child: block, in_parent: "
                    "{position: [0, 0, 0.05]}}\n";
  text +=
      "forces: [{name: spring, type: spring_damper, body_a: world, point_a: [-0.5, 0, 0.05], "
      "body_b: block, point_b: [0, 0, 0], stiffness: 100.0, free_length: 0.5}]\n";
  if (contact) {
    text +=
        "constraints: [{name: belt_contact, type: contact, body: block, point: [0, 0, -0.05], "
        "other_body: belt, normal: [0, 0, 1], plane_point: [0, 0, 0], friction: {static: 0.6, "
        "kinetic: 0.4}}]\n";
  }
  return io::parse_model_file(text, "belt.yaml", ".").model;
}

void BM_StickSlip(benchmark::State& bench, bool contact) {
  const model::Model model = belt(contact);
  simulate::SimulationOptions options;
  options.duration = 100 * 0.8008322171201989;  // 100 cycles
  options.integrator = "rk4";
  options.step = 1e-3;
  options.every = 1000;
  run_timed(bench, model, options, "events");
}

// The four-bar of examples/constraints/four_bar_on_a_stop.yaml, with its crank's stop or without.
model::Model four_bar(bool stop) {
  std::ifstream in("examples/constraints/four_bar_on_a_stop.yaml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string limits = ",\n     limits: {lower: -0.5, restitution: 0.5}";
  const std::size_t at = text.find(limits);
  if (at == std::string::npos) throw std::runtime_error("four_bar_on_a_stop.yaml: no crank stop");
  if (!stop) text.erase(at, limits.size());
  return io::parse_model_file(text, "four_bar_on_a_stop.yaml", ".").model;
}

void BM_FourBarOnAStop(benchmark::State& bench, bool stop) {
  const model::Model model = four_bar(stop);
  simulate::SimulationOptions options;
  options.duration = 10.0;
  options.integrator = "rk4";
  options.step = 1e-3;
  options.every = 1000;
  run_timed(bench, model, options, "events");
}

// One impact with friction (dynamics::frictional_impact), the rod of examples/falling_rod.yaml
// striking the floor by its lower end at 1.962 m/s (e = 0.5): its course followed where the
// normal and the slip couple — the end sticking (μs 0.5, μk 0.4: the course in closed form),
// sliding from rest (μ 0.2: straight, stepped exactly), its slip turning (a sideways slip of
// 0.5 m/s, μ 0.3: the adaptive integration in p) — beside the frictionless impact
// (dynamics::restitution_impact) of the same state: what following the course costs over the
// three unit impulse solves that find W.
void BM_FrictionalImpact(benchmark::State& bench, double mu_s, double mu_k, double sideways) {
  const model::Model model = io::read_model_file("examples/falling_rod.yaml").model;
  const VecX q = model.initial_q();
  VecX v = VecX::Zero(model.nv());
  v[5] = -9.81 * 0.2;
  v[4] = sideways;
  const dynamics::PointContact end{0, Vec3::Zero(), 1, Vec3(0, 0, -0.5), Vec3::UnitZ()};
  for (auto _ : bench) {
    if (mu_s == 0.0) {
      benchmark::DoNotOptimize(dynamics::restitution_impact(model, q, v, end, 0.5).normal_impulse);
    } else {
      benchmark::DoNotOptimize(
          dynamics::frictional_impact(model, q, v, end, 0.5, mu_s, mu_k).normal_impulse);
    }
  }
}

BENCHMARK_CAPTURE(BM_FrictionalImpact, frictionless, 0.0, 0.0, 0.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_FrictionalImpact, sticking, 0.5, 0.4, 0.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_FrictionalImpact, sliding_from_rest, 0.2, 0.2, 0.0)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_FrictionalImpact, slip_turning, 0.3, 0.3, 0.5)->Unit(benchmark::kMicrosecond);

BENCHMARK_CAPTURE(BM_FourBarOnAStop, rk4_stop, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FourBarOnAStop, rk4_free, false)->Unit(benchmark::kMillisecond);

BENCHMARK_CAPTURE(BM_StickSlip, rk4_belt, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StickSlip, rk4_spring_alone, false)->Unit(benchmark::kMillisecond);

BENCHMARK_CAPTURE(BM_Bounces, rk4_floor, std::string("rk4"), false, true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Bounces, rk4_no_floor, std::string("rk4"), false, false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Bounces, dopri5_floor, std::string("dopri5"), false, true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Bounces, dopri5_no_floor, std::string("dopri5"), false, false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Bounces, rk4_free_contact, std::string("rk4"), true, true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Bounces, rk4_free_no_floor, std::string("rk4"), true, false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Bounces, dopri5_free_contact, std::string("dopri5"), true, true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Bounces, dopri5_free_no_floor, std::string("dopri5"), true, false)
    ->Unit(benchmark::kMillisecond);

}  // namespace
