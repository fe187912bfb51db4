// `momenta sweep` and `momenta sweep-merge` as a user runs them: the same file from any thread
// count, MPI rank count or shard split; a killed sweep resumed to the file an uninterrupted one
// writes; rows equal to `momenta simulate` and `momenta modes` runs of the changed model.

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace momenta::test {
namespace {

const std::string kRide = "examples/sweeps/quarter_car_ride.yaml";
const std::string kPoles = "examples/sweeps/quarter_car_poles.yaml";

class SweepCli : public CliTest {
 protected:
  std::string at(const std::string& name) const { return quoted((dir_ / name).string()); }
  // A shell command line with the momenta binary in front: for mpirun and timeout.
  int shell(const std::string& before, const std::string& args) const {
    const std::string command = before + " " + quoted(MOMENTA_CLI_PATH) + " " + args + " >" +
                                quoted((dir_ / "shell.out").string()) + " 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::string file(const std::string& name) const { return slurp(dir_ / name); }
  // A results file with its `inputs` cells blanked: for sweeps of two sweep files that differ in
  // their trajectories' folder alone, whose inputs differ as their bytes do.
  std::string file_but_inputs(const std::string& name) const {
    return std::regex_replace(file(name), std::regex(",sha256:[0-9a-f]{16},"), ",,");
  }
  // Starts a sweep in the background and kills it (SIGKILL: no chance to tidy up) as soon as its
  // file holds a few rows, whatever the build's speed (a fixed timeout killed a sanitizer build
  // before its first row). Gives up waiting after 60 s.
  void kill_once_rows_are_written(const std::string& sweep, const std::string& name) const {
    const std::string out = at(name);
    const std::string script = quoted(MOMENTA_CLI_PATH) + " sweep " + sweep + " -o " + out +
                               " --no-timing --threads 2 >/dev/null 2>&1 & pid=$!; i=0; "
                               "while [ \"$(cat " +
                               out +
                               " 2>/dev/null | wc -l)\" -lt 4 ] && [ $i -lt 3000 ] && "
                               "kill -0 $pid 2>/dev/null; do sleep 0.02; i=$((i+1)); done; "
                               "kill -KILL $pid 2>/dev/null; wait $pid 2>/dev/null; true";
    ASSERT_EQ(std::system(script.c_str()), 0);
  }
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  return cells;
}

// A sweep file with CSV trajectories into the folder `folder`: four quarter cars.
void write_trajectory_sweep(const std::filesystem::path& path, const std::string& folder) {
  std::ofstream(path) << "model: "
                      << std::filesystem::absolute("examples/quarter_car.yaml").string()
                      << "\nsimulation: {duration: 0.5, step: 0.001, integrator: rk4, every: 10}\n"
                         "parameters:\n  - {path: bodies.body.mass, name: m2, values: [300, 350, "
                         "400, 450]}\nmetrics:\n  - final: body_y\ntrajectories: "
                      << folder << "\n";
}

TEST_F(SweepCli, ThreadCountsRanksAndShardsGiveTheSameFile) {
  const CliRun one = momenta("sweep " + kRide + " -o " + at("t1.csv") + " --threads 1 --no-timing");
  ASSERT_EQ(one.code, 0) << one.err;
  EXPECT_NE(one.err.find("48 runs"), std::string::npos) << one.err;
  EXPECT_NE(one.err.find("max(body_y)"), std::string::npos) << one.err;  // the summary
  const std::string whole = file("t1.csv");
  ASSERT_EQ(lines_of(whole).size(), 49U);
  for (const char* threads : {"2", "8"}) {
    const std::string name = std::string("t") + threads + ".csv";
    ASSERT_EQ(
        momenta("sweep " + kRide + " -o " + at(name) + " --no-timing --threads " + threads).code,
        0);
    EXPECT_EQ(file(name), whole) << threads << " threads";
  }
  // Three shards, merged (given out of order).
  for (int k = 1; k <= 3; ++k) {
    const std::string name = fmt::format("s{}.csv", k);
    ASSERT_EQ(
        momenta("sweep " + kRide + " -o " + at(name) + fmt::format(" --no-timing --shard {}/3", k))
            .code,
        0);
  }
  const CliRun merged = momenta("sweep-merge " + kRide + " " + at("s3.csv") + " " + at("s1.csv") +
                                " " + at("s2.csv") + " -o " + at("merged.csv") + " --no-timing");
  ASSERT_EQ(merged.code, 0) << merged.err;
  EXPECT_EQ(file("merged.csv"), whole);
  const CliRun short_one =
      momenta("sweep-merge " + kRide + " " + at("s1.csv") + " -o " + at("m2.csv") + " --no-timing");
  EXPECT_EQ(short_one.code, 1);
  EXPECT_NE(short_one.err.find("run 1 is in none of the files"), std::string::npos)
      << short_one.err;
  // The default file carries each run's wall time: the same rows but for that column.
  ASSERT_EQ(momenta("sweep " + kRide + " -o " + at("timed.csv")).code, 0);
  const auto timed = lines_of(file("timed.csv"));
  EXPECT_EQ(cells_of(timed[0]).at(10), "wall_s");
}

#ifdef MOMENTA_TEST_MPI
TEST_F(SweepCli, MpiRanksGiveTheFileOneProcessWrites) {
  ASSERT_EQ(momenta("sweep " + kRide + " -o " + at("one.csv") + " --no-timing").code, 0);
  // Ranks × threads: one thread a rank, and several (a rank's threads take the runs it was
  // handed as they free up, and it asks for more before they run out).
  const std::vector<std::pair<std::string, std::string>> splits = {
      {"1", "1"}, {"2", "1"}, {"3", "1"}, {"2", "3"}};
  for (const auto& [ranks, threads] : splits) {
    const std::string name = "mpi" + ranks + "x" + threads + ".csv";
    // Under AddressSanitizer (CI's second build), OpenMPI's own allocations at exit are not
    // momenta's leaks: leak checking is off for the ranks.
    const int code =
        shell(std::string("ASAN_OPTIONS=\"$ASAN_OPTIONS:detect_leaks=0\" "
                          "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
                          "OMPI_MCA_rmaps_base_oversubscribe=1 timeout 120 mpirun "
                          "--oversubscribe -n ") +
                  ranks,
              "sweep " + kRide + " -o " + at(name) + " --no-timing --threads " + threads);
    ASSERT_EQ(code, 0) << file("shell.out");
    EXPECT_EQ(file(name), file("one.csv")) << ranks << " ranks × " << threads << " threads";
    EXPECT_NE(file("shell.out").find(std::string("on ") + ranks + " ranks"), std::string::npos)
        << file("shell.out");
  }
}

// Rank 0 writes every run's trajectory: its own threads' as they finish, the other ranks' (their
// text formatted there) as they arrive. The files are those of one process.
TEST_F(SweepCli, MpiRanksWriteTheTrajectoriesOneProcessWrites) {
  write_trajectory_sweep(dir_ / "one.yaml", "one");
  ASSERT_EQ(momenta("sweep " + at("one.yaml") + " -o " + at("one.csv") + " --no-timing").code, 0);
  for (const std::string threads : {"1", "3"}) {
    const std::string mpi = "mpi" + threads;
    write_trajectory_sweep(dir_ / (mpi + ".yaml"), mpi);
    const int code = shell(
        "ASAN_OPTIONS=\"$ASAN_OPTIONS:detect_leaks=0\" OMPI_ALLOW_RUN_AS_ROOT=1 "
        "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 timeout 120 mpirun "
        "--oversubscribe -n 2",
        "sweep " + at(mpi + ".yaml") + " -o " + at(mpi + ".csv") + " --no-timing --threads " +
            threads);
    ASSERT_EQ(code, 0) << file("shell.out");
    EXPECT_EQ(file_but_inputs(mpi + ".csv"), file_but_inputs("one.csv")) << threads << " threads";
    for (int run = 0; run < 4; ++run) {
      const std::string name = fmt::format("run_{:06d}.csv", run);
      EXPECT_EQ(slurp(dir_ / mpi / name), slurp(dir_ / "one" / name)) << name;
    }
  }
}

// Ctrl-C under mpirun ends the whole job: mpirun sends every rank SIGTERM a second later and
// SIGKILL a second after that, and MPI_Finalize waits on mpirun, which no longer answers. Rank 0
// says how to go on before then; the rows written are whole. (960 runs of about 12 ms: the job
// outlasts the second before the SIGTERM on any machine; the interrupt comes once rows are
// written, whatever the build's speed. `timeout --foreground` passes the one SIGINT on to mpirun
// alone: without it, timeout also signals its process group, and mpirun, seeing a second Ctrl-C,
// kills the job at once.)
TEST_F(SweepCli, AnInterruptedMpiSweepSaysHowToGoOn) {
  std::ofstream(dir_ / "long.yaml")
      << "model: " << std::filesystem::absolute("examples/quarter_car.yaml").string()
      << "\nsimulation: {duration: 2.0, step: 0.001, integrator: rk4}\n"
         "parameters:\n"
         "  - {path: forces.suspension.stiffness, range: {from: 6e4, to: 2e5, count: 40}}\n"
         "  - {path: forces.suspension.damping, range: {from: 2000, to: 20000, count: 24}}\n"
         "metrics:\n  - max: body_y\n";
  const std::string out = at("cut.csv");
  const std::string script =
      "ASAN_OPTIONS=\"$ASAN_OPTIONS:detect_leaks=0\" OMPI_ALLOW_RUN_AS_ROOT=1 "
      "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 timeout --foreground "
      "120 mpirun --oversubscribe -n 2 " +
      quoted(MOMENTA_CLI_PATH) + " sweep " + at("long.yaml") + " -o " + out +
      " --no-timing --threads 1 >" + at("shell.out") + " 2>&1 & pid=$!; i=0; while [ \"$(cat " +
      out +
      " 2>/dev/null | wc -l)\" -lt 4 ] && [ $i -lt 3000 ] && kill -0 $pid 2>/dev/null; do sleep "
      "0.02; i=$((i+1)); done; kill -INT $pid; wait $pid; echo $? >" +
      at("code");
  ASSERT_EQ(std::system(script.c_str()), 0);
  const std::string said = file("shell.out");
  EXPECT_NE(file("code").find("1"), std::string::npos) << file("code");  // mpirun's, not ours
  const std::regex interrupted(
      "momenta: interrupted: ([0-9]+) of 960 runs written to .*cut\\.csv; "
      "`momenta sweep .*long\\.yaml -o .*cut\\.csv --resume` goes on");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(said, match, interrupted)) << said;
  const auto rows = lines_of(file("cut.csv"));
  EXPECT_EQ(rows.size(), std::stoul(match[1]) + 1);  // the header and the runs it names
  EXPECT_LT(rows.size(), 961U);
  const auto commas = [](const std::string& row) {
    return std::count(row.begin(), row.end(), ',');
  };
  for (const std::string& row : rows) EXPECT_EQ(commas(row), commas(rows[0])) << row;
}
#endif

TEST_F(SweepCli, AKilledSweepResumesToTheFileAnUninterruptedOneWrites) {
  // 240 runs of about 3 ms each (release build; 0.3 s on two threads, the kill comes within
  // 40 ms of the first rows), killed (SIGKILL) after its first few rows. Short runs keep the
  // sanitizer build's three sweeps of it within the test's time on a busy machine.
  std::ofstream(dir_ / "long.yaml")
      << "model: " << std::filesystem::absolute("examples/quarter_car.yaml").string()
      << "\nsimulation: {duration: 0.5, step: 0.001, integrator: rk4}\n"
         "parameters:\n"
         "  - {path: forces.suspension.stiffness, range: {from: 6e4, to: 2e5, count: 40}}\n"
         "  - {path: forces.suspension.damping, range: {from: 2000, to: 20000, count: 6}}\n"
         "metrics:\n  - max: body_y\n  - {settling_time: body_y}\n";
  const std::string sweep = at("long.yaml");
  ASSERT_EQ(momenta("sweep " + sweep + " -o " + at("whole.csv") + " --no-timing").code, 0);
  kill_once_rows_are_written(sweep, "cut.csv");
  const std::size_t written = lines_of(file("cut.csv")).size();
  ASSERT_GT(written, 1U) << "killed before any run was written";
  ASSERT_LT(written, 241U) << "finished before it was killed: nothing to resume";
  // Without --resume or --force the file is kept.
  const CliRun refused = momenta("sweep " + sweep + " -o " + at("cut.csv") + " --no-timing");
  EXPECT_EQ(refused.code, 1);
  EXPECT_NE(refused.err.find("--resume continues"), std::string::npos) << refused.err;
  const CliRun resumed =
      momenta("sweep " + sweep + " -o " + at("cut.csv") + " --no-timing --resume");
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("runs left"), std::string::npos) << resumed.err;
  EXPECT_EQ(file("cut.csv"), file("whole.csv"));
  // Resuming a finished sweep runs nothing and changes nothing; another sweep's file is refused.
  ASSERT_EQ(momenta("sweep " + sweep + " -o " + at("cut.csv") + " --no-timing --resume").code, 0);
  EXPECT_EQ(file("cut.csv"), file("whole.csv"));
  const CliRun other =
      momenta("sweep " + kPoles + " -o " + at("cut.csv") + " --no-timing --resume");
  EXPECT_EQ(other.code, 1);
  EXPECT_NE(other.err.find("another sweep"), std::string::npos) << other.err;
  EXPECT_EQ(momenta("sweep " + sweep + " -o " + at("x.csv") + " --resume --force").code, 2);
}

TEST_F(SweepCli, TrajectoriesHoldEveryRunsWholeTable) {
  write_trajectory_sweep(dir_ / "traj.yaml", "runs");
  const CliRun r = momenta("sweep " + at("traj.yaml") + " -o " + at("traj.csv") + " --no-timing");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = lines_of(file("traj.csv"));
  for (int run = 0; run < 4; ++run) {
    const std::string name = fmt::format("run_{:06d}.csv", run);
    const auto table = lines_of(slurp(dir_ / "runs" / name));
    ASSERT_EQ(table.size(), 52U) << run;  // the header and 51 rows: every 10th of 500 steps
    const auto header = cells_of(table[0]);
    const auto y = static_cast<std::size_t>(std::find(header.begin(), header.end(), "body_y") -
                                            header.begin());
    ASSERT_LT(y, header.size());
    // The metric is the table's last body_y, the same digits.
    EXPECT_EQ(cells_of(table.back())[y], cells_of(rows[static_cast<std::size_t>(run) + 1])[2]);
  }
  // Each thread writes the files of its own runs: one thread writes the same bytes as three.
  write_trajectory_sweep(dir_ / "traj1.yaml", "runs1");
  ASSERT_EQ(
      momenta("sweep " + at("traj1.yaml") + " -o " + at("traj1.csv") + " --no-timing --threads 1")
          .code,
      0);
  write_trajectory_sweep(dir_ / "traj3.yaml", "runs3");
  ASSERT_EQ(
      momenta("sweep " + at("traj3.yaml") + " -o " + at("traj3.csv") + " --no-timing --threads 3")
          .code,
      0);
  for (int run = 0; run < 4; ++run) {
    const std::string name = fmt::format("run_{:06d}.csv", run);
    EXPECT_EQ(slurp(dir_ / "runs1" / name), slurp(dir_ / "runs" / name)) << name;
    EXPECT_EQ(slurp(dir_ / "runs3" / name), slurp(dir_ / "runs" / name)) << name;
  }
  // Run again without --force: the folder with its tables is kept.
  EXPECT_EQ(momenta("sweep " + at("traj.yaml") + " -o " + at("traj2.csv") + " --no-timing").code,
            1);
}

// A model file with the suspension's numbers set, as a user would edit it by hand.
std::string edited_quarter_car(double ks, double b) {
  std::string text = slurp("examples/quarter_car.yaml");
  text = std::regex_replace(text, std::regex("stiffness: 130000\\.0"),
                            fmt::format("stiffness: {}", ks));
  text = std::regex_replace(text, std::regex("damping: 9800\\.0"), fmt::format("damping: {}", b));
  return text;
}

TEST_F(SweepCli, RowsEqualSimulateAndModesRunsOfTheEditedModel) {
  ASSERT_EQ(momenta("sweep " + kRide + " -o " + at("ride.csv") + " --no-timing").code, 0);
  const auto ride = lines_of(file("ride.csv"));
  for (std::size_t row : {1U, 20U, 48U}) {
    const auto cells = cells_of(ride[row]);
    std::ofstream(dir_ / "car.yaml")
        << edited_quarter_car(std::stod(cells[1]), std::stod(cells[2]));
    const CliRun sim = momenta("simulate " + at("car.yaml") +
                               " --integrator rk4 --dt 0.001 "
                               "--duration 2 --force -o " +
                               at("car.csv"));
    ASSERT_EQ(sim.code, 0) << sim.err;
    const auto table = lines_of(file("car.csv"));
    const auto header = cells_of(table[0]);
    const auto y = static_cast<std::size_t>(std::find(header.begin(), header.end(), "body_y") -
                                            header.begin());
    double y_max = -1e300;
    std::string y_max_text;
    for (std::size_t r = 1; r < table.size(); ++r) {
      const std::string cell = cells_of(table[r])[y];
      if (std::stod(cell) > y_max) {
        y_max = std::stod(cell);
        y_max_text = cell;
      }
    }
    EXPECT_EQ(cells[3], y_max_text) << "row " << row;  // the same digits: the same double
  }
  ASSERT_EQ(momenta("sweep " + kPoles + " -o " + at("poles.csv") + " --no-timing").code, 0);
  const auto poles = lines_of(file("poles.csv"));
  for (std::size_t row : {1U, 100U, 189U}) {
    const auto cells = cells_of(poles[row]);
    std::string text = edited_quarter_car(std::stod(cells[1]), std::stod(cells[2]));
    text = std::regex_replace(text, std::regex("mass: 375\\.0"), "mass: " + cells[3]);
    std::ofstream(dir_ / "car.yaml") << text;
    const CliRun modes = momenta("modes " + at("car.yaml") + " --json");
    ASSERT_EQ(modes.code, 0) << modes.err;
    const nlohmann::json j = nlohmann::json::parse(modes.out);
    for (std::size_t i = 0; i < 4; ++i) {
      const auto& lambda = j.at("modes").at(i).at("eigenvalue");
      EXPECT_EQ(std::stod(cells[4 + 2 * i]), lambda.at(0).get<double>()) << row << " pole " << i;
      EXPECT_EQ(std::stod(cells[5 + 2 * i]), lambda.at(1).get<double>()) << row << " pole " << i;
    }
  }
}

}  // namespace
}  // namespace momenta::test
