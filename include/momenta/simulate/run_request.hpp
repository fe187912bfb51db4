#pragma once
// How a front end (the command line, Python) asks for a run on top of a model file's
// `simulation:` section: what it gives overrides the file, and what neither gives takes the
// defaults. The one place those rules live (docs/cli.md, "simulate").

#include <optional>
#include <string>
#include <vector>

#include "momenta/model/simulation_settings.hpp"
#include "momenta/simulate/simulation.hpp"

namespace momenta::simulate {

/// What the caller asks for: a run's settings, as a model file's `simulation:` section says them
/// (the fields it leaves unset fall back to the file's, then to the defaults; its events are
/// watched besides the file's, one named like a file's replacing it — `--stop-when` on a
/// condition the file records), and what only a request has.
struct RunRequest {
  model::SimulationSettings settings;
  bool reactions = false;  ///< record each joint's reaction
};

/// Adaptive methods without a step given take at most duration / kAdaptiveSteps per step, so a
/// table has at least that many rows.
inline constexpr double kAdaptiveSteps = 1000.0;

/// Without `every` from the caller or the file, a fixed-step run records at most this many
/// steps plus the first and the last (the double pendulum's 100 s at 1 ms would otherwise be a
/// 55 MB table). The rows recorded are exact states.
inline constexpr double kDefaultRows = 10000.0;

/// The options a run uses, and what the caller should be told about them.
struct ResolvedRun {
  SimulationOptions options;
  /// Non-empty when the default row stride thinned a long run: "recording one row every 20 of
  /// 200000 steps (10001 rows)".
  std::string thinning_note;
};

/// Merges `request` over `file` over the defaults:
///  - the integrator: the request's; else dopri5 when the request gives a tolerance and the file
///    names no adaptive integrator; else the file's; else dopri5 when the file gives a tolerance;
///    else rk4;
///  - the step: the request's, the file's, or 1 ms (an adaptive method: duration / 1000);
///  - every: the request's, the file's, or 1, thinned to keep kDefaultRows rows of a fixed-step
///  run;
///  - events: the file's, then the request's (which replace the file's of the same name).
/// Throws InvalidArgument for an unknown integrator (with the known names), and when the request
/// gives a tolerance for a fixed-step integrator (naming it). Checks of the values themselves
/// (positive, finite) are Simulation's.
ResolvedRun resolve_run(const RunRequest& request, const model::SimulationSettings& file);

}  // namespace momenta::simulate
