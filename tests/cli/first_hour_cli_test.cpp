// What a new user meets in the first hour (issue 26): bare `momenta`, `simulate` on a terminal,
// outputs checked before anything runs, and each kind of bad input a battery of 1 759 cases
// found answered badly — a hang, a non-finite number printed as a result, a library's raw
// message, data lost, a mistake accepted, a wrong exit code. Each test failed before its fix.
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta {
namespace {
namespace first_hour {  // the file's helpers apart from the other CLI tests' (one unity unit)

namespace fs = std::filesystem;
using test::CliRun;
using test::quoted;
using test::slurp;

std::string source_dir() { return fs::absolute(test::source_dir()).lexically_normal().string(); }

std::string example(const std::string& name) { return quoted(source_dir() + "/examples/" + name); }

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Neither "nan" nor "inf" as a word: what a result must never show.
bool shows_non_finite(const std::string& text) {
  static const std::regex word(R"((^|[^A-Za-z_])(-?nan|-?inf)([^A-Za-z_]|$))", std::regex::icase);
  return std::regex_search(text, word);
}

class FirstHourCli : public test::CliTest {
 protected:
  std::string at(const std::string& name) const { return quoted((dir_ / name).string()); }
  // `momenta <args>` with stdout a terminal (script(1) gives it a pseudo-terminal); what the
  // terminal shows.
  std::string on_a_terminal(const std::string& args) const {
    const fs::path out = dir_ / "terminal.txt";
    const std::string command = "script -qec " +
                                quoted(quoted(MOMENTA_CLI_PATH) + " " + args + " 2>/dev/null") +
                                " /dev/null >" + quoted(out.string());
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    return slurp(out);
  }
  // The same with the exit code and stderr kept apart.
  CliRun on_a_terminal_run(const std::string& args) const {
    const fs::path out = dir_ / "terminal.txt", err = dir_ / "terminal_err.txt";
    const std::string command =
        "script -qec " +
        quoted(quoted(MOMENTA_CLI_PATH) + " " + args + " 2>" + quoted(err.string())) +
        " /dev/null >" + quoted(out.string());
    CliRun r;
    const int status = std::system(command.c_str());
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }
  // A sweep file beside the scratch folder's files, over the example quarter car.
  fs::path sweep_file(const std::string& name, const std::string& parameters,
                      const std::string& metrics = "  - max: body_y\n",
                      const std::string& design = "") const {
    return write(name, "name: test sweep\nmodel: " + source_dir() +
                           "/examples/quarter_car.yaml\njob: simulate\n"
                           "simulation: {duration: 0.05, step: 0.001}\n" +
                           design + "parameters:\n" + parameters + "metrics:\n" + metrics);
  }
};

TEST_F(FirstHourCli, BareMomentaListsEveryCommandOnALineEach) {
  const CliRun bare = momenta("");
  EXPECT_EQ(bare.code, 0);
  // The commands CLI11 knows, from --help, each listed once on a line of its own.
  const CliRun help = momenta("--help");
  std::set<std::string> known;
  std::istringstream lines(help.out.substr(help.out.find("Subcommands:")));
  std::string line;
  std::getline(lines, line);
  const std::regex command_line("^  ([a-z-]+)  +.*");  // a description's own lines are not
  std::smatch match;
  while (std::getline(lines, line) && !line.empty()) {
    if (std::regex_match(line, match, command_line)) known.insert(match[1]);
  }
  ASSERT_GE(known.size(), 15u) << help.out;
  for (const std::string& name : known) {
    EXPECT_TRUE(std::regex_search(bare.out, std::regex("\n  " + name + " +[a-z]"))) << name;
  }
  EXPECT_EQ(std::count(bare.out.begin(), bare.out.end(), '\n'), static_cast<long>(known.size()) + 9)
      << bare.out;
}

TEST_F(FirstHourCli, SimulateOnATerminalShowsATableAndHowToSaveEveryRow) {
  const std::string shown =
      on_a_terminal("simulate " + example("double_pendulum.yaml") + " --duration 1");
  EXPECT_TRUE(has(shown, "time")) << shown;
  EXPECT_TRUE(has(shown, "2001 rows x 17 columns in all")) << shown;
  EXPECT_TRUE(has(shown, "-o run.csv")) << shown;
  EXPECT_LT(std::count(shown.begin(), shown.end(), '\n'), 15) << shown;
  // The last row shown is t = 1 s.
  EXPECT_TRUE(std::regex_search(shown, std::regex("\n +1 +-0\\.625088"))) << shown;
  // Piped, stdout is the whole CSV.
  const CliRun piped = momenta("simulate " + example("double_pendulum.yaml") + " --duration 1");
  EXPECT_EQ(piped.code, 0);
  EXPECT_EQ(std::count(piped.out.begin(), piped.out.end(), '\n'), 2002);
}

TEST_F(FirstHourCli, OutputsAreCheckedBeforeAnythingRunsOrIsWritten) {
  // A run refused up front leaves no file, and --force does not replace the old one by a header.
  CliRun r =
      momenta("simulate " + example("pendulum.yaml") + " --duration 1e7 -o " + at("new.csv"));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "about 1e+10 steps")) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "new.csv"));
  write("old.csv", "the user's data\n");
  r = momenta("simulate " + example("pendulum.yaml") + " --duration 1e7 --force -o " +
              at("old.csv"));
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(slurp(dir_ / "old.csv"), "the user's data\n");
  // One file for both outputs, even with --force.
  r = momenta("simulate " + example("pendulum.yaml") + " -o " + at("same") + " --report " +
              at("./same") + " --force");
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "--output and --report both name")) << r.err;
  // The report's names, checked before the run rather than silently dropped after it.
  r = momenta("simulate " + example("pendulum.yaml") + " -o " + at("run.csv") + " --report " +
              at("r.html") + " --inputs nosuch");
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "no input named 'nosuch'")) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "run.csv"));
  EXPECT_FALSE(fs::exists(dir_ / "r.html"));
  // `report` refuses an existing page before it simulates.
  write("page.html", "mine");
  r = momenta("report " + example("pendulum.yaml") + " -o " + at("page.html"));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "pass --force")) << r.err;
  EXPECT_EQ(slurp(dir_ / "page.html"), "mine");
}

