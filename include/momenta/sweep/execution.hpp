#pragma once
// Carrying out a sweep's runs on every core: a pool of threads, each taking the next run not yet
// taken (runs differ in cost, so the load balances itself), with the outcomes handed on in the
// order of the run list whatever order they finish in — so what is written does not depend on
// the thread count. Across machines: sweep/distributed.hpp.

#include <atomic>
#include <functional>
#include <span>

#include "momenta/sweep/runner.hpp"

namespace momenta::sweep {

/// Receives outcomes, in the order of the run list, on the thread that called run_in_order.
using Deliver = std::function<void(RunOutcome&& outcome)>;
/// Takes each outcome first on the thread that ran it, in any order and concurrently with the
/// others: the place for what need not wait for the run order (a run's own file), so that the
/// one delivering thread does not hold up the rest.
using Finish = std::function<void(RunOutcome& outcome)>;

/// The number of threads to use when none is asked for: the hardware's, at least 1.
int default_thread_count();

/// Runs `runs` (indices into the runner's plan) on `threads` threads (≥ 1) and delivers every
/// outcome in list order. When `stop` becomes true no new run starts; the runs finished in an
/// unbroken prefix of the list are delivered and the count delivered is returned (else
/// runs.size()). An exception from `deliver` (a full disk) stops the pool and is rethrown; one
/// from `finish` (optional, called before an outcome waits its turn) fails the sweep the same way.
std::size_t run_in_order(const SweepRunner& runner, std::span<const long> runs, int threads,
                         const Deliver& deliver, const std::atomic<bool>* stop = nullptr,
                         const Finish& finish = {});

}  // namespace momenta::sweep
