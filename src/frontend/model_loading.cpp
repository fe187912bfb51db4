#include "momenta/frontend/model_loading.hpp"

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/simulate/event_monitor.hpp"
#include "momenta/system/multibody_system.hpp"

namespace momenta::frontend {

void accept_model(const io::ModelFile& file) {
  try {
    system::check_simulable(file.model);
  } catch (const Error& e) {
    if (auto located = file.locate(e)) throw *located;
    throw;
  }
  // Each event of `simulation:` watches a quantity the run has (known once the outputs are).
  const model::SimulationSettings& s = file.simulation;
  for (std::size_t i = 0; i < s.events.size(); ++i) {
    try {
      simulate::check_event(file.model, file.outputs, s.events[i]);
    } catch (const InvalidArgument& e) {
      const model::SimulationSettings::Position& at = s.event_positions[i];
      throw ParseError(file.file, at.line, at.column,
                       fmt::format("simulation.events[{}]: {}", i, e.what()));
    }
  }
}

io::ModelFile load_model(const std::filesystem::path& path, const io::ModelFileOptions& options) {
  io::ModelFile file = io::read_model_file(path, options);
  accept_model(file);
  return file;
}

}  // namespace momenta::frontend