TEST_F(FirstHourCli, AYamlAliasBombIsRefusedAtOnceByEveryReader) {
  // 9 levels of 9 aliases (1.2 kB): the unterminated-quote check once walked 387 million nodes.
  std::string bomb = "a0: &a0 [lol]\n";
  for (int level = 1; level < 9; ++level) {
    bomb += "a" + std::to_string(level) + ": &a" + std::to_string(level) + " [";
    for (int k = 0; k < 9; ++k) bomb += (k ? ", *a" : "*a") + std::to_string(level - 1);
    bomb += "]\n";
  }
  const fs::path file = write("lol.yaml", bomb);
  // `timeout` turns a hang into exit 124 instead of holding the test to its limit.
  for (const std::string command : {"info", "inertia", "sweep"}) {
    const CliRun r = momenta_with_timeout(command + " " + quoted(file.string()) +
                                          (command == "sweep" ? " -o " + at("x.csv") : ""));
    EXPECT_EQ(r.code, 1) << command << ": " << r.err;
    EXPECT_TRUE(has(r.err, "lol.yaml:7:")) << r.err;
    EXPECT_TRUE(has(r.err, "expand it to more than 1000000 nodes")) << r.err;
  }
}

TEST_F(FirstHourCli, StateFilesAreReadInMomentasWordsWithTheirPosition) {
  const std::string pendulum = example("pendulum.yaml");
  const auto error_of = [&](const std::string& name, const std::string& text) {
    const fs::path file = write(name, text);
    const CliRun r = momenta("modes " + pendulum + " --about " + quoted(file.string()));
    EXPECT_EQ(r.code, 1) << name;
    EXPECT_FALSE(has(r.err, "json.exception")) << r.err;
    EXPECT_FALSE(has(r.err, "internal error")) << r.err;
    return r.err;
  };
  EXPECT_TRUE(has(error_of("empty.json", ""), "empty.json:1:1: the file is empty"));
  EXPECT_TRUE(has(error_of("nan.json", "{\"q\": [NaN], \"v\": [0]}"),
                  "nan.json:1:8: JSON has no NaN or Infinity"));
  EXPECT_TRUE(has(error_of("inf.json", "{\"q\": [0],\n \"v\": [Infinity]}"), "inf.json:2:8:"));
  EXPECT_TRUE(has(error_of("big.json", "{\"q\": [1e400], \"v\": [0]}"),
                  "big.json:1:8: 1e400 is beyond double precision"));
  EXPECT_TRUE(has(error_of("tail.json", "{\"q\": [0], \"v\": [0]} and more"),
                  "tail.json:1:22: text after the JSON value"));
  EXPECT_TRUE(has(error_of("binary.json", std::string("\x7f"
                                                      "ELF\x02\x01",
                                                      6)),
                  "binary.json:1:5: not a text file (byte 0x02)"));
  EXPECT_TRUE(has(error_of("huge.json", "{\"q\": [1e200], \"v\": [0]}"),
                  "huge.json: q[0] = 1e+200 is beyond ±1e+100"));
  // A missing or wrongly sized state is refused even where it would not be used: equations
  // hold at every instant, so --state and --time belong to --form linear and --transfer.
  const CliRun unused = momenta("equations " + pendulum + " --state " + at("gone.json"));
  EXPECT_EQ(unused.code, 2);
  EXPECT_TRUE(has(unused.err, "--state: sets the operating point of --form linear")) << unused.err;
  const CliRun late = momenta("equations " + pendulum + " --time 1e300");
  EXPECT_EQ(late.code, 2);
}

TEST_F(FirstHourCli, EveryPrintedNumberIsFiniteOrTheCommandRefuses) {
  struct Case {
    std::string args;
    int code;  // 0: runs and prints only finite numbers; else the exit code of the refusal
  };
  const std::vector<Case> cases = {
      {"inertia " + example("parts/flywheel.yaml") + " --about 1e308 0 0", 2},
      {"inertia " + example("parts/flywheel.yaml") + " --about 1e100 0 0", 0},
      {"balance " + example("parts/overhung_fan.yaml") + " --bearings 0.05 0.25 --speed 1e150", 2},
      {"balance " + example("parts/overhung_fan.yaml") +
           " --bearings 0.05 0.25 --speed 3000 --alpha 1e300",
       2},
      {"balance " + example("parts/overhung_fan.yaml") +
           " --bearings 0.05 0.25 --speed 3000 --gravity nan",
       2},
      {"balance " + example("parts/overhung_fan.yaml") +
           " --bearings 0.05 0.25 --speed-range 100 200 --points 100000000",
       2},
      {"steady " + example("heavy_top.yaml") + " --tilt 20 --spin 0", 0},
      {"steady " + example("heavy_top.yaml") + " --tilt 20 --spin 0 --json", 0},
      {"steady " + example("heavy_top.yaml") + " --tilt 120 --spin 0", 0},
      {"steady " + example("heavy_top.yaml") + " --tilt 20 --spin 1e308", 2},
      {"steady " + example("heavy_top.yaml") + " --tilt nan --spin 1", 2},
      {"kinematics " + example("kinematics/turntable_bead.yaml") +
           " --point bead:1e308,0,0 --frame turntable",
       2},
      {"modes " + example("constraints/chaplygin_sleigh.yaml"), 0},
      {"modes " + example("free_body_tennis_racket.yaml"), 0},
      {"response " + example("satellite_attitude.yaml") + " --input thrust --output theta --step",
       0},
      {"response " + example("satellite_attitude.yaml") +
           " --input thrust --output theta --bode 0.1 10 --csv -",
       0},
      {"response " + example("cruise_control.yaml") +
           " --input u --output speed --step --duration 1e-300",
       0},
  };
  for (const Case& c : cases) {
    const CliRun r = momenta(c.args);
    EXPECT_EQ(r.code, c.code) << c.args << "\n" << r.out << r.err;
    EXPECT_FALSE(shows_non_finite(r.out)) << c.args << "\n" << r.out;
    EXPECT_FALSE(has(r.err, "internal error")) << c.args << "\n" << r.err;
  }
  // A top without gravity: the vertical is world z (as for its modes), every number finite.
  std::string top = slurp(source_dir() + "/examples/heavy_top.yaml");
  const std::string gravity = "gravity: [0, 0, -9.81]";
  ASSERT_NE(top.find(gravity), std::string::npos);
  top.replace(top.find(gravity), gravity.size(), "gravity: [0, 0, 0]");
  const std::string weightless = quoted(write("weightless_top.yaml", top).string());
  for (const std::string format : {"", " --json"}) {
    const CliRun r = momenta("steady " + weightless + " --tilt 20 --spin 300" + format);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_FALSE(shows_non_finite(r.out)) << r.out;
    EXPECT_FALSE(has(r.out, "null")) << r.out;
  }
  // Unstable: the response overflows double precision in time; refused, naming when.
  // An inverted pendulum, linearized about its upright initial state: λ = ±√(g/L) = ±3.13/s.
  const fs::path unstable = write("unstable.yaml", R"(gravity: [0, 0, -9.81]
inputs:
  - {name: u, type: step, start: 0, initial: 0, final: 1}
bodies:
  - {name: bob, shape: point_mass, mass: 1, position: [0, 0, 1]}
joints:
  - {name: pivot, type: revolute, parent: world, child: bob, axis: [0, 1, 0]}
forces:
  - {name: push, type: torque, body: bob, vector: [0, 1, 0], signal: u}
outputs:
  - {name: theta, joint: pivot, quantity: position}
)");
  const CliRun overflow = momenta("response " + quoted(unstable.string()) +
                                  " --input u --output theta --step --duration 1000");
  EXPECT_EQ(overflow.code, 1) << overflow.out << overflow.err;
  EXPECT_TRUE(has(overflow.err, "overflows before t = 1000 s; choose a shorter final time"))
      << overflow.err;
  EXPECT_FALSE(shows_non_finite(overflow.out)) << overflow.out;
}

