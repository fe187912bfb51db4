#include <chrono>
#include <climits>
#include <condition_variable>
#include <cstdint>
#include <cstdlib>
#include <cstring>
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
constexpr int kAskTag = 1;     // a rank's outcomes so far and how many runs it wants next
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

void work_for_root(const SweepRunner& runner, int threads) {
  Writer report;
  report.put(static_cast<std::uint64_t>(threads));  // the first ask: no outcomes yet
  while (true) {
    send(report.bytes, kRoot, kAskTag);
    const std::vector<char> assignment = receive(kRoot, kAssignTag);
    Reader r(assignment);
    const auto first = r.get<std::uint64_t>();
    std::vector<long> runs;
    while (!r.done()) runs.push_back(static_cast<long>(r.get<std::int64_t>()));
    if (runs.empty()) return;
    report = Writer();
    report.put(static_cast<std::uint64_t>(threads));
    std::uint64_t position = first;
    run_in_order(runner, runs, threads,
                 [&](RunOutcome&& o) { put_outcome(report, position++, o); });
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
    const auto wanted = std::max<std::uint64_t>(1, r.get<std::uint64_t>());
    while (!r.done()) {
      auto [position, outcome] = get_outcome(r);
      pool.add(position, std::move(outcome));
    }
    Writer assignment;
    const std::size_t first = stopped() ? runs.size() : next.fetch_add(wanted);
    assignment.put(static_cast<std::uint64_t>(first));
    for (std::size_t p = first; p < std::min<std::size_t>(first + wanted, runs.size()); ++p) {
      assignment.put(static_cast<std::int64_t>(runs[p]));
    }
    if (first >= runs.size()) --remote_working;
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
    work_for_root(runner, threads);
    return 0;
  }
  return lead(world, runner, runs, threads, deliver, stop, finish);
}

}  // namespace momenta::sweep
