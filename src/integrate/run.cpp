#include "momenta/integrate/run.hpp"

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
}

// Throws naming the first non-finite coordinate, what the last step was, and what to try.
void check_finite(const SecondOrderSystem& system, const Integrator& integrator, const State& state,
                  double h) {
  if (state.q.allFinite() && state.v.allFinite()) return;
  const bool in_q = !state.q.allFinite();
  const VecX& x = in_q ? state.q : state.v;
  int i = 0;
  while (std::isfinite(x[i])) ++i;
  throw NumericalError(fmt::format(
      "the state became non-finite at t = {:.9g} s: {} = {} after a {} step of {:.3g} s. The step "
      "may be too large for the fastest motion (try a smaller --dt, or --integrator dopri5), or "
      "the model may be singular or stiff there",
      state.t, system.coordinate_name(i, !in_q), x[i], integrator.name(), h));
}

}  // namespace

RunSummary run(SecondOrderSystem& system, Integrator& integrator, State& state,
               const RunOptions& options, const std::function<void(const State&)>& observer) {
  check_options(state, options);
  const auto start = std::chrono::steady_clock::now();
  integrator.initialize(system, state);
  observer(state);
  const double t0 = state.t;
  long k = 0;
  bool reported = true;
  while (state.t < options.t_end) {
    double h = std::min(options.h, options.t_end - state.t);
    h = integrator.step(system, state, h);
    ++k;
    // Fixed steps land on t0 + k h exactly instead of accumulating round-off in t.
    if (!integrator.adaptive()) state.t = std::min(t0 + k * options.h, options.t_end);
    // An interval h does not divide leaves a last step of round-off size: absorb it.
    if (options.t_end - state.t <= 1e-12 * std::max(1.0, std::abs(options.t_end))) {
      state.t = options.t_end;
    }
    check_finite(system, integrator, state, h);
    reported = k % options.every == 0;
    if (reported) observer(state);
  }
  if (!reported) observer(state);
  RunSummary summary;
  summary.statistics = integrator.statistics();
  summary.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace momenta::integrate
