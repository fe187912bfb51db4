#include "state_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string_view>
#include <system_error>
#include <utility>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/io/state_file.hpp"
#include "momenta/simulate/run_request.hpp"
#include "momenta/simulate/state_at.hpp"
#include "option_checks.hpp"

namespace momenta::cli {

analysis::OperatingPoint read_state_file(const std::string& path, const model::Model& model) {
  const io::StateFile state = io::read_state_file(path, model.nq(), model.nv());
  analysis::OperatingPoint p;
  p.t = state.t;
  p.q = state.q;
  p.v = state.v;
  return p;
}

void add_instant_options(CLI::App* command, InstantOptions& o) {
  CLI::Option* time =
      command
          ->add_option("--time", o.time,
                       "The instant, s: the model run from its initial state to this time with "
                       "its simulation settings (default 0, the initial state)")
          ->check(non_negative_finite());
  command
      ->add_option("--state", o.state,
                   "The instant from a STATE.json file {\"q\": [...], \"v\": [...], \"t\": 0}")
      ->excludes(time);
}

integrate::State instant_of(const io::ModelFile& file, const InstantOptions& o) {
  if (o.state) {
    const analysis::OperatingPoint p = read_state_file(*o.state, file.model);
    return {p.t, p.q, p.v};
  }
  const simulate::ResolvedRun run = simulate::resolve_run({}, file.simulation);
  return simulate::state_at(file.model, o.time.value_or(0.0), run.options);
}

}  // namespace momenta::cli