// A URDF file is a model file (docs/model-formats.md): `info` lists what momenta does not use with
// its line; `simulate` runs the double pendulum as its YAML twin does, row for row; a bad file is
// an error at its line, exit 1.
TEST_F(FirstHourCli, UrdfFilesAreModelFiles) {
  const std::string arm = quoted(source_dir() + "/tests/data/models/urdf/three_link_arm.urdf");
  CliRun r = momenta("info " + arm);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "three link arm")) << r.out;
  EXPECT_TRUE(has(r.out, "not used by momenta (6)")) << r.out;
  // Its <limit>s are stops; their effort and velocity are listed as not enforced.
  EXPECT_TRUE(has(r.out,
                  "elbow  revolute, upper → fore, damping 0.1, stops: lower -2 rad, upper "
                  "2 rad, restitution 0"))
      << r.out;
  EXPECT_TRUE(has(r.out,
                  "three_link_arm.urdf:39: joint 'elbow': its effort (50) and velocity (3) "
                  "limits are not enforced"))
      << r.out;
  r = momenta("info " + arm + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out).at("not_used").size(), 6u);

  const std::string urdf = quoted(source_dir() + "/tests/data/models/urdf/double_pendulum.urdf");
  r = momenta("simulate " + urdf + " --duration 0.5 --dt 0.0005 --every 20 -o " + at("urdf.csv"));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string rows = slurp(dir_ / "urdf.csv");
  EXPECT_EQ(std::count(rows.begin(), rows.end(), '\n'), 52);
  // Hanging at rest, its normal modes are the double pendulum's: ω² = (g/l)(2 ∓ √2).
  r = momenta("modes " + urdf + " --about equilibrium --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto normal = nlohmann::json::parse(r.out).at("normal_modes");
  ASSERT_EQ(normal.size(), 2u);
  EXPECT_NEAR(normal[0].at("squared_frequency").get<double>(), 9.81 * (2 - std::sqrt(2.0)), 1e-11);
  EXPECT_NEAR(normal[1].at("squared_frequency").get<double>(), 9.81 * (2 + std::sqrt(2.0)), 1e-11);

  const fs::path bad = write("bad.urdf",
                             "<robot name='r'>\n<link name='a'/>\n<link name='b'/>\n"
                             "<joint name='j' type='hinge'><parent link='a'/>"
                             "<child link='b'/></joint>\n</robot>\n");
  r = momenta("info " + quoted(bad.string()));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "bad.urdf:4: joint 'j': unknown type 'hinge'")) << r.err;
}

TEST_F(FirstHourCli, MjcfFilesAreModelFiles) {
  const std::string arm = quoted(source_dir() + "/tests/data/models/mjcf/arm7.xml");
  CliRun r = momenta("info " + arm + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto info = nlohmann::json::parse(r.out);
  EXPECT_EQ(info.at("not_used").size(), 6u) << r.out;
  r = momenta("info " + arm);
  ASSERT_EQ(r.code, 0) << r.err;
  // Its ranges are stops (range="-170 170" in degrees).
  EXPECT_TRUE(has(r.out, "stops: lower -2.96706 rad, upper 2.96706 rad, restitution 0")) << r.out;
  // The humanoid falls freely for 0.2 s (no contacts): every row written.
  const std::string human = quoted(source_dir() + "/tests/data/models/mjcf/humanoid.xml");
  r = momenta("simulate " + human + " --duration 0.2 --dt 0.001 --every 50 -o " + at("fall.csv"));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string rows = slurp(dir_ / "fall.csv");
  EXPECT_EQ(std::count(rows.begin(), rows.end(), '\n'), 6);

  const fs::path bad = write("bad.xml",
                             "<mujoco>\n<worldbody>\n<body><joint type='hinge' axs='0 1 0'/>"
                             "<geom size='0.1'/></body>\n</worldbody>\n</mujoco>\n");
  r = momenta("info " + quoted(bad.string()));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "bad.xml:3:27: <joint>: unknown attribute 'axs' (did you mean 'axis'?)"))
      << r.err;
}

