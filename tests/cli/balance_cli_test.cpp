// `momenta balance`, run as a user runs it: its JSON equals the library's numbers bit for bit on
// the bundled rotors, its text names every quantity, and bad input is one line with the exit
// code of its kind (1: the physics or the file, 2: the options).

#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fmt/format.h>

#include "cli_runner.hpp"
#include "momenta/inertia/balancing.hpp"
#include "momenta/io/part_file.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta {
namespace {

using nlohmann::json;
using test::CliRun;

class BalanceCli : public test::CliTest {
 protected:
  static std::string example(const std::string& name) {
    return test::quoted((std::filesystem::current_path() / "examples" / "parts" / name).string());
  }
};

Vec2 xy(const json& j) { return {j.at("x").get<double>(), j.at("y").get<double>()}; }

TEST_F(BalanceCli, JsonIsTheLibrarysNumbers) {
  const CliRun r = momenta("balance " + example("two_disk_shaft.yaml") +
                           " --bearings 0 1 --speed 3000 --planes 0.25 0.75 --radius 0.15 "
                           "--grade 2.5 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const json j = json::parse(r.out);
  const io::CompositePart part = io::read_part_file("examples/parts/two_disk_shaft.yaml");
  const inertia::Unbalance u = inertia::unbalance(part.total, {});
  EXPECT_EQ(j.at("mass").get<double>(), u.mass);
  EXPECT_EQ(xy(j.at("unbalance").at("static_unbalance")), u.static_unbalance);
  EXPECT_EQ(xy(j.at("unbalance").at("couple_unbalance")), u.couple_unbalance);
  const double omega = 3000 * 2 * std::numbers::pi / 60;
  const inertia::BearingReactions R = inertia::bearing_reactions(u, 0, 1, omega);
  const json& row = j.at("reactions").at(0);
  EXPECT_EQ(row.at("omega").get<double>(), omega);
  EXPECT_EQ(xy(row.at("A")), R.A);
  EXPECT_EQ(xy(row.at("B")), R.B);
  // The correction gives back the file's 12 g and 8 g, and the grade passes only after it.
  const json& masses = j.at("correction").at("masses");
  EXPECT_NEAR(masses.at(0).at("mass").get<double>(), 0.012, 1e-14);
  EXPECT_NEAR(masses.at(1).at("mass").get<double>(), 0.008, 1e-14);
  EXPECT_EQ(masses.at(0).at("action"), "add");
  EXPECT_FALSE(j.at("grade").at("pass").get<bool>());
  EXPECT_TRUE(j.at("grade_after_correction").at("pass").get<bool>());
  EXPECT_EQ(j.at("grade").at("permissible").get<double>(),
            inertia::check_grade(u, 2.5, omega, 0, 1).permissible);
}

// examples/unbalanced_rotor.yaml (a disk skewed 2° on a vertical shaft, bearings at z = 0 and
// 0.4 m, ω = 100 rad/s) states its bearing couple in its header: (C − A) ω² sin δ cos δ =
// 4.30165 N·m, ±10.754 N along y. The model's body on its revolute joint is the rotor.
TEST_F(BalanceCli, ModelFileRotorIsItsBodyOnTheRevoluteJoint) {
  const double rpm = 100.0 * 60 / (2 * std::numbers::pi);
  const CliRun r = momenta("balance " + example("../unbalanced_rotor.yaml") +
                           " --bearings 0 0.4 --speed " + fmt::format("{:.17g}", rpm) + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j.at("joint"), "bearing");
  const double C = 0.5 * 5 * 0.01, A = 5 * (3 * 0.01 + 0.0004) / 12,
               delta = 2 * std::numbers::pi / 180;
  // The shaft is symmetric: the disk's couple alone, (C − A) sin δ cos δ.
  EXPECT_NEAR(xy(j.at("unbalance").at("couple_unbalance")).norm(),
              (C - A) * std::sin(delta) * std::cos(delta), 1e-15);
  const Vec2 RA = xy(j.at("reactions").at(0).at("A")), RB = xy(j.at("reactions").at(0).at("B"));
  const double force = (C - A) * 1e4 * std::sin(delta) * std::cos(delta) / 0.4;  // 10.754 N
  EXPECT_NEAR(RA.norm(), force, 1e-11);
  EXPECT_NEAR(RB.norm(), force, 1e-11);
  EXPECT_NEAR(std::abs(RA.y()), force, 1e-11);  // along y, the tilt being about x
  EXPECT_NEAR(force, 10.754, 5e-4);
  EXPECT_MATRIX_NEAR(RA + RB, Vec2::Zero(), 1e-12);
}

// The static loads use the model file's own gravity: its |g| (9.81 here, not 9.80665), split
// m g between the bearings; a model without gravity has none, and says so. --gravity overrides.
TEST_F(BalanceCli, StaticLoadsTakeTheModelsGravity) {
  const std::string rotor = example("../unbalanced_rotor.yaml");
  const std::string args = " --bearings 0 0.4 --speed 1000";
  const CliRun own = momenta("balance " + rotor + args + " --json");
  ASSERT_EQ(own.code, 0) << own.err;
  const json j = json::parse(own.out);
  const double m = j.at("mass");
  EXPECT_EQ(j.at("static_loads").at("g"), 9.81);
  EXPECT_NEAR(double(j.at("static_loads").at("A")) + double(j.at("static_loads").at("B")), m * 9.81,
              1e-12 * m * 9.81);
  const CliRun text = momenta("balance " + rotor + args);
  EXPECT_NE(text.out.find("g = 9.81 m/s², the model's"), std::string::npos) << text.out;
  std::string weightless =
      slurp(std::filesystem::current_path() / "examples" / "unbalanced_rotor.yaml");
  const std::size_t g = weightless.find("gravity: [0, 0, -9.81]");
  ASSERT_NE(g, std::string::npos);
  weightless.replace(g, 22, "gravity: [0, 0, 0]");
  const CliRun none = momenta("balance " + quoted(write("rotor.yaml", weightless).string()) + args);
  ASSERT_EQ(none.code, 0) << none.err;
  EXPECT_NE(none.out.find("static loads: none (g = 0, the model's gravity)"), std::string::npos)
      << none.out;
  EXPECT_EQ(none.out.find("9.80665"), std::string::npos) << none.out;
  const CliRun given = momenta("balance " + rotor + args + " --gravity 9.80665 --json");
  EXPECT_EQ(json::parse(given.out).at("static_loads").at("g"), 9.80665);
}

TEST_F(BalanceCli, RemovingMassPlacesItOpposite) {
  const std::string base =
      "balance " + example("two_disk_shaft.yaml") + " --planes 0.25 0.75 --json";
  const json add = json::parse(momenta(base).out);
  const json remove = json::parse(momenta(base + " --remove").out);
  for (int k = 0; k < 2; ++k) {
    const double a = add.at("correction").at("masses").at(k).at("angle_deg").get<double>();
    const double b = remove.at("correction").at("masses").at(k).at("angle_deg").get<double>();
    EXPECT_NEAR(std::abs(std::remainder(a - b, 360.0)), 180.0, 1e-9);
    EXPECT_EQ(remove.at("correction").at("masses").at(k).at("action"), "remove");
  }
}

TEST_F(BalanceCli, TextNamesEveryQuantity) {
  const CliRun r = momenta("balance " + example("overhung_fan.yaml") +
                           " --bearings 0.05 0.25 --speed-range 0 3000 --points 4 --plane 0.35 "
                           "--radius 0.2 --grade 6.3 --speed 3000");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* text :
       {"static unbalance", "couple unbalance", "principal axis tilt", "bearing reactions",
        "static loads", "single-plane correction", "overhung rotor", "verdict  FAIL", "3000"}) {
    EXPECT_NE(r.out.find(text), std::string::npos) << text << " missing from\n" << r.out;
  }
}

TEST_F(BalanceCli, BadInputIsOneLine) {
  struct Case {
    std::string args;
    int code;
    std::string says;
  };
  const std::string fan = example("overhung_fan.yaml");
  for (const Case& c : {
           Case{"balance " + fan + " --planes 0.3 0.3", 1, "coincide"},
           Case{"balance " + fan + " --bearings 0.1 0.1 --speed 100", 1, "coincide"},
           Case{"balance " + fan + " --axis 0 0 0", 1, "no direction"},
           Case{"balance " + fan + " --radius 0.1", 2, "--planes"},
           Case{"balance " + fan + " --radius 0 --planes 0 1", 2, "--radius"},
           Case{"balance " + fan + " --speed 3000", 2, "--bearings"},
           Case{"balance " + fan + " --bearings 0 1 --grade 2.5", 2, "--speed"},
           Case{"balance " + fan + " --bearings 0 1 --speed-range 3000 10", 2, "A < B"},
           Case{"balance " + example("../../README.md"), 1, "unsupported file extension"},
           Case{"balance " + example("../double_pendulum.yaml"), 1, "name the rotor with --body"},
           Case{"balance " + example("../cruise_control.yaml"), 1, "revolute"},
           Case{"balance " + example("../unbalanced_rotor.yaml") + " --axis 1 0 0", 2, "revolute"},
           Case{"balance " + example("../unbalanced_rotor.yaml") + " --body disc", 1,
                "did you mean"},
           Case{"balance " + fan + " --body shaft", 2, "model file"},
       }) {
    const CliRun r = momenta(c.args);
    EXPECT_EQ(r.code, c.code) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << c.args;
  }
}

}  // namespace
}  // namespace momenta
