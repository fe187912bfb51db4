// The command line under bad input, as found by a bad-input battery and a mutation fuzzer: every
// case ends in a one-line message and exit 1 (user error) or 2 (usage error) — never a hang, an
// internal error, a non-finite number printed as a result, or a user's file overwritten — and a
// run stopped by the user leaves whole rows.
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta {
namespace {

namespace fs = std::filesystem;
using test::CliRun;
using test::quoted;
using test::slurp;

std::string example(const std::string& name) { return test::source_dir() + "/examples/" + name; }

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

int lines(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

class BadInputCli : public test::CliTest {};

TEST_F(BadInputCli, VersionAndAMistypedCommand) {
  const CliRun version = momenta("--version");
  EXPECT_EQ(version.code, 0);
  EXPECT_EQ(version.out.rfind("momenta 0.", 0), 0u) << version.out;
  const CliRun typo = momenta("simulat " + quoted(example("pendulum.yaml")));
  EXPECT_EQ(typo.code, 2);
  EXPECT_TRUE(has(typo.err, "unknown command 'simulat' (did you mean 'simulate'?)")) << typo.err;
}

// Out-of-range values: a usage error with the value named, not CLI11's 309-digit bound.
TEST_F(BadInputCli, OptionValuesOutOfRangeAreUsageErrorsInOneShortLine) {
  const std::string pendulum = quoted(example("pendulum.yaml"));
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"simulate " + pendulum + " --every 1e400", "--every: must be a whole number"},
      {"simulate " + pendulum + " --duration 1e400", "--duration: must be a positive finite"},
      {"simulate " + pendulum + " --dt nan", "--dt: must be a positive finite number, got nan"},
      {"inertia " + quoted(example("parts/flywheel.yaml")) + " --about nan 0 0",
       "--about: must be a finite number, got nan"},
      {"response " + quoted(example("cruise_control.yaml")) +
           " --input u --output speed --bode 1 inf",
       "--bode: must be a positive finite number, got inf"},
      {"simulate " + pendulum + " -o " + quoted(dir_.string()), "is a folder"},
  };
  for (const auto& [args, message] : cases) {
    const CliRun r = momenta(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_TRUE(has(r.err, message)) << args << "\n" << r.err;
    EXPECT_LT(r.err.size(), 300u) << r.err;
  }
}

TEST_F(BadInputCli, ResponseCsvIsNeverOverwrittenWithoutForce) {
  const fs::path csv = write("bode.csv", "keep me\n");
  const std::string args = "response " + quoted(example("cruise_control.yaml")) +
                           " --input u --output speed --step --csv " + quoted(csv.string());
  const CliRun refused = momenta(args);
  EXPECT_EQ(refused.code, 1);
  EXPECT_TRUE(has(refused.err, "--force")) << refused.err;
  EXPECT_EQ(slurp(csv), "keep me\n");
  EXPECT_EQ(momenta(args + " --force").code, 0);
  EXPECT_EQ(slurp(csv).rfind("time,", 0), 0u);
}

// What used to run forever: each is refused up front, with the estimate or the reason.
TEST_F(BadInputCli, RunsThatWouldNotEndAreRefusedUpFront) {
  const std::string pendulum = quoted(example("pendulum.yaml"));
  std::string text = slurp(example("pendulum.yaml"));
  const CliRun tiny_step = momenta("simulate " + pendulum + " --dt 1e-300");
  EXPECT_EQ(tiny_step.code, 1);
  EXPECT_TRUE(has(tiny_step.err, "below the resolution of time")) << tiny_step.err;
  const CliRun denormal = momenta("simulate " + pendulum + " --dt 4.9e-324");
  EXPECT_EQ(denormal.code, 1) << denormal.err;
  const CliRun endless = momenta("simulate " + pendulum + " --duration 1e99 --every 1000000000");
  EXPECT_EQ(endless.code, 1);
  EXPECT_TRUE(has(endless.err, "resolution of time")) << endless.err;
  // Past ±1e100, the bound every number of a file has, the option itself is refused.
  const CliRun beyond = momenta("simulate " + pendulum + " --duration 1e300");
  EXPECT_EQ(beyond.code, 2);
  EXPECT_TRUE(has(beyond.err, "--duration: must be within ±1e+100")) << beyond.err;
  const CliRun long_run = momenta("simulate " + pendulum + " --duration 1e7 --dt 1e-3");
  EXPECT_EQ(long_run.code, 1);
  EXPECT_TRUE(has(long_run.err, "would take about 1e+10 steps")) << long_run.err;
  const CliRun tight = momenta("simulate " + pendulum + " --rtol 1e-300 --atol 1e-300");
  EXPECT_EQ(tight.code, 1);
  EXPECT_TRUE(has(tight.err,
                  "--rtol 1e-300, --atol 1e-300 ask for more than double precision "
                  "holds: the relative tolerance must be at least 2.2e-14"))
      << tight.err;
  // A pulse train 1e-12 s wide every 1e-9 s: 2e10 discontinuities, each ending a step.
  std::string satellite = slurp(example("satellite_attitude.yaml"));
  const std::string width = "    width: 1.0           # s";
  ASSERT_NE(satellite.find(width), std::string::npos);
  satellite.replace(satellite.find(width), width.size(), "    width: 1e-12\n    period: 1e-9");
  const CliRun pulses = momenta("simulate " + quoted(write("pulses.yaml", satellite).string()));
  EXPECT_EQ(pulses.code, 1);
  EXPECT_TRUE(has(pulses.err, "input discontinuities")) << pulses.err;
  EXPECT_TRUE(has(pulses.err, "widen the input's pulses")) << pulses.err;
}

// Numbers whose products overflow, and text that is not UTF-8, are refused at their line.
TEST_F(BadInputCli, HugeNumbersAndInvalidUtf8AreRefusedAtTheirLine) {
  const fs::path stiff = write("stiff.yaml", R"(bodies:
  - {name: slider, mass: 1}
joints:
  - {name: rail, type: prismatic, parent: world, child: slider, axis: [1, 0, 0], q0: [0.1]}
forces:
  - {name: spring, type: spring_damper, body_a: world, body_b: slider, stiffness: 1e308}
)");
  CliRun r = momenta("simulate " + quoted(stiff.string()));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "stiff.yaml:6:")) << r.err;
  EXPECT_TRUE(has(r.err, "1e308 is too large")) << r.err;
  const fs::path inertia = write("inertia.yaml", R"(bodies:
  - {name: b, mass: 1, inertia: [1, 1, 1e308]}
joints:
  - {name: f, type: free, parent: world, child: b}
)");
  r = momenta("info " + quoted(inertia.string()));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "inertia.yaml:2:")) << r.err;
  const fs::path part = write("part.yaml",
                              "parts:\n  - {shape: sphere, radius: 0.1, mass: 1, "
                              "position: [1e308, 0, 0]}\n");
  r = momenta("inertia " + quoted(part.string()));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "part.yaml:2:")) << r.err;
  const fs::path utf8 = write("utf8.yaml",
                              "bodies:\n  - {name: \"b\xff\", mass: 1}\njoints:\n"
                              "  - {name: f, type: free, parent: world, child: b}\n");
  for (const char* command : {"info --json", "simulate"}) {
    r = momenta(std::string(command) + " " + quoted(utf8.string()));
    EXPECT_EQ(r.code, 1) << command;
    EXPECT_TRUE(has(r.err, "utf8.yaml:2:")) << r.err;
    EXPECT_TRUE(has(r.err, "not valid UTF-8")) << r.err;
    EXPECT_FALSE(has(r.err, "internal error")) << r.err;
  }
}