// A URDF whose links are meshes on package:// paths: found with --package-path, weighed with
// --link-density (the total: the four solids' closed forms at 2700 kg/m³ plus the 0.5 kg payload,
// to the COLLADA hand's single precision); weighed without the path, an error at the line of the
// collision mesh that is weighed, naming the package
// and saying what to give.
TEST_F(FirstHourCli, UrdfMeshesOnAPackagePath) {
  const std::string arm =
      quoted(source_dir() + "/tests/data/models/urdf/packages/mesh_arm/urdf/mesh_arm.urdf");
  const std::string packages = quoted(source_dir() + "/tests/data/models/urdf/packages");
  CliRun r = momenta("info " + arm + " --package-path " + packages + " --link-density 2700 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const double solids = 0.25 * 0.25 * 0.125 + 1.5 * std::sqrt(3.0) * 0.04 * 0.04 * 0.375 +
                        0.3125 * 0.0625 * 0.0625 + 0.05 * 0.08 * 0.03;  // m³
  EXPECT_NEAR(nlohmann::json::parse(r.out).at("total_mass").get<double>(), 2700 * solids + 0.5,
              1e-6)
      << r.out;
  r = momenta("simulate " + arm + " --package-path " + packages +
              " --link-density 2700 --duration 0.1 -o " + at("arm.csv"));
  ASSERT_EQ(r.code, 0) << r.err;
  r = momenta("info " + arm + " --link-density 2700");
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err,
                  "mesh_arm.urdf:16: 'package://mesh_arm/meshes/base.stl' names package "
                  "'mesh_arm', and no package path is given: give the folder that holds "
                  "it with --package-path"))
      << r.err;
  r = momenta("info " + arm + " --package-path " + packages + " --link-density -3");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(has(r.err, "--link-density")) << r.err;
}

// The URDF tutorial's R2-D2 as ROS users pass it around: every link has its <inertial>, the meshes
// come from a package (pr2_description) that is not there. It loads, says at each mesh's line
// that it is not drawn and what to give, and simulates.
TEST_F(FirstHourCli, AUrdfWithoutItsMeshPackagesLoadsWhereNothingNeedsTheMeshes) {
  std::ofstream(dir_ / "r2d2.urdf") << R"(<robot name="r2d2">
  <link name="base_link">
    <visual><geometry><cylinder length="0.6" radius="0.2"/></geometry></visual>
    <inertial><mass value="10"/><inertia ixx="1e-3" ixy="0" ixz="0" iyy="1e-3" iyz="0" izz="1e-3"/></inertial>
  </link>
  <link name="head">
    <visual><geometry><mesh filename="package://pr2_description/meshes/gripper_v0/l_finger.dae"/></geometry></visual>
    <collision><geometry><mesh filename="package://pr2_description/meshes/gripper_v0/l_finger.dae"/></geometry></collision>
    <inertial><mass value="2"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
  </link>
  <joint name="head_swivel" type="continuous">
    <parent link="base_link"/><child link="head"/><axis xyz="0 0 1"/><origin xyz="0 0 0.3"/>
  </joint>
</robot>)";
  CliRun r = momenta("info " + at("r2d2.urdf"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.out,
                  "r2d2.urdf:7: not drawn: 'package://pr2_description/meshes/gripper_v0/"
                  "l_finger.dae' names package 'pr2_description', and no package path is "
                  "given: give the folder that holds it with --package-path or "
                  "ROS_PACKAGE_PATH"))
      << r.out;
  EXPECT_FALSE(has(r.out, "‹")) << r.out;
  r = momenta("simulate " + at("r2d2.urdf") + " --duration 0.1 -o " + at("r2d2.csv"));
  EXPECT_EQ(r.code, 0) << r.err;
}

// MuJoCo users keep the states they work from as keyframes: `info` lists them, `--keyframe NAME`
// starts any command from one (here the run's first row is the key's state in momenta's layout).
TEST_F(FirstHourCli, AnMjcfKeyframeIsTheStateAskedFor) {
  const std::string keyed = quoted(source_dir() + "/tests/data/models/mjcf/keyed_box.xml");
  CliRun r = momenta("info " + keyed);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.out,
                  "keyframes (1): the state of one is the initial state with --keyframe "
                  "NAME\n  tilted  (line 7), moving"))
      << r.out;
  r = momenta("simulate " + keyed + " --keyframe tilted --duration 0.001 -o " + at("keyed.csv"));
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream csv(dir_ / "keyed.csv");
  std::string header, first;
  std::getline(csv, header);
  std::getline(csv, first);
  EXPECT_TRUE(has(header,
                  "time,root.x,root.y,root.z,root.qw,root.qx,root.qy,root.qz,hinge.angle,"
                  "root.wx,root.wy,root.wz,root.vx,root.vy,root.vz,hinge.angle_rate"))
      << header;
  EXPECT_TRUE(has(first, "0,1,2,3,1,0,0,0,0.429203673205103")) << first;  // 2 − π/2
  EXPECT_TRUE(has(first, ",4,5,6,1,2,3,7,")) << first;
  r = momenta("info " + keyed + " --keyframe tiltd");
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "keyframe 'tiltd':")) << r.err;
  EXPECT_TRUE(has(r.err, "(did you mean 'tilted'?); its keys: tilted")) << r.err;
}

