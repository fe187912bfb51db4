// `momenta version`: prints the version the binary was built as.

#include <fmt/format.h>

#include "commands.hpp"

namespace momenta::cli {

void add_version_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("version", "Print momenta's version");
  command->callback([] { fmt::print("momenta {}\n", MOMENTA_VERSION); });
}

}  // namespace momenta::cli