TEST_F(BadInputCli, StateAndMeshFileErrorsAreUserErrorsNamingTheFile) {
  const fs::path state = write("state.json", R"({"t": 1e400, "q": [0.1], "v": [0]})");
  CliRun r = momenta("linearize " + quoted(example("pendulum.yaml")) + " --about " +
                     quoted(state.string()));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "state.json:1:7: 1e400 is beyond double precision")) << r.err;
  EXPECT_FALSE(has(r.err, "internal error")) << r.err;
  const fs::path stl = write("nan.stl",
                             "solid a\nfacet normal 0 0 0\nouter loop\nvertex 0 0 nan\n"
                             "vertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n");
  r = momenta("inertia " + quoted(stl.string()));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "nan.stl:4:12:")) << r.err;
  const fs::path obj = write("words.obj", "v x y z\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  r = momenta("inertia " + quoted(obj.string()));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "words.obj:1:3: expected a number, got 'x'")) << r.err;
}

// A long run records at most 10 001 rows unless asked, and says so; rows stay exact states.
TEST_F(BadInputCli, LongRunsRecordASensibleNumberOfRows) {
  const CliRun r = momenta("simulate " + quoted(example("double_pendulum.yaml")) +
                           " --duration 100 -o " + quoted((dir_ / "dp.csv").string()));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.err, "recording one row every 20 of 200000 steps (10001 rows)")) << r.err;
  EXPECT_EQ(lines(slurp(dir_ / "dp.csv")), 10002);  // header + rows
}

