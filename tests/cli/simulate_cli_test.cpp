// `momenta simulate` and `momenta info`, run as a user runs them: the built binary
// (MOMENTA_CLI_PATH), its CSV against the library's Simulation on the same model file, its exit
// codes (0 ok, 1 user error, 2 usage error) and messages, and `info --json` against the Model.

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/simulate/simulation.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using test::CliRun;
using test::quoted;
using test::slurp;

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  std::string field;
  while (std::getline(in, field, separator)) fields.push_back(field);
  return fields;
}

// The CSV as a header and rows of numbers.
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
};

Csv parse_csv(const std::string& text) {
  Csv csv;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  csv.header = split(line, ',');
  while (std::getline(in, line)) {
    std::vector<double> row;
    for (const std::string& f : split(line, ',')) row.push_back(std::strtod(f.c_str(), nullptr));
    csv.rows.push_back(std::move(row));
  }
  return csv;
}

std::string example(const std::string& name) { return test::source_dir() + "/examples/" + name; }
std::string test_model(const std::string& name) {
  return test::source_dir() + "/tests/data/models/" + name;
}

class SimulateCli : public test::CliTest {};

// The CSV holds exactly what the library's Simulation produces from the same file and options,
// bit for bit (numbers are written in their shortest round-trip form).
TEST_F(SimulateCli, PendulumCsvMatchesTheLibrary) {
  const std::string model = example("pendulum.yaml");
  const fs::path csv_path = dir_ / "run.csv";
  const CliRun r = momenta("simulate " + quoted(model) + " --duration 1 --dt 0.01 --every 10 " +
                           "--output " + quoted(csv_path.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  const Csv csv = parse_csv(slurp(csv_path));

  const io::ModelFile file = io::read_model_file(model);
  simulate::SimulationOptions o;
  o.duration = 1.0;
  o.step = 0.01;
  o.every = 10;
  simulate::Simulation sim(file.model, file.outputs, o);
  simulate::TableSink table;
  sim.run(table);
  EXPECT_EQ(csv.header, table.columns);
  ASSERT_EQ(csv.rows.size(), table.rows.size());
  for (std::size_t i = 0; i < csv.rows.size(); ++i)
    for (std::size_t c = 0; c < table.columns.size(); ++c)
      EXPECT_EQ(csv.rows[i][c], table.rows[i][c]) << i << " " << table.columns[c];
  // The summary on stderr.
  EXPECT_NE(r.err.find("100 accepted, 0 rejected; 400 evaluations"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("conservation audit"), std::string::npos) << r.err;
}

TEST_F(SimulateCli, HeaderWithReactionsAndCsvOnStdout) {
  const CliRun r = momenta("simulate " + quoted(example("pendulum.yaml")) +
                           " --duration 0.1 --dt 0.01 --reactions");
  ASSERT_EQ(r.code, 0) << r.err;
  const Csv csv = parse_csv(r.out);
  const std::vector<std::string> expected = {"time",
                                             "pivot.angle",
                                             "pivot.angle_rate",
                                             "energy_kinetic",
                                             "energy_potential",
                                             "energy_total",
                                             "H_x",
                                             "H_y",
                                             "H_z",
                                             "theta",
                                             "bob.x",
                                             "bob.y",
                                             "bob.z",
                                             "pivot.reaction.Fx",
                                             "pivot.reaction.Fy",
                                             "pivot.reaction.Fz",
                                             "pivot.reaction.Mx",
                                             "pivot.reaction.My",
                                             "pivot.reaction.Mz",
                                             "audit.energy_drift"};
  EXPECT_EQ(csv.header, expected);
  EXPECT_EQ(csv.rows.size(), 11u);
  // Released from rest at θ0 = 120° (m = 1 kg, L = 1 m): a = L θ̈ e_t with θ̈ = −(g/L) sin θ0 and
  // e_t = (−cos θ, 0, sin θ); the pin's force on the bob is m (a − g). Round-off: ulps of m g.
  const double theta0 = 2.0 * M_PI / 3.0, g = 9.81;
  const double theta_ddot = -g * std::sin(theta0);
  const double ax = -std::cos(theta0) * theta_ddot, az = std::sin(theta0) * theta_ddot;
  const auto& row0 = csv.rows.front();
  EXPECT_NEAR(row0[13], ax, 1e-12 * g);
  EXPECT_NEAR(row0[15], az + g, 1e-12 * g);
}

TEST_F(SimulateCli, NeverOverwritesWithoutForce) {
  const fs::path csv_path = dir_ / "existing.csv";
  std::ofstream(csv_path) << "keep me\n";
  const std::string args = "simulate " + quoted(example("pendulum.yaml")) +
                           " --duration 0.1 --output " + quoted(csv_path.string());
  const CliRun refused = momenta(args);
  EXPECT_EQ(refused.code, 1);
  EXPECT_EQ(refused.err.rfind("momenta: error: ", 0), 0u) << refused.err;
  EXPECT_NE(refused.err.find("existing.csv"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--force"), std::string::npos) << refused.err;
  EXPECT_EQ(slurp(csv_path), "keep me\n");
  const CliRun forced = momenta(args + " --force");
  EXPECT_EQ(forced.code, 0) << forced.err;
  EXPECT_EQ(slurp(csv_path).rfind("time,", 0), 0u);
}

// The file's simulation section gives duration 0.01 s and step 1e-5 s; --dt 0.01 makes RK4
// unstable (ω h = 100): exit 1, the time and coordinate named, the rows so far kept.
TEST_F(SimulateCli, NonFiniteStateExitsOneWithTheTime) {
  const fs::path csv_path = dir_ / "blowup.csv";
  const CliRun r = momenta("simulate " + quoted(test_model("stiff_spring.yaml")) +
                           " --duration 100 --dt 0.01 --output " + quoted(csv_path.string()));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(r.err.rfind("momenta: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("non-finite at t = "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("rail."), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("step"), std::string::npos) << r.err;
  const Csv csv = parse_csv(slurp(csv_path));
  EXPECT_GT(csv.rows.size(), 1u);
  EXPECT_EQ(csv.rows.front().size(), csv.header.size());
}

// Options over the file's section: the file says 0.01 s at 1e-5 s (1000 steps); --every 100
// keeps 11 rows; --duration 0.001 then leaves 100 steps and 2 rows.
TEST_F(SimulateCli, OptionsOverrideTheFileSection) {
  const std::string model = quoted(test_model("stiff_spring.yaml"));
  const CliRun a = momenta("simulate " + model + " --every 100");
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_EQ(parse_csv(a.out).rows.size(), 11u);
  EXPECT_NE(a.err.find("1000 accepted"), std::string::npos) << a.err;
  const CliRun b = momenta("simulate " + model + " --every 100 --duration 0.001");
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_EQ(parse_csv(b.out).rows.size(), 2u);
  // Tolerances alone choose dopri5.
  const CliRun c = momenta("simulate " + model + " --rtol 1e-6 --atol 1e-9");
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_NE(c.err.find("dopri5"), std::string::npos) << c.err;
}

TEST_F(SimulateCli, BadIntegratorAndOptions) {
  const std::string model = quoted(example("pendulum.yaml"));
  const CliRun unknown = momenta("simulate " + model + " --integrator rk5");
  EXPECT_EQ(unknown.code, 1);
  EXPECT_NE(unknown.err.find("did you mean 'rk4'"), std::string::npos) << unknown.err;
  EXPECT_NE(unknown.err.find("splitting"), std::string::npos) << unknown.err;
  // A tolerance for a fixed-step method is a usage error.
  EXPECT_EQ(momenta("simulate " + model + " --integrator rk4 --rtol 1e-6").code, 2);
  EXPECT_EQ(momenta("simulate " + model + " --dt -1").code, 2);
  EXPECT_EQ(momenta("simulate").code, 2);
  const CliRun missing = momenta("simulate " + quoted((dir_ / "none.yaml").string()));
  EXPECT_EQ(missing.code, 1);
  EXPECT_NE(missing.err.find("none.yaml"), std::string::npos) << missing.err;
}

// Events from the file and the command line: the rod's wire going slack ends the run on the
// row of the event (its time in the summary); --event adds rows; a condition that is not one is
// a usage error, a quantity the run lacks an error naming the ones there are — at the file's
// line when the file names it.
TEST_F(SimulateCli, EventsAddRowsAndStopTheRun) {
  const fs::path csv_path = dir_ / "slack.csv";
  const CliRun slack =
      momenta("simulate " + quoted(example("constraints/rod_on_shaft_spinning_down.yaml")) +
              " --output " + quoted(csv_path.string()));
  ASSERT_EQ(slack.code, 0) << slack.err;
  EXPECT_NE(slack.err.find("events       slack (tension < 0) at t = 4.02977959498 s: the run "
                           "stops there"),
            std::string::npos)
      << slack.err;
  const Csv csv = parse_csv(slurp(csv_path));
  EXPECT_NEAR(csv.rows.back()[0], 4.02977959498, 1e-11);

  const std::string pendulum = quoted(example("pendulum.yaml"));
  const CliRun swings = momenta("simulate " + pendulum +
                                " --duration 2 --dt 0.01 --event 'pivot.angle = 0' "
                                "--stop-when 'pivot.angle_rate > 0'");
  ASSERT_EQ(swings.code, 0) << swings.err;
  // Through the bottom at a quarter period (0.6885 s); the swing turns at half of it (1.377 s).
  EXPECT_NE(swings.err.find("events       pivot.angle = 0 at t = 0.688522"), std::string::npos)
      << swings.err;
  EXPECT_NE(swings.err.find("             pivot.angle_rate > 0 at t = 1.377044"), std::string::npos)
      << swings.err;
  const Csv rows = parse_csv(swings.out);
  EXPECT_EQ(rows.rows.size(), 1u + 137u + 2u);  // t = 0, 137 steps to 1.37 s, two events

  const CliRun not_one = momenta("simulate " + pendulum + " --event 'pivot.angle'");
  EXPECT_EQ(not_one.code, 2) << not_one.err;
  EXPECT_NE(not_one.err.find("no comparison"), std::string::npos) << not_one.err;
  const CliRun unknown = momenta("simulate " + pendulum + " --stop-when 'pivot.angel < 0'");
  EXPECT_EQ(unknown.code, 1) << unknown.err;
  EXPECT_NE(unknown.err.find("did you mean 'pivot.angle'"), std::string::npos) << unknown.err;

  const fs::path model = dir_ / "watch.yaml";
  std::ofstream(model) << slurp(example("pendulum.yaml"))
                       << "  events:\n    - {name: slack, when: tension < 0}\n";
  const CliRun in_file = momenta("simulate " + quoted(model.string()));
  EXPECT_EQ(in_file.code, 1) << in_file.err;
  EXPECT_NE(in_file.err.find("watch.yaml:"), std::string::npos) << in_file.err;
  EXPECT_NE(in_file.err.find("simulation.events[0]: event 'slack': no quantity 'tension'"),
            std::string::npos)
      << in_file.err;
}

// A model the reader accepts but the system layer refuses (the gimbal of crba_test rolled 90°: the
// rod lies along the yaw axis, so nothing resists yaw at the initial state): every command that
// reads models reports it at the joint's line, file:line:column.
TEST_F(SimulateCli, SingularMassMatrixAtTheInitialStateIsReportedAtTheJointsLine) {
  const fs::path model = dir_ / "gimbal.yaml";
  std::ofstream(model) << R"(bodies:
  - {name: gimbal, mass: 0}
  - {name: rod, mass: 2, inertia: [0.1667, 0, 0.1667]}
joints:
  - {name: yaw, type: revolute, parent: world, child: gimbal, axis: [0, 0, 1]}
  - {name: roll, type: revolute, parent: gimbal, child: rod, axis: [1, 0, 0], q0_deg: 90}
)";
  for (const char* command : {"simulate", "info", "linearize"}) {
    const CliRun r = momenta(std::string(command) + " " + quoted(model.string()));
    EXPECT_EQ(r.code, 1) << command << ": " << r.err;
    EXPECT_NE(r.err.find("gimbal.yaml:5:5: joint 'yaw': the mass matrix is singular along its "
                         "coordinate 'yaw.angle_rate'"),
              std::string::npos)
        << command << ": " << r.err;
  }
}

// The integrator registry is what the model file and the command line both accept: `exact` in
// the file's `simulation:` section runs (it was refused before the registry).
TEST_F(SimulateCli, ModelFileNamesAStructurePreservingIntegrator) {
  const fs::path model = dir_ / "spinner.yaml";
  std::ofstream(model) << R"(bodies:
  - {name: b, mass: 1, inertia: [1, 2, 3]}
joints:
  - {name: f, type: free, parent: world, child: b, v0: [0.01, 2, 0.01, 0, 0, 0]}
gravity: [0, 0, 0]
simulation: {integrator: exact, duration: 1, step: 0.01}
)";
  const CliRun r =
      momenta("simulate " + quoted(model.string()) + " -o " + quoted((dir_ / "run.csv").string()));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("exact"), std::string::npos) << r.err;
}

// `info --json` against the Model read by the library.
TEST_F(SimulateCli, InfoJsonDescribesTheModel) {
  const std::string model = example("double_pendulum.yaml");
  const CliRun r = momenta("info " + quoted(model) + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  const io::ModelFile file = io::read_model_file(model);
  EXPECT_EQ(j.at("name"), file.name);
  EXPECT_EQ(j.at("nq"), file.model.nq());
  EXPECT_EQ(j.at("nv"), file.model.nv());
  ASSERT_EQ(j.at("bodies").size(), 2u);
  EXPECT_EQ(j.at("bodies")[1].at("name"), "mass2");
  EXPECT_EQ(j.at("bodies")[1].at("mass").get<double>(), 1.0);
  EXPECT_EQ(j.at("joints")[1].at("parent"), "mass1");
  // One name for a coordinate: the CSV column, Model::q_name and Python's q_names agree.
  EXPECT_EQ(j.at("joints")[1].at("coordinates")[0].at("name"), "lower.angle");
  EXPECT_EQ(j.at("joints")[1].at("coordinates")[0].at("unit"), "rad");
  EXPECT_EQ(j.at("joints")[1].at("speeds")[0].at("unit"), "rad/s");
  EXPECT_EQ(j.at("degrees_of_freedom").at("free"), 2);
  EXPECT_EQ(j.at("conserves_energy"), true);
  EXPECT_EQ(j.at("outputs")[2].at("columns"), json({"tip.x", "tip.y", "tip.z"}));
  // The text form names the same things.
  const CliRun text = momenta("info " + quoted(model));
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("degrees of freedom  2\n"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("nq 2, nv 2"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("lower  revolute, mass1 → mass2"), std::string::npos) << text.out;
}

TEST_F(SimulateCli, InfoShowsPrescribedJointsAndSignals) {
  const CliRun r = momenta("info " + quoted(example("quarter_car.yaml")) + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j.at("joints")[0].at("prescribed_by"), json({"road"}));
  EXPECT_EQ(j.at("signals")[0].at("name"), "road");
  EXPECT_EQ(j.at("force_elements")[0].at("kind"), "linear_spring_damper");
  EXPECT_EQ(j.at("conserves_energy"), false);
}

// A joint's stops: `info` lists them (text and JSON, the absent bound null), `simulate` says each
// impact on stderr with its rates, impulse and energy, the rest with its Zeno limit, and with
// --reactions the stop's force is a column (docs/contacts.md).
TEST_F(SimulateCli, JointStopsAreListedAndTheirImpactsSaid) {
  const std::string ball = quoted(example("bouncing_ball.yaml"));
  const CliRun info = momenta("info " + ball);
  ASSERT_EQ(info.code, 0) << info.err;
  EXPECT_NE(info.out.find("stops: lower 0 m, upper none, restitution 0.8"), std::string::npos)
      << info.out;
  const json j = json::parse(momenta("info " + ball + " --json").out);
  EXPECT_EQ(j.at("joints")[0].at("limits"),
            json({{"lower", 0.0}, {"upper", nullptr}, {"restitution", 0.8}}));

  const CliRun run = momenta("simulate " + ball + " --reactions");
  ASSERT_EQ(run.code, 0) << run.err;
  // t₁ = √(2/9.81) = 0.451523640986 s, arriving at √(2 g) = 4.42945 m/s.
  EXPECT_NE(run.err.find("stops        drop lower stop impact at t = 0.451523640986 s: rate "
                         "-4.42945 -> 3.54356, impulse 0.7973, 0.35316 J lost"),
            std::string::npos)
      << run.err;
  // At rest from t₁ (1 + e)/(1 − e) = 4.06371276887 s.
  EXPECT_NE(run.err.find("(its bounces end at t = 4.06371276887 s)"), std::string::npos) << run.err;
  const Csv csv = parse_csv(run.out);
  ASSERT_EQ(csv.header.back(), "drop.stop_force");
  EXPECT_NEAR(csv.rows.back().back(), 0.1 * 9.81, 1e-13);

  const fs::path model = dir_ / "stops.yaml";
  std::ofstream(model) << "bodies: [{name: b, shape: sphere, mass: 1, radius: 0.1}]\n"
                          "joints:\n"
                          "  - {name: j, type: prismatic, parent: world, child: b,\n"
                          "     limits: {lower: 0, restitution: 2}}\n";
  const CliRun bad = momenta("info " + quoted(model.string()));
  EXPECT_EQ(bad.code, 1) << bad.err;
  EXPECT_NE(bad.err.find("stops.yaml:4:"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("restitution 2 is above 1"), std::string::npos) << bad.err;
}

// A contact: `info` lists it (text and JSON) and counts no freedom taken (it is open there);
// `simulate` says each impact on stderr with the normal speeds, and --reactions gives its force.
TEST_F(SimulateCli, ContactsAreListedAndTheirImpactsSaid) {
  const std::string sphere = quoted(example("bouncing_sphere.yaml"));
  const CliRun info = momenta("info " + sphere);
  ASSERT_EQ(info.code, 0) << info.err;
  EXPECT_NE(info.out.find("degrees of freedom  6\n"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("constraints (1)\n  floor  contact, ball's sphere (radius 0.05 m, centre "
                          "[0, 0, 0] m) on the ground plane (normal [0, 0, 1], through [0, 0, 0] "
                          "m), restitution 0.8, frictionless\n"),
            std::string::npos)
      << info.out;
  const json j = json::parse(momenta("info " + sphere + " --json").out);
  const json& floor = j.at("constraints")[0];
  EXPECT_EQ(floor.at("type"), "contact");
  EXPECT_EQ(floor.at("radius"), 0.05);
  EXPECT_EQ(floor.at("restitution"), 0.8);
  EXPECT_EQ(floor.at("plane").at("normal"), json({0.0, 0.0, 1.0}));
  const json cradle =
      json::parse(momenta("info " + quoted(example("newtons_cradle.yaml")) + " --json").out);
  EXPECT_EQ(cradle.at("constraints")[0].at("other_body"), "ball1");
  EXPECT_EQ(cradle.at("constraints")[0].at("other_radius"), 0.025);
  // A disk against a sphere: the disk (face and rim), not its rim alone; its resting contact's
  // normal speed 0, not −0.
  const std::string turntable = quoted(example("ball_on_turntable.yaml"));
  EXPECT_NE(momenta("info " + turntable)
                .out.find("face  contact, table's disk (radius 0.3 m, centre [0, 0, 0] m, axis "
                          "[0, 0, 1]) on ball's sphere (radius 0.03 m, centre [0, 0, 0] m), "
                          "restitution 0, friction μs 0.5, μk 0.4\n"),
            std::string::npos);
  EXPECT_NE(momenta("simulate " + turntable + " --duration 0.01")
                .err.find("contact face holds the body from t = 0 s, sticking (normal speed 0 -> "
                          "0, 0 J lost)"),
            std::string::npos);

  const CliRun run = momenta("simulate " + sphere + " --reactions");
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.err.find("stops        contact floor impact at t = 0.451523640986 s: normal speed "
                         "-4.42945 -> 3.54356, impulse 0.7973, 0.35316 J lost"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("contact floor holds the body from t = "), std::string::npos) << run.err;
  const Csv csv = parse_csv(run.out);
  const auto normal = std::find(csv.header.begin(), csv.header.end(), "floor.normal");
  ASSERT_NE(normal, csv.header.end());
  EXPECT_NEAR(csv.rows.back()[static_cast<std::size_t>(normal - csv.header.begin())], 0.1 * 9.81,
              1e-13);
}

// Friction: info gives the coefficients; a run says where the ball stops skidding, and records the
// friction along the plane's tangents (−μk m g while it slides, 0 once it rolls).
TEST_F(SimulateCli, FrictionIsListedAndItsStickSaid) {
  const std::string ball = quoted(example("skidding_ball.yaml"));
  const CliRun info = momenta("info " + ball);
  ASSERT_EQ(info.code, 0) << info.err;
  EXPECT_NE(info.out.find("restitution 0, friction μs 0.12, μk 0.1\n"), std::string::npos)
      << info.out;
  const json lane = json::parse(momenta("info " + ball + " --json").out).at("constraints")[0];
  EXPECT_EQ(lane.at("static_friction"), 0.12);
  EXPECT_EQ(lane.at("kinetic_friction"), 0.1);
  EXPECT_EQ(lane.at("rows"), 3);

  const CliRun run = momenta("simulate " + ball + " --reactions --duration 2");
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.err.find("stops        contact lane holds the body from t = 0 s, sliding"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("contact lane sticks at t = 1.74748798602 s"), std::string::npos)
      << run.err;
  const Csv csv = parse_csv(run.out);
  const auto column = [&](const std::string& name) {
    const auto it = std::find(csv.header.begin(), csv.header.end(), name);
    EXPECT_NE(it, csv.header.end()) << name;
    return static_cast<std::size_t>(it - csv.header.begin());
  };
  EXPECT_NEAR(csv.rows[1][column("lane.tangent_1")], -0.1 * 7 * 9.81, 1e-11);
  EXPECT_NEAR(csv.rows.back()[column("lane.tangent_1")], 0.0, 1e-11);
  EXPECT_EQ(csv.rows.back()[column("lane.tangent_2")], 0.0);

  // The belt: a slip where the spring's pull reaches the cone μs m g.
  const CliRun belt = momenta("simulate " + quoted(example("belt_stick_slip.yaml")) +
                              " --duration 1 -o " + quoted((dir_ / "belt.csv").string()));
  ASSERT_EQ(belt.code, 0) << belt.err;
  EXPECT_NE(belt.err.find("contact belt_contact slips at t = 0.3924 s (its friction reached "
                          "μs N = 5.886 N)"),
            std::string::npos)
      << belt.err;
}

// Freedoms are counted after prescribed motion and constraints take theirs: the crank-driven
// four-bar has three joint speeds, one prescribed, two independent loop rows (of the hinge's five:
// the out-of-plane ones are implied) and none left; the sleigh's rolling rows leave its
// planar joint's three speeds two.
TEST_F(SimulateCli, InfoCountsFreedomsAfterConstraints) {
  const CliRun r = momenta("info " + quoted(example("constraints/four_bar.yaml")) + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json f = json::parse(r.out).at("degrees_of_freedom");
  EXPECT_EQ(f.at("speeds"), 3);
  EXPECT_EQ(f.at("prescribed"), 1);
  EXPECT_EQ(f.at("independent_constraint_rows"), 2);
  EXPECT_EQ(f.at("free"), 0);
  const CliRun text = momenta("info " + quoted(example("constraints/four_bar.yaml")));
  EXPECT_NE(text.out.find("degrees of freedom  0 (3 joint speeds, 1 prescribed, 2 independent "
                          "constraint rows of 5)"),
            std::string::npos)
      << text.out;
  // The rods' products of inertia are round-off (5e-20 against 8e-4 kg·m²) and print as 0.
  EXPECT_EQ(text.out.find("e-20"), std::string::npos) << text.out;
  EXPECT_EQ(text.out.find("e-36"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("inertia about com  [ 0.000000e+00  0.000000e+00  0.000000e+00 ]"),
            std::string::npos)
      << text.out;
  const CliRun sleigh =
      momenta("info " + quoted(example("constraints/chaplygin_sleigh.yaml")) + " --json");
  ASSERT_EQ(sleigh.code, 0) << sleigh.err;
  EXPECT_EQ(json::parse(sleigh.out).at("degrees_of_freedom").at("free"), 2);
}

}  // namespace
}  // namespace momenta
