// momenta: model, simulate and analyse mechanical systems from first principles.
//
// Exit codes: 0 success; 1 user error (bad input file, unphysical quantity), message on stderr;
// 2 usage error (unknown option, missing argument).

#include <exception>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "momenta/common/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "momenta — model, simulate and analyse mechanical systems from first principles.\n"
      "Run `momenta <command> --help` for a command's options and an example."};
  app.require_subcommand(1);
  momenta::cli::add_version_command(app);
  momenta::cli::add_inertia_command(app);
  momenta::cli::add_simulate_command(app);
  momenta::cli::add_info_command(app);
  momenta::cli::add_linearize_command(app);
  momenta::cli::add_modes_command(app);
  momenta::cli::add_response_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const momenta::Error& e) {
    fmt::print(stderr, "momenta: error: {}\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "momenta: internal error: {}\n", e.what());
    return 1;
  }
  return 0;
}