// --rtol without --integrator asks for the adaptive method even when the file names rk4; its
// rows land on the grid of the largest step, t = n h exactly.
TEST_F(BadInputCli, ToleranceChoosesDopri5AndRowsLandOnTheGrid) {
  std::string text = slurp(example("pendulum.yaml"));
  ASSERT_TRUE(has(text, "integrator: rk4")) << text;
  const CliRun r = momenta("simulate " + quoted(example("pendulum.yaml")) +
                           " --rtol 1e-9 --duration 5 --dt 0.01");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.err, "dopri5")) << r.err;
  std::istringstream in(r.out);
  std::string line;
  std::getline(in, line);
  // Early steps are shorter than h (the error control starts small); a step that reaches a grid
  // time ends exactly on it.
  int on_grid = 0;
  double last = 0;
  while (std::getline(in, line)) {
    last = std::stod(line.substr(0, line.find(',')));
    const double n = std::round(last / 0.01);
    if (std::abs(last - n * 0.01) < 1e-9) {
      EXPECT_EQ(last, n * 0.01) << "row at " << last;
      ++on_grid;
    }
  }
  EXPECT_EQ(on_grid, 501);
  EXPECT_EQ(last, 5.0);
}

// Every line of a CSV has the header's number of columns and ends in a newline ("" passes: no
// file was written); returns the number of rows.
int expect_whole_rows(const std::string& text) {
  if (text.empty()) return 0;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  const auto columns = std::count(line.begin(), line.end(), ',');
  int row = 0;
  while (std::getline(in, line)) {
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), columns) << "row " << row;
    ++row;
  }
  EXPECT_EQ(text.back(), '\n');
  return row;
}

// SIGINT or SIGTERM ends the run on a whole row: every line of the CSV has every column; exit
// 130. (SIGTERM here: a shell's background job ignores SIGINT until the program takes it.) The
// signal goes once the CSV has rows — the handler is in place before the file is opened — not
// after a fixed second, which a loaded machine (a sanitizer build beside another build) can
// spend before main() is reached (the run was killed outright: exit 143, no file).
TEST_F(BadInputCli, InterruptLeavesWholeRows) {
  const fs::path csv = dir_ / "long.csv", err = dir_ / "err.txt";
  const std::string command =
      quoted(MOMENTA_CLI_PATH) + " simulate " + quoted(example("double_pendulum.yaml")) +
      " --duration 100000 --every 1 -q -o " + quoted(csv.string()) + " 2>" + quoted(err.string()) +
      " & pid=$!; for i in $(seq 1200); do [ -s " + quoted(csv.string()) +
      " ] && break; sleep 0.1; done; sleep 0.2; kill -TERM $pid; wait $pid; exit $?";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130) << slurp(err);
  EXPECT_TRUE(has(slurp(err), "whole rows written")) << slurp(err);
  EXPECT_GT(expect_whole_rows(slurp(csv)), 10);
}

// Runs `momenta <args>` as a shell script's background job (SIGINT ignored until momenta takes
// it), sends SIGINT as soon as /proc shows momenta running with it caught (bit 2 of SigCgt),
// then runs `after` (a shell command), and returns the exit status; a watchdog kills the run
// after 60 s (exit 137), so a lost signal fails, not hangs.
int interrupt_once_caught(const std::string& args, const std::string& after = ":") {
  const std::string command =
      quoted(MOMENTA_CLI_PATH) + " " + args +
      " & pid=$!; (sleep 60 & s=$!; trap \"kill $s; exit\" TERM; wait $s; kill -KILL $pid) "
      ">/dev/null 2>&1 & watchdog=$!;"
      " for i in $(seq 100000); do"
      "   [[ $(readlink /proc/$pid/exe) == */momenta ]] || continue;"
      "   mask=$(sed -n 's/^SigCgt:[[:space:]]*//p' /proc/$pid/status 2>/dev/null);"
      "   [ -n \"$mask\" ] && (( 0x$mask & 2 )) && break; done;"
      " kill -INT $pid; " +
      after + "; wait $pid; code=$?; kill $watchdog; exit $code";
  return std::system(("bash -c " + quoted(command)).c_str());
}

