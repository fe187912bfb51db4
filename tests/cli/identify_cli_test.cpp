// `momenta identify`, run as a user runs it on the bundled arm's log (efforts from the textbook's
// closed form with noise, make_two_link_arm_log.py): its JSON is the library's estimate bit for
// bit, the estimates hold the built arm's base parameters, the text names each quantity with its
// unit, and bad data is one line naming the file, line and column.

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "momenta/identify/inertia_data.hpp"
#include "momenta/io/measured_data.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta_test/two_link_arm.hpp"

namespace momenta {
namespace {

using nlohmann::json;
using test::CliRun;

class IdentifyCli : public test::CliTest {
 protected:
  static std::string example(const std::string& name) {
    return (std::filesystem::current_path() / "examples" / "identification" / name).string();
  }
  static std::string arm_command(const std::string& data) {
    return "identify " + test::quoted(example("two_link_arm.yaml")) + " --data " +
           test::quoted(data);
  }
};

// The built arm (Spong's §7.4.1 figures in the example's header): 0, −(m1 lc1 + m2 l1),
// I1 + m1 lc1² + m2 l1², 0, −m2 lc2, I2 + m2 lc2² — each within 4 standard errors of the estimate.
TEST_F(IdentifyCli, TheBundledArmsLogGivesTheBuiltArmsBaseParameters) {
  const CliRun r = momenta(arm_command(example("two_link_arm_log.csv")) + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  const double built[6] = {
      0.0,        -(2.0 * 0.35 + 1.5 * 0.8), 0.12 + 2.0 * 0.35 * 0.35 + 1.5 * 0.64, 0.0,
      -1.5 * 0.4, 0.06 + 1.5 * 0.16};
  ASSERT_EQ(j.at("base_parameters").size(), 6u);
  for (int k = 0; k < 6; ++k) {
    const json& p = j.at("base_parameters")[k];
    EXPECT_LT(std::abs(p.at("estimate").get<double>() - built[k]),
              4 * p.at("standard_error").get<double>())
        << p.at("name");
  }
  EXPECT_EQ(j.at("base_parameters")[2].at("name"), "upper.I_yy + 0.64·lower.m");
  EXPECT_EQ(j.at("regrouped"), json({"lower.m"}));
  EXPECT_EQ(j.at("samples"), 501);

  // The library on the same file gives the same numbers, bit for bit.
  const io::ModelFile file = io::read_model_file(example("two_link_arm.yaml"));
  const io::MeasuredTable table = io::read_measured_csv(example("two_link_arm_log.csv"));
  const identify::InertiaEstimate e = identify::estimate_inertia(
      file.model, identify::inertia_samples(file.model, table.columns, table.values, table.source),
      identify::base_parameters(file.model));
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(j.at("base_parameters")[k].at("estimate").get<double>(), e.beta[k]);
    EXPECT_EQ(j.at("base_parameters")[k].at("standard_error").get<double>(), e.standard_error[k]);
  }
  EXPECT_NEAR(j.at("noise").at("shoulder.effort").get<double>(), 0.02, 0.002);
}

TEST_F(IdentifyCli, TextNamesEachQuantityWithItsUnit) {
  const CliRun r = momenta(arm_command(example("two_link_arm_log.csv")));
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* expected :
       {"6 of the 20 inertial parameters are identifiable from joint efforts (996 degrees of "
        "freedom)",
        "upper.I_yy + 0.64·lower.m   kg·m²", "95 % interval", "shoulder.effort: σ 0.02",
        " N·m, RMS ", "regrouped (told only in the combinations above): lower.m",
        "never felt by the joints (no data of this kind can tell them): upper.m,",
        "lower: consistent (with lower.m = 1.2 kg from the model)"}) {
    EXPECT_NE(r.out.find(expected), std::string::npos) << expected << "\n" << r.out;
  }
}

// A slow log (the arm weighed more than accelerated) is called poorly excited, naming the
// moments of inertia as what it barely tells; a log whose efforts carry joint friction the model
// lacks is called correlated. Both logs written here from Spong's closed form.
TEST_F(IdentifyCli, SaysWhenTheExperimentOrTheModelFallsShort) {
  const test::TwoLinkArm arm;
  const auto log = [&](double speed, double friction) {
    std::mt19937 rng(19);
    std::normal_distribution<double> noise(0.0, 0.01);
    std::string text = test::slurp(example("two_link_arm_log.csv"));
    std::string out = text.substr(0, text.find('\n') + 1);
    for (int i = 0; i < 300; ++i) {
      const double t = 0.02 * i;
      const Eigen::Vector2d q(1.2 * std::sin(0.9 * t) + 0.5 * std::sin(2.3 * t + 1),
                              std::sin(1.3 * t + 0.5) + 0.6 * std::sin(2.9 * t + 2.5));
      const Eigen::Vector2d v =
          speed * Eigen::Vector2d(1.08 * std::cos(0.9 * t) + 1.15 * std::cos(2.3 * t + 1),
                                  1.3 * std::cos(1.3 * t + 0.5) + 1.74 * std::cos(2.9 * t + 2.5));
      const Eigen::Vector2d a =
          speed *
          Eigen::Vector2d(-0.972 * std::sin(0.9 * t) - 2.645 * std::sin(2.3 * t + 1),
                          -1.69 * std::sin(1.3 * t + 0.5) - 5.046 * std::sin(2.9 * t + 2.5));
      const Eigen::Vector2d tau =
          arm.torque(q, v, a) + friction * v + Eigen::Vector2d(noise(rng), noise(rng));
      out += fmt::format("{},{},{},{},{},{},{},{},{}\n", t, q[0], q[1], v[0], v[1], a[0], a[1],
                         tau[0], tau[1]);
    }
    return write(fmt::format("log_{}_{}.csv", speed, friction), out).string();
  };
  const CliRun slow = momenta(arm_command(log(0.01, 0.0)));
  ASSERT_EQ(slow.code, 0) << slow.err;
  EXPECT_NE(slow.out.find("poorly excited (above 100): least determined by this data: "),
            std::string::npos)
      << slow.out;
  EXPECT_NE(slow.out.find("[upper.I_yy + 0.64·lower.m]"), std::string::npos) << slow.out;
  const CliRun rubbing = momenta(arm_command(log(1.0, 0.3)));
  ASSERT_EQ(rubbing.code, 0) << rubbing.err;
  EXPECT_EQ(rubbing.out.find("poorly excited"), std::string::npos) << rubbing.out;
  EXPECT_NE(rubbing.out.find("correlated: the model's structure misses something the data has"),
            std::string::npos)
      << rubbing.out;
}

// An encoder's log — positions and efforts only: the rates and accelerations are taken from the
// positions (a cubic over 5 samples at 50 Hz), and the built arm's base parameters come out within
// 1 % (measured 0.45 % at worst: the acceleration's O(h²) bias, which the whiteness test then
// notices). Without a time column, or for a ball joint, it says why it cannot.
TEST_F(IdentifyCli, TakesRatesAndAccelerationsFromPositionsWhereTheLogHasNone) {
  const std::string text = test::slurp(example("two_link_arm_log.csv"));
  std::string positions_only, no_time;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> f;
    std::istringstream fields(line);
    for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
    positions_only += fmt::format("{},{},{},{},{}\n", f[0], f[1], f[2], f[7], f[8]);
    no_time += fmt::format("{},{},{},{}\n", f[1], f[2], f[7], f[8]);
  }
  const CliRun r = momenta(arm_command(write("encoders.csv", positions_only).string()) + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  const double built[6] = {0.0, -1.9, 1.325, 0.0, -0.6, 0.3};
  for (int k = 0; k < 6; ++k) {
    EXPECT_NEAR(j.at("base_parameters")[k].at("estimate").get<double>(), built[k],
                0.01 * std::max(std::abs(built[k]), 1.0))
        << k;
  }
  EXPECT_NE(j.at("derived").get<std::string>().find("rates and accelerations from the positions"),
            std::string::npos);
  const CliRun timeless = momenta(arm_command(write("timeless.csv", no_time).string()));
  EXPECT_EQ(timeless.code, 1);
  EXPECT_NE(timeless.err.find("there is no 'time' column"), std::string::npos) << timeless.err;
  const CliRun top = momenta(
      "identify " +
      test::quoted((std::filesystem::current_path() / "examples" / "heavy_top.yaml").string()) +
      " --data " +
      test::quoted(write("top.csv",
                         "time,tip.qw,tip.qx,tip.qy,tip.qz,tip.effort_wx,"
                         "tip.effort_wy,tip.effort_wz\n0,1,0,0,0,0,0,0\n")
                       .string()));
  EXPECT_EQ(top.code, 1);
  EXPECT_NE(top.err.find("is not the rate of a position"), std::string::npos) << top.err;
}

TEST_F(IdentifyCli, BadDataIsOneLineNamingFileLineAndColumn) {
  const auto error_of = [&](const std::string& csv) {
    const CliRun r = momenta(arm_command(write("log.csv", csv).string()));
    EXPECT_EQ(r.code, 1) << r.err;
    return r.err;
  };
  std::string log = test::slurp(example("two_link_arm_log.csv"));
  const std::string header = log.substr(0, log.find('\n') + 1);
  EXPECT_NE(error_of(header + "0,1,1,1,1,1,1,1,1\n0,1,1,1,1,1,1,1,1\n")
                .find("log.csv:3: time must increase: 0 does not come after 0"),
            std::string::npos);
  EXPECT_NE(error_of(header + "0,1,1,1,nan,1,1,1,1\n")
                .find("log.csv:2: column 'elbow.angle_rate': 'nan' is not a finite number"),
            std::string::npos);
  EXPECT_NE(error_of(header + "0,1,1,1\n").find("log.csv:2: 4 values for the header's 9 columns"),
            std::string::npos);
  std::string misspelt = header;
  misspelt.replace(misspelt.find("elbow.effort"), 12, "elbow.efort");
  const std::string missing = error_of(misspelt + "0,1,1,1,1,1,1,1,1\n");
  EXPECT_NE(missing.find("log.csv: no column 'elbow.effort' (the effort the actuator applied "
                         "along elbow.angle_rate) (did you mean 'elbow.efort'?)"),
            std::string::npos)
      << missing;
  EXPECT_EQ(std::count(missing.begin(), missing.end(), '\n'), 1);
}

// The grey-box route: `momenta identify FILE.yaml` of an identification file. The quarter car's
// log was made by SciPy from Franklin's equations (make_grey_box_logs.py) with ks = 130 000 N/m
// and b = 9 800 N·s/m; the JSON's intervals hold them, and -o writes a model file that reads
// back with the estimates in place and the rest of the file as it was.
TEST_F(IdentifyCli, AnIdentificationFileFitsTheModelsNumbersAndWritesTheIdentifiedModel) {
  const std::string identified = (dir_ / "identified.yaml").string();
  const CliRun r = momenta("identify " + test::quoted(example("quarter_car_identify.yaml")) +
                           " --json -o " + test::quoted(identified));
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_TRUE(j.at("converged").get<bool>());
  EXPECT_TRUE(j.at("identifiability").at("identifiable").get<bool>());
  const double truth[2] = {130000.0, 9800.0};
  for (int i = 0; i < 2; ++i) {
    const json& p = j.at("parameters")[i];
    EXPECT_LE(p.at("interval_95")[0].get<double>(), truth[i]) << p.at("name");
    EXPECT_GE(p.at("interval_95")[1].get<double>(), truth[i]) << p.at("name");
  }
  EXPECT_EQ(j.at("channels")[0].at("noise_given"), true);

  const io::ModelFile written = io::read_model_file(identified);
  const io::ModelFile original =
      io::read_model_file(std::filesystem::current_path() / "examples" / "quarter_car.yaml");
  const auto stiffness = [](const io::ModelFile& f) {
    return std::get<model::LinearSpringDamper>(f.model.force_elements()[1]).stiffness;
  };
  EXPECT_EQ(stiffness(written), j.at("parameters")[0].at("estimate").get<double>());
  EXPECT_NE(stiffness(written), stiffness(original));
  EXPECT_EQ(written.model.spatial_inertia(2).mass, original.model.spatial_inertia(2).mass);

  // Not overwritten without --force; with it, written again.
  const CliRun again = momenta("identify " + test::quoted(example("quarter_car_identify.yaml")) +
                               " -o " + test::quoted(identified));
  EXPECT_NE(again.code, 0);
  EXPECT_NE(again.err.find("pass --force"), std::string::npos) << again.err;
}

TEST_F(IdentifyCli, AFreeResponseWithoutAForceSaysWhatItCannotTell) {
  write("msd.yaml",
        "name: mass spring damper\n"
        "gravity: [0, 0, 0]\n"
        "bodies: [{name: mass, mass: 2.0}]\n"
        "joints:\n"
        "  - {name: slide, type: prismatic, parent: world, child: mass, axis: [1, 0, 0],\n"
        "     q0: 0.1, damping: 0.8}\n"
        "forces: [{name: spring, type: torsional_spring, joint: slide, stiffness: 50.0}]\n");
  std::ostringstream log;
  log << "time,x\n";
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 1e-3);
  const double w = 5.0, zeta = 0.04, wd = w * std::sqrt(1.0 - zeta * zeta);
  for (int k = 0; k <= 300; ++k) {
    const double t = 0.02 * k;
    log << t << ","
        << 0.1 * std::exp(-zeta * w * t) *
                   (std::cos(wd * t) + zeta / std::sqrt(1.0 - zeta * zeta) * std::sin(wd * t)) +
               noise(rng)
        << "\n";
  }
  write("free.csv", log.str());
  const auto file =
      write("fit.yaml",
            "model: msd.yaml\n"
            "parameters:\n"
            "  - {name: m, path: bodies.mass.mass, guess: 1.5}\n"
            "  - {name: k, path: forces.spring.stiffness, guess: 40}\n"
            "  - {name: b, path: joints.slide.damping, guess: 1.0}\n"
            "experiments:\n"
            "  - {data: free.csv, outputs: [{column: x, channel: slide.position}]}\n");
  const CliRun r = momenta("identify " + test::quoted(file.string()));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("NOT IDENTIFIABLE from these experiments:\n  m, k and b scaled by one "
                       "factor together change no output: the data determine only the ratios "
                       "k/m and b/m"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("not determined"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
}

TEST_F(IdentifyCli, AModelFileWithoutDataSaysWhatToGive) {
  const CliRun r = momenta("identify " + test::quoted(example("damped_pendulum.yaml")));
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("give its measured motion and efforts with --data"), std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace momenta
