#include "momenta/integrate/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::integrate {

namespace {

void check_options(const State& state, const RunOptions& options) {
  if (!std::isfinite(state.t) || !(options.t_end > state.t) || !std::isfinite(options.t_end)) {
    throw InvalidArgument(fmt::format("the final time {} s must be finite and after the start {} s",
                                      options.t_end, state.t));
  }
  if (!(options.h > 0.0) || !std::isfinite(options.h)) {
    throw InvalidArgument(
        fmt::format("the step size must be positive and finite, got {} s", options.h));
  }
  if (options.every < 1) {
    throw InvalidArgument(
        fmt::format("the output interval must be at least 1 step, got {}", options.every));
  }
  if (options.t_end + options.h == options.t_end || state.t + options.h == state.t) {
    throw InvalidArgument(OptionMessage{fmt::format(
        "the step {:.3g} s is below the resolution of time at t = {:.6g} s (double precision "
        "holds about 16 digits): no step would advance it; take a larger ‹step› or a shorter "
        "‹duration›",
        options.h, options.t_end)});
  }
}

// The input discontinuities in (t, t_end): counted when there are at most `limit`, else
// extrapolated from the rate of the first `limit` of them (a pulse train of tiny period).
double count_breakpoints(const SecondOrderSystem& system, double t, double t_end, long limit) {
  long n = 0;
  double first = t, last = t;
  for (double b = system.next_discontinuity(t); b < t_end; b = system.next_discontinuity(b)) {
    if (!(b > last)) break;  // a signal that does not advance: left to the run's own guard
    if (n == 0) first = b;
    last = b;
    if (++n == limit) return n * (t_end - first) / std::max(last - first, 1e-300);
  }
  return static_cast<double>(n);
}

// Refuses a run whose step count is absurd before it starts, with the estimate: the grid steps
// of a fixed-step method plus one step per input discontinuity (extrapolated from the first
// ones when there are many: a pulse train of tiny width and period).
void check_step_budget(const SecondOrderSystem& system, const Integrator& integrator,
                       const State& state, const RunOptions& options) {
  const double span = options.t_end - state.t;
  const double grid_steps = integrator.adaptive() ? 0.0 : std::ceil(span / options.h);
  const double breakpoints = count_breakpoints(system, state.t, options.t_end, 10000);
  const double steps = grid_steps + breakpoints;
  if (steps > kMaxRunSteps) {
    throw InvalidArgument(OptionMessage{fmt::format(
        "this run would take about {:.3g} steps ({:.3g} of {:.3g} s{}), more than the {:.0e} a run "
        "may take: shorten the ‹duration›, lengthen the ‹step›{}",
        steps, grid_steps, options.h,
        breakpoints > 0 ? fmt::format(", plus {:.3g} input discontinuities", breakpoints) : "",
        kMaxRunSteps, breakpoints > grid_steps ? ", or widen the input's pulses" : "")});
  }
}

// Throws naming the first non-finite coordinate, what the last step was, and what to try.
void check_finite(const SecondOrderSystem& system, const Integrator& integrator, const State& state,
                  double h) {
  if (state.q.allFinite() && state.v.allFinite()) return;
  const bool in_q = !state.q.allFinite();
  const VecX& x = in_q ? state.q : state.v;
  int i = 0;
  while (std::isfinite(x[i])) ++i;
  throw NumericalError(OptionMessage{fmt::format(
      "the state became non-finite at t = {:.9g} s: {} = {} after a {} step of {:.3g} s. The step "
      "may be too large for the fastest motion (try a smaller ‹step›, or ‹integrator=dopri5›; "
      "‹integrator=bdf› for a stiff model), or the model may be singular or stiff there",
      state.t, system.coordinate_name(i, !in_q), x[i], integrator.name(), h)});
}

// Throws for a run whose last kCrawlingSteps steps each advanced it by less than kCrawlingStep of
// its span.
[[noreturn]] void throw_crawling(const Integrator& integrator, const State& state, double t_before,
                                 double h, double t_end) {
  throw NumericalError(OptionMessage{fmt::format(
      "the run crawls at t = {:.12g} s of {:.6g} s: {}'s last {} steps each advanced it by less "
      "than {:.0e} of its span (the last by {:.3g} s, the step it chose {:.3g} s), and at that "
      "pace it would not end. Its right side is discontinuous or nearly singular there: a "
      "friction switching direction faster than any step (a contact starting to slip at its "
      "cone's edge, or sliding near Painlevé's paradox; docs/contacts.md), or a stiff model "
      "(‹integrator=bdf›)",
      state.t, t_end, integrator.name(), kCrawlingSteps, kCrawlingStep, state.t - t_before, h)});
}

}  // namespace

