#pragma once
// The threads of one process working through a run list (execution.cpp, distributed_mpi.cpp):
// each thread takes the next position from a counter it may share with other takers (MPI ranks),
// hands the outcome to a Finish on its own thread, and finished outcomes wait, by position, to be
// taken in list order.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <span>
#include <thread>
#include <vector>

#include "momenta/sweep/execution.hpp"

namespace momenta::sweep::detail {

class RunPool {
 public:
  /// Starts `threads` threads taking positions from `next` until the list is done or `stopped`
  /// says so; each hands its outcome to `finish` (if any) before it waits to be taken.
  RunPool(const SweepRunner& runner, std::span<const long> runs, int threads,
          std::atomic<std::size_t>& next, std::function<bool()> stopped, Finish finish)
      : working_(threads) {
    for (int t = 0; t < threads; ++t) {
      pool_.emplace_back([this, &runner, runs, &next, stopped, finish] {
        while (!stopped() && !failed()) {
          const std::size_t position = next.fetch_add(1);
          if (position >= runs.size()) break;
          RunOutcome outcome = runner.run(runs[position]);
          try {
            if (finish) finish(outcome);
          } catch (...) {
            fail(std::current_exception());
            break;
          }
          add(position, std::move(outcome));
        }
        const std::lock_guard lock(mutex_);
        --working_;
        changed_.notify_all();
      });
    }
  }

  /// An outcome finished elsewhere (on another rank).
  void add(std::size_t position, RunOutcome&& outcome) {
    const std::lock_guard lock(mutex_);
    done_.emplace(position, std::move(outcome));
    changed_.notify_all();
  }

  /// The outcome at `position` once it is finished; nothing when every thread has left without
  /// it, or (with `wait`) when `wait` passes first. Rethrows what a thread's `finish` threw.
  std::optional<RunOutcome> take(std::size_t position,
                                 std::optional<std::chrono::microseconds> wait = std::nullopt) {
    std::unique_lock lock(mutex_);
    const auto ready = [&] { return done_.contains(position) || working_ == 0 || failure_; };
    if (wait) {
      changed_.wait_for(lock, *wait, ready);
    } else {
      changed_.wait(lock, ready);
    }
    if (failure_) std::rethrow_exception(failure_);
    if (!done_.contains(position)) return std::nullopt;
    return std::move(done_.extract(position).mapped());
  }

  /// Whether any thread is still taking runs.
  bool working() {
    const std::lock_guard lock(mutex_);
    return working_ > 0;
  }

 private:
  void fail(std::exception_ptr failure) {
    const std::lock_guard lock(mutex_);
    if (!failure_) failure_ = std::move(failure);
    changed_.notify_all();
  }
  bool failed() {
    const std::lock_guard lock(mutex_);
    return failure_ != nullptr;
  }

  std::mutex mutex_;
  std::condition_variable changed_;
  std::map<std::size_t, RunOutcome> done_;
  std::exception_ptr failure_;  // the first exception from a thread's finish
  int working_;
  std::vector<std::jthread> pool_;  // last: joined first, while the rest still exists
};

}  // namespace momenta::sweep::detail
