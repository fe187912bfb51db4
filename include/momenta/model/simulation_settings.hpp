#pragma once
// How a model asks to be run: the `simulation:` section of a model file, defaults that the
// command line's options override. A description only; simulate::SimulationOptions is what a run
// uses once the two are merged.

#include <optional>
#include <string>

namespace momenta::model {

struct SimulationSettings {
  std::optional<double> duration;         ///< s, > 0
  std::optional<double> step;             ///< fixed step, or an adaptive method's largest, s
  std::optional<std::string> integrator;  ///< a name of model::integrators() (integrators.hpp)
  std::optional<double> relative_tolerance;
  std::optional<double> absolute_tolerance;
  std::optional<long> every;  ///< record every n-th step
};

}  // namespace momenta::model
