#include "momenta/simulate/run_request.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/model/integrators.hpp"
#include "momenta/system/integrators.hpp"

namespace momenta::simulate {
namespace {

// Tolerances without an integrator ask for an adaptive one: from the caller they override a
// fixed-step integrator the file names; in the file they choose one when it names none.
std::string choose_integrator(const RunRequest& request, const model::SimulationSettings& file) {
  if (request.integrator) return *request.integrator;
  const bool tolerances_given = request.relative_tolerance || request.absolute_tolerance;
  const bool file_adaptive = file.integrator && model::integrator_info(*file.integrator).adaptive;
  if (tolerances_given && !file_adaptive) return "dopri5";
  if (file.integrator) return *file.integrator;
  return file.relative_tolerance || file.absolute_tolerance ? "dopri5" : "rk4";
}

}  // namespace

ResolvedRun resolve_run(const RunRequest& request, const model::SimulationSettings& file) {
  ResolvedRun resolved;
  SimulationOptions& s = resolved.options;
  s.duration = request.duration.value_or(file.duration.value_or(s.duration));
  s.tolerances.relative =
      request.relative_tolerance.value_or(file.relative_tolerance.value_or(s.tolerances.relative));
  s.tolerances.absolute =
      request.absolute_tolerance.value_or(file.absolute_tolerance.value_or(s.tolerances.absolute));
  s.integrator = choose_integrator(request, file);

  const std::unique_ptr<integrate::Integrator> probe =
      system::make_integrator(s.integrator, s.tolerances);
  if ((request.relative_tolerance || request.absolute_tolerance) && !probe->adaptive()) {
    throw InvalidArgument(fmt::format(
        "{} applies to adaptive integrators (dopri5, bdf); '{}' takes a fixed step",
        request.relative_tolerance ? "the relative tolerance" : "the absolute tolerance",
        s.integrator));
  }

  const double default_step = probe->adaptive() ? s.duration / kAdaptiveSteps : s.step;
  s.step = request.step.value_or(file.step.value_or(default_step));
  s.every = request.every.value_or(file.every.value_or(s.every));
  if (!request.every && !file.every && !probe->adaptive()) {
    const double steps = std::ceil(s.duration / s.step);
    if (steps > kDefaultRows && steps < 1e18) {
      s.every = static_cast<long>(std::ceil(steps / kDefaultRows));
      resolved.thinning_note =
          fmt::format("recording one row every {} of {:.0f} steps ({} rows)", s.every, steps,
                      static_cast<long>(std::ceil(steps / s.every)) + 1);
    }
  }
  s.reactions = request.reactions;
  s.events = file.events;
  for (const model::EventSpec& event : request.events) {
    const auto same = std::find_if(s.events.begin(), s.events.end(),
                                   [&](const model::EventSpec& e) { return e.name == event.name; });
    if (same != s.events.end()) {
      *same = event;  // the caller's action for the file's condition
    } else {
      s.events.push_back(event);
    }
  }
  return resolved;
}

}  // namespace momenta::simulate
