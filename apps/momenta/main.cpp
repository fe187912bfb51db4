// momenta: model, simulate and analyse mechanical systems from first principles.
//
// Exit codes: 0 success; 1 user error (bad input file, unphysical quantity), message on stderr;
// 2 usage error (unknown option, missing argument).

#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"

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

}  // namespace

int main(int argc, char** argv) {
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
  momenta::cli::add_campbell_command(app);
  momenta::cli::add_steady_command(app);
  momenta::cli::add_kinematics_command(app);
  momenta::cli::add_diagram_command(app);
  momenta::cli::add_equations_command(app);
  momenta::cli::add_sweep_command(app);
  momenta::cli::add_sweep_merge_command(app);

  if (refuse_unknown_command(app, argc, argv)) return 2;
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
    fmt::print(stderr, "momenta: error: {}\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "momenta: internal error: {}\n", e.what());
    return 1;
  }
  return 0;
}
