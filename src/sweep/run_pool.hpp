#pragma once
// The threads of one process working through a run list (execution.cpp, distributed_mpi.cpp):
// each thread takes the next position from a counter it may share with other takers (MPI ranks),
// and finished outcomes wait, by position, to be taken in list order.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <span>
#include <thread>
#include <vector>

#include "momenta/sweep/runner.hpp"

namespace momenta::sweep::detail {

class RunPool {
 public:
  /// Starts `threads` threads taking positions from `next` until the list is done or `stopped`
  /// says so.
  RunPool(const SweepRunner& runner, std::span<const long> runs, int threads,
          std::atomic<std::size_t>& next, std::function<bool()> stopped)
      : working_(threads) {
    for (int t = 0; t < threads; ++t) {
      pool_.emplace_back([this, &runner, runs, &next, stopped] {
        while (!stopped()) {
          const std::size_t position = next.fetch_add(1);
          if (position >= runs.size()) break;
          add(position, runner.run(runs[position]));
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
  /// it, or (with `wait`) when `wait` passes first.
  std::optional<RunOutcome> take(std::size_t position,
                                 std::optional<std::chrono::microseconds> wait = std::nullopt) {
    std::unique_lock lock(mutex_);
    const auto ready = [&] { return done_.contains(position) || working_ == 0; };
    if (wait) {
      changed_.wait_for(lock, *wait, ready);
    } else {
      changed_.wait(lock, ready);
    }
    if (!done_.contains(position)) return std::nullopt;
    return std::move(done_.extract(position).mapped());
  }

  /// Whether any thread is still taking runs.
  bool working() {
    const std::lock_guard lock(mutex_);
    return working_ > 0;
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::map<std::size_t, RunOutcome> done_;
  int working_;
  std::vector<std::jthread> pool_;  // last: joined first, while the rest still exists
};

}  // namespace momenta::sweep::detail
