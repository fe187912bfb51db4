// run_in_order (sweep/execution.hpp): every outcome delivered once, in list order, on the calling
// thread; each taken first by Finish on the thread that ran it; an exception from Finish fails the
// sweep as one from Deliver does.

#include <algorithm>
#include <mutex>
#include <numeric>
#include <set>
#include <thread>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/io/sweep_file.hpp"
#include "momenta/sweep/execution.hpp"

namespace momenta::sweep {
namespace {

// The flywheel rim's 44 mass-property runs: quick, and enough to keep three threads busy.
struct Flywheel {
  SweepRunner runner{io::read_sweep_file("examples/sweeps/flywheel_rim.yaml")};
  std::vector<long> runs = [this] {
    std::vector<long> all(static_cast<std::size_t>(runner.run_count()));
    std::iota(all.begin(), all.end(), 0L);
    return all;
  }();
};

TEST(RunInOrder, FinishTakesEachOutcomeOnItsOwnThreadBeforeDelivery) {
  const Flywheel flywheel;
  std::mutex mutex;
  std::set<std::thread::id> finishing_threads;
  std::vector<long> finished, delivered;
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::thread::id> delivering_threads;
  const std::size_t count = run_in_order(
      flywheel.runner, flywheel.runs, 3,
      [&](RunOutcome&& o) {
        EXPECT_EQ(o.message, "finished") << o.run;  // Finish came first
        delivered.push_back(o.run);
        delivering_threads.push_back(std::this_thread::get_id());
      },
      nullptr,
      [&](RunOutcome& o) {
        const std::lock_guard lock(mutex);
        finishing_threads.insert(std::this_thread::get_id());
        finished.push_back(o.run);
        o.message = "finished";
      });
  EXPECT_EQ(count, flywheel.runs.size());
  EXPECT_EQ(delivered, flywheel.runs);  // in list order
  std::sort(finished.begin(), finished.end());
  EXPECT_EQ(finished, flywheel.runs);  // each once
  EXPECT_FALSE(finishing_threads.contains(caller));
  EXPECT_LE(finishing_threads.size(), 3U);
  EXPECT_TRUE(std::all_of(delivering_threads.begin(), delivering_threads.end(),
                          [&](std::thread::id t) { return t == caller; }));
}

TEST(RunInOrder, AnExceptionFromFinishFailsTheSweepAfterAnUnbrokenPrefix) {
  const Flywheel flywheel;
  std::vector<long> delivered;
  EXPECT_THROW(run_in_order(
                   flywheel.runner, flywheel.runs, 2,
                   [&](RunOutcome&& o) { delivered.push_back(o.run); }, nullptr,
                   [](RunOutcome& o) {
                     if (o.run == 20) throw FileError("runs/run_000020.csv: writing failed");
                   }),
               FileError);
  ASSERT_LE(delivered.size(), 20U);
  for (std::size_t k = 0; k < delivered.size(); ++k) EXPECT_EQ(delivered[k], static_cast<long>(k));
}

}  // namespace
}  // namespace momenta::sweep
