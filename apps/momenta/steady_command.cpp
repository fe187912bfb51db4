// `momenta steady MODEL --tilt DEG --spin W`: the steady precessions of a symmetric top at a tilt
// and spin of the user's choosing — both precession rates, the spin range where they exist, the
// sleeping top's critical spin, the gyroscopic approximation with its error, the nutation
// frequencies — and, with --state, a state file of the top precessing on a root (for `--about
// STATE.json`). Calls momenta::analysis (steady_motion.hpp); documented in docs/cli.md.

#include <cmath>
#include <fstream>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "commands.hpp"
#include "linear_model_options.hpp"
#include "momenta/analysis/steady_motion.hpp"
#include "momenta/common/error.hpp"
#include "momenta/frontend/model_loading.hpp"
#include "option_checks.hpp"
#include "output_format.hpp"

namespace momenta::cli {
namespace {

using json = nlohmann::ordered_json;

struct SteadyOptions {
  std::string model;
  double tilt_deg = 0.0;
  double spin = 0.0;  // rad/s
  bool json = false;
  std::optional<std::string> state;
  std::string root = "slow";
  bool force = false;
};

json state_json(const analysis::OperatingPoint& p) {
  return {{"q", std::vector<double>(p.q.data(), p.q.data() + p.q.size())},
          {"v", std::vector<double>(p.v.data(), p.v.data() + p.v.size())},
          {"t", p.t}};
}

// The state on the root asked for, written where --state says (never over a file without
// --force).
void write_state(const SteadyOptions& o, const analysis::FoundPrecession& found) {
  const bool slow = o.root == "slow";
  const double rate = slow ? found.roots.slow : found.roots.fast;
  if (!std::isfinite(rate)) {
    throw InvalidArgument(
        fmt::format("no {} steady precession at this tilt and spin{}", o.root,
                    found.roots.minimum_spin > 0.0
                        ? fmt::format(" (it needs ω₃ ≥ {:.6g} rad/s)", found.roots.minimum_spin)
                        : std::string()));
  }
  const analysis::OperatingPoint& p = found.states[slow ? 0 : found.states.size() - 1];
  std::ofstream(*o.state) << json_text(state_json(p)) << "\n";
  fmt::print("state of the {} root written to {} (use it with --about {})\n", o.root, *o.state,
             *o.state);
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

void run(const SteadyOptions& o) {
  if (o.state && std::filesystem::exists(*o.state) && !o.force) {
    throw FileError(
        fmt::format("{}: the state file exists; pass --force to overwrite it", *o.state));
  }
  const io::ModelFile file = frontend::load_model(o.model);
  const analysis::FoundPrecession found =
      analysis::find_steady_precession(file.model, o.tilt_deg * std::numbers::pi / 180.0, o.spin);
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
      "Steady precessions of a symmetric top at a tilt and spin: both precession rates, where "
      "they exist, the critical spin, the gyroscopic approximation, the nutation frequencies");
  command
      ->add_option("MODEL", options->model,
                   "A model file: one body on a spherical joint, symmetric about the axis "
                   "through its centre of mass")
      ->required();
  command->add_option("--tilt", options->tilt_deg, "Tilt of the axis from the upward vertical, °")
      ->required()
      ->check(finite_within(0.0, 180.0));
  command->add_option("--spin", options->spin, "Spin ω₃ about the axis, rad/s")
      ->required()
      ->check(finite());
  command->add_flag("--json", options->json, "Print JSON (with both states) instead of text");
  command
      ->add_option("--state", options->state,
                   "Write the state {q, v, t} of the top precessing on --root to this file (for "
                   "--about FILE); never over a file without --force")
      ->check(not_a_folder());
  command->add_option("--root", options->root, "slow (default) or fast")
      ->check(CLI::IsMember({"slow", "fast"}));
  command->add_flag("--force", options->force, "Overwrite the --state file if it exists");
  command->footer(
      "Example:\n"
      "  momenta steady examples/heavy_top.yaml --tilt 20 --spin 300\n"
      "The model's own initial state is analysed by `momenta modes MODEL --about steady` "
      "(docs/analysis.md).");
  command->callback([options] { run(*options); });
}

}  // namespace momenta::cli
