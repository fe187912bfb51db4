#include <chrono>
#include <climits>
#include <condition_variable>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <mpi.h>

#include "momenta/common/error.hpp"
#include "momenta/sweep/distributed.hpp"
#include "run_pool.hpp"

namespace momenta::sweep {
namespace {

constexpr int kRoot = 0;
constexpr int kAskTag = 1;     // a rank's outcomes so far and how many runs it wants (0: done)
constexpr int kAssignTag = 2;  // rank 0's answer: the runs to do (none: done)

// --- outcomes as bytes ----------------------------------------------------------------------

class Writer {
 public:
  template <class T>
  void put(const T& value) {
    const auto* p = reinterpret_cast<const char*>(&value);
    bytes.insert(bytes.end(), p, p + sizeof(T));
  }
  void put(const std::string& text) {
    put(static_cast<std::uint64_t>(text.size()));
    bytes.insert(bytes.end(), text.begin(), text.end());
  }
  void put(const std::vector<double>& values) {
    put(static_cast<std::uint64_t>(values.size()));
    const auto* p = reinterpret_cast<const char*>(values.data());
    bytes.insert(bytes.end(), p, p + values.size() * sizeof(double));
  }
  std::vector<char> bytes;
};

class Reader {
 public:
  explicit Reader(const std::vector<char>& bytes) : bytes_(bytes) {}
  bool done() const { return at_ == bytes_.size(); }
  template <class T>
  T get() {
    T value;
    take(&value, sizeof(T));
    return value;
  }
  std::string text() {
    std::string s(get<std::uint64_t>(), '\0');
    take(s.data(), s.size());
    return s;
  }
  std::vector<double> numbers() {
    std::vector<double> v(get<std::uint64_t>());
    take(v.data(), v.size() * sizeof(double));
    return v;
  }

 private:
  void take(void* to, std::size_t n) {
    if (n == 0) return;  // an empty list: `to` may be null
    if (at_ + n > bytes_.size()) throw NumericalError("a malformed message between MPI ranks");
    std::memcpy(to, bytes_.data() + at_, n);
    at_ += n;
  }
  const std::vector<char>& bytes_;
  std::size_t at_ = 0;
};

void put_outcome(Writer& w, std::uint64_t position, const RunOutcome& o) {
  w.put(position);
  w.put(static_cast<std::int64_t>(o.run));
  w.put(static_cast<std::uint8_t>(o.ok));
  w.put(o.wall_seconds);
  w.put(o.parameters);
  w.put(o.metrics);
  w.put(o.message);
  w.put(static_cast<std::uint64_t>(o.trajectory_columns.size()));
  for (const std::string& c : o.trajectory_columns) w.put(c);
  w.put(o.trajectory);
  w.put(o.trajectory_csv);
}

std::pair<std::uint64_t, RunOutcome> get_outcome(Reader& r) {
  const auto position = r.get<std::uint64_t>();
  RunOutcome o;
  o.run = static_cast<long>(r.get<std::int64_t>());
  o.ok = r.get<std::uint8_t>() != 0;
  o.wall_seconds = r.get<double>();
  o.parameters = r.numbers();
  o.metrics = r.numbers();
  o.message = r.text();
  o.trajectory_columns.resize(r.get<std::uint64_t>());
  for (std::string& c : o.trajectory_columns) c = r.text();
  o.trajectory = r.numbers();
  o.trajectory_csv = r.text();
  return {position, std::move(o)};
}

void send(const std::vector<char>& bytes, int to, int tag) {
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) {
    throw InvalidArgument("a batch of outcomes over 2 GB (trajectories too long for MPI messages)");
  }
  MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD);
}

