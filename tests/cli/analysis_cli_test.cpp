// `momenta linearize`, `momenta modes` and `momenta response`, run as a user runs them: the built
// binary (MOMENTA_CLI_PATH), exit codes (0 ok, 1 user error, 2 usage error) and JSON checked
// against the library on the example models.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "momenta/analysis/linearize.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using test::CliRun;
using test::slurp;

class AnalysisCli : public test::CliTest {
 protected:
  static std::string example(const std::string& name) {
    return fmt::format("'{}/examples/{}.yaml'", test::source_dir(), name);
  }
};

MatX matrix(const json& rows, Eigen::Index cols) {
  MatX M(static_cast<Eigen::Index>(rows.size()), cols);
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (Eigen::Index k = 0; k < cols; ++k)
      M(static_cast<Eigen::Index>(i), k) = rows.at(i).at(static_cast<std::size_t>(k)).get<double>();
  return M;
}

TEST_F(AnalysisCli, LinearizeJsonMatchesTheLibrary) {
  const CliRun r = momenta("linearize " + example("quarter_car") +
                           " --inputs road --outputs body_y,wheel_x --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  const io::ModelFile file = io::read_model_file(test::source_dir() + "/examples/quarter_car.yaml");
  analysis::LinearizationOptions options;
  options.inputs = {"road"};
  options.outputs = {"body_y", "wheel_x"};
  options.output_specs = file.outputs;
  const analysis::LinearModel lin =
      analysis::linearize(file.model, analysis::initial_operating_point(file.model), options);
  EXPECT_EQ(j.at("state_names").get<std::vector<std::string>>(), lin.system.state_names());
  EXPECT_EQ(j.at("input_names").get<std::vector<std::string>>(), std::vector<std::string>{"road"});
  EXPECT_EQ(j.at("output_names").get<std::vector<std::string>>(),
            (std::vector<std::string>{"body_y", "wheel_x"}));
  // JSON prints doubles round-trip exactly: the same numbers.
  EXPECT_MATRIX_NEAR(matrix(j.at("A"), 4), lin.system.A(), 0.0);
  EXPECT_MATRIX_NEAR(matrix(j.at("B"), 1), lin.system.B(), 0.0);
  EXPECT_MATRIX_NEAR(matrix(j.at("C"), 4), lin.system.C(), 0.0);
  EXPECT_MATRIX_NEAR(matrix(j.at("D"), 1), lin.system.D(), 0.0);
  ASSERT_EQ(j.at("eigenvalues").size(), 4u);
  EXPECT_EQ(j.at("eigenvalues").at(0).size(), 2u);
}

// The bead on the turntable at t = 1 s, seen from the turntable: x = x0 cosh Ω t, ẋ = x0 Ω sinh Ω t
// (Ω = 2 rad/s, x0 = 0.05 m; RK4 at 1 ms: 1e-12), Coriolis 2 Ω ẋ, centripetal −Ω² x; from a
// state file the instant is the file's.
TEST_F(AnalysisCli, KinematicsOfTheTurntableBead) {
  const std::string model = "'" + test::source_dir() + "/examples/kinematics/turntable_bead.yaml'";
  const CliRun r =
      momenta("kinematics " + model + " --point bead --frame turntable --time 1 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  const double W = 2.0, x = 0.05 * std::cosh(W), x_dot = 0.05 * W * std::sinh(W);
  const auto vec = [&](const json& a) {
    return Vec3(a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>());
  };
  EXPECT_MATRIX_NEAR(vec(j.at("position")), Vec3(x, 0, 0), 1e-12);
  EXPECT_MATRIX_NEAR(vec(j.at("velocity").at("relative")), Vec3(x_dot, 0, 0), 1e-11);
  EXPECT_MATRIX_NEAR(vec(j.at("acceleration").at("coriolis")), Vec3(0, 2 * W * x_dot, 0), 1e-10);
  EXPECT_MATRIX_NEAR(vec(j.at("acceleration").at("centripetal")), Vec3(-W * W * x, 0, 0), 1e-11);
  // T = ½ m (ẋ² + (Ω x)²) + ½ (2/5 m r²) Ω² for the 0.02 kg, 4 mm bead.
  const double m = 0.02, I = 0.4 * m * 0.004 * 0.004;
  EXPECT_NEAR(j.at("kinetic_energy").at("translation").get<double>(),
              0.5 * m * (x_dot * x_dot + W * W * x * x), 1e-13);
  EXPECT_NEAR(j.at("kinetic_energy").at("rotation").get<double>(), 0.5 * I * W * W, 1e-16);

  // The text form, and a state file's instant: q = (angle, x), v = (Ω, ẋ).
  std::ofstream(dir_ / "s.json") << R"({"q": [0.3, 0.1], "v": [2.0, 0.5], "t": 0.15})";
  const CliRun text = momenta("kinematics " + model + " --point bead --frame turntable --state '" +
                              (dir_ / "s.json").string() + "'");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("at t = 0.15 s"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("Coriolis     2 Ω × v_rel    [0, 2, 0]"), std::string::npos) << text.out;

  const CliRun bad = momenta("kinematics " + model + " --point bead:1,2 --frame turntable");
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.err.find("expected BODY:x,y,z"), std::string::npos) << bad.err;
  const CliRun unknown = momenta("kinematics " + model + " --point bead --frame turntabel");
  EXPECT_NE(unknown.err.find("did you mean 'turntable'"), std::string::npos) << unknown.err;
}

// The struck rod (examples/struck_rod.yaml: 4 kg, 1.2 m, I_O = m L²/3 = 1.92 kg·m²) struck by
// 4 N·s at its centre of percussion d = 0.8 m: θ̇ = −P d / I_O, no impulse at the pin; at its tip
// θ̇ = −2.5 rad/s and the pin's impulse R = P (m d L / (2 I_O) − 1) = 2 N·s along P. Kelvin's work
// equals the energy gained. A point or vector that is not three numbers is refused, naming it.
TEST_F(AnalysisCli, ImpactOnTheStruckRodAsTheTextbookHasIt) {
  const std::string model = example("struck_rod");
  for (const auto& [depth, rate, pin] :
       {std::tuple{0.8, -4.0 * 0.8 / 1.92, 0.0}, std::tuple{1.2, -2.5, 2.0}}) {
    const CliRun r =
        momenta(fmt::format("impact {} --at rod:0,0,{} --impulse 4,0,0 --json", model, -depth));
    ASSERT_EQ(r.code, 0) << r.err;
    const json j = json::parse(r.out);
    EXPECT_NEAR(j.at("v_after").at("pin.angle_rate").get<double>(), rate, 1e-14);
    EXPECT_NEAR(j.at("joint_impulses").at("pin").at("force").at(0).get<double>(), pin, 1e-14);
    const double gained = j.at("kinetic_energy").at("change").get<double>();
    EXPECT_NEAR(gained, 0.5 * 1.92 * rate * rate, 1e-14);
    EXPECT_NEAR(j.at("impulse_work").get<double>(), gained, 1e-14);
  }
  const CliRun text = momenta("impact " + model + " --at rod:0,0,-0.8 --impulse 4,0,0");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("pin.angle_rate  0 → -1.66667 rad/s"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("pin  force [0, 0, 0] N·s"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("gained 2.66667 J"), std::string::npos) << text.out;
  const CliRun bad = momenta("impact " + model + " --at rod --impulse 4,0");
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.err.find("--impulse: '4,0': expected x,y,z"), std::string::npos) << bad.err;
  // A collision (examples/eccentric_impact.yaml): a 0.5 kg sphere at 3 m/s strikes the hanging
  // 4 kg, 1.2 m rod 1.1 m below its pin with e = 0.6 — the closed forms of the file's comment.
  const std::string eccentric = example("eccentric_impact");
  const CliRun hit =
      momenta("impact " + eccentric +
              " --between sphere rod:0,0,-1.1 --normal 1,0,0 --restitution 0.6 --json");
  ASSERT_EQ(hit.code, 0) << hit.err;
  const json h = json::parse(hit.out);
  const double I_O = 1.92, ms = 0.5, v0 = 3.0, d = 1.1, e = 0.6;
  const double omega = ms * v0 * d * (1 + e) / (I_O + ms * d * d);
  const double v_s = v0 * (ms * d * d - e * I_O) / (I_O + ms * d * d);
  EXPECT_NEAR(h.at("v_after").at("pin.angle_rate").get<double>(), -omega, 1e-14);
  EXPECT_NEAR(h.at("v_after").at("slide.position_rate").get<double>(), v_s, 1e-14);
  EXPECT_NEAR(h.at("separation_speed").get<double>(), e * v0, 1e-14);
  EXPECT_NEAR(h.at("joint_impulses").at("pin").at("force").at(0).get<double>(),
              4.0 * omega * 0.6 - ms * (v0 - v_s), 1e-14);
  // With friction (examples/bouncing_sphere.yaml at t = 0.4 s: falling at g t, sliding sideways
  // at 1 m/s, spinning about the vertical): the ball strikes the floor at its lowest point, its
  // slip stopped within the impact — it leaves rolling, v_x = 5/7 m/s, ω_y = 5 / (7 r) — by the
  // friction impulse −2 m u / 7; compression ends at half the normal impulse's (1 + e).
  const CliRun rough = momenta("impact " + example("bouncing_sphere") +
                               " --time 0.4 --between world:0,0,0 ball:0,0,-0.05 --normal 0,0,1 "
                               "--restitution 0.6 --friction 0.5,0.4 --json");
  ASSERT_EQ(rough.code, 0) << rough.err;
  const json r = json::parse(rough.out);
  EXPECT_EQ(r.at("friction").at("outcome"), "sliding, then sticking");
  EXPECT_NEAR(r.at("friction").at("compression_impulse").get<double>(), 0.1 * 9.81 * 0.4, 1e-14);
  EXPECT_NEAR(r.at("friction").at("impulse").at(0).get<double>(), -2.0 * 0.1 / 7.0, 1e-14);
  EXPECT_NEAR(r.at("v_after").at("free.vx").get<double>(), 5.0 / 7.0, 1e-14);
  // ω in the ball's axes, turned 1.2 rad about the vertical by then: its horizontal part.
  const json& w = r.at("v_after");
  EXPECT_NEAR(std::hypot(w.at("free.wx").get<double>(), w.at("free.wy").get<double>()),
              5.0 / (7.0 * 0.05), 1e-12);
  EXPECT_NEAR(w.at("free.wz").get<double>(), 3.0, 1e-12);
  EXPECT_NEAR(r.at("separation_speed").get<double>(), 0.6 * 9.81 * 0.4, 1e-12);
  const CliRun rough_text = momenta("impact " + example("bouncing_sphere") +
                                    " --time 0.4 --between world:0,0,0 ball:0,0,-0.05 --normal "
                                    "0,0,1 --restitution 0.6 --friction 0.5,0.4");
  EXPECT_NE(rough_text.out.find("friction (μs 0.5, μk 0.4): sliding, then sticking, friction "
                                "impulse [-0.0285714, 0, 0] N·s; slip [1, 0, 0] → [0, 0, 0] m/s "
                                "(compression ends at a normal impulse of 0.3924 N·s)"),
            std::string::npos)
      << rough_text.out;
  // A rod striking by one end (examples/falling_rod.yaml at t = 0.2 s, falling at V = g t): the
  // normal impulse would make the end slip; within μs = 0.5 it sticks, P_n = (1 + e) m V a / 4,
  // P_t = 3 sin θ cos θ P_n / a (a = 1 + 3 cos² θ); with μ = 0.2 it slides from rest, P_t = μ P_n.
  const auto rod_impact = [&](const std::string& friction) {
    return momenta("impact " + example("falling_rod") +
                   " --time 0.2 --between world:0,0,0 rod:0,0,-0.5 --normal 0,0,1 --restitution "
                   "0.5 --friction " +
                   friction + " --json");
  };
  const CliRun stuck = rod_impact("0.5,0.4"), slid = rod_impact("0.2");
  ASSERT_EQ(stuck.code, 0) << stuck.err;
  ASSERT_EQ(slid.code, 0) << slid.err;
  const double V = 9.81 * 0.2, sn = 0.5, cs = std::sqrt(3.0) / 2, a = 1 + 3 * cs * cs;
  const json st = json::parse(stuck.out), sl = json::parse(slid.out);
  EXPECT_EQ(st.at("friction").at("outcome"), "sticking");
  EXPECT_NEAR(st.at("normal_impulse").get<double>(), 1.5 * V * a / 4, 1e-13);
  EXPECT_NEAR(st.at("friction").at("impulse").at(0).get<double>(), 1.5 * V * 3 * sn * cs / 4,
              1e-13);
  EXPECT_EQ(sl.at("friction").at("outcome"), "sliding from rest");
  const double P_n = 1.5 * V / (1 + 3 * sn * sn - 3 * 0.2 * sn * cs);
  EXPECT_NEAR(sl.at("normal_impulse").get<double>(), P_n, 1e-13);
  EXPECT_NEAR(sl.at("friction").at("impulse").at(0).get<double>(), 0.2 * P_n, 1e-13);
  const CliRun apart = momenta("impact " + eccentric +
                               " --between sphere rod:0,0,-1.1 --normal -1,0,0 --restitution 0.6");
  EXPECT_NE(apart.err.find("do not approach along the normal"), std::string::npos) << apart.err;
  const CliRun neither = momenta("impact " + eccentric);
  EXPECT_NE(neither.err.find("give an applied impulse"), std::string::npos) << neither.err;
  const CliRun world = momenta("impact " + model + " --at world --impulse 4,0,0");
  EXPECT_NE(world.err.find("the world is not a moving body"), std::string::npos) << world.err;
}

// Round-off is not shown as a value (one rule, common/number_text.hpp): the flexible satellite's
// rigid-body pair (computed 1.5e-17 ± 2.4e-9j against its 1 rad/s boom mode) prints as
// "0 (rigid-body mode)"; --json keeps the computed values.
TEST_F(AnalysisCli, RigidBodyModesPrintAsZero) {
  const CliRun text = momenta("modes " + example("flexible_satellite"));
  ASSERT_EQ(text.code, 0) << text.err;
  std::size_t rigid = 0;
  for (auto at = text.out.find("0 (rigid-body mode)"); at != std::string::npos;
       at = text.out.find("0 (rigid-body mode)", at + 1))
    ++rigid;
  EXPECT_EQ(rigid, 2u) << text.out;
  EXPECT_EQ(text.out.find("e-09"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("1.0005"), std::string::npos) << text.out;  // the boom mode stays
  const json j = json::parse(momenta("modes " + example("flexible_satellite") + " --json").out);
  const double w = j.at("modes").at(0).at("natural_frequency_rad_s").get<double>();
  EXPECT_GT(w, 0.0);
  EXPECT_LT(w, 1e-6);
}

#if MOMENTA_TEST_SYMBOLIC
// An expression as GiNaC prints it, in a canonical order: the terms of each sum and the factors
// of each product sorted (GiNaC orders them by its symbols' creation, which can differ from run
// to run), parenthesized groups likewise, spaces dropped. Enough for the sums of products the
// CLI prints.
std::string canonical(const std::string& spaced) {
  std::string text;
  for (const char c : spaced)
    if (c != ' ') text += c;
  const auto split = [](const std::string& s, char separator) {
    std::vector<std::string> parts(1);
    int depth = 0;
    for (const char c : s) {
      depth += c == '(' ? 1 : c == ')' ? -1 : 0;
      if (c == separator && depth == 0) {
        parts.emplace_back();
      } else {
        parts.back() += c;
      }
    }
    return parts;
  };
  const auto within = [&](const std::string& factor) {  // groups canonical, recursively
    std::string out;
    for (std::size_t i = 0; i < factor.size(); ++i) {
      if (factor[i] != '(') {
        out += factor[i];
        continue;
      }
      int depth = 1;
      std::size_t j = i + 1;
      for (; j < factor.size() && depth > 0; ++j)
        depth += factor[j] == '(' ? 1 : factor[j] == ')' ? -1 : 0;
      out += '(';
      out += canonical(factor.substr(i + 1, j - i - 2));
      out += ')';
      i = j - 1;
    }
    return out;
  };
  std::vector<std::string> terms;
  for (const std::string& term : split(text, '+')) {
    std::vector<std::string> factors;
    for (const std::string& f : split(term, '*')) factors.push_back(within(f));
    std::sort(factors.begin(), factors.end());
    std::string joined;
    for (const std::string& f : factors) {
      if (!joined.empty()) joined += '*';
      joined += f;
    }
    terms.push_back(joined);
  }
  std::sort(terms.begin(), terms.end());
  std::string out;
  for (const std::string& t : terms) {
    if (!out.empty()) out += '+';
    out += t;
  }
  return out;
}

// The text after `prefix` on the line that starts with it, canonical.
std::string canonical_after(const std::string& out, const std::string& prefix) {
  const auto at = out.find(prefix);
  if (at == std::string::npos) return "(no line " + prefix + ")";
  const auto start = at + prefix.size();
  return canonical(out.substr(start, out.find('\n', start) - start));
}

TEST_F(AnalysisCli, EquationsTheirLinearizationAndATransferFunctionInSymbols) {
  // The cruise control (FPE ch. 2): m v̇ + b v = u, and V(s)/U(s) = 1/(m s + b): the engine's
  // unit direction (1 N per unit of u) is no symbol.
  const CliRun eom = momenta("equations " + example("cruise_control") + " --all-symbols --text");
  ASSERT_EQ(eom.code, 0) << eom.err;
  const auto line = eom.out.substr(eom.out.find('\n') + 1);
  const auto equals = line.find(" = ");
  EXPECT_EQ(canonical(line.substr(0, equals)), canonical("m_car*road_ddot+c_road*road_dot"))
      << eom.out;
  EXPECT_EQ(canonical_after(line, " = "), canonical("u")) << eom.out;
  const CliRun tf =
      momenta("equations " + example("cruise_control") + " --all-symbols --transfer u:speed");
  ASSERT_EQ(tf.code, 0) << tf.err;
  EXPECT_EQ(canonical_after(tf.out, "G(s) = speed(s) / u(s) = "), canonical("1/(m_car*s+c_road)"))
      << tf.out;
  const CliRun linear =
      momenta("equations " + example("cruise_control") + " --all-symbols --form linear");
  ASSERT_EQ(linear.code, 0) << linear.err;
  EXPECT_EQ(canonical_after(linear.out, "A[1,1] = "), "-c_road/m_car") << linear.out;
  EXPECT_EQ(canonical_after(linear.out, "B[1,0] = "), "1/m_car") << linear.out;
  const CliRun bad = momenta("equations " + example("cruise_control") + " --transfer x:speed");
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.err.find("no input 'x'; the inputs are u"), std::string::npos) << bad.err;
}

TEST_F(AnalysisCli, EquationsOfAConstrainedModelPrintItsForcesAndRows) {
  // The Chaplygin sleigh: the blade's force λ on the right of the equations, then its row.
  const CliRun sleigh =
      momenta("equations " + example("constraints/chaplygin_sleigh") + " --all-symbols");
  ASSERT_EQ(sleigh.code, 0) << sleigh.err;
  EXPECT_NE(sleigh.out.find("λ the rows' forces [lambda_blade_lateral]"), std::string::npos)
      << sleigh.out;
  // ẏ cos φ − ẋ sin φ = 0 (the expression itself is checked in equations_test.cpp).
  const auto row = sleigh.out.find("blade.lateral (velocity):\n  ");
  ASSERT_NE(row, std::string::npos) << sleigh.out;
  const std::string line = sleigh.out.substr(row, sleigh.out.find('\n', row + 30) - row);
  for (const char* part : {"floor_plane_y_dot", "cos(floor_plane_angle)", "sin(floor_plane_angle)",
                           "floor_plane_x_dot", " = 0"})
    EXPECT_NE(line.find(part), std::string::npos) << line;
  // The four-bar's hinge rows out of the plane hold identically; --form matrix adds G and k.
  const CliRun four_bar =
      momenta("equations " + example("constraints/four_bar") + " --form matrix");
  ASSERT_EQ(four_bar.code, 0) << four_bar.err;
  EXPECT_NE(four_bar.out.find("closure.z (position):\n  0 = 0  (identically"), std::string::npos)
      << four_bar.out;
  EXPECT_NE(four_bar.out.find("G[4,1] = "), std::string::npos) << four_bar.out;
  EXPECT_NE(four_bar.out.find("k[0] = "), std::string::npos) << four_bar.out;
  // The linearization in symbols of a constrained model points to the numeric one.
  const CliRun linear = momenta("equations " + example("constraints/four_bar") + " --form linear");
  EXPECT_NE(linear.code, 0);
  EXPECT_NE(linear.err.find("`momenta linearize` does that numerically"), std::string::npos)
      << linear.err;
}

// Same file, same bytes: GiNaC's own order moves with address randomization from run to run
// (before this was fixed, five runs of the double pendulum gave five different texts). Each
// form of a planar chain and of a rolling disk (inexact coefficients, quaternions) three times.
// Under AddressSanitizer each form runs once, which goes through the same code; the repeats
// (42 of the 63 derivations, 15 s in Release, several times that sanitized) are Release's.
TEST_F(AnalysisCli, EquationsPrintTheSameBytesEveryRun) {
#if defined(__SANITIZE_ADDRESS__)
  constexpr int kRepeats = 0;
#else
  constexpr int kRepeats = 2;
#endif
  for (const std::string model :
       {"double_pendulum", "constraints/four_bar", "constraints/rolling_disk_on_axle"}) {
    for (const char* form : {"", " --all-symbols", " --latex", " --form matrix",
                             " --form newton-euler", " --cpp", " --python"}) {
      const std::string command = "equations " + example(model) + form;
      const CliRun first = momenta(command);
      ASSERT_EQ(first.code, 0) << command << "\n" << first.err;
      for (int run = 0; run < kRepeats; ++run)
        EXPECT_EQ(momenta(command).out, first.out) << command;
    }
  }
}

// The human form: accelerations first, then speed terms, then the rest; within a product
// numbers, parameters, functions, coordinates, accelerations; spaces around + and −.
// The CLI's text with each broken equation joined back onto one line.
std::string joined(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 5, "\n    ") == 0) {
      out += ' ';
      i += 4;
    } else {
      out += text[i];
    }
  }
  return out;
}

