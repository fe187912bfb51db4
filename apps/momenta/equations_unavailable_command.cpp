// `momenta equations` in a build without the symbolic layer (MOMENTA_WITH_SYMBOLIC=OFF): GiNaC and
// CLN are GPL-2.0-or-later, so a build may leave them out; the command then says so and how to
// get it, instead of being an unknown word.

#include <string>
#include <vector>

#include "commands.hpp"
#include "momenta/common/error.hpp"

namespace momenta::cli {

void add_equations_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "equations", "Equations of motion in symbols (not in this build: MOMENTA_WITH_SYMBOLIC=OFF)");
  command->allow_extras();
  command->callback([] {
    throw Error(
        "momenta equations needs the symbolic layer, which this build leaves out "
        "(-DMOMENTA_WITH_SYMBOLIC=OFF: it links GiNaC and CLN, GPL-2.0-or-later; "
        "THIRD-PARTY-NOTICES.md). Rebuild with -DMOMENTA_WITH_SYMBOLIC=ON to have it.");
  });
}

}  // namespace momenta::cli