std::vector<char> receive(int from, int tag, int* source = nullptr) {
  MPI_Status status;
  MPI_Probe(from, tag, MPI_COMM_WORLD, &status);
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  std::vector<char> bytes(static_cast<std::size_t>(count));
  MPI_Recv(bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, tag, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  if (source != nullptr) *source = status.MPI_SOURCE;
  return bytes;
}

// --- a rank other than 0 ------------------------------------------------------------------------

// The runs rank 0 has handed this rank and its threads' outcomes, shared by those threads and
// the rank's MPI thread. The threads take runs as they free up; the MPI thread asks for more
// while a few are still queued, so that no thread waits on a round trip to rank 0 or for the
// slowest run of a batch (docs/sweeps.md, "On many cores").
struct RankQueue {
  std::mutex mutex;
  std::condition_variable changed;
  std::deque<std::pair<std::uint64_t, long>> queued;           // position in rank 0's list, run
  std::vector<std::pair<std::uint64_t, RunOutcome>> finished;  // not yet sent
  int running = 0;
  bool closed = false;  // no more runs will come (rank 0 has none, or this rank failed)

  // Closes early (a failure on this rank): runs not yet started are dropped.
  void close() {
    const std::lock_guard lock(mutex);
    closed = true;
    queued.clear();
    changed.notify_all();
  }
};

// One of the rank's threads: runs what is queued, each outcome through `finish` (if any) on this
// thread; an outcome `finish` fails on goes to rank 0 as it is.
void take_runs(const SweepRunner& runner, const Finish& finish, RankQueue& queue) {
  std::unique_lock lock(queue.mutex);
  while (true) {
    queue.changed.wait(lock, [&] { return !queue.queued.empty() || queue.closed; });
    if (queue.queued.empty()) return;
    const auto [position, run] = queue.queued.front();
    queue.queued.pop_front();
    ++queue.running;
    queue.changed.notify_all();  // the MPI thread asks for more as the queue runs low
    lock.unlock();
    RunOutcome outcome = runner.run(run);
    if (finish) {
      try {
        finish(outcome);
      } catch (...) {  // rank 0 takes the outcome unfinished (and finishes it if it must)
      }
    }
    lock.lock();
    --queue.running;
    queue.finished.emplace_back(position, std::move(outcome));
    queue.changed.notify_all();
  }
}

void work_for_root(const SweepRunner& runner, int threads, const Finish& finish) {
  // Asks again when fewer than `reserve` runs wait, for enough to keep every thread busy and
  // `reserve` waiting: the round trip is hidden, and at the end of the list this rank holds at
  // most `reserve` runs the others might have shared.
  const int reserve = std::max(1, threads / 4);
  RankQueue queue;
  struct Closing {  // however this ends, the threads stop waiting for runs
    RankQueue& queue;
    ~Closing() { queue.close(); }
  };
  std::vector<std::jthread> pool;
  const Closing closing{queue};  // after the pool: destroyed first, it closes before the join
  for (int t = 0; t < threads; ++t) pool.emplace_back([&] { take_runs(runner, finish, queue); });
  std::uint64_t wanted = static_cast<std::uint64_t>(threads + reserve);
  while (true) {
    // Ask: the outcomes so far and how many runs are wanted (0: this rank is done).
    std::vector<std::pair<std::uint64_t, RunOutcome>> finished;
    {
      const std::lock_guard lock(queue.mutex);
      finished.swap(queue.finished);
    }
    Writer ask;
    ask.put(wanted);
    for (const auto& [position, outcome] : finished) put_outcome(ask, position, outcome);
    send(ask.bytes, kRoot, kAskTag);
    if (wanted == 0) return;
    const std::vector<char> assignment = receive(kRoot, kAssignTag);
    Reader r(assignment);
    std::uint64_t position = r.get<std::uint64_t>();
    std::unique_lock lock(queue.mutex);
    if (r.done()) queue.closed = true;  // none: rank 0's list is exhausted (or it stopped)
    while (!r.done())
      queue.queued.emplace_back(position++, static_cast<long>(r.get<std::int64_t>()));
    queue.changed.notify_all();
    if (queue.closed) {
      queue.changed.wait(lock, [&] { return queue.queued.empty() && queue.running == 0; });
      wanted = 0;
    } else {
      queue.changed.wait(lock, [&] { return static_cast<int>(queue.queued.size()) < reserve; });
      wanted = static_cast<std::uint64_t>(threads + reserve -
                                          static_cast<int>(queue.queued.size()) - queue.running);
    }
  }
}

// --- rank 0 -------------------------------------------------------------------------------------

std::size_t lead(const MpiWorld& world, const SweepRunner& runner, std::span<const long> runs,
                 int threads, const Deliver& deliver, const std::atomic<bool>* stop,
                 const Finish& finish) {
  const auto stopped = [stop] { return stop != nullptr && stop->load(std::memory_order_relaxed); };
  std::atomic<std::size_t> next{0};  // shared by this rank's threads and the other ranks
  detail::RunPool pool(runner, runs, threads, next, stopped, finish);
  int remote_working = world.size() - 1;
  std::size_t delivered = 0;
  while (true) {
    // Hand on what is ready, in order; wait a little for the next when no rank is asking.
    int asking = 0;
    MPI_Iprobe(MPI_ANY_SOURCE, kAskTag, MPI_COMM_WORLD, &asking, MPI_STATUS_IGNORE);
    const auto wait = std::chrono::microseconds(asking ? 0 : 200);
    while (std::optional<RunOutcome> outcome = pool.take(delivered, wait)) {
      deliver(std::move(*outcome));
      ++delivered;
    }
    // Every rank and thread has finished (or stopped) and nothing more can be handed on.
    if (remote_working == 0 && !pool.working()) {
      if (std::optional<RunOutcome> outcome = pool.take(delivered, std::chrono::microseconds(0))) {
        deliver(std::move(*outcome));
        ++delivered;
        continue;
      }
      break;
    }
    if (!asking) {
      // Only other ranks are at work: poll for them without spinning a core.
      if (!pool.working()) std::this_thread::sleep_for(std::chrono::microseconds(200));
      continue;
    }
    // Serve the rank that asks: keep its outcomes, give it its next runs (none: it is done).
    int rank = 0;
    const std::vector<char> ask = receive(MPI_ANY_SOURCE, kAskTag, &rank);
    Reader r(ask);
    const auto wanted = r.get<std::uint64_t>();
    while (!r.done()) {
      auto [position, outcome] = get_outcome(r);
      pool.add_arrived(position, std::move(outcome));
    }
    if (wanted == 0) {  // its last outcomes: that rank is done
      --remote_working;
      continue;
    }
    Writer assignment;
    const std::size_t first =
        stopped() ? runs.size() : std::min(next.fetch_add(wanted), runs.size());
    assignment.put(static_cast<std::uint64_t>(first));
    for (std::size_t p = first; p < std::min<std::size_t>(first + wanted, runs.size()); ++p) {
      assignment.put(static_cast<std::int64_t>(runs[p]));
    }
    send(assignment.bytes, rank, kAssignTag);
  }
  return delivered;
}

}  // namespace

bool mpi_available() { return true; }

bool started_by_mpi_launcher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(name) != nullptr) return true;
  }
  return false;
}

MpiWorld::MpiWorld() {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiWorld::~MpiWorld() { MPI_Finalize(); }

bool MpiWorld::agree(bool ready) const {
  int flag = ready ? 1 : 0;
  MPI_Bcast(&flag, 1, MPI_INT, kRoot, MPI_COMM_WORLD);
  return flag != 0;
}

void MpiWorld::abort(int code) const {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

std::size_t run_across_ranks(const MpiWorld& world, const SweepRunner& runner,
                             std::span<const long> runs, int threads, const Deliver& deliver,
                             const std::atomic<bool>* stop, const Finish& finish) {
  if (world.rank() != kRoot) {
    work_for_root(runner, threads, finish);
    return 0;
  }
  return lead(world, runner, runs, threads, deliver, stop, finish);
}

}  // namespace momenta::sweep