// A signal that comes as a run starts — while the model is read — is kept for the run, not lost.
// A shell's background job starts with SIGINT ignored, and an ignored signal is discarded: momenta
// takes SIGINT as main() begins, before the command line is parsed or the model read. The signal
// goes as soon as /proc shows it caught (bit 2 of SigCgt), so before or while the model loads on
// any machine but a very fast one; the run (100 000 s) must end within the watchdog's 60 s with
// exit 130, no file or whole rows, and the reason said.
TEST_F(BadInputCli, InterruptAsTheRunStartsIsHonoured) {
  const fs::path csv = dir_ / "early.csv", err = dir_ / "err.txt";
  const int status = interrupt_once_caught("simulate " + quoted(example("double_pendulum.yaml")) +
                                           " --duration 100000 --every 10 -q -o " +
                                           quoted(csv.string()) + " 2>" + quoted(err.string()));
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130) << slurp(err);
  EXPECT_TRUE(has(slurp(err), "stopped")) << slurp(err);
  expect_whole_rows(slurp(csv));
}

// The same while the inputs are read, deterministically: the state file is a FIFO, so momenta
// waits in its open() until the test has sent the signal and then writes the state. The run
// never begins, and nothing is written. (Before the handler was taken first, the signal was
// discarded — SIGINT ignored — and the 100 000 s run began.)
TEST_F(BadInputCli, InterruptWhileTheInputsAreReadEndsBeforeTheRun) {
  const fs::path fifo = dir_ / "state.fifo", csv = dir_ / "never.csv", err = dir_ / "err.txt";
  ASSERT_EQ(std::system(("mkfifo " + quoted(fifo.string())).c_str()), 0);
  const int status = interrupt_once_caught(
      "simulate " + quoted(example("pendulum.yaml")) + " --duration 100000 -q --state " +
          quoted(fifo.string()) + " -o " + quoted(csv.string()) + " 2>" + quoted(err.string()),
      "echo '{\"q\": [0.5], \"v\": [0]}' > " + quoted(fifo.string()));
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130) << slurp(err);
  EXPECT_TRUE(has(slurp(err), "stopped on request before the run began; nothing was written"))
      << slurp(err);
  EXPECT_FALSE(fs::exists(csv));
}

// With SIGINT's default action inherited (a terminal's foreground job), a signal at any moment
// ends the run promptly: killed before main() (no file), or stopped by momenta with whole rows.
// The delay counts from momenta's exec (/proc/PID/exe), not from the shell's fork: until `env`
// has reset it, the background job's SIGINT is the shell's ignored one.
TEST_F(BadInputCli, InterruptAtAnyMomentEndsTheRunPromptly) {
  for (const char* delay : {"0", "0.005", "0.02", "0.05", "0.2"}) {
    SCOPED_TRACE(delay);
    const fs::path csv = dir_ / (std::string("at_") + delay + ".csv");
    const std::string command =
        "env --default-signal=INT " + quoted(MOMENTA_CLI_PATH) + " simulate " +
        quoted(example("double_pendulum.yaml")) + " --duration 100000 --every 10 -q -o " +
        quoted(csv.string()) +
        " 2>/dev/null & pid=$!; (sleep 60 & s=$!; trap \"kill $s; exit\" TERM; wait $s; kill -KILL "
        "$pid) >/dev/null 2>&1 &" +
        " watchdog=$!; for i in $(seq 100000); do"
        " [[ $(readlink /proc/$pid/exe) == */momenta ]] && break; done; sleep " +
        delay + "; kill -INT $pid; wait $pid; code=$?; kill $watchdog; exit $code";
    const int status = std::system(("bash -c " + quoted(command)).c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 130);  // 128 + SIGINT, killed or stopped: not the watchdog's 137
    expect_whole_rows(slurp(csv));
  }
}

}  // namespace
}  // namespace momenta