// A joint's armature (a motor's reflected rotor inertia I_a) in a model file: the pendulum
// (m = 1 kg at L = 1 m) with I_a = 0.25 kg·m² swings as (m L² + I_a) θ̈ + m g L sin θ = 0 — its
// small oscillation ω² = m g L / (m L² + I_a) = 7.848 s⁻², the equation with the term I_a θ̈, and
// a run whose energy (½ I_a θ̇² included) is conserved to RK4's truncation.
TEST_F(FirstHourCli, AJointsArmatureIsItsRotorsInertia) {
  std::ofstream(dir_ / "p.yaml") << R"(name: motor pendulum
bodies:
  - {name: bob, shape: point_mass, mass: 1.0, position: [0, 0, -1.0]}
joints:
  - {name: pivot, type: revolute, parent: world, child: bob, axis: [0, 1, 0], q0_deg: 10,
     armature: 0.25}
)";
  CliRun r = momenta("modes " + at("p.yaml") + " --about equilibrium --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const double omega2 =
      nlohmann::json::parse(r.out).at("normal_modes").at(0).at("squared_frequency").get<double>();
  EXPECT_NEAR(omega2, 9.81 / 1.25, 1e-12 * 7.848) << r.out;
  r = momenta("equations " + at("p.yaml") + " --symbols Ia_pivot,m_bob,g");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "pivot_ddot*(Ia_pivot + m_bob) + g*m_bob*sin(pivot) = 0")) << r.out;
  // Newton–Euler: the bob feels the joint's moment less what turns the rotor.
  r = momenta("equations " + at("p.yaml") + " --form newton-euler --symbols Ia_pivot");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "along pivot_dot:  N_pivot_y = -Ia_pivot*pivot_ddot")) << r.out;
  // Written to MJCF as MuJoCo's joint armature, and read back.
  r = momenta("export " + at("p.yaml") + " --mjcf " + at("p.xml"));
  ASSERT_EQ(r.code, 0) << r.err;
  r = momenta("info " + at("p.xml") + " --json");
  EXPECT_EQ(nlohmann::json::parse(r.out).at("joints").at(0).at("armature").get<double>(), 0.25)
      << r.out;
  r = momenta("simulate " + at("p.yaml") + " --duration 5 -o " + at("p.csv"));
  ASSERT_EQ(r.code, 0) << r.err;
  // RK4 at h = 1e-3 on ω ≈ 2.8 s⁻¹: (ω h)⁴ ≈ 6e-11 per unit time at most; measured 3e-16.
  const std::size_t at_energy = r.err.find("energy ");
  ASSERT_NE(at_energy, std::string::npos) << r.err;
  EXPECT_LT(std::abs(std::stod(r.err.substr(at_energy + 7))), 1e-10) << r.err;
  r = momenta("info " + at("p.yaml") + " --json");
  EXPECT_EQ(nlohmann::json::parse(r.out).at("joints").at(0).at("armature").get<double>(), 0.25)
      << r.out;
}

TEST_F(FirstHourCli, ExportWritesMjcfAndUrdf) {
  // The four-bar as MJCF, drawn assembled: read back, its pin is two connects (six rows, two
  // independent beside the planar pins), one degree of freedom — the crank, now free to turn.
  const std::string bar = example("constraints/four_bar.yaml");
  CliRun r = momenta("export " + bar + " --mjcf " + at("bar.xml"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "bar.xml (MJCF: 3 bodies, 3 degrees of freedom)")) << r.out;
  EXPECT_TRUE(has(r.err, "not written: the prescribed motion of joint 'crank_pin'")) << r.err;
  r = momenta("info " + at("bar.xml") + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto freedoms = nlohmann::json::parse(r.out).at("degrees_of_freedom");
  EXPECT_EQ(freedoms.at("constraint_rows"), 6) << r.out;
  EXPECT_EQ(freedoms.at("independent_constraint_rows"), 2) << r.out;
  EXPECT_EQ(freedoms.at("free"), 1) << r.out;
  // Never over the user's file without --force; a loop URDF cannot close is refused by name.
  r = momenta("export " + bar + " --mjcf " + at("bar.xml"));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "the output file exists; pass --force")) << r.err;
  EXPECT_EQ(momenta("export " + bar + " --mjcf " + at("bar.xml") + " --force").code, 0);
  r = momenta("export " + bar + " --urdf " + at("bar.urdf"));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "constraint 'closure' (hinge): URDF describes trees")) << r.err;
  EXPECT_TRUE(has(r.err, "write MJCF (--mjcf), which keeps loops")) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "bar.urdf"));
  // The double pendulum as URDF, and its modes from the file written.
  r = momenta("export " + example("double_pendulum.yaml") + " --urdf " + at("dp.urdf"));
  ASSERT_EQ(r.code, 0) << r.err;
  r = momenta("modes " + at("dp.urdf") + " --about equilibrium --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto normal = nlohmann::json::parse(r.out).at("normal_modes");
  ASSERT_EQ(normal.size(), 2u);
  EXPECT_NEAR(normal[0].at("squared_frequency").get<double>(), 9.81 * (2 - std::sqrt(2.0)), 1e-11);
  EXPECT_EQ(momenta("export " + bar).code, 2);  // neither --mjcf nor --urdf
}

TEST_F(FirstHourCli, LibraryMessagesAreSaidInMomentasWords) {
  // A 300-character output name: the system's words, with the file, exit 1.
  CliRun r = momenta("simulate " + example("pendulum.yaml") + " -o " + at(std::string(300, 'a')));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "File name too long")) << r.err;
  EXPECT_FALSE(has(r.err, "internal error")) << r.err;
  // A file name that is not UTF-8, echoed in JSON: still valid JSON.
  const fs::path odd = dir_ / "bad\xff.yaml";
  fs::copy_file(source_dir() + "/examples/pendulum.yaml", odd);
  r = momenta("info " + quoted(odd.string()) + " --json");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(has(r.err, "json.exception")) << r.err;
  // A mesh unit no double can hold; the tolerances named by their options.
  r = momenta("inertia " + example("parts/meshes/bus.stl") + " --scale 1e-300");
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "outside 1e-9 … 1e9")) << r.err;
  r = momenta("simulate " + example("pendulum.yaml") + " --rtol 1e-30 -o " + at("x.csv"));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "dopri5: --rtol 1e-30, --atol 1e-10 ask for more than double")) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "x.csv"));
  // A folder where a file is asked for: named as one.
  fs::create_directory(dir_ / "folder");
  r = momenta("diagram " + example("pendulum.yaml") + " --body bob -o " + at("folder"));
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(has(r.err, "is a folder")) << r.err;
  for (const std::string command : {"sweep", "sweep-merge"}) {
    const std::string tail = command == "sweep" ? " -o " + at("x.csv") : " a.csv -o " + at("x.csv");
    r = momenta(command + " " + at("missing.yaml") + tail);
    EXPECT_EQ(r.code, 1) << command;
    EXPECT_TRUE(has(r.err, "missing.yaml: file not found")) << r.err;
    r = momenta(command + " " + at("folder") + tail);
    EXPECT_EQ(r.code, 1) << command;
    EXPECT_TRUE(has(r.err, "is a folder")) << r.err;
  }
  // A transfer function in JSON is JSON.
  r = momenta("equations " + example("cruise_control.yaml") + " --transfer u:speed --json");
  if (r.code == 1 && has(r.err, "MOMENTA_WITH_SYMBOLIC")) return;  // a build without GiNaC
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("{\n", 0), 0u) << r.out;
  EXPECT_TRUE(has(r.out, "\"text\": ")) << r.out;
  EXPECT_TRUE(has(r.out, "\"latex\": ")) << r.out;
}

