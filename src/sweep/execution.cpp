#include "momenta/sweep/execution.hpp"

#include "run_pool.hpp"

namespace momenta::sweep {

int default_thread_count() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : static_cast<int>(n);
}

std::size_t run_in_order(const SweepRunner& runner, std::span<const long> runs, int threads,
                         const Deliver& deliver, const std::atomic<bool>* stop,
                         const Finish& finish) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> abandon{false};  // the deliverer failed: take nothing more
  detail::RunPool pool(
      runner, runs, threads, next,
      [&] { return abandon.load() || (stop != nullptr && stop->load(std::memory_order_relaxed)); },
      finish);
  std::size_t delivered = 0;
  try {
    while (delivered < runs.size()) {
      std::optional<RunOutcome> outcome = pool.take(delivered);
      if (!outcome) break;  // every thread left: stopped
      deliver(std::move(*outcome));
      ++delivered;
    }
  } catch (...) {
    abandon = true;
    throw;  // the pool's threads finish their runs and are joined on the way out
  }
  return delivered;
}

}  // namespace momenta::sweep