TEST_F(AnalysisCli, EquationsReadAccelerationsFirst) {
  const CliRun pendulum = momenta("equations " + example("pendulum") + " --all-symbols");
  ASSERT_EQ(pendulum.code, 0) << pendulum.err;
  EXPECT_NE(pendulum.out.find("\nL_bob^2*m_bob*pivot_ddot + L_bob*g*m_bob*sin(pivot) = 0\n"),
            std::string::npos)
      << pendulum.out;
  const CliRun flexible = momenta("equations " + example("flexible_satellite") + " --all-symbols");
  EXPECT_NE(joined(flexible.out)
                .find("\nI_hub_zz*theta1_ddot + c_boom*(theta1_dot - theta2_dot) + "
                      "k_boom*(theta1 - theta2) = tc\n"),
            std::string::npos)
      << flexible.out;
  // Equation k leads with coordinate k's own acceleration, positive: the sleigh's third (its
  // heading) starts with its turning inertia, not with −c m sin θ ẍ; and no equation of these
  // bundled models starts with a minus.
  const CliRun sleigh =
      momenta("equations " + example("constraints/chaplygin_sleigh") + " --all-symbols");
  EXPECT_NE(sleigh.out.find("\nfloor_plane_angle_ddot*(I_sleigh_zz + L_sleigh^2*m_sleigh)\n"),
            std::string::npos)
      << sleigh.out;
  for (const char* model :
       {"double_pendulum", "gyroscope", "free_body_tennis_racket", "constraints/chaplygin_sleigh",
        "constraints/rolling_coin", "constraints/four_bar", "quarter_car"}) {
    const CliRun r = momenta("equations " + example(model));
    ASSERT_EQ(r.code, 0) << model << r.err;
    EXPECT_EQ(r.out.find("\n-"), std::string::npos) << model << "\n" << r.out;
  }
}