TEST_F(FirstHourCli, SweepsRefuseWhatWouldMixLoseOrExhaust) {
  const std::string grid =
      "  - {path: forces.suspension.stiffness, name: ks, values: [6e4, 8e4, 1e5]}\n";
  const fs::path sweep = sweep_file("grid.yaml", grid);
  // The output may not be the sweep's own input, nor the report.
  CliRun r =
      momenta("sweep " + quoted(sweep.string()) + " -o " + quoted(sweep.string()) + " --force");
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "is the sweep's own input")) << r.err;
  EXPECT_TRUE(has(slurp(sweep), "name: test sweep"));
  r = momenta("sweep " + quoted(sweep.string()) + " -o " + at("r.csv") + " --report " +
              at("r.csv"));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "--output and --report both name")) << r.err;
  // Shards and threads: an empty or overflowing shard, absurd threads.
  for (const std::string shard : {"''", "1/99999999999999999999", "1/4"}) {
    r = momenta("sweep " + quoted(sweep.string()) + " -o " + at("s.csv") + " --shard " + shard);
    EXPECT_EQ(r.code, 2) << shard << ": " << r.err;
  }
  r = momenta("sweep " + quoted(sweep.string()) + " -o " + at("t.csv") + " --threads 100000");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(has(r.err, "100000 threads on")) << r.err;
  // 10¹² Monte Carlo samples: refused with the estimate, not after seconds of allocation.
  const fs::path huge = sweep_file(
      "huge.yaml",
      "  - {path: forces.suspension.stiffness, distribution: {type: normal, mean: 1e5, sd: 1e4}}\n",
      "  - max: body_y\n", "design: monte_carlo\nsamples: 1000000000000\nseed: 1\n");
  r = momenta("sweep " + quoted(huge.string()) + " -o " + at("h.csv"));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "this sweep has 1e+12 runs")) << r.err;
  // The same path twice; a metric named like the file's own column or twice.
  r = momenta(
      "sweep " +
      quoted(
          sweep_file("twice.yaml",
                     grid + "  - {path: forces.suspension.stiffness, name: k2, values: [1, 2]}\n")
              .string()) +
      " -o " + at("w.csv"));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "is varied twice")) << r.err;
  // A model that is a folder, and a duration no step can reach: refused at their lines and keys.
  r = momenta("sweep " +
              quoted(write("folder.yaml",
                           "model: .\nparameters:\n  - {path: forces.suspension.stiffness, "
                           "values: [6e4]}\nmetrics:\n  - max: body_y\n")
                         .string()) +
              " -o " + at("f.csv"));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "folder.yaml:1:8: model: '.' is a folder, not a model file")) << r.err;
  r = momenta("sweep " +
              quoted(write("long.yaml", "model: " + source_dir() +
                                            "/examples/quarter_car.yaml\n"
                                            "simulation: {duration: 1e100}\nparameters:\n"
                                            "  - {path: forces.suspension.stiffness, values: "
                                            "[6e4]}\nmetrics:\n  - max: body_y\n")
                         .string()) +
              " -o " + at("l.csv"));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err,
                  "long.yaml:2:24: simulation.duration: the step 0.001 s is below the "
                  "resolution of time at t = 1e+100 s"))
      << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "l.csv"));
  // A parameter named like one of the file's own columns: refused at its line.
  for (const std::string name : {"run", "status", "inputs", "wall_s", "message"}) {
    r = momenta("sweep " +
                quoted(sweep_file("p.yaml", "  - {path: forces.suspension.stiffness, name: " +
                                                name + ", values: [6e4, 8e4]}\n")
                           .string()) +
                " -o " + at("p.csv"));
    EXPECT_EQ(r.code, 1) << name;
    EXPECT_TRUE(has(r.err, "p.yaml:6:5: parameter name '" + name +
                               "' is one of the results file's own columns"))
        << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "p.csv"));
  }
  for (const std::string metrics :
       {"  - {max: body_y, name: status}\n", "  - max: body_y\n  - max: body_y\n"}) {
    r = momenta("sweep " + quoted(sweep_file("m.yaml", grid, metrics).string()) + " -o " +
                at("m.csv"));
    EXPECT_EQ(r.code, 1) << metrics;
    EXPECT_TRUE(has(r.err, "give the metric another name")) << r.err;
  }
}

TEST_F(FirstHourCli, ResumeRefusesAnotherSweepsFileOrAChangedModel) {
  const fs::path first = sweep_file(
      "first.yaml", "  - {path: forces.suspension.stiffness, name: ks, values: [6e4, 8e4, 1e5]}\n");
  ASSERT_EQ(momenta("sweep " + quoted(first.string()) + " -o " + at("r.csv") + " --no-timing").code,
            0);
  const std::string written = slurp(dir_ / "r.csv");
  // Another range with the same columns, in a file older than the results: its run 0 is not
  // this file's run 0, and the file's contents say so.
  const fs::path other = sweep_file(
      "other.yaml",
      "  - {path: forces.suspension.stiffness, name: ks, values: [6e4, 9e4, 1.2e5, 1.5e5]}\n");
  fs::last_write_time(other, fs::last_write_time(dir_ / "r.csv") - std::chrono::hours(1));
  CliRun r =
      momenta("sweep " + quoted(other.string()) + " -o " + at("r.csv") + " --no-timing --resume");
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "was made from other inputs")) << r.err;
  EXPECT_EQ(slurp(dir_ / "r.csv"), written);
  // The sweep file changed after the results were written.
  const fs::path grown = sweep_file(
      "first.yaml",
      "  - {path: forces.suspension.stiffness, name: ks, values: [6e4, 8e4, 1e5, 1.2e5]}\n");
  r = momenta("sweep " + quoted(grown.string()) + " -o " + at("r.csv") + " --no-timing --resume");
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "was made from other inputs")) << r.err;
  EXPECT_EQ(slurp(dir_ / "r.csv"), written);
}

