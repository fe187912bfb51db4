#include "state_file.hpp"

#include <algorithm>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "momenta/common/error.hpp"
#include "momenta/simulate/run_request.hpp"
#include "momenta/simulate/state_at.hpp"
#include "option_checks.hpp"

namespace momenta::cli {

using json = nlohmann::ordered_json;

analysis::OperatingPoint read_state_file(const std::string& path, const model::Model& model) {
  std::ifstream in(path);
  if (!in) throw FileError(fmt::format("{}: cannot open the state file", path));
  json j;
  try {
    j = json::parse(in);
  } catch (const json::exception& e) {
    // Malformed text, or a number beyond double precision ("t": 1e400).
    throw InvalidArgument(fmt::format("{}: not a valid state file: {}", path, e.what()));
  }
  if (!j.is_object()) {
    throw InvalidArgument(
        fmt::format("{}: expected an object {{\"q\": [...], \"v\": [...]}}", path));
  }
  for (const auto& [key, value] : j.items()) {
    if (key != "q" && key != "v" && key != "t") {
      throw InvalidArgument(
          fmt::format("{}: unknown key '{}' (expected q, v and optionally t)", path, key));
    }
  }
  const auto vector = [&](const char* key, int size) {
    if (!j.contains(key)) {
      throw InvalidArgument(fmt::format("{}: missing '{}' ({} numbers)", path, key, size));
    }
    const json& a = j.at(key);
    if (!a.is_array() || static_cast<int>(a.size()) != size ||
        !std::all_of(a.begin(), a.end(), [](const json& x) { return x.is_number(); })) {
      throw InvalidArgument(
          fmt::format("{}: '{}' must be a list of {} numbers (the model's {}); "
                      "got {}",
                      path, key, size, key[0] == 'q' ? "nq" : "nv", a.dump()));
    }
    VecX x(size);
    for (int i = 0; i < size; ++i) x[i] = a.at(static_cast<std::size_t>(i)).get<double>();
    return x;
  };
  analysis::OperatingPoint p;
  p.q = vector("q", model.nq());
  p.v = vector("v", model.nv());
  if (j.contains("t")) {
    if (!j.at("t").is_number())
      throw InvalidArgument(fmt::format("{}: 't' must be a number", path));
    p.t = j.at("t").get<double>();
  }
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
