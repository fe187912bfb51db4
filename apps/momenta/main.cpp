// momenta: model, simulate and analyse mechanical systems from first principles.
//
// Exit codes: 0 success; 1 user error (bad input file, unphysical quantity), message on stderr;
// 2 usage error (unknown option, missing argument).

#include <exception>
#include <filesystem>
#include <new>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "interrupt.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "option_spelling.hpp"
#include "stable_addresses.hpp"

namespace {

// `momenta simulat ...`: CLI11 would only say that a subcommand is required. Names the word it
// did not know, the nearest command and every command.
bool refuse_unknown_command(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return false;
  const std::string_view word = argv[1];
  std::vector<std::string> names;
  for (const CLI::App* command : app.get_subcommands({})) names.push_back(command->get_name());
  for (const std::string& name : names) {
    if (name == word) return false;
  }
  const std::vector<std::string_view> candidates(names.begin(), names.end());
  fmt::print(
      stderr,
      "momenta: unknown command '{}'{}; commands: {}\nRun with --help for more information.\n",
      word, momenta::did_you_mean(word, candidates), fmt::join(names, ", "));
  return true;
}

// Bare `momenta`: what each command is for, one line each, in the order a user meets them. The
// CLI test checks that every command is listed here (and nothing else).
constexpr std::pair<std::string_view, std::string_view> kCommandSummaries[] = {
    {"inertia", "mass, centre of mass, inertia tensor and principal axes of a part or mesh"},
    {"balance", "a rotor's unbalance, bearing forces and correction masses"},
    {"info", "what a model file holds: freedoms, bodies, joints, forces, signals"},
    {"simulate", "integrate a model: CSV rows, summary and conservation audit"},
    {"report", "simulate and write one offline HTML page: 3-D motion, plots, analysis"},
    {"linearize", "state space A, B, C, D about an operating point"},
    {"modes", "eigenvalues, natural frequencies, damping ratios, mode shapes"},
    {"response", "step, impulse or Bode response of one input-output pair"},
    {"lqr", "linear-quadratic regulator: state-feedback gain K and closed-loop poles"},
    {"place", "pole placement: the state-feedback gain K for the closed-loop poles asked"},
    {"campbell", "a rotor's whirl frequencies against spin speed; critical speeds"},
    {"steady", "steady precession of a symmetric top"},
    {"kinematics", "a point's motion seen from a rotating body's frame"},
    {"impact", "impulse and momentum: speeds after an impulse, the joints' impulses"},
    {"diagram", "a body's free-body and kinetic diagrams (SVG)"},
    {"equations", "equations of motion in symbols, LaTeX or generated code"},
    {"export", "write a model as MJCF (MuJoCo) or URDF (ROS)"},
    {"identify", "a robot's inertial parameters from measured motion and efforts"},
    {"sweep", "a parameter grid or Monte Carlo study, one CSV row per run"},
    {"sweep-merge", "join the shards of a sweep into one results file"},
    {"version", "print momenta's version"},
};

void print_command_list() {
  fmt::print("momenta {} — model, simulate and analyse mechanical systems.\n\n", MOMENTA_VERSION);
  fmt::print("Usage: momenta <command> [options]\n\nCommands:\n");
  for (const auto& [name, summary] : kCommandSummaries) fmt::print("  {:<12} {}\n", name, summary);
  fmt::print(
      "\nRun `momenta <command> --help` for a command's options and an example, e.g.\n"
      "  momenta simulate examples/pendulum.yaml -o run.csv\n"
      "The manual: docs/cli.md.\n");
}

}  // namespace

int main(int argc, char** argv) {
  // First of all: a stop asked for while the command line is parsed or the model read is kept
  // for the run, not lost (apps/momenta/interrupt.hpp).
  if (argc > 1 && momenta::cli::stops_on_request(argv[1])) momenta::cli::stop_on_signals();
  CLI::App app{
      "momenta — model, simulate and analyse mechanical systems from first principles.\n"
      "Run `momenta <command> --help` for a command's options and an example."};
  app.require_subcommand(1);
  app.set_version_flag("--version", fmt::format("momenta {}", MOMENTA_VERSION));
  momenta::cli::add_version_command(app);
  momenta::cli::add_inertia_command(app);
  momenta::cli::add_balance_command(app);
  momenta::cli::add_simulate_command(app);
  momenta::cli::add_report_command(app);
  momenta::cli::add_info_command(app);
  momenta::cli::add_linearize_command(app);
  momenta::cli::add_modes_command(app);
  momenta::cli::add_response_command(app);
  momenta::cli::add_lqr_command(app);
  momenta::cli::add_place_command(app);
  momenta::cli::add_campbell_command(app);
  momenta::cli::add_steady_command(app);
  momenta::cli::add_kinematics_command(app);
  momenta::cli::add_impact_command(app);
  momenta::cli::add_diagram_command(app);
  momenta::cli::add_export_command(app);
  momenta::cli::add_identify_command(app);
  momenta::cli::add_equations_command(app);  // without MOMENTA_WITH_SYMBOLIC: says how to get it
  momenta::cli::add_sweep_command(app);
  momenta::cli::add_sweep_merge_command(app);

  if (argc == 1) {
    print_command_list();
    return 0;
  }
  if (refuse_unknown_command(app, argc, argv)) return 2;
  if (std::string_view(argv[1]) == "equations") momenta::cli::run_with_stable_addresses(argv);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const momenta::cli::QuietExit& e) {
    return e.code;
  } catch (const momenta::Interrupted& e) {
    fmt::print(stderr, "momenta: {}\n", e.what());
    return 130;
  } catch (const momenta::Error& e) {
    fmt::print(stderr, "momenta: error: {}\n", e.spelled(momenta::cli::command_line_spelling));
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {
    // A path the system refuses (a name too long, a folder without permission): its words, not
    // the library's "filesystem error: status: …".
    fmt::print(stderr, "momenta: error: {}: {}\n", e.path1().string(), e.code().message());
    return 1;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr,
               "momenta: error: out of memory: the problem asked for is larger than this "
               "machine holds (fewer points, samples or a shorter run)\n");
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "momenta: internal error: {}\n", e.what());
    return 1;
  }
  return 0;
}