// The model a sweep reads changed, but its file is older than the results (copied, checked out,
// restored from a backup): refused by the files' contents, which every row records; the same
// bytes at a newer time resume.
TEST_F(FirstHourCli, ResumeChecksTheModelsContentsNotItsTime) {
  const std::string car = slurp(source_dir() + "/examples/quarter_car.yaml");
  ASSERT_TRUE(has(car, "mass: 375.0"));
  const fs::path model = write("car.yaml", car);
  const fs::path sweep =
      write("s.yaml",
            "model: car.yaml\njob: simulate\nsimulation: {duration: 0.05, step: 0.001}\n"
            "parameters:\n  - {path: forces.suspension.stiffness, name: ks, values: [6e4, "
            "8e4, 1e5]}\nmetrics:\n  - max: body_y\n");
  ASSERT_EQ(momenta("sweep " + quoted(sweep.string()) + " -o " + at("r.csv") + " --no-timing").code,
            0);
  const std::string whole = slurp(dir_ / "r.csv");
  const std::size_t header_end = whole.find('\n');
  ASSERT_TRUE(has(whole.substr(0, header_end), ",status,inputs,message")) << whole;
  // Keep the header and the first run, as a sweep killed after it would.
  std::ofstream(dir_ / "r.csv", std::ios::binary)
      << whole.substr(0, whole.find('\n', header_end + 1) + 1);
  const auto results_time = fs::last_write_time(dir_ / "r.csv");
  std::string heavier = car;
  heavier.replace(heavier.find("mass: 375.0"), 11, "mass: 400.0");
  write("car.yaml", heavier);
  fs::last_write_time(model, results_time - std::chrono::hours(24));
  CliRun r =
      momenta("sweep " + quoted(sweep.string()) + " -o " + at("r.csv") + " --no-timing --resume");
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "row 2 (run 0) was made from other inputs")) << r.err;
  EXPECT_TRUE(has(r.err, "resuming would mix two models")) << r.err;
  // The original bytes again, newer than the results: the same inputs, so the sweep goes on.
  write("car.yaml", car);
  fs::last_write_time(model, results_time + std::chrono::hours(1));
  r = momenta("sweep " + quoted(sweep.string()) + " -o " + at("r.csv") + " --no-timing --resume");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(slurp(dir_ / "r.csv"), whole);
  // A results file that does not record its inputs (an earlier momenta's) is refused, saying so.
  std::ofstream(dir_ / "old.csv", std::ios::binary)
      << "run,ks,max(body_y),status,message\n0,60000,0.1,ok,\n";
  r = momenta("sweep " + quoted(sweep.string()) + " -o " + at("old.csv") + " --no-timing --resume");
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "does not record what its results were made from")) << r.err;
}

