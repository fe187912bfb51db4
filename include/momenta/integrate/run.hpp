#pragma once
// Drives an integrator from t0 to t_end, reports states to an observer, and stops with a clear
// error when the state stops being finite.

#include <functional>

#include "momenta/integrate/integrator.hpp"

namespace momenta::integrate {

struct RunOptions {
  double t_end = 0.0;  ///< final time, s (> state.t)
  double h = 0.0;      ///< fixed step, or the largest step of an adaptive method, s (> 0)
  long every = 1;      ///< report every `every`-th step (the first and last states always)
};

struct RunSummary {
  IntegratorStatistics statistics;
  double wall_seconds = 0.0;
};

/// Advances `state` to options.t_end with `integrator` (which this initializes), calling
/// observer(state) at the start, after every options.every-th step, and at the end. Fixed-step
/// methods take steps of exactly h (the last one shorter when h does not divide the interval;
/// times are t0 + k h, not accumulated sums). No step straddles a discontinuity of the system's
/// inputs (SecondOrderSystem::next_discontinuity): a step is cut short to end on it — for a fixed
/// step method that extra step is not counted for `every` and not reported — so that the methods
/// keep their order across a step or a pulse. Throws InvalidArgument for a bad option, and
/// NumericalError naming the time, the first non-finite coordinate and a hint when the state
/// stops being finite.
RunSummary run(SecondOrderSystem& system, Integrator& integrator, State& state,
               const RunOptions& options, const std::function<void(const State&)>& observer);

}  // namespace momenta::integrate
