#pragma once
// Drives an integrator from t0 to t_end, reports states to an observer, and stops with a clear
// error when the state stops being finite.

#include <functional>

#include "momenta/integrate/integrator.hpp"

namespace momenta::integrate {

/// The most steps one run may take (grid steps and steps cut short on input discontinuities):
/// about an hour of a small model, and far beyond any sensible run; more is refused up front when
/// it can be foreseen (run), stopped with NumericalError when not.
inline constexpr double kMaxRunSteps = 1e9;

/// An adaptive run whose steps, this many in a row, each advance it by less than
/// kCrawlingStep of its span crawls: together they cover a millionth of it at most, and at that
/// pace the run would not end (a step size held down by a discontinuous or nearly singular right
/// side, not by the motion). It is stopped with NumericalError naming the time and the step.
inline constexpr long kCrawlingSteps = 10000;
inline constexpr double kCrawlingStep = 1e-10;

struct RunOptions {
  double t_end = 0.0;  ///< final time, s (> state.t)
  double h = 0.0;      ///< fixed step, or the largest step of an adaptive method, s (> 0)
  long every = 1;      ///< report every `every`-th step (the first and last states always)
  /// When set, the run ends as soon as the observer has made it true (an event that stops the
  /// run): run() returns after that call, with `state` at the step the observer was handed.
  const bool* finished = nullptr;
  /// When set, the observer may replace the state it is handed (the caller's `state`, which it
  /// holds by reference) by an earlier one inside the step just taken — a stop's impact located
  /// there — and make this true: run() then clears it, tells the integrator
  /// (Integrator::state_changed) and steps again to the same grid time.
  bool* restarted = nullptr;
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
/// keep their order across a step or a pulse. Adaptive methods take steps of at most h and end a
/// step exactly on the grid t0 + n h when they reach it. Throws InvalidArgument for a bad option:
/// a step below the resolution of time, or a run foreseen to take more than kMaxRunSteps steps
/// (the grid, plus one per input discontinuity, estimated from the first 10⁴ of them); and
/// NumericalError naming the time, the first non-finite coordinate and a hint when the state
/// stops being finite, or when a run passes kMaxRunSteps steps after all.
/// The checks run() makes before its first step (the options, the foreseen step count), on their
/// own: a front end calls it before it opens an output, so a refused run leaves no file behind.
/// Throws InvalidArgument as run() does.
void check_run(const SecondOrderSystem& system, const Integrator& integrator, const State& state,
               const RunOptions& options);

RunSummary run(SecondOrderSystem& system, Integrator& integrator, State& state,
               const RunOptions& options, const std::function<void(const State&)>& observer);

}  // namespace momenta::integrate