void check_run(const SecondOrderSystem& system, const Integrator& integrator, const State& state,
               const RunOptions& options) {
  check_options(state, options);
  check_step_budget(system, integrator, state, options);
}

RunSummary run(SecondOrderSystem& system, Integrator& integrator, State& state,
               const RunOptions& options, const std::function<void(const State&)>& observer) {
  check_run(system, integrator, state, options);
  const auto start = std::chrono::steady_clock::now();
  integrator.initialize(system, state);
  const auto done = [&] { return options.finished != nullptr && *options.finished; };
  const auto finish = [&] {
    RunSummary summary;
    summary.statistics = integrator.statistics();
    summary.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return summary;
  };
  observer(state);
  if (done()) return finish();
  const double t0 = state.t;
  const auto close = [&](double a, double b) {
    return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b));
  };
  long k = 0;      // steps taken that end on the output grid (fixed steps) or anywhere (adaptive)
  long taken = 0;  // every step, those cut short on a discontinuity included
  long crawling = 0;  // adaptive steps in a row that advanced less than kCrawlingStep of the span
  const double crawling_step = kCrawlingStep * (options.t_end - t0);
  bool reported = true;
  while (state.t < options.t_end) {
    if (++taken > static_cast<long>(kMaxRunSteps)) {
      throw NumericalError(fmt::format(
          "the run took {:.0e} steps by t = {:.9g} s of {:.6g} s and was stopped: the adaptive "
          "step stays tiny (a stiff or nearly singular model), or the inputs switch that often",
          kMaxRunSteps, state.t, options.t_end));
    }
    // The step ends at the next grid time t0 + n h — for adaptive methods, at most h ahead, on
    // the grid when it gets there (times are grid values, not accumulated sums) — and never past
    // the end or the next discontinuity of the inputs: a step that straddled one would be first
    // order.
    const double t_grid =
        integrator.adaptive()
            ? t0 + (std::floor((state.t - t0) / options.h * (1 + 1e-12)) + 1) * options.h
            : t0 + (k + 1) * options.h;
    double t_target = std::min(t_grid, options.t_end);
    double t_break = system.next_discontinuity(state.t);
    while (close(t_break, state.t)) t_break = system.next_discontinuity(t_break);
    // A discontinuity on the grid time (to round-off) is landed on exactly; one before it ends
    // a shorter step that is not a grid step.
    bool grid_step = true;
    if (close(t_break, t_target)) {
      t_target = t_break;
    } else if (t_break < t_target) {
      t_target = t_break;
      grid_step = false;
    }
    const double t_before = state.t;
    const double h = integrator.step(system, state, t_target - state.t);
    if (system.project(state.t, state.q, state.v)) integrator.state_changed();
    // Land exactly on the target when the step reached it; an interval h does not divide leaves
    // a last step of round-off size: absorb it.
    if (close(state.t, t_target)) state.t = t_target;
    if (close(state.t, options.t_end)) state.t = options.t_end;
    check_finite(system, integrator, state, h);
    // Steps that stop short on a discontinuity are neither counted for `every` nor reported.
    if (!integrator.adaptive() && !grid_step) continue;
    ++k;
    reported = k % options.every == 0 || state.t == options.t_end;
    if (reported) observer(state);
    if (done()) return finish();
    if (options.restarted != nullptr && *options.restarted) {
      // The observer took the state back inside this step: the step to this grid time again.
      *options.restarted = false;
      integrator.state_changed();
      --k;
      reported = true;
    }
    crawling = state.t - t_before < crawling_step ? crawling + 1 : 0;
    if (crawling == kCrawlingSteps) throw_crawling(integrator, state, t_before, h, options.t_end);
  }
  if (!reported) observer(state);
  return finish();
}

}  // namespace momenta::integrate
