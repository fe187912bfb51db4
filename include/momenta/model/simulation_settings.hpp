#pragma once
// How a model asks to be run: the `simulation:` section of a model file, defaults that the
// command line's options override. A description only; simulate::SimulationOptions is what a run
// uses once the two are merged.

#include <optional>
#include <string>
#include <vector>

#include "momenta/model/event_spec.hpp"

namespace momenta::model {

struct SimulationSettings {
  std::optional<double> duration;         ///< s, > 0
  std::optional<double> step;             ///< fixed step, or an adaptive method's largest, s
  std::optional<std::string> integrator;  ///< a name of model::integrators() (integrators.hpp)
  std::optional<double> relative_tolerance;
  std::optional<double> absolute_tolerance;
  std::optional<long> every;      ///< record every n-th step
  std::vector<EventSpec> events;  ///< conditions the run watches (event_spec.hpp)
  /// Where the file writes each event (1-based line and column), for messages about it.
  struct Position {
    int line = 0, column = 0;
  };
  std::vector<Position> event_positions;
  /// Where the file writes the section, its duration and its step (0: not written), for a run
  /// refused for them (a step below time's resolution at the duration).
  Position position, duration_position, step_position;
};

/// `top` over `below`, one value over another: each of top's fields where it is set, else below's;
/// the events below's, then top's (one of top's named like one of below's replaces it, keeping
/// its place). The positions are below's (a file's, for messages).
SimulationSettings over(const SimulationSettings& top, const SimulationSettings& below);

}  // namespace momenta::model
