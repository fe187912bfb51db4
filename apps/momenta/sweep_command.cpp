// `momenta sweep SWEEP.yaml -o results.csv` and `momenta sweep-merge`: a sweep's runs on every
// core, across the ranks of an MPI job, or one shard of them (docs/sweeps.md).

#include <unistd.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "interrupt.hpp"
#include "momenta/common/error.hpp"
#include "momenta/io/files_read.hpp"
#include "momenta/io/sweep_file.hpp"
#include "momenta/report/report.hpp"
#include "momenta/sweep/distributed.hpp"
#include "momenta/sweep/execution.hpp"
#include "momenta/sweep/inputs_digest.hpp"
#include "momenta/sweep/results_file.hpp"
#include "momenta/sweep/trajectory_store.hpp"
#include "option_checks.hpp"

namespace momenta::cli {
namespace {

struct SweepOptions {
  std::string sweep;
  std::string output;
  int threads = 0;  // 0: every core (shared among the ranks on a host)
  bool resume = false;
  bool force = false;
  bool no_timing = false;
  bool quiet = false;
  std::optional<std::string> shard;  // "k/N"
  std::string report;                // the HTML page, when asked
};

struct Shard {
  long index = 0;  // 0-based
  long count = 1;
};

// "k/N" with 1 ≤ k ≤ N ≤ the number of runs (a shard with no run would be a mistake).
Shard parse_shard(const std::string& text, long run_count) {
  const auto whole = [](std::string_view part, long& value) {
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
    return ec == std::errc() && end == part.data() + part.size();
  };
  const auto slash = text.find('/');
  long k = 0, n = 0;
  const std::string_view all(text);
  if (slash == std::string::npos || !whole(all.substr(0, slash), k) ||
      !whole(all.substr(slash + 1), n) || n < 1 || k < 1 || k > n) {
    throw CLI::ValidationError("--shard",
                               fmt::format("'{}': give k/N with 1 ≤ k ≤ N (--shard 2/4)", text));
  }
  if (n > run_count) {
    throw CLI::ValidationError(
        "--shard", fmt::format("'{}': {} shards of a sweep of {} runs would leave shards with no "
                               "run; N is at most {}",
                               text, n, run_count, run_count));
  }
  return Shard{k - 1, n};
}

// Outputs that would overwrite an input or each other are refused before anything runs.
void check_sweep_outputs(const SweepOptions& o, const sweep::SweepRunner& runner) {
  const std::string model = runner.spec().model.string();
  for (const auto& [output, option] :
       {std::pair{o.output, "--output"}, std::pair{o.report, "--report"}}) {
    if (output.empty()) continue;
    for (const std::string& input : {o.sweep, model}) {
      if (same_file(output, input)) {
        throw InvalidArgument(fmt::format(
            "{} {} is the sweep's own input {}: it would be overwritten; give another file", option,
            output, input));
      }
    }
  }
  if (!o.report.empty() && same_file(o.output, o.report)) {
    throw InvalidArgument(fmt::format(
        "--output and --report both name {}: the page would replace the results; give two files",
        o.output));
  }
}

// Threads beyond this many per core only cost memory and switching (and 10⁵ of them fail to
// start at all): refused with the machine's count.
int check_thread_count(int asked) {
  const int cores = sweep::default_thread_count();
  const int most = std::max(256, 16 * cores);
  if (asked > most) {
    throw CLI::ValidationError(
        "--threads", fmt::format("{} threads on {} cores: at most {} (the default, {}, uses "
                                 "every core)",
                                 asked, cores, most, cores));
  }
  return asked;
}

// The runs this process is responsible for: every run, or those of its shard (run % N == k − 1).
std::vector<long> runs_of(long run_count, const Shard& shard) {
  std::vector<long> runs;
  for (long run = shard.index; run < run_count; run += shard.count) runs.push_back(run);
  return runs;
}

// With --resume: the file must be this sweep's, of this model: each row made from the inputs the
// sweep file and the files its model reads have now (else the rows would mix two models; by their
// contents, not their times, which a copy or a checkout changes), its runs the first of the list,
// each with the parameter values this sweep gives it (else they came from another range or
// design with the same columns).
std::size_t finished_prefix(const SweepOptions& o, const sweep::SweepRunner& runner,
                            const std::vector<std::string>& header, const std::vector<long>& runs,
                            const std::string& inputs) {
  const std::vector<long> finished = sweep::read_finished_runs(o.output, header, inputs);
  const sweep::ResultsColumns written =
      sweep::read_result_columns(o.output, runner.parameter_columns());
  for (std::size_t i = 0; i < finished.size(); ++i) {
    if (i >= runs.size() || finished[i] != runs[i]) {
      throw FileError(fmt::format(
          "{}: row {} holds run {}, not run {} that this sweep{} writes there: the file was "
          "written by another sweep or shard",
          o.output, i + 2, finished[i], i < runs.size() ? runs[i] : -1, o.shard ? " shard" : ""));
    }
    const std::vector<double> expected = runner.parameter_values(runs[i]);
    for (std::size_t p = 0; p < expected.size(); ++p) {
      const double value = written.values[p][i];
      if (value == expected[p] || (std::isnan(value) && std::isnan(expected[p]))) continue;
      throw FileError(fmt::format(
          "{}: row {} holds run {} with {} = {}, but this sweep gives run {} {} = {}: the file "
          "was written by another sweep (another range or design). Start over with --force, or "
          "write to another file",
          o.output, i + 2, finished[i], runner.parameter_columns()[p], value, runs[i],
          runner.parameter_columns()[p], expected[p]));
    }
  }
  return finished.size();
}

int threads_per_process(int asked) {
  if (asked > 0) return asked;
  int on_this_host = 1;
  if (const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE"))
    on_this_host = std::atoi(local);
  return std::max(1, sweep::default_thread_count() / std::max(1, on_this_host));
}

// A progress line on a terminal: runs done, failures, elapsed, an estimate of what is left.
class Progress {
 public:
  Progress(bool shown, std::size_t total) : shown_(shown), total_(total) {}
  void count(bool ok) {
    ++done_;
    failed_ += ok ? 0 : 1;
    if (!shown_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(200) && done_ < total_) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double left = elapsed * static_cast<double>(total_ - done_) / static_cast<double>(done_);
    fmt::print(stderr,
               "\r  run {} of {} ({:.0f} %), {} failed, {:.1f} s elapsed, about {:.1f} s left   ",
               done_, total_, 100.0 * static_cast<double>(done_) / static_cast<double>(total_),
               failed_, elapsed, left);
  }
  void clear() const {
    if (shown_) fmt::print(stderr, "\r\033[K");
  }

 private:
  bool shown_;
  std::size_t total_;
  std::size_t done_ = 0;
  std::size_t failed_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_ = start_;
};

void print_summary(const sweep::SweepRunner& runner, const std::string& output, double seconds,
                   const std::string& where) {
  const sweep::ResultsSummary s = sweep::summarize_results(output, runner.metric_columns());
  fmt::print(stderr, "momenta: {} runs in {}: {} ok, {} failed; {:.3g} s {}\n", s.runs, output,
             s.runs - s.failures, s.failures, seconds, where);
  if (s.failures > 0) fmt::print(stderr, "  first failure: {}\n", s.first_failure);
  std::size_t width = 6;
  for (const auto& f : s.figures) width = std::max(width, f.column.size());
  fmt::print(stderr, "  {:<{}}  {:>6}  {:>13}  {:>13}  {:>13}\n", "metric", width, "runs", "min",
             "median", "max");
  for (const auto& f : s.figures) {
    if (f.count == 0) {
      fmt::print(stderr, "  {:<{}}  {:>6}  {:>13}\n", f.column, width, 0, "(undefined)");
      continue;
    }
    fmt::print(stderr, "  {:<{}}  {:>6}  {:>13.6g}  {:>13.6g}  {:>13.6g}\n", f.column, width,
               f.count, f.min, f.median, f.max);
  }
}

// The sweep's HTML page, from every row of its results file.
void write_sweep_report(const SweepOptions& o, const sweep::SweepRunner& runner) {
  std::vector<std::string> columns = runner.parameter_columns();
  columns.insert(columns.end(), runner.metric_columns().begin(), runner.metric_columns().end());
  sweep::ResultsColumns table = sweep::read_result_columns(o.output, columns);
  report::SweepResults results;
  results.title = runner.spec().name;
  results.source = o.sweep;
  results.parameters = runner.parameter_columns();
  results.metrics = runner.metric_columns();
  results.parameter_units = runner.parameter_units();
  results.metric_units = runner.metric_units();
  results.runs = std::move(table.runs);
  results.ok = std::move(table.ok);
  results.values = std::move(table.values);
  report::write_report(o.report, report::sweep_report_html(results), true);
  fmt::print(stderr, "momenta: report written to {}\n", o.report);
}

void run_sweep(const SweepOptions& o) {
  std::optional<sweep::MpiWorld> world;
  if (sweep::started_by_mpi_launcher() && sweep::mpi_available()) world.emplace();
  const bool root = !world || world->rank() == 0;
  try {
    check_input_file(o.sweep, "a sweep file");
    // What the results are made from: the sweep file and every file its model reads.
    io::FilesReadLog files_read;
    const sweep::SweepRunner runner(io::read_sweep_file(o.sweep));
    const std::string inputs = sweep::inputs_digest(files_read.files());
    check_sweep_outputs(o, runner);
    const Shard shard = o.shard ? parse_shard(*o.shard, runner.run_count()) : Shard{};
    const std::vector<long> all = runs_of(runner.run_count(), shard);
    const std::vector<std::string> header = sweep::results_header(runner, !o.no_timing);
    const int threads = threads_per_process(check_thread_count(o.threads));

    // Rank 0 (or the one process) opens the outputs; the others work for it.
    std::unique_ptr<sweep::ResultsWriter> writer;
    std::unique_ptr<sweep::TrajectoryStore> trajectories;
    std::size_t skipped = 0;
    if (root) {
      try {
        // The report is refused before the runs, not after them, when it would overwrite a file.
        if (!o.report.empty() && std::filesystem::exists(o.report) && !o.force) {
          throw FileError(
              fmt::format("{}: the report file exists; pass --force to overwrite it", o.report));
        }
        const bool resuming = o.resume && std::filesystem::exists(o.output);
        if (resuming) skipped = finished_prefix(o, runner, header, all, inputs);
        writer = std::make_unique<sweep::ResultsWriter>(o.output, header, o.force, resuming);
        if (const auto& path = runner.spec().trajectories) {
          std::filesystem::path where = *path;
          if (shard.count > 1 && (where.extension() == ".h5" || where.extension() == ".hdf5")) {
            where.replace_extension(fmt::format(".shard{}of{}{}", shard.index + 1, shard.count,
                                                path->extension().string()));
          }
          trajectories = sweep::open_trajectory_store(where, resuming, o.force);
        }
      } catch (...) {
        if (world) world->agree(false);
        throw;
      }
    }
    if (world && !world->agree(true)) throw Interrupted("rank 0 could not start");
    const std::span<const long> runs = std::span(all).subspan(root ? skipped : 0);

    Progress progress(root && !o.quiet && isatty(STDERR_FILENO), runs.size());
    // A folder's CSV files are written by the threads that ran their runs (docs/sweeps.md, "On
    // every core"); under MPI another rank's are formatted by its threads, and written by rank
    // 0's between their runs. The rest is written here, in run order, by this one thread.
    const auto& trajectory_path = runner.spec().trajectories;
    const bool csv_files = trajectory_path && sweep::stores_csv_files(*trajectory_path);
    const sweep::Finish finish = [&](sweep::RunOutcome& outcome) {
      if (!root) {
        if (csv_files) sweep::format_csv_trajectory(outcome);
        return;
      }
      if (!trajectories || !trajectories->writes_concurrently()) return;
      trajectories->write(outcome);
      outcome.trajectory = {};
      outcome.trajectory_columns = {};
      outcome.trajectory_csv = {};
      outcome.trajectory_stored = true;
    };
    const sweep::Deliver deliver = [&](sweep::RunOutcome&& outcome) {
      writer->write(sweep::results_row(outcome, !o.no_timing, inputs));
      if (trajectories && !outcome.trajectory_stored) trajectories->write(outcome);
      progress.count(outcome.ok);
    };
    const std::atomic<bool>& stop = stop_on_signals();
    const auto start = std::chrono::steady_clock::now();
    std::size_t delivered = 0;
    try {
      delivered =
          world ? sweep::run_across_ranks(*world, runner, runs, threads, deliver, &stop, finish)
                : sweep::run_in_order(runner, runs, threads, deliver, &stop, finish);
    } catch (...) {
      progress.clear();
      if (world && world->size() > 1) {
        fmt::print(stderr, "momenta: error on rank 0 during the sweep; ending every rank\n");
        world->abort(1);
      }
      throw;
    }
    progress.clear();
    if (!root) return;
    if (delivered < runs.size()) {
      // Said here, not by main: interrupted under mpirun, the whole job ends — mpirun sends every
      // rank SIGTERM, then SIGKILL a second later, and MPI_Finalize (as `world` goes) waits on
      // mpirun, which no longer answers.
      fmt::print(stderr,
                 "momenta: interrupted: {} of {} runs written to {}; `momenta sweep {} -o {} "
                 "--resume` goes on\n",
                 skipped + delivered, all.size(), o.output, o.sweep, o.output);
      std::fflush(stderr);
      throw QuietExit{130};
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string where = world
                                  ? fmt::format("on {} ranks × {} threads", world->size(), threads)
                                  : fmt::format("on {} thread{}", threads, threads == 1 ? "" : "s");
    print_summary(
        runner, o.output, seconds,
        skipped > 0 ? fmt::format("for the {} runs left, {}", runs.size(), where) : where);
    if (!o.report.empty()) write_sweep_report(o, runner);
  } catch (const Error&) {
    if (!root) throw QuietExit{1};  // rank 0 says it
    throw;
  }
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* command = app.add_subcommand(
      "sweep",
      "Run a sweep or Monte Carlo study (docs/sweeps.md): one row per run in a CSV file.\n"
      "Example: momenta sweep examples/sweeps/quarter_car_ride.yaml -o ride.csv\n"
      "Across machines: mpirun -n 8 momenta sweep SWEEP.yaml -o results.csv");
  command->add_option("sweep", o->sweep, "The sweep file (YAML)")->required();
  command->add_option("-o,--output", o->output, "The results file (CSV)")
      ->required()
      ->check(not_a_folder());
  command
      ->add_option("--threads", o->threads,
                   "Threads per process (default: every core, shared among the MPI ranks on a "
                   "host)")
      ->check(whole_number_from_one());
  command->add_flag("--resume", o->resume,
                    "Go on with the runs a killed or interrupted sweep did not write");
  command->add_flag("--force", o->force, "Replace an existing results file");
  command->add_flag("--no-timing", o->no_timing,
                    "Leave out the wall_s column, so that two sweeps' files are identical");
  command->add_option("--shard", o->shard,
                      "Run only shard k of N (runs with run % N = k − 1), for schedulers without "
                      "MPI; `momenta sweep-merge` joins the shards");
  command->add_flag("-q,--quiet", o->quiet, "No progress line on the terminal");
  command
      ->add_option("--report", o->report,
                   "Also write the sweep's HTML page: scatter plots and parallel coordinates "
                   "of parameters and metrics (docs/sweeps.md)")
      ->check(not_a_folder());
  command->callback([o] {
    if (o->resume && o->force) {
      throw CLI::ValidationError("--resume", "give --resume or --force, not both");
    }
    run_sweep(*o);
  });
}

void add_sweep_merge_command(CLI::App& app) {
  struct MergeOptions {
    std::string sweep;
    std::vector<std::string> parts;
    std::string output;
    bool force = false;
    bool no_timing = false;
  };
  auto o = std::make_shared<MergeOptions>();
  CLI::App* command = app.add_subcommand(
      "sweep-merge",
      "Join the results of a sweep's shards into one file, in run order, checking that every run "
      "is there once.\nExample: momenta sweep-merge SWEEP.yaml part1.csv part2.csv -o results.csv");
  command->add_option("sweep", o->sweep, "The sweep file the shards ran")->required();
  command->add_option("parts", o->parts, "The shards' results files")->required();
  command->add_option("-o,--output", o->output, "The merged results file")
      ->required()
      ->check(not_a_folder());
  command->add_flag("--force", o->force, "Replace an existing output file");
  command->add_flag("--no-timing", o->no_timing, "The shards were written with --no-timing");
  command->callback([o] {
    check_input_file(o->sweep, "a sweep file");
    for (const std::string& part : o->parts) {
      check_input_file(part, "a results file");
      if (same_file(part, o->output)) {
        throw InvalidArgument(fmt::format(
            "--output {} is one of the shards being merged: it would be overwritten; give "
            "another file",
            o->output));
      }
    }
    const sweep::SweepRunner runner(io::read_sweep_file(o->sweep));
    const std::vector<std::filesystem::path> parts(o->parts.begin(), o->parts.end());
    sweep::merge_results(parts, sweep::results_header(runner, !o->no_timing), runner.run_count(),
                         o->output, o->force);
    fmt::print(stderr, "momenta: {} runs from {} files merged into {}\n", runner.run_count(),
               parts.size(), o->output);
  });
}

}  // namespace momenta::cli