// What a student writing the notes' problems from scratch met, each as they met it.
TEST_F(FirstHourCli, LinearizeShowsEachColumnsWholeName) {
  const CliRun r = momenta("linearize " + source_dir() + "/examples/cruise_control.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::size_t a = r.out.find("A (2×2):\n");
  ASSERT_NE(a, std::string::npos) << r.out;
  const std::string header = r.out.substr(a, r.out.find('\n', r.out.find('\n', a) + 1) - a);
  EXPECT_TRUE(has(header, " road.position ")) << header;
  EXPECT_TRUE(has(header, " road.position_rate")) << header;
}

// The cruise car's 500 N step (Franklin ch. 2: m v̇ + b v = u): final speed u/b = 10 m/s, rise
// time (10 % → 90 %) ln 9 · m/b = 43.944491546724 s, the same as the unit step's.
TEST_F(FirstHourCli, ResponseTakesTheStepsAmplitude) {
  const std::string car = source_dir() + "/examples/cruise_control.yaml";
  const CliRun unit = momenta("response " + car + " --input u --output speed --step");
  ASSERT_EQ(unit.code, 0) << unit.err;
  EXPECT_TRUE(has(unit.out, "unit step: final value 0.02,")) << unit.out;
  const CliRun step =
      momenta("response " + car + " --input u --output speed --step --amplitude 500");
  ASSERT_EQ(step.code, 0) << step.err;
  EXPECT_TRUE(has(step.out, "step of 500: final value 10, rise time 43.94449155 s")) << step.out;
  const CliRun csv = momenta("response " + car +
                             " --input u --output speed --step --amplitude 500 --points 3 "
                             "--duration 20 --csv -");
  ASSERT_EQ(csv.code, 0) << csv.err;
  // v(20 s) = 10 (1 − e⁻¹) m/s.
  const std::string last = csv.out.substr(csv.out.rfind("\n", csv.out.size() - 2) + 1);
  EXPECT_NEAR(std::stod(last.substr(last.find(',') + 1)), 10.0 * (1.0 - std::exp(-1.0)), 1e-9)
      << csv.out;
  EXPECT_EQ(momenta("response " + car + " --input u --output speed --step --amplitude 0").code, 2);
}

// A revolute q0 past a whole turn is taken as written, in radians, with a note at its line; a
// spinning joint's rate in rpm.
TEST_F(FirstHourCli, AJointAngleBeyondATurnIsNotedAndRatesTakeRpm) {
  std::string pendulum = slurp(source_dir() + "/examples/pendulum.yaml");
  ASSERT_TRUE(has(pendulum, "q0_deg: 120 ") && has(pendulum, "v0: 0 ")) << pendulum;
  pendulum.replace(pendulum.find("q0_deg: 120 "), 12, "q0: 30 ");
  pendulum.replace(pendulum.find("v0: 0 "), 6, "v0_rpm: 60 ");
  const fs::path model = write("p.yaml", pendulum);
  const CliRun r =
      momenta("simulate " + quoted(model.string()) + " --duration 0.001 -o " + at("p.csv"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.err, "momenta: note: " + model.string() + ":")) << r.err;
  EXPECT_TRUE(has(r.err, "q0: 30 rad is 4.77 turns; if degrees are meant, write q0_deg: 30"))
      << r.err;
  // The first row: q = 30 rad, v = 60 rpm = 2π rad/s.
  const std::string csv = slurp(dir_ / "p.csv");
  const std::string first = csv.substr(csv.find('\n') + 1);
  std::vector<double> cells;
  std::istringstream in(first.substr(0, first.find('\n')));
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(std::stod(cell));
  ASSERT_GE(cells.size(), 3U);
  EXPECT_EQ(cells[1], 30.0);
  EXPECT_NEAR(cells[2], 2.0 * std::numbers::pi, 1e-15);
  // In degrees, no note.
  std::string degrees = pendulum;
  degrees.replace(degrees.find("q0: 30"), 6, "q0_deg: 30");
  const CliRun quiet = momenta("simulate " + quoted(write("d.yaml", degrees).string()) +
                               " --duration 0.001 -o " + at("d.csv"));
  ASSERT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_FALSE(has(quiet.err, "note:")) << quiet.err;
}

// A flow list or map left open: the parser notices at the next key; the message says where it
// began.
TEST_F(FirstHourCli, AnUnclosedListIsNamedWhereItBegan) {
  const fs::path list = write("l.yaml", "name: x\nbodies: [a, b\njoints: []\n");
  CliRun r = momenta("info " + quoted(list.string()));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "the list [ that begins at line 2, column 9 has no closing ]")) << r.err;
  const fs::path map =
      write("m.yaml",
            "name: x  # a comment with [ and {\nbodies:\n  - {name: 'a[', mass: 1\n"
            "joints: []\n");
  r = momenta("info " + quoted(map.string()));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err, "the map { that begins at line 3, column 5 has no closing }")) << r.err;
  // A block list's item out of line with its siblings ("end of sequence not found").
  const fs::path block =
      write("b.yaml",
            "name: x\nbodies:\n  - {name: a, mass: 1}\n  - name: b\n    mass: 2\n"
            "   - name: c\njoints: []\n");
  r = momenta("info " + quoted(block.string()));
  EXPECT_EQ(r.code, 1);
  EXPECT_TRUE(has(r.err,
                  "b.yaml:6:4: malformed YAML: end of sequence not found: the list that "
                  "begins at line 3, column 3 has its items ('-') at column 3; this one is "
                  "at column 4"))
      << r.err;
}

// On a terminal the table leads with what the model file asks for: the cruise car's outputs
// speed, distance and u after the time, the momentum (nothing of a car on a road) not in the
// seven columns shown. --columns chooses for the table and the CSV alike, checked before a file.
TEST_F(FirstHourCli, SimulateShowsTheModelsOutputsFirstAndTakesColumns) {
  const std::string car = source_dir() + "/examples/cruise_control.yaml";
  const std::string shown = on_a_terminal("simulate " + car + " --duration 1");
  EXPECT_TRUE(std::regex_search(shown, std::regex("^ *time +speed +distance +u +road\\.position")))
      << shown;
  EXPECT_FALSE(has(shown.substr(0, shown.find('\n')), "H_x")) << shown;
  const CliRun chosen = momenta("simulate " + car + " --duration 1 --columns time,speed");
  ASSERT_EQ(chosen.code, 0) << chosen.err;
  EXPECT_EQ(chosen.out.substr(0, chosen.out.find('\n')), "time,speed");
  EXPECT_EQ(std::count(chosen.out.begin(), chosen.out.end(), ','),
            std::count(chosen.out.begin(), chosen.out.end(), '\n'));  // two columns a line
  const CliRun table = on_a_terminal_run("simulate " + car + " --duration 1 --columns u,speed");
  EXPECT_TRUE(std::regex_search(table.out, std::regex("^ *u +speed\r?\n"))) << table.out;
  const CliRun wrong =
      momenta("simulate " + car + " --duration 1 --columns time,sped -o " + at("x.csv"));
  EXPECT_EQ(wrong.code, 1);
  EXPECT_TRUE(has(wrong.err, "--columns: the run has no column 'sped' (did you mean 'speed'?)"))
      << wrong.err;
  EXPECT_FALSE(fs::exists(dir_ / "x.csv"));
}

// A state file (as `momenta steady --state` writes) is where a run starts: its first row.
TEST_F(FirstHourCli, SimulateAndReportStartFromAStateFile) {
  const fs::path state = write("s.json", R"({"q": [0.5], "v": [0.25], "t": 0})");
  const std::string pendulum = source_dir() + "/examples/pendulum.yaml";
  const CliRun r = momenta("simulate " + pendulum + " --duration 0.01 --state " +
                           quoted(state.string()) + " --columns time,pivot.angle,pivot.angle_rate");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string first = r.out.substr(r.out.find('\n') + 1);
  EXPECT_EQ(first.substr(0, first.find('\n')), "0,0.5,0.25");
  const CliRun page = momenta("report " + pendulum + " --duration 0.01 --state " +
                              quoted(state.string()) + " -o " + at("p.html"));
  ASSERT_EQ(page.code, 0) << page.err;
  const CliRun wrong = momenta("simulate " + pendulum + " --state " +
                               quoted(write("w.json", R"({"q": [0.5, 1], "v": [0]})").string()));
  EXPECT_EQ(wrong.code, 1);
  EXPECT_TRUE(has(wrong.err, "w.json")) << wrong.err;
}

}  // namespace first_hour
}  // namespace
}  // namespace momenta