// Round-off in a body's mass properties is no coefficient: the gyroscope's composed rotor has a
// product of inertia of 1.9e-20 kg·m² (against 5.6e-3) that printed as
// "-1.88799714869e-20*sin(spin)*pivot_wx_dot" and, with --all-symbols, as a parameter I_rotor_xz.
// The textbook's symbols: the file's `symbols:` names, θ on request, a wrong name at its line.
// The quarter car as Franklin writes it (FPE ch. 2), m₁ẍ + b(ẋ − ẏ) + k_s(x − y) + k_w(x − r) = 0:
// each spring is relaxed at q = 0, so its free length and the joints' offsets cancel and are left
// out. A suspension 5 cm shorter than that is stretched by 5 cm at q = 0: d0_suspension names it.
TEST_F(AnalysisCli, TheQuarterCarsSpringsReadAsFranklinWritesThem) {
  const CliRun r = momenta("equations " + example("quarter_car") + " --all-symbols");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(joined(r.out).find("m_wheel*wheel_travel_ddot + c_suspension*(wheel_travel_dot - "
                               "body_travel_dot) + k_suspension*(wheel_travel - body_travel) + "
                               "k_tyre*(wheel_travel - road) = 0"),
            std::string::npos)
      << r.out;
  EXPECT_NE(joined(r.out).find("m_body*body_travel_ddot + c_suspension*(body_travel_dot - "
                               "wheel_travel_dot) + k_suspension*(body_travel - wheel_travel) = 0"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("l0_"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("L_"), std::string::npos) << r.out;
  std::string car = slurp(test::source_dir() + "/examples/quarter_car.yaml");
  car.replace(car.find("free_length: 0.5 "), 17, "free_length: 0.45");
  const CliRun shorter =
      momenta("equations " + test::quoted(write("short.yaml", car).string()) + " --all-symbols");
  ASSERT_EQ(shorter.code, 0) << shorter.err;
  EXPECT_NE(joined(shorter.out).find("k_suspension*(wheel_travel - body_travel - d0_suspension)"),
            std::string::npos)
      << shorter.out;
}

// A uniform rod (shape: slender_rod, 2 kg, 1 m, pivoted at its end) with its mass a symbol: its
// inertia is m × its tensor per unit mass, so the equation reads m L²/3 θ̈ + m g L/2 sin θ = 0 in
// m — (1/12 + 1/4) m = 0.333333333333 m — not 0.1666… + 0.25 m with I_G a number. Asked for
// as a symbol itself, I_rod_yy stays one.
TEST_F(AnalysisCli, AUniformRodsInertiaScalesWithItsMassSymbol) {
  const CliRun m = momenta("equations " + example("compound_pendulum") + " --symbols m_rod");
  ASSERT_EQ(m.code, 0) << m.err;
  EXPECT_NE(m.out.find("\n0.333333333333*m_rod*pivot_ddot + 4.905*m_rod*sin(pivot) = 0\n"),
            std::string::npos)
      << m.out;
  const CliRun I =
      momenta("equations " + example("compound_pendulum") + " --symbols m_rod,I_rod_yy");
  ASSERT_EQ(I.code, 0) << I.err;
  EXPECT_NE(I.out.find("I_rod_yy"), std::string::npos) << I.out;
  // Its length a symbol too: Ī = m L²/12 as the textbook writes it, the fraction inside the sum
  // (GiNaC keeps 1/12 θ̈ (12 m d² + m L²), printed 0.08333333333333333*… before), in LaTeX a
  // \frac.
  const CliRun L =
      momenta("equations " + example("compound_pendulum") + " --symbols m_rod,g,length_rod,L_rod");
  ASSERT_EQ(L.code, 0) << L.err;
  EXPECT_NE(L.out.find("\npivot_ddot*(L_rod^2*m_rod + length_rod^2*m_rod/12) + "
                       "L_rod*g*m_rod*sin(pivot) = 0\n"),
            std::string::npos)
      << L.out;
  const CliRun latex = momenta("equations " + example("compound_pendulum") +
                               " --symbols m_rod,g,length_rod,L_rod --latex");
  ASSERT_EQ(latex.code, 0) << latex.err;
  EXPECT_NE(latex.out.find("\\frac{\\mathrm{length\\_rod}^{2} \\, m_{\\mathrm{rod}}}{12}"),
            std::string::npos)
      << latex.out;
}

// The heavy top in the notes' Euler angles (--coordinates euler:ZXZ): precession φ, nutation θ,
// spin ψ, as Goldstein (§5.7) writes the symmetric top, with the file's symbols A (transverse
// about G), C (axial), m, l: the spin's equation d/dt[C (ψ̇ + φ̇ cos θ)] = 0 and the nutation's
// gravity term −m g l sin θ. The equations themselves against Lagrange's: SymbolicEquations.
// TheHeavyTopInEulerAnglesReadsAsLagrangeWritesIt.
TEST_F(AnalysisCli, EquationsOfATopInEulerAngles) {
  const fs::path top = write(
      "top.yaml",
      "name: top\ngravity: [0, 0, -9.81]\nbodies:\n  - {name: top, shape: cone, mass: 1.0, "
      "radius: 0.05, height: 0.1}\njoints:\n  - {name: tip, type: spherical, parent: world, child: "
      "top, q0: {euler: {sequence: ZXZ, angles_deg: [0, 20, 0]}}}\nsymbols: {I_top_xx: A, "
      "I_top_yy: A, I_top_zz: C, m_top: m, L_top: l}\n");
  const CliRun r = momenta("equations " + test::quoted(top.string()) +
                           " --coordinates euler:ZXZ --all-symbols --greek");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\nC*ψ̈ + C*cos(θ)*φ̈ - C*sin(θ)*φ̇*θ̇ = 0\n"), std::string::npos) << r.out;
  EXPECT_NE(joined(r.out).find("θ̈*(A + l^2*m)"), std::string::npos) << r.out;
  EXPECT_NE(joined(r.out).find("- g*l*m*sin(θ) = 0"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("_qw"), std::string::npos) << r.out;  // no quaternion component
  // Refused, with the reason: the top upright (gimbal lock), an extrinsic sequence, no ball joint.
  std::string upright = slurp(top);
  upright.replace(upright.find("[0, 20, 0]"), 10, "[0, 0, 0]");
  CliRun bad = momenta("equations " + test::quoted(write("upright.yaml", upright).string()) +
                       " --coordinates euler:ZXZ");
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("gimbal lock"), std::string::npos) << bad.err;
  bad = momenta("equations " + test::quoted(top.string()) + " --coordinates euler:zxz");
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("extrinsic"), std::string::npos) << bad.err;
  bad = momenta("equations " + example("pendulum") + " --coordinates euler:ZXZ");
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("no ball (spherical) or free joint"), std::string::npos) << bad.err;
  EXPECT_EQ(momenta("equations " + test::quoted(top.string()) + " --coordinates euler:ABC").code,
            2);
}

