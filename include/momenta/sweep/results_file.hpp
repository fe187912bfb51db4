#pragma once
// The results of a sweep as a CSV file (docs/sweeps.md, "results"): a header, then one row per
// run in the order of the run list —
//
//     run, <parameter columns>, <metric columns>, status, inputs, [wall_s,] message
//
// status is `ok` or `failed`; inputs is what the run was made from, the same in every row
// (sweep/inputs_digest.hpp); a metric a run does not define (or a failed run's) is an empty
// cell; numbers are written in the shortest form that reads back to the same double. Each row is
// written whole and flushed, so a killed sweep leaves whole rows (at worst a partial last line,
// which resuming removes). wall_s, the run's wall-clock time, is the one column that differs
// between two sweeps of the same file; without it the files are identical byte for byte.

#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "momenta/sweep/runner.hpp"

namespace momenta::sweep {

/// The results file's own columns, which no parameter or metric may be named.
inline constexpr std::string_view kOwnResultsColumns = "run, status, inputs, wall_s, message";
bool is_own_results_column(std::string_view name);

/// The header of a sweep's results.
std::vector<std::string> results_header(const SweepRunner& runner, bool with_timing);

/// One row of results: the fields joined by commas, ending in '\n'; `inputs` is what the results
/// were made from (sweep/inputs_digest.hpp).
std::string results_row(const RunOutcome& outcome, bool with_timing, std::string_view inputs);

/// The rows already in a results file, for --resume: checked to have `header`, and each row to
/// be made from `inputs`; their run indices in file order. A partial last line (a sweep killed
/// while writing it) is cut off the file. Throws FileError when the file cannot be read or cut,
/// or a row was made from other inputs; ParseError (file:line) when its header differs (a file
/// without an `inputs` column is refused so, with the reason), or a row is not a row of it.
std::vector<long> read_finished_runs(const std::filesystem::path& path,
                                     std::span<const std::string> header, std::string_view inputs);

/// Appends rows to a results file, flushing each.
class ResultsWriter {
 public:
  /// Creates `path` with `header` (refusing an existing file unless `overwrite`: FileError), or,
  /// with `append`, opens it to add rows after those already there.
  ResultsWriter(const std::filesystem::path& path, std::span<const std::string> header,
                bool overwrite, bool append);
  ~ResultsWriter();
  ResultsWriter(const ResultsWriter&) = delete;
  ResultsWriter& operator=(const ResultsWriter&) = delete;

  /// Writes one row and flushes it. Throws FileError when the write fails.
  void write(const std::string& row);

 private:
  std::filesystem::path path_;
  std::FILE* file_ = nullptr;
};

/// Every row of the results files `parts` (shards of one sweep, each with `header`), merged
/// into `output` in run order. Throws ParseError when a file's header differs, InvalidArgument
/// naming the run when a run is missing or appears twice (runs 0 … run_count − 1 must each
/// appear once) or the files' rows were made from different inputs, FileError as ResultsWriter.
void merge_results(std::span<const std::filesystem::path> parts,
                   std::span<const std::string> header, long run_count,
                   const std::filesystem::path& output, bool overwrite);

/// Columns of a results file, for the summary and the report: each asked-for column's values
/// (NaN for an empty cell), and each row's run and whether it is ok.
struct ResultsColumns {
  std::vector<long> runs;
  std::vector<bool> ok;
  std::vector<std::string> messages;
  std::vector<std::vector<double>> values;  ///< one per asked column, one value per row
};
/// Reads `columns` of the results file at `path`. Throws FileError when it cannot be read,
/// ParseError when a column is not in its header or a row is not a row of it.
ResultsColumns read_result_columns(const std::filesystem::path& path,
                                   std::span<const std::string> columns);

/// Minimum, median and maximum of each metric column over the runs that gave it, with the counts
/// of runs and failures: the summary `momenta sweep` prints.
struct ResultsSummary {
  long runs = 0;
  long failures = 0;
  std::string first_failure;  ///< the message of the first failed run
  struct Figure {
    std::string column;
    long count = 0;  ///< runs that define it
    double min = 0.0, median = 0.0, max = 0.0;
  };
  std::vector<Figure> figures;
};
ResultsSummary summarize_results(const std::filesystem::path& path,
                                 std::span<const std::string> metric_columns);

}  // namespace momenta::sweep
