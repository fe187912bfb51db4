#include "momenta/model/simulation_settings.hpp"

#include <algorithm>

namespace momenta::model {

SimulationSettings over(const SimulationSettings& top, const SimulationSettings& below) {
  SimulationSettings merged = below;
  if (top.duration) merged.duration = top.duration;
  if (top.step) merged.step = top.step;
  if (top.integrator) merged.integrator = top.integrator;
  if (top.relative_tolerance) merged.relative_tolerance = top.relative_tolerance;
  if (top.absolute_tolerance) merged.absolute_tolerance = top.absolute_tolerance;
  if (top.every) merged.every = top.every;
  for (const EventSpec& event : top.events) {
    const auto same = std::find_if(merged.events.begin(), merged.events.end(),
                                   [&](const EventSpec& e) { return e.name == event.name; });
    if (same != merged.events.end()) {
      *same = event;
    } else {
      merged.events.push_back(event);
    }
  }
  return merged;
}

}  // namespace momenta::model