TEST_F(AnalysisCli, EquationsInTheTextbooksSymbols) {
  const std::string pendulum =
      "name: pendulum\n"
      "bodies:\n  - {name: bob, shape: point_mass, mass: 1.0, position: [0, 0, -1.0]}\n"
      "joints:\n  - {name: pivot, type: revolute, parent: world, child: bob, axis: [0, 1, 0]}\n"
      "symbols:\n  m_bob: m\n  L_bob: L\n";
  std::ofstream(dir_ / "named.yaml") << pendulum;
  const CliRun named = momenta("equations " + (dir_ / "named.yaml").string() + " --all-symbols");
  ASSERT_EQ(named.code, 0) << named.err;
  EXPECT_NE(named.out.find("\nL^2*m*pivot_ddot + L*g*m*sin(pivot) = 0\n"), std::string::npos)
      << named.out;
  const CliRun greek =
      momenta("equations " + (dir_ / "named.yaml").string() + " --symbols greek,L,m --latex");
  ASSERT_EQ(greek.code, 0) << greek.err;
  EXPECT_NE(greek.out.find("L^{2} m \\ddot{\\theta} + 9.81 L m \\sin(\\theta) = 0\n"),
            std::string::npos)
      << greek.out;
  std::ofstream(dir_ / "misnamed.yaml") << pendulum << "  m_bobb: M\n";
  const CliRun misnamed = momenta("equations " + (dir_ / "misnamed.yaml").string());
  EXPECT_EQ(misnamed.code, 1);
  EXPECT_NE(misnamed.err.find("misnamed.yaml:9:11: "), std::string::npos) << misnamed.err;
  EXPECT_NE(misnamed.err.find("did you mean 'm_bob'"), std::string::npos) << misnamed.err;
}

