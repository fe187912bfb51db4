#include "momenta/simulate/run_request.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/integrate/integrator.hpp"
#include "momenta/model/integrators.hpp"

namespace momenta::simulate {
namespace {

// Tolerances without an integrator ask for an adaptive one: from the caller they override a
// fixed-step integrator the file names; in the file they choose one when it names none.
std::string choose_integrator(const model::SimulationSettings& request,
                              const model::SimulationSettings& file) {
  if (request.integrator) return *request.integrator;
  const bool tolerances_given = request.relative_tolerance || request.absolute_tolerance;
  const bool file_adaptive = file.integrator && model::integrator_info(*file.integrator).adaptive;
  if (tolerances_given && !file_adaptive) return "dopri5";
  if (file.integrator) return *file.integrator;
  return file.relative_tolerance || file.absolute_tolerance ? "dopri5" : "rk4";
}

}  // namespace

ResolvedRun resolve_run(const RunRequest& request, const model::SimulationSettings& file) {
  const model::SimulationSettings& asked = request.settings;
  const model::SimulationSettings merged = model::over(asked, file);
  ResolvedRun resolved;
  SimulationOptions& s = resolved.options;
  s.duration = merged.duration.value_or(s.duration);
  s.tolerances.relative = merged.relative_tolerance.value_or(s.tolerances.relative);
  s.tolerances.absolute = merged.absolute_tolerance.value_or(s.tolerances.absolute);
  s.integrator = choose_integrator(asked, file);

  const bool adaptive = model::integrator_info(s.integrator).adaptive;
  if ((asked.relative_tolerance || asked.absolute_tolerance) && !adaptive) {
    throw InvalidArgument(OptionMessage{fmt::format(
        "‹{}› applies to adaptive integrators (dopri5, bdf); ‹integrator={}› takes a fixed "
        "step (‹step›)",
        asked.relative_tolerance ? "relative_tolerance" : "absolute_tolerance", s.integrator)});
  }
  // The tolerances' values, checked where they are chosen (the integrator checks them again).
  if (adaptive) integrate::check_tolerances(s.integrator, s.tolerances);

  const double default_step = adaptive ? s.duration / kAdaptiveSteps : s.step;
  s.step = merged.step.value_or(default_step);
  s.every = merged.every.value_or(s.every);
  if (!merged.every && !adaptive) {
    const double steps = std::ceil(s.duration / s.step);
    if (steps > kDefaultRows && steps < 1e18) {
      s.every = static_cast<long>(std::ceil(steps / kDefaultRows));
      resolved.thinning_note =
          fmt::format("recording one row every {} of {:.0f} steps ({} rows)", s.every, steps,
                      static_cast<long>(std::ceil(steps / s.every)) + 1);
    }
  }
  s.reactions = request.reactions;
  s.events = merged.events;
  return resolved;
}

}  // namespace momenta::simulate
