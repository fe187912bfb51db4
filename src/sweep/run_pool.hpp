#pragma once
// The threads of one process working through a run list (execution.cpp, distributed_mpi.cpp):
// each thread takes the next position from a counter it may share with other takers (MPI ranks),
// hands the outcome to a Finish on its own thread, and finished outcomes wait, by position, to be
// taken in list order. Outcomes run elsewhere (other MPI ranks) go through the same Finish on
// these threads, between their runs, so that what it does (writing a run's file) is not left to
// the one thread that takes them in order.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
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
      : finish_(std::move(finish)), working_(threads) {
    for (int t = 0; t < threads; ++t) {
      pool_.emplace_back([this, &runner, runs, &next, stopped] {
        while (!stopped() && !failed()) {
          if (finish_arrived()) continue;
          const std::size_t position = next.fetch_add(1);
          if (position >= runs.size()) break;
          RunOutcome outcome = runner.run(runs[position]);
          if (!finish_and_add(position, std::move(outcome))) break;
        }
        // Leaves once no arrived outcome waits for it (the last thread finishes them all).
        std::unique_lock lock(mutex_);
        while (!arrived_.empty() && !failure_) {
          lock.unlock();
          finish_arrived();
          lock.lock();
        }
        --working_;
        changed_.notify_all();
      });
    }
  }

  /// An outcome run elsewhere (on another rank): finished by one of the threads between its
  /// runs, or here when none is left.
  void add_arrived(std::size_t position, RunOutcome&& outcome) {
    {
      const std::lock_guard lock(mutex_);
      if (working_ > 0) {
        arrived_.emplace_back(position, std::move(outcome));
        return;
      }
    }
    finish_and_add(position, std::move(outcome));
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
  // Puts an outcome through finish_ and makes it ready to take; false when finish_ threw (the
  // pool has failed).
  bool finish_and_add(std::size_t position, RunOutcome&& outcome) {
    try {
      if (finish_) finish_(outcome);
    } catch (...) {
      fail(std::current_exception());
      return false;
    }
    const std::lock_guard lock(mutex_);
    done_.emplace(position, std::move(outcome));
    changed_.notify_all();
    return true;
  }

  // Finishes one outcome that arrived from elsewhere, if one waits; whether one did.
  bool finish_arrived() {
    std::pair<std::size_t, RunOutcome> item;
    {
      const std::lock_guard lock(mutex_);
      if (arrived_.empty()) return false;
      item = std::move(arrived_.front());
      arrived_.pop_front();
    }
    finish_and_add(item.first, std::move(item.second));
    return true;
  }

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
  const Finish finish_;
  std::map<std::size_t, RunOutcome> done_;
  std::deque<std::pair<std::size_t, RunOutcome>> arrived_;  // from elsewhere, to finish
  std::exception_ptr failure_;  // the first exception from a thread's finish
  int working_;
  std::vector<std::jthread> pool_;  // last: joined first, while the rest still exists
};

}  // namespace momenta::sweep::detail