// Golden texts: every printed form of the double pendulum (every parameter a symbol), the
// pendulum's planar Newton–Euler forms, Greek angles and a constrained model's rows are the bytes
// tests/cli/golden/equations/ holds (generated code as .hpp.txt and .py.txt: texts to compare, not
// sources to format), so a change to what a reader sees shows as a diff.
// MOMENTA_UPDATE_GOLDEN=1 rewrites them (then read the diff before committing).
TEST_F(AnalysisCli, EquationsEqualTheirGoldenTexts) {
  const std::vector<std::array<std::string, 3>> cases = {
      {"double_pendulum.txt", "double_pendulum", "--all-symbols"},
      {"double_pendulum.tex", "double_pendulum", "--all-symbols --latex"},
      {"double_pendulum.greek.txt", "double_pendulum", "--all-symbols --greek"},
      {"double_pendulum.matrix.txt", "double_pendulum", "--all-symbols --form matrix"},
      {"double_pendulum.newton_euler.txt", "double_pendulum", "--all-symbols --form newton-euler"},
      {"double_pendulum.linear.txt", "double_pendulum", "--all-symbols --form linear"},
      {"double_pendulum.json", "double_pendulum", "--all-symbols --json"},
      {"double_pendulum.hpp.txt", "double_pendulum", "--all-symbols --cpp"},
      {"double_pendulum.py.txt", "double_pendulum", "--all-symbols --python"},
      {"pendulum.newton_euler_nt.txt", "pendulum", "--all-symbols --form newton-euler --nt"},
      {"cruise_control.transfer.txt", "cruise_control", "--all-symbols --transfer u:speed"},
      {"chaplygin_sleigh.txt", "constraints/chaplygin_sleigh", "--all-symbols"},
  };
  const std::filesystem::path golden =
      std::filesystem::path(test::source_dir()) / "tests/cli/golden/equations";
  const bool update = std::getenv("MOMENTA_UPDATE_GOLDEN") != nullptr;
  for (const auto& [file, model, options] : cases) {
    const CliRun r = momenta("equations " + example(model) + " " + options);
    ASSERT_EQ(r.code, 0) << file << r.err;
    if (update) std::ofstream(golden / file, std::ios::binary) << r.out;
    std::ifstream in(golden / file, std::ios::binary);
    ASSERT_TRUE(in) << "no golden text " << (golden / file);
    const std::string expected((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
    EXPECT_EQ(r.out, expected) << file << " differs from its golden text";
  }
}

TEST_F(AnalysisCli, EquationsLeaveRoundOffOut) {
  const CliRun numbers = momenta("equations " + example("gyroscope"));
  ASSERT_EQ(numbers.code, 0) << numbers.err;
  EXPECT_EQ(numbers.out.find("e-2"), std::string::npos) << numbers.out;
  const CliRun symbols = momenta("equations " + example("gyroscope") + " --all-symbols");
  ASSERT_EQ(symbols.code, 0) << symbols.err;
  EXPECT_EQ(symbols.out.find("I_rotor_xz"), std::string::npos) << symbols.out;
  EXPECT_NE(symbols.out.find("I_rotor_xx"), std::string::npos) << symbols.out;
}

// A long equation is broken at its terms: no line over 100 characters but one term alone (a
// term is not broken), continuation lines indented by four spaces, and joined back it is the
// equation `--json` gives, unchanged.
TEST_F(AnalysisCli, LongEquationsBreakAtTheirTerms) {
  const CliRun r = momenta("equations " + example("double_pendulum") + " --all-symbols");
  ASSERT_EQ(r.code, 0) << r.err;
  std::size_t lines = 0, continued = 0;
  for (std::size_t at = 0, end; at < r.out.size(); at = end + 1) {
    end = r.out.find('\n', at);
    const std::string line = r.out.substr(at, end - at);
    int depth = 0, breaks = 0;  // " + ", " - " or " = " outside parentheses after the start
    for (std::size_t i = 5; i + 2 < line.size(); ++i) {
      depth += line[i] == '(' ? 1 : line[i] == ')' ? -1 : 0;
      if (depth == 0 && line[i] == ' ' && line[i + 2] == ' ' &&
          (line[i + 1] == '+' || line[i + 1] == '-' || line[i + 1] == '='))
        ++breaks;
    }
    EXPECT_TRUE(line.size() <= 100u || breaks == 0) << line;
    ++lines;
    if (line.starts_with("    + ") || line.starts_with("    - ")) ++continued;
  }
  EXPECT_GE(continued, 4u) << r.out;
  const json j =
      json::parse(momenta("equations " + example("double_pendulum") + " --all-symbols --json").out);
  const std::string whole = joined(r.out);
  ASSERT_EQ(j.at("equations").size(), 2u);
  for (const auto& equation : j.at("equations")) {
    EXPECT_NE(whole.find("\n" + equation.get<std::string>() + "\n"), std::string::npos) << whole;
  }
}

// A 10-link chain's equations as text would be a tree of hundreds of megabytes (the default form
// printed nothing in 14 minutes): refused at once, pointing to the generated code, which writes
// each shared part once.
TEST_F(AnalysisCli, EquationsTooLargeToPrintPointToTheCode) {
  const std::string chain = fmt::format("'{}/bench/models/chain10.yaml'", test::source_dir());
  for (const char* form : {"", " --latex", " --form matrix"}) {
    const CliRun r = momenta("equations " + chain + form);
    EXPECT_EQ(r.code, 1) << form;
    EXPECT_NE(r.err.find("the same equations written as code (--cpp or --python) compute each "
                         "shared part once"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.out, "") << form;  // the error alone: no half a page before it
  }
  // Its linearization in symbols (more than two minutes before) is refused too, pointing to the
  // numeric one.
  const CliRun linear = momenta("equations " + chain + " --form linear");
  EXPECT_EQ(linear.code, 1);
  EXPECT_NE(linear.err.find("the numeric linearization (`momenta linearize`) takes the same model"),
            std::string::npos)
      << linear.err;
  const CliRun code = momenta("equations " + chain + " --cpp");
  EXPECT_EQ(code.code, 0) << code.err;
  EXPECT_LT(code.out.size(), 1'000'000u);
}
#else
TEST_F(AnalysisCli, EquationsSayTheyAreLeftOutOfThisBuild) {
  const CliRun eom = momenta("equations " + example("cruise_control") + " --all-symbols");
  EXPECT_EQ(eom.code, 1);
  EXPECT_NE(eom.err.find("-DMOMENTA_WITH_SYMBOLIC=OFF"), std::string::npos) << eom.err;
}
#endif  // MOMENTA_TEST_SYMBOLIC

TEST_F(AnalysisCli, DiagramOfThePendulumBobWritesTheSvgAndKeepsTheUsersFile) {
  // The bob of examples/pendulum.yaml from a state file at θ = 60°, θ̇ = 2 rad/s: the rod pulls
  // with T = m g cos θ + m L θ̇² = 4.905 + 4 = 8.905 N.
  std::ofstream(dir_ / "s.json") << R"({"q": [1.0471975511965976], "v": [2.0]})";
  const std::string svg = (dir_ / "fbd.svg").string();
  const std::string args = "diagram " + example("pendulum") + " --body bob --state '" +
                           (dir_ / "s.json").string() + "' -o '" + svg + "'";
  const CliRun r = momenta(args + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_EQ(j.at("loads").size(), 2U);
  const json& pin = j.at("loads").at(1);
  EXPECT_EQ(pin.at("name"), "pivot");
  EXPECT_EQ(pin.at("kind"), "reaction");
  const Vec3 F(pin.at("force").at(0).get<double>(), pin.at("force").at(1).get<double>(),
               pin.at("force").at(2).get<double>());
  EXPECT_NEAR(F.norm(), 9.81 * 0.5 + 4.0, 1e-12);
  const std::string picture = slurp(dir_ / "fbd.svg");
  EXPECT_EQ(picture.rfind("<svg", 0), 0U);
  EXPECT_NE(picture.find("data-name=\"pivot\""), std::string::npos);
  // The text form names the balance; the SVG is not overwritten without --force.
  const CliRun again = momenta(args);
  EXPECT_EQ(again.code, 1);
  EXPECT_NE(again.err.find("pass --force"), std::string::npos) << again.err;
  const CliRun text = momenta(args + " --force");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("ΣF − m a_G"), std::string::npos) << text.out;
  const CliRun unknown = momenta("diagram " + example("pendulum") + " --body bobb");
  EXPECT_EQ(unknown.code, 1);
  EXPECT_NE(unknown.err.find("did you mean 'bob'"), std::string::npos) << unknown.err;
}

TEST_F(AnalysisCli, DiagramOfAnImpactIsTheImpulseMomentumDiagram) {
  // The eccentric impact (examples/eccentric_impact.yaml, e = 0.6): the rod at rest before, the
  // contact's impulse m_s (v0 − v_s) and the pin's m ω L/2 − m_s (v0 − v_s) on it, then m ω L/2.
  const double I_O = 1.92, ms = 0.5, v0 = 3.0, d = 1.1, e = 0.6;
  const double omega = ms * v0 * d * (1 + e) / (I_O + ms * d * d);
  const double v_s = v0 * (ms * d * d - e * I_O) / (I_O + ms * d * d);
  const std::string svg = (dir_ / "impulse.svg").string();
  const std::string args = "diagram " + example("eccentric_impact") +
                           " --body rod --between sphere rod:0,0,-1.1 --normal 1,0,0 "
                           "--restitution 0.6 -o '" +
                           svg + "'";
  const CliRun r = momenta(args + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_EQ(j.at("impulses").size(), 2U);
  EXPECT_EQ(j.at("impulses").at(0).at("name"), "contact impulse");
  EXPECT_NEAR(j.at("impulses").at(0).at("impulse").at(0).get<double>(), ms * (v0 - v_s), 1e-14);
  EXPECT_EQ(j.at("impulses").at(1).at("name"), "pin");
  EXPECT_NEAR(j.at("impulses").at(1).at("impulse").at(0).get<double>(),
              4.0 * omega * 0.6 - ms * (v0 - v_s), 1e-14);
  EXPECT_EQ(j.at("before").at("linear").at(0).get<double>(), 0.0);
  EXPECT_NEAR(j.at("after").at("linear").at(0).get<double>(), 4.0 * omega * 0.6, 1e-14);
  const std::string picture = slurp(dir_ / "impulse.svg");
  for (const char* panel : {"before", "impulses", "after"}) {
    EXPECT_NE(picture.find(fmt::format("data-panel=\"{}\"", panel)), std::string::npos) << panel;
  }
  const CliRun text = momenta(args + " --force");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("impulsive reaction of joint pin (from world)"), std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("m v̄₁ + ΣP − m v̄₂"), std::string::npos) << text.out;
  // A blow half given is refused, as `momenta impact` refuses it.
  const CliRun half = momenta("diagram " + example("eccentric_impact") +
                              " --body rod --between sphere rod:0,0,-1.1 --restitution 0.6");
  EXPECT_EQ(half.code, 2);  // a usage error
  EXPECT_NE(half.err.find("a collision needs --between A:x,y,z B:x,y,z, --normal"),
            std::string::npos)
      << half.err;
}

TEST_F(AnalysisCli, ModesOfThePendulumAboutItsEquilibriumFromAState) {
  // A state file at the bottom: ω = √(g/L) = 3.1321 rad/s = 0.49849 Hz.
  std::ofstream(dir_ / "bottom.json") << R"({"q": [0.0], "v": [0.0]})";
  const CliRun r = momenta("modes " + example("pendulum") + " --about '" +
                           (dir_ / "bottom.json").string() + "' --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  const double w = std::sqrt(9.81);
  // Richardson-extrapolated stiffness: 1e-12 relative.
  EXPECT_TRUE(test::relatively_near(j.at("modes").at(0).at("natural_frequency_rad_s").get<double>(),
                                    w, 1e-12));
  EXPECT_TRUE(test::relatively_near(j.at("modes").at(0).at("natural_frequency_hz").get<double>(),
                                    w / (2 * M_PI), 1e-12));
  EXPECT_TRUE(test::relatively_near(
      j.at("normal_modes").at(0).at("natural_frequency_rad_s").get<double>(), w, 1e-12));
}

TEST_F(AnalysisCli, StepResponseCsvFollowsTheClosedForm) {
  // Cruise control, unit force: v = (1/b)(1 − e^(−bt/m)).
  const fs::path csv = dir_ / "step.csv";
  const CliRun r = momenta("response " + example("cruise_control") +
                           " --input u --output speed --step --duration 100 --points 101 --csv '" +
                           csv.string() + "' --digits 6");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("poles (1/s): -0.05"), std::string::npos) << r.out;
  std::istringstream in(slurp(csv));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "time,speed");
  int rows = 0;
  while (std::getline(in, line)) {
    const double t = std::stod(line.substr(0, line.find(',')));
    const double v = std::stod(line.substr(line.find(',') + 1));
    // ZOH samples exact for the linear model: 1e-14 of the 0.02 m/s final value.
    EXPECT_NEAR(v, (1.0 / 50) * (1 - std::exp(-50 * t / 1000)), 1e-14) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 101);
}

// examples/sleeping_top.yaml, --about steady: the cone upright at 300 rad/s is stable (critical
// 2√(I₁ m g l)/I₃ = 182.63 rad/s) and precesses, seen from space, at the roots of
// I₁ σ² − I₃ ω₃ σ + m g l = 0; the other commands refuse what the analysis does not cover.
// A state that moves without accelerating (the sleeping top spinning upright) is no equilibrium:
// `modes` about it says so and gives no undamped normal modes, which would leave its gyroscopic
// terms out and call the stable top unstable (issue 28: "ω² = -115.412 unstable"). At a tilt of
// 90° cos θ is round-off: steady precession exists at any spin (issue 28: "needs ω₃ ≥ 1.4e-06").
TEST_F(AnalysisCli, AMovingStateIsNoEquilibriumAndRoundOffNeedsNoSpin) {
  const CliRun r = momenta("modes " + example("sleeping_top"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("note: this state is not an equilibrium (largest acceleration 0, largest "
                       "speed 300)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("no undamped normal modes: undamped_modes: the point moves"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("unstable"), std::string::npos) << r.out;
  const CliRun json_run = momenta("modes " + example("sleeping_top") + " --json");
  ASSERT_EQ(json_run.code, 0) << json_run.err;
  EXPECT_TRUE(json::parse(json_run.out).at("normal_modes").is_null());
  const CliRun tilt = momenta("steady " + example("heavy_top") + " --tilt 90 --spin 100");
  ASSERT_EQ(tilt.code, 0) << tilt.err;
  EXPECT_NE(tilt.out.find("exists at any spin"), std::string::npos) << tilt.out;
  EXPECT_EQ(tilt.out.find("needs ω₃"), std::string::npos) << tilt.out;
}

TEST_F(AnalysisCli, SleepingTopSteadyMotionModes) {
  const CliRun r = momenta("modes " + example("sleeping_top") + " --about steady --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_TRUE(j.at("stable").get<bool>());
  EXPECT_EQ(j.at("residual").get<double>(), 0.0);
  const double I1 = 0.6 * 0.01 + 0.15 * 0.0025, I3 = 0.3 * 0.0025, mgl = 9.81 * 0.075, w = 300;
  const double D = std::sqrt(I3 * I3 * w * w - 4 * I1 * mgl);
  std::vector<double> space;
  for (const json& s : j.at("space_frequencies")) {
    space.push_back(s.at("frequency_rad_s").get<double>());
    EXPECT_EQ(s.at("whirl"), "forward");
  }
  std::sort(space.begin(), space.end());
  ASSERT_EQ(space.size(), 2u);
  EXPECT_NEAR(space[0], (I3 * w - D) / (2 * I1), 1e-10 * 32);
  EXPECT_NEAR(space[1], (I3 * w + D) / (2 * I1), 1e-10 * 32);
  EXPECT_NE(j.at("verdict").get<std::string>().find("182.631"), std::string::npos);
  // The heavy top precesses steadily at a tilt: steady in its precessing frame, the symmetric
  // top's closed form — the slow root 3.618637 rad/s its file states.
  const CliRun tilted = momenta("modes " + example("heavy_top") + " --about steady --json");
  ASSERT_EQ(tilted.code, 0) << tilted.err;
  const json p = json::parse(tilted.out);
  EXPECT_EQ(p.at("motion"), "steady precession");
  EXPECT_NEAR(p.at("slow").get<double>(), 3.618637, 5e-7);
  EXPECT_LT(p.at("residual").get<double>(), 1e-15);
  // The tennis racket's deliberately disturbed spin is no steady motion: said so.
  const CliRun racket = momenta("modes " + example("free_body_tennis_racket") + " --about steady");
  EXPECT_EQ(racket.code, 1);
  EXPECT_NE(racket.err.find("not in a steady motion"), std::string::npos) << racket.err;
  // Two bodies, revolute joints: not a spinning body.
  EXPECT_EQ(momenta("modes " + example("double_pendulum") + " --about steady").code, 1);
  // response has inputs and outputs; the Euler–Poisson analysis has none: said so, with the way
  // to model a rotor that has them.
  const CliRun response = momenta("response " + example("sleeping_top") +
                                  " --about steady --input u --output y --step");
  EXPECT_EQ(response.code, 2);
  EXPECT_NE(response.err.find("universal joint and a revolute spin joint"), std::string::npos)
      << response.err;
  // linearize prints the Euler–Poisson A.
  const CliRun lin = momenta("linearize " + example("sleeping_top") + " --about steady");
  ASSERT_EQ(lin.code, 0) << lin.err;
  EXPECT_NE(lin.out.find("A (d/dt of the state, Euler–Poisson)"), std::string::npos) << lin.out;
}

// `momenta campbell`: a top hanging below its ball (l = 0.1 m, I₁ = 0.05, I₃ = 0.02 kg·m² about
// the ball), spinning about the vertical, has one critical speed, where its forward whirl
// meets the 1× line: I₁Ω² − I₃Ω² − m g l = 0, Ω_c = √(m g l/(I₁ − I₃)).
TEST_F(AnalysisCli, CampbellDiagramOfAHangingTop) {
  const fs::path model = dir_ / "hanging_top.yaml";
  std::ofstream(model) << "name: hanging top\n"
                          "gravity: [0, 0, -9.81]\n"
                          "bodies:\n"
                          "  - {name: top, mass: 1, com: [0, 0, -0.1], inertia: [0.05, 0.05, 0.02],"
                          " inertia_about: [0, 0, 0]}\n"
                          "joints:\n"
                          "  - {name: ball, type: spherical, parent: world, child: top, v0: [0, 0, "
                          "10]}\n";
  const CliRun r = momenta("campbell '" + model.string() + "' --speed-range 10 200 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_EQ(j.at("critical_speeds").size(), 1u);
  const double expected = std::sqrt(9.81 * 0.1 / (0.05 - 0.02));
  EXPECT_NEAR(j.at("critical_speeds")[0].at("speed_rad_s").get<double>(), expected,
              1e-10 * expected);
  EXPECT_EQ(j.at("critical_speeds")[0].at("whirl"), "forward");
  EXPECT_EQ(j.at("points").size(), 41u);
  // The table as CSV, one row per speed; bad ranges and an unsymmetric model are refused.
  const CliRun csv =
      momenta("campbell '" + model.string() + "' --speed-range 10 200 --points 5 --csv -");
  ASSERT_EQ(csv.code, 0) << csv.err;
  EXPECT_EQ(csv.out.substr(0, csv.out.find('\n')),
            "speed_rpm,speed_rad_s,backward_1_rad_s,forward_1_rad_s");
  EXPECT_EQ(momenta("campbell '" + model.string() + "' --speed-range 200 10").code, 2);
  EXPECT_EQ(momenta("campbell " + example("free_body_tennis_racket") + " --speed-range 10 20").code,
            1);
}

// `momenta steady`: the heavy top's cone at the file's 20° and 300 rad/s gives the file's slow
// root 3.618637 rad/s; upright, the sleeping top's precession frequencies 3.6468 and 31.647; the
// state of a root goes to a file, never over one without --force.
TEST_F(AnalysisCli, SteadyPrecessionSolver) {
  const std::string top = example("heavy_top");
  const CliRun r = momenta("steady " + top + " --tilt 20 --spin 300 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_NEAR(j.at("slow").get<double>(), 3.618637, 5e-7);
  EXPECT_NEAR(j.at("critical_spin").get<double>(), 182.63, 5e-3);
  EXPECT_EQ(j.at("states").size(), 2u);
  const CliRun upright = momenta("steady " + top + " --tilt 0 --spin 300");
  ASSERT_EQ(upright.code, 0) << upright.err;
  EXPECT_NE(upright.out.find("slow precession φ̇ = 3.6468"), std::string::npos) << upright.out;
  EXPECT_NE(upright.out.find("fast precession φ̇ = 31.647"), std::string::npos) << upright.out;
  // Below the minimum spin at 20°: no root, said so; the state cannot be written.
  const CliRun slow = momenta("steady " + top + " --tilt 20 --spin 100");
  ASSERT_EQ(slow.code, 0) << slow.err;
  EXPECT_NE(slow.out.find("slow precession: none"), std::string::npos) << slow.out;
  const fs::path state = dir_ / "precessing.json";
  EXPECT_EQ(
      momenta("steady " + top + " --tilt 20 --spin 100 --state '" + state.string() + "'").code, 1);
  ASSERT_EQ(momenta("steady " + top + " --tilt 20 --spin 300 --state '" + state.string() +
                    "' --root fast")
                .code,
            0);
  const json s = json::parse(std::ifstream(state));
  EXPECT_EQ(s.at("q").size(), 4u);
  EXPECT_EQ(s.at("v").size(), 3u);
  EXPECT_EQ(
      momenta("steady " + top + " --tilt 20 --spin 300 --state '" + state.string() + "'").code,
      1);  // exists: --force
  EXPECT_EQ(momenta("steady " + top + " --tilt 200 --spin 300").code, 2);
  EXPECT_EQ(momenta("steady " + example("pendulum") + " --tilt 20 --spin 300").code, 1);
}

// `momenta steady` on rolling bodies (issue 28): the coin's circle of 0.5 m at a lean of 20°
// (Ω = 2.169577594958739 rad/s from the moment equation, as the example's own state), both
// circles at its speed, Beer's SP 18.2 from the spin; `modes --about steady` on the example's
// state gives the wobble and the displaced circle's Ω; usage errors say what a rolling body takes.
TEST_F(AnalysisCli, SteadyRollingCoinAndDiskOnAxle) {
  const std::string coin = example("constraints/rolling_coin");
  const CliRun circle = momenta("steady " + coin + " --lean 20 --radius 0.5 --json");
  ASSERT_EQ(circle.code, 0) << circle.err;
  const json j = json::parse(circle.out);
  ASSERT_EQ(j.at("motions").size(), 1u);
  const json& m = j.at("motions")[0];
  EXPECT_NEAR(m.at("precession").get<double>(), 2.169577594958739, 1e-12);
  EXPECT_NEAR(m.at("spin").get<double>(), 10.84788797479370, 1e-11);
  EXPECT_NEAR(m.at("contact_force").at("normal").get<double>(), 9.81, 1e-12);
  EXPECT_TRUE(m.at("stable").get<bool>());
  EXPECT_EQ(m.at("state").at("q").size(), 7u);
  const CliRun by_speed = momenta("steady " + coin + " --lean 20 --speed 1.0847887974793695");
  ASSERT_EQ(by_speed.code, 0) << by_speed.err;
  EXPECT_NE(by_speed.out.find("1 (slow):\n  precession Ω = 2.169577595 rad/s"), std::string::npos)
      << by_speed.out;
  EXPECT_NE(by_speed.out.find("2 (fast):\n  precession Ω = -192.47"), std::string::npos)
      << by_speed.out;
  EXPECT_NE(by_speed.out.find("leaning out of the turn"), std::string::npos) << by_speed.out;
  const CliRun straight = momenta("steady " + coin + " --lean 0 --speed 0.3");
  ASSERT_EQ(straight.code, 0) << straight.err;
  EXPECT_NE(straight.out.find("on a straight line"), std::string::npos) << straight.out;
  EXPECT_NE(straight.out.find("unstable: a disturbance grows at 7.54188 1/s"), std::string::npos)
      << straight.out;

  const CliRun beer =
      momenta("steady " + example("constraints/rolling_disk_on_axle") + " --spin 20");
  ASSERT_EQ(beer.code, 0) << beer.err;
  EXPECT_NE(beer.out.find("precession Ω = -6.666666667 rad/s"), std::string::npos) << beer.out;
  EXPECT_NE(beer.out.find("normal 52.5733 N"), std::string::npos) << beer.out;

  const CliRun modes = momenta("modes " + coin + " --about steady --json");
  ASSERT_EQ(modes.code, 0) << modes.err;
  const json mj = json::parse(modes.out);
  EXPECT_EQ(mj.at("motion"), "steady rolling");
  ASSERT_EQ(mj.at("eigenvalues").size(), 1u);
  EXPECT_NEAR(mj.at("eigenvalues")[0][1].get<double>(), 15.1414290837, 1e-8);
  EXPECT_NEAR(mj.at("circle_shift")[0][1].get<double>(), 2.169577594958739, 1e-8);
  EXPECT_EQ(mj.at("A").size(), 8u);

  // A condition is needed, only one, a lean for a free body, none of a top's options.
  EXPECT_EQ(momenta("steady " + coin + " --lean 20").code, 2);
  EXPECT_EQ(momenta("steady " + coin + " --lean 20 --radius 1 --speed 2").code, 2);
  EXPECT_EQ(momenta("steady " + coin + " --lean 20 --radius zero").code, 2);
  EXPECT_EQ(momenta("steady " + coin + " --tilt 20 --spin 3").code, 2);
  const CliRun no_lean = momenta("steady " + coin + " --radius 1");
  EXPECT_EQ(no_lean.code, 1);
  EXPECT_NE(no_lean.err.find("give its lean"), std::string::npos) << no_lean.err;
  EXPECT_EQ(momenta("steady " + example("heavy_top") + " --lean 20 --speed 1").code, 2);
  const CliRun response =
      momenta("response " + coin + " --about steady --input x --output y --step");
  EXPECT_EQ(response.code, 2);
  EXPECT_NE(response.err.find("rolling body"), std::string::npos) << response.err;
}

// A rotor in joint coordinates (examples/rotor_on_bearings.yaml): --about steady leaves the spin
// angle out; modes name each whirl; campbell finds both critical speeds (the closed forms are
// checked in tests/validation/examples/campbell_examples_test.cpp); response works about the
// steady motion — a force at bearing B moves it by 1/k_B at DC, the rotor being rigid.
TEST_F(AnalysisCli, RotorInJointCoordinatesAboutItsSteadyMotion) {
  const std::string rotor = example("rotor_on_bearings");
  const CliRun modes = momenta("modes " + rotor + " --about steady --json");
  ASSERT_EQ(modes.code, 0) << modes.err;
  const json m = json::parse(modes.out);
  EXPECT_EQ(m.at("state_names").size(), 9u);
  const json& steady = m.at("steady_motion");
  EXPECT_EQ(steady.at("turning"), json::array({"spin.angle"}));
  std::vector<std::string> whirls;
  for (const json& w : steady.at("whirls")) whirls.push_back(w.at("whirl"));
  EXPECT_EQ(whirls, (std::vector<std::string>{"backward", "forward", "backward", "forward"}));
  EXPECT_NEAR(steady.at("whirls")[3].at("frequency_rad_s").get<double>(), 281.98997613, 1e-8 * 282);
  const CliRun text = momenta("modes " + rotor + " --about steady");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("forward whirl"), std::string::npos) << text.out;
  EXPECT_EQ(text.out.find("undamped normal modes"), std::string::npos) << text.out;

  const CliRun c = momenta("campbell " + rotor + " --speed-range 500 5000 --json");
  ASSERT_EQ(c.code, 0) << c.err;
  const json cj = json::parse(c.out);
  ASSERT_EQ(cj.at("critical_speeds").size(), 2u);
  EXPECT_NEAR(cj.at("critical_speeds")[0].at("speed_rpm").get<double>(), 1934.204401, 1e-6);
  EXPECT_NEAR(cj.at("critical_speeds")[1].at("speed_rpm").get<double>(), 2835.038083, 1e-6);
  EXPECT_EQ(cj.at("turning"), "spin.angle");

  const CliRun r = momenta("response " + rotor +
                           " --about steady --input hammer --output bearing_B.x --step --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json rj = json::parse(r.out);
  EXPECT_NEAR(rj.at("dc_gain").get<double>(), 1 / 3e5, 1e-9 / 3e5);
  // Bearing B's y: its zeros (a double imaginary pair) are where Eigen's QZ cycles; they come
  // from A − b c / d instead. The axial direction does not respond at all: no Bode plot, said so.
  const CliRun by = momenta("response " + rotor +
                            " --about steady --input hammer --output bearing_B.y --bode 10 1000");
  EXPECT_EQ(by.code, 0) << by.err;
  const CliRun bz = momenta("response " + rotor +
                            " --about steady --input hammer --output bearing_B.z --bode 10 1000");
  EXPECT_EQ(bz.code, 1);
  EXPECT_NE(bz.err.find("'bearing_B.z' does not respond to the input 'hammer' (G ≡ 0"),
            std::string::npos)
      << bz.err;
  // An output that reads the spin angle is not one of the reduced model.
  const CliRun angle = momenta("linearize " + rotor + " --about steady --outputs spin.angle");
  EXPECT_EQ(angle.code, 1);
  EXPECT_NE(angle.err.find("reads the turning position 'spin.angle'"), std::string::npos)
      << angle.err;
}

// --json: full precision. The step figures are exact (τ ln 9, τ ln 50 for the cruise control's
// τ = m/b = 20 s, to 1e-12), and the text's default numbers read back to the JSON's doubles.
TEST_F(AnalysisCli, ResponseJsonIsExactAndTheTextReadsBack) {
  const std::string args =
      "response " + example("cruise_control") + " --input u --output speed --step";
  const CliRun r = momenta(args + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  const json& info = j.at("step_info");
  EXPECT_NEAR(info.at("rise_time").get<double>(), 20 * std::log(9.0), 1e-12 * 44);
  EXPECT_NEAR(info.at("settling_time").get<double>(), 20 * std::log(50.0), 1e-12 * 79);
  EXPECT_EQ(info.at("overshoot_percent").get<double>(), 0.0);
  EXPECT_EQ(j.at("samples").at("time").size(), j.at("samples").at("output").size());
  const double pole = j.at("poles").at(0).at(0).get<double>();
  EXPECT_NEAR(pole, -0.05, 1e-15);
  // The text shows the ten digits the linearization is good for (the cruise control's DC gain
  // 0.02, not 0.019999999999999997); --digits 17 reads back to the same doubles.
  const auto figure_after = [](const std::string& out, const std::string& label) {
    const std::string rest = out.substr(out.find(label) + label.size());
    return rest.substr(0, rest.find('\n'));
  };
  const CliRun text = momenta(args);
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_EQ(figure_after(text.out, "DC gain: "), "0.02") << text.out;
  EXPECT_TRUE(
      test::relatively_near(std::stod(figure_after(text.out, "poles (1/s): ")), pole, 1e-10));
  const CliRun exact = momenta(args + " --digits 17");
  ASSERT_EQ(exact.code, 0) << exact.err;
  EXPECT_EQ(std::stod(figure_after(exact.out, "poles (1/s): ")), pole) << exact.out;
  EXPECT_EQ(std::stod(figure_after(exact.out, "DC gain: ")), j.at("dc_gain").get<double>());
  // --json and --csv are two ways to the samples: one at a time.
  EXPECT_EQ(momenta(args + " --json --csv -").code, 2);
}

// The whole path on the command line: design on the plant, write the controller into a copy,
// simulate the nonlinear loop, linearize the closed loop; and the closed loop's own commands.
TEST_F(AnalysisCli, LqrWritesTheControllerAndTheCopyRunsTheLoop) {
  const std::string copy = (dir_ / "held.yaml").string();
  CliRun r = momenta("lqr " + example("cart_pendulum") +
                     " --Q x.position=1,tilt.angle=1 --R 1 --json --write " + test::quoted(copy));
  ASSERT_EQ(r.code, 0) << r.err;
  const json design = json::parse(r.out);
  EXPECT_EQ(design.at("written").get<std::string>(), copy);
  // The copy: the pulse input gone (the controller drives `force`), K at full precision.
  const io::ModelFile held = io::read_model_file(copy);
  ASSERT_EQ(held.model.controllers().size(), 1u);
  const MatX K = matrix(design.at("K"), 4);
  EXPECT_EQ(held.model.controllers()[0].spec.gain, K);
  EXPECT_TRUE(held.model.is_driven(*held.model.find_signal("force")));
  // Its closed loop has the designed poles.
  r = momenta("linearize " + test::quoted(copy) + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const MatX A = matrix(json::parse(r.out).at("A"), 4);
  std::vector<double> real;
  for (const auto& p : A.eigenvalues()) real.push_back(p.real());
  std::sort(real.begin(), real.end());
  EXPECT_NEAR(real.back(), design.at("closed_loop_poles").at(0).at(0).get<double>(), 1e-9);
  // --open-loop: the plant again, the force an input.
  r = momenta("linearize " + test::quoted(copy) + " --open-loop --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(json::parse(r.out).at("input_names"), json({"force"}));
  // The copy simulates, and info names the controller.
  r = momenta("simulate " + test::quoted(copy) + " --duration 0.5 -o " +
              test::quoted((dir_ / "run.csv").string()));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(slurp(dir_ / "run.csv").find("state_feedback.force"), std::string::npos);
  r = momenta("info " + test::quoted(copy));
  EXPECT_NE(r.out.find("state_feedback  state_feedback measuring x.position, tilt.angle, "
                       "x.position_rate, tilt.angle_rate, driving force, continuous"),
            std::string::npos)
      << r.out;
  // Never over a file without --force, never over the model itself.
  r = momenta("lqr " + example("cart_pendulum") + " --Q 1 --R 1 --write " + test::quoted(copy));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("the file exists; pass --force"), std::string::npos) << r.err;
  r = momenta("lqr " + test::quoted(copy) + " --Q 1 --R 1 --write " + test::quoted(copy));
  EXPECT_EQ(r.code, 1);
  // The closed loop's modes and step response to the reference: the cruise PI's poles.
  r = momenta("modes " + example("cruise_control_pi") + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("cruise.integral"), std::string::npos);
  r = momenta("response " + example("cruise_control_pi") +
              " --input target_speed --output speed --step --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NEAR(json::parse(r.out).at("dc_gain").get<double>(), 1.0, 1e-12);
}

TEST_F(AnalysisCli, ErrorsAndUsage) {
  // Unknown output: user error, one line, with a suggestion.
  CliRun r = momenta("linearize " + example("quarter_car") + " --outputs body_yy");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("did you mean 'body_y'"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  // No equilibrium under the cruise-control push.
  r = momenta("modes " + example("cruise_control") + " --about equilibrium");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("no equilibrium"), std::string::npos) << r.err;
  // A state file of the wrong size.
  std::ofstream(dir_ / "bad.json") << R"({"q": [0.0, 1.0], "v": [0.0]})";
  r = momenta("linearize " + example("pendulum") + " --about '" + (dir_ / "bad.json").string() +
              "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("'q' must be a list of 1 numbers"), std::string::npos) << r.err;
  // Usage: no response kind, two kinds.
  EXPECT_EQ(momenta("response " + example("pendulum") + " --input x --output theta").code, 2);
  EXPECT_EQ(momenta("response " + example("cruise_control") +
                    " --input u --output speed --step --impulse")
                .code,
            2);
  // An unstable equilibrium is noted on stderr, the command succeeds.
  r = momenta("linearize " + example("pendulum") + " --about equilibrium");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("unstable"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace momenta
