// The results file (sweep/results_file.hpp): rows that read back to the same doubles, a partial
// last row cut on resume, shards merged in run order with every run once.

#include <charconv>
#include <fstream>
#include <limits>
#include <string_view>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/sweep/results_file.hpp"
#include "momenta_test/scratch_dir.hpp"

namespace momenta::sweep {
namespace {

const std::vector<std::string> kHeader = {"run", "k", "max(y)", "status", "inputs", "message"};
constexpr std::string_view kInputs = "sha256:0123456789abcdef";

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

using ResultsFile = test::ScratchDirTest;

RunOutcome outcome(long run, double k, double y, bool ok = true, std::string message = "") {
  RunOutcome o;
  o.run = run;
  o.parameters = {k};
  o.metrics = {y};
  o.ok = ok;
  o.message = std::move(message);
  return o;
}

TEST_F(ResultsFile, RowsReadBackToTheSameDoublesAndUndefinedFiguresAreEmpty) {
  const double y = 0.1 + 0.2;  // not a short decimal
  const std::string row = results_row(outcome(3, 1e-320, y), false, kInputs);
  EXPECT_EQ(row, "3,1e-320,0.30000000000000004,ok,sha256:0123456789abcdef,\n");
  double back = 0.0;
  const std::string cell = "0.30000000000000004";
  std::from_chars(cell.data(), cell.data() + cell.size(), back);
  EXPECT_EQ(back, y);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(results_row(outcome(4, 2.0, nan, false, "bad, \"very\" bad"), false, kInputs),
            "4,2,,failed,sha256:0123456789abcdef,\"bad, \"\"very\"\" bad\"\n");
}

TEST_F(ResultsFile, ResumingCutsAPartialLastRowAndKnowsTheFinishedRuns) {
  const auto path = dir_ / "r.csv";
  {
    ResultsWriter w(path, kHeader, false, false);
    w.write(results_row(outcome(0, 1, 2), false, kInputs));
    w.write(results_row(outcome(1, 1, 3, false, "diverged, at t = 0.2 s"), false, kInputs));
  }
  std::ofstream(path, std::ios::app) << "2,1,4";  // killed while writing
  EXPECT_EQ(read_finished_runs(path, kHeader, kInputs), (std::vector<long>{0, 1}));
  EXPECT_EQ(read(path).back(), '\n');  // the partial row is gone
  // Another sweep's file is refused at its header.
  const std::vector<std::string> other = {"run", "m", "max(y)", "status", "inputs", "message"};
  EXPECT_THROW(read_finished_runs(path, other, kInputs), ParseError);
  // Without --force an existing file is not replaced.
  EXPECT_THROW(ResultsWriter(path, kHeader, false, false), FileError);
}

// --resume goes on only from rows made from the inputs the files have now, and refuses, with the
// reason, a file that does not say what it was made from.
TEST_F(ResultsFile, ResumingRefusesRowsMadeFromOtherInputsOrFromUnrecordedOnes) {
  const auto path = dir_ / "r.csv";
  {
    ResultsWriter w(path, kHeader, false, false);
    w.write(results_row(outcome(0, 1, 2), false, kInputs));
  }
  try {
    read_finished_runs(path, kHeader, "sha256:fedcba9876543210");
    ADD_FAILURE() << "rows of other inputs were taken";
  } catch (const FileError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("row 2 (run 0) was made from other inputs (sha256:0123456789abcdef)"),
              std::string::npos)
        << message;
    EXPECT_EQ(e.options(), std::vector<std::string>{"force"}) << message;
  }
  const auto old = dir_ / "old.csv";
  std::ofstream(old, std::ios::binary) << "run,k,max(y),status,message\n0,1,2,ok,\n";
  try {
    read_finished_runs(old, kHeader, kInputs);
    ADD_FAILURE() << "a file without its inputs was taken";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("does not record what its results were made from"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(ResultsFile, ShardsMadeFromOtherInputsAreNotMerged) {
  const auto a = dir_ / "a.csv", b = dir_ / "b.csv";
  {
    ResultsWriter wa(a, kHeader, false, false), wb(b, kHeader, false, false);
    wa.write(results_row(outcome(0, 1, 2), false, kInputs));
    wb.write(results_row(outcome(1, 1, 2), false, "sha256:fedcba9876543210"));
  }
  const std::vector<std::filesystem::path> parts = {a, b};
  try {
    merge_results(parts, kHeader, 2, dir_ / "merged.csv", false);
    ADD_FAILURE() << "shards of two models were merged";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("was made from other inputs"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir_ / "merged.csv"));
}

TEST_F(ResultsFile, ShardsMergeInRunOrderWithEveryRunOnce) {
  const auto a = dir_ / "a.csv", b = dir_ / "b.csv", whole = dir_ / "whole.csv";
  {
    ResultsWriter wa(a, kHeader, false, false), wb(b, kHeader, false, false),
        ww(whole, kHeader, false, false);
    for (long run = 0; run < 5; ++run) {
      const std::string row = results_row(outcome(run, 1.5 * run, run * run), false, kInputs);
      (run % 2 == 0 ? wa : wb).write(row);
      ww.write(row);
    }
  }
  const std::vector<std::filesystem::path> parts = {b, a};
  merge_results(parts, kHeader, 5, dir_ / "merged.csv", false);
  EXPECT_EQ(read(dir_ / "merged.csv"), read(whole));
  const std::vector<std::filesystem::path> missing = {a};
  EXPECT_THROW(merge_results(missing, kHeader, 5, dir_ / "m2.csv", false), InvalidArgument);
  const std::vector<std::filesystem::path> twice = {a, b, a};
  EXPECT_THROW(merge_results(twice, kHeader, 5, dir_ / "m3.csv", false), InvalidArgument);
}

TEST_F(ResultsFile, TheSummaryGivesMinimumMedianAndMaximumOfTheRunsThatDefineAFigure) {
  const auto path = dir_ / "s.csv";
  {
    ResultsWriter w(path, kHeader, false, false);
    for (double y : {4.0, 1.0, 3.0, 2.0}) w.write(results_row(outcome(0, 0, y), false, kInputs));
    w.write(results_row(outcome(4, 0, std::numeric_limits<double>::quiet_NaN(), false, "x"), false,
                        kInputs));
  }
  const std::vector<std::string> metrics = {"max(y)"};
  const ResultsSummary s = summarize_results(path, metrics);
  EXPECT_EQ(s.runs, 5);
  EXPECT_EQ(s.failures, 1);
  EXPECT_EQ(s.first_failure, "x");
  ASSERT_EQ(s.figures.size(), 1U);
  EXPECT_EQ(s.figures[0].count, 4);
  EXPECT_EQ(s.figures[0].min, 1.0);
  EXPECT_EQ(s.figures[0].median, 2.5);
  EXPECT_EQ(s.figures[0].max, 4.0);
}

}  // namespace
}  // namespace momenta::sweep
