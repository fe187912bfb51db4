// `momenta steady MODEL`: steady motions found at conditions of the user's choosing.
//  - A symmetric top (--tilt DEG --spin W): both precession rates, the spin range where they
//    exist, the sleeping top's critical spin, the gyroscopic approximation with its error, the
//    nutation frequencies (analysis/steady_motion.hpp).
//  - A rolling body of revolution (--lean DEG and one of --speed, --radius, --precession,
//    --spin): each steady motion's rates, circle and contact force, and whether a disturbance
//    grows (analysis/rolling_steady_motion.hpp).
// With --state, a state file of a root (for `--about STATE.json`, or a model's initial state).
// Documented in docs/cli.md.

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "commands.hpp"
#include "linear_model_options.hpp"
#include "model_argument.hpp"
#include "momenta/analysis/rolling_steady_motion.hpp"
#include "momenta/analysis/steady_motion.hpp"
#include "momenta/common/error.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "option_checks.hpp"
#include "output_format.hpp"
#include "rolling_steady_output.hpp"

namespace momenta::cli {
namespace {

using json = nlohmann::ordered_json;

struct SteadyOptions {
  ModelArgument model;
  std::optional<double> tilt_deg;
  std::optional<double> spin;  // rad/s
  // A rolling body: its lean and one condition.
  std::optional<double> lean_deg;
  std::optional<double> speed;        // m/s
  std::optional<std::string> radius;  // m, or inf
  std::optional<double> precession;   // rad/s
  bool json = false;
  std::optional<std::string> state;
  std::string root = "slow";
  bool force = false;
};

constexpr double kRadian = std::numbers::pi / 180.0;

json state_json(const analysis::OperatingPoint& p) {
  return {{"q", std::vector<double>(p.q.data(), p.q.data() + p.q.size())},
          {"v", std::vector<double>(p.v.data(), p.v.data() + p.v.size())},
          {"t", p.t}};
}

void write_state_file(const std::string& path, const analysis::OperatingPoint& p,
                      const std::string& root) {
  std::ofstream(path) << json_text(state_json(p)) << "\n";
  fmt::print("state of the {} root written to {} (use it with --about {})\n", root, path, path);
}

// The state on the root asked for, written where --state says (never over a file without
// --force).
void write_state(const SteadyOptions& o, const analysis::FoundPrecession& found) {
  const bool slow = o.root == "slow" || o.root == "1";
  const double rate = slow ? found.roots.slow : found.roots.fast;
  if (!std::isfinite(rate)) {
    throw InvalidArgument(
        fmt::format("no {} steady precession at this tilt and spin{}", o.root,
                    found.roots.minimum_spin > 0.0
                        ? fmt::format(" (it needs ω₃ ≥ {:.6g} rad/s)", found.roots.minimum_spin)
                        : std::string()));
  }
  write_state_file(*o.state, found.states[slow ? 0 : found.states.size() - 1], o.root);
}

void print_text(const io::ModelFile& file, const analysis::SteadyPrecession& r) {
  constexpr double deg = 180.0 / std::numbers::pi;
  fmt::print("{}: steady precession at tilt {:.6g}° and spin ω₃ = {:.6g} rad/s\n", file.name,
             r.tilt * deg, r.spin);
  fmt::print("  I₁ = {:.6g} kg·m², I₃ = {:.6g} kg·m² (about the fixed point), m g l = {:.6g} N·m\n",
             r.I1, r.I3, r.mgl);
  fmt::print("  roots of I₁ cos θ φ̇² − I₃ ω₃ φ̇ + m g l = 0:\n");
  const auto root = [](const char* name, double rate, double nutation) {
    if (std::isfinite(rate)) {
      fmt::print("    {} precession φ̇ = {:.10g} rad/s, nutation about it {:.6g} rad/s\n", name,
                 rate, nutation);
    } else {
      fmt::print("    {} precession: none\n", name);
    }
  };
  root("slow", r.slow, r.slow_nutation);
  root("fast", r.fast, r.fast_nutation);
  // Undefined without spin (a conical pendulum), and without a slow root to compare with.
  if (!std::isfinite(r.gyroscopic)) {
    fmt::print("  gyroscopic approximation m g l/(I₃ ω₃): none without spin (ω₃ = 0)\n");
  } else if (!std::isfinite(r.gyroscopic_error)) {
    fmt::print(
        "  gyroscopic approximation m g l/(I₃ ω₃) = {:.6g} rad/s (no slow root to compare)\n",
        r.gyroscopic);
  } else {
    fmt::print(
        "  gyroscopic approximation m g l/(I₃ ω₃) = {:.6g} rad/s ({:+.3g} % of the slow root)\n",
        r.gyroscopic, 100 * r.gyroscopic_error);
  }
  if (r.minimum_spin > 0.0) {
    fmt::print("  steady precession at this tilt needs ω₃ ≥ 2√(I₁ m g l cos θ)/I₃ = {:.6g} rad/s\n",
               r.minimum_spin);
  } else if (r.mgl == 0.0) {
    fmt::print("  steady precession exists at any spin without a gravity torque (m g l = 0)\n");
  } else {
    fmt::print("  steady precession at this tilt exists at any spin (cos θ ≤ 0)\n");
  }
  if (r.critical_spin > 0.0) {
    fmt::print("  upright (a sleeping top) it is stable above 2√(I₁ m g l)/I₃ = {:.6g} rad/s\n",
               r.critical_spin);
  }
  if (r.tilt == 0.0) {
    fmt::print(
        "  (at θ = 0 the roots are the sleeping top's precession frequencies for a small "
        "tilt)\n");
  }
}

// The one condition a rolling body's steady motion is found at.
struct RollingChoice {
  analysis::RollingCondition condition = analysis::RollingCondition::speed;
  double value = 0.0;
  std::string text;  // "radius 0.5 m"
};

RollingChoice rolling_choice(const SteadyOptions& o) {
  std::vector<RollingChoice> given;
  if (o.speed)
    given.push_back(
        {analysis::RollingCondition::speed, *o.speed, fmt::format("speed {:.10g} m/s", *o.speed)});
  if (o.radius) {
    char* end = nullptr;
    const double r = std::strtod(o.radius->c_str(), &end);
    if (o.radius->empty() || *end != '\0' || std::isnan(r) || r == 0.0 ||
        (std::isfinite(r) && std::abs(r) > 1e100)) {
      throw CLI::ValidationError("--radius", fmt::format("'{}' is not a nonzero length in m (or "
                                                         "inf for a straight line)",
                                                         *o.radius));
    }
    given.push_back(
        {analysis::RollingCondition::radius, r,
         std::isinf(r) ? std::string("a straight line") : fmt::format("radius {:.10g} m", r)});
  }
  if (o.precession)
    given.push_back({analysis::RollingCondition::precession, *o.precession,
                     fmt::format("precession {:.10g} rad/s", *o.precession)});
  if (o.spin)
    given.push_back(
        {analysis::RollingCondition::spin, *o.spin, fmt::format("spin {:.10g} rad/s", *o.spin)});
  if (given.size() != 1) {
    throw CLI::ValidationError(
        "steady", fmt::format("a rolling body's steady motion is found at exactly one of --speed, "
                              "--radius, --precession or --spin ({} given)",
                              given.size()));
  }
  return given.front();
}

void run_rolling(const SteadyOptions& o, const io::ModelFile& file) {
  if (o.tilt_deg) {
    throw CLI::ValidationError("--tilt",
                               "--tilt is a top's; a rolling body takes --lean (the "
                               "disk's plane from the vertical, °)");
  }
  const RollingChoice choice = rolling_choice(o);
  const analysis::RollingBodyInfo info = analysis::rolling_body_info(file.model);
  std::optional<double> lean;
  if (o.lean_deg) lean = *o.lean_deg * kRadian;
  const std::vector<analysis::RollingSteadyMotion> found =
      analysis::find_rolling_steady_motions(file.model, lean, choice.condition, choice.value);
  std::vector<analysis::RollingSteadyModes> modes;
  for (const analysis::RollingSteadyMotion& m : found) {
    modes.push_back(analysis::rolling_steady_modes(file.model, m));
  }
  if (o.json) {
    json j = {{"model", file.name},
              {"body", info.body},
              {"contact", info.contact},
              {"pivoted", info.pivoted},
              {"condition", analysis::rolling_condition_name(choice.condition)},
              {"value", finite_or_null(choice.value)}};
    json motions = json::array();
    for (const analysis::RollingSteadyModes& m : modes) motions.push_back(rolling_motion_json(m));
    j["motions"] = std::move(motions);
    fmt::print("{}\n", json_text(j, ListSpacing::spaced));
  } else {
    fmt::print(
        "{}: steady rolling of '{}' (contact '{}', r = {:.6g} m) {} with {}\n", file.name,
        info.body, info.contact, info.radius,
        info.pivoted ? std::string("on its pivot") : fmt::format("at lean {:.6g}°", *o.lean_deg),
        choice.text);
    fmt::print(
        "  m = {:.6g} kg; about G: I₁ = {:.6g} kg·m² across the axis, I₃ = {:.6g} kg·m² "
        "along it\n",
        info.mass, info.transverse_moment, info.axial_moment);
    if (info.pivoted && !found.empty()) {
      fmt::print("  the pivot and the floor set the lean: {:.6g}°\n", found[0].lean / kRadian);
    }
    if (found.empty()) {
      fmt::print("no steady motion rolls with this {} ({})\n",
                 analysis::rolling_condition_name(choice.condition),
                 info.pivoted ? "on its pivot the centre of mass circles at one radius: give the "
                                "spin or the precession"
                              : "the moment equation about G has no real root");
    }
    const auto count = static_cast<int>(modes.size());
    for (int k = 0; k < count; ++k)
      print_rolling_motion(modes[static_cast<std::size_t>(k)], info.joint, k + 1, count);
  }
  if (o.state) {
    const std::size_t index = (o.root == "slow" || o.root == "1") ? 0 : 1;
    if (index >= found.size()) {
      throw InvalidArgument(
          fmt::format("no {} steady motion here ({} found)", o.root, found.size()));
    }
    std::ofstream(*o.state) << json_text(state_json(found[index].point)) << "\n";
    fmt::print(
        "state of the {} root written to {} (the joint's q0 and v0 above: a model starting there "
        "is analysed by `momenta modes MODEL --about steady`)\n",
        o.root, *o.state);
  }
}

void run(const SteadyOptions& o) {
  if (o.state && std::filesystem::exists(*o.state) && !o.force) {
    throw FileError(
        fmt::format("{}: the state file exists; pass --force to overwrite it", *o.state));
  }
  const io::ModelFile file = load_model(o.model);
  if (analysis::rolling_steady_applies(file.model)) return run_rolling(o, file);
  for (const auto& [given, name] :
       {std::pair{o.lean_deg.has_value(), "--lean"}, std::pair{o.speed.has_value(), "--speed"},
        std::pair{o.radius.has_value(), "--radius"},
        std::pair{o.precession.has_value(), "--precession"}}) {
    if (given) {
      throw CLI::ValidationError(
          name, fmt::format("{} is a rolling body's (one body on a free or spherical joint with a "
                            "rolling disk); this model's steady motion is a top's: --tilt and "
                            "--spin",
                            name));
    }
  }
  if (!o.tilt_deg || !o.spin) {
    throw CLI::ValidationError("steady", "a top's steady precession needs --tilt and --spin");
  }
  const analysis::FoundPrecession found =
      analysis::find_steady_precession(file.model, *o.tilt_deg * kRadian, *o.spin);
  const analysis::SteadyPrecession& r = found.roots;
  if (o.json) {
    json j = {{"model", file.name}};
    j.update(precession_roots_json(r));
    j["critical_spin"] = r.critical_spin;
    json states = json::array();
    for (const analysis::OperatingPoint& p : found.states) states.push_back(state_json(p));
    j["states"] = std::move(states);
    fmt::print("{}\n", json_text(j, ListSpacing::spaced));
  } else {
    print_text(file, r);
  }
  if (o.state) write_state(o, found);
}

}  // namespace

void add_steady_command(CLI::App& app) {
  auto options = std::make_shared<SteadyOptions>();
  CLI::App* command = app.add_subcommand(
      "steady",
      "Steady motions at conditions you choose: a symmetric top's precessions at a tilt and spin "
      "(both rates, where they exist, the critical spin, the gyroscopic approximation, the "
      "nutation frequencies), or a rolling disk's steady circle at a lean and a speed, radius, "
      "precession or spin (its rates, circle, contact force and stability)");
  add_model_argument(command, options->model,
                     "A model file: one body on a spherical joint, symmetric about the axis "
                     "through its centre of mass (a top); or one body of revolution on a free or "
                     "spherical joint with a rolling disk on a level floor");
  command
      ->add_option("--tilt", options->tilt_deg,
                   "A top: tilt of its axis from the upward vertical, °")
      ->check(finite_within(0.0, 180.0));
  command->add_option("--spin", options->spin, "Spin ω·e about the axis, rad/s (a top: ω₃)")
      ->check(finite());
  command
      ->add_option("--lean", options->lean_deg,
                   "A free rolling body: its disk's plane from the vertical, ° (> 0 leaning to "
                   "the lateral side, into a turn of positive radius)")
      ->check(finite_within(-90.0, 90.0));
  command->add_option("--speed", options->speed, "A rolling body: its centre of mass's speed, m/s")
      ->check(finite());
  command->add_option("--radius", options->radius,
                      "A rolling body: the radius of its centre of mass's circle, m (inf: a "
                      "straight line)");
  command
      ->add_option("--precession", options->precession,
                   "A rolling body: its turning rate Ω about the vertical, rad/s")
      ->check(finite());
  command->add_flag("--json", options->json, "Print JSON (with both states) instead of text");
  command
      ->add_option("--state", options->state,
                   "Write the state {q, v, t} of the top precessing on --root to this file (for "
                   "--about FILE); never over a file without --force")
      ->check(not_a_folder());
  command->add_option("--root", options->root, "slow (default) or fast (also 1 or 2)")
      ->check(CLI::IsMember({"slow", "fast", "1", "2"}));
  command->add_flag("--force", options->force, "Overwrite the --state file if it exists");
  command->footer(
      "Examples:\n"
      "  momenta steady examples/heavy_top.yaml --tilt 20 --spin 300\n"
      "  momenta steady examples/constraints/rolling_coin.yaml --lean 20 --radius 0.5\n"
      "  momenta steady examples/constraints/rolling_disk_on_axle.yaml --spin 20\n"
      "The model's own initial state is analysed by `momenta modes MODEL --about steady` "
      "(docs/analysis.md).");
  command->callback([options] { run(*options); });
}

}  // namespace momenta::cli
