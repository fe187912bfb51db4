// The URDF reader (io/urdf_file.hpp): a URDF and an independent description of the same robot
// give the same dynamics — the double pendulum against its model file, a spatial arm with turned
// frames against the arm built in code with SciPy-convention Euler angles — and every problem of a
// file is an error at its line, every element momenta does not use a note at its line.

#include "momenta/io/urdf_file.hpp"

#include <limits>
#include <random>
#include <string>
#include <tuple>
#include <variant>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/data.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta/io/mjcf_file.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta/model/model_builder.hpp"
#include "momenta_test/model_comparison.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::io {
namespace {

std::string urdf_path(const std::string& name) {
  return test::source_dir() + "/tests/data/models/urdf/" + name + ".urdf";
}

using test::largest_difference;

TEST(UrdfFile, DoublePendulumIsItsModelFile) {
  const ModelFile urdf = read_urdf_file(urdf_path("double_pendulum"));
  const ModelFile yaml = read_model_file(test::source_dir() + "/examples/double_pendulum.yaml");
  EXPECT_EQ(urdf.name, "double pendulum");
  // The root link is welded to the world: a massless body on a fixed joint, and a note says so.
  EXPECT_EQ(urdf.model.num_bodies(), 4);
  ASSERT_EQ(urdf.notes.size(), 1u);
  EXPECT_NE(urdf.notes[0].find(":4: link 'base', the root, is fixed to the world"),
            std::string::npos)
      << urdf.notes[0];
  // The same masses on the same axes: M and ABA agree to round-off.
  EXPECT_LT(largest_difference(urdf.model, yaml.model, 20), 1e-14);
}

// The arm built in code: rpy as SciPy's extrinsic "xyz" (roll about x, then pitch about the
// fixed y, then yaw about the fixed z), the inertia turned into the link's axes by hand.
model::Model arm_in_code() {
  const auto pose = [](const Vec3& xyz, const Vec3& rpy) {
    return Transform(rotation_from_euler("xyz", rpy), xyz);
  };
  const auto inertia = [](double xx, double yy, double zz, double xy, double xz, double yz) {
    Mat3 I;
    I << xx, xy, xz, xy, yy, yz, xz, yz, zz;
    return I;
  };
  model::ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -9.81));
  const Transform X_upper = pose({0.02, 0.01, 0.15}, {0.1, -0.2, 0.3});
  b.add_body("base", inertia::MassProperties());
  b.add_body("upper", inertia::MassProperties(
                          2.0, X_upper.p,
                          X_upper.R * inertia(0.03, 0.028, 0.012, 0.001, -0.002, 0.0015) *
                              X_upper.R.transpose()));
  b.add_body("fore",
             inertia::MassProperties(1.2, Vec3(0, 0, 0.12), inertia(0.01, 0.012, 0.002, 0, 0, 0)));
  b.add_body("tool",
             inertia::MassProperties(0.3, Vec3::Zero(), inertia(1e-4, 1e-4, 5e-5, 0, 0, 0)));
  const auto joint = [&](std::string name, model::JointType type, std::string parent,
                         std::string child, const Transform& X_PJ, const Vec3& axis) {
    model::Joint j;
    j.name = std::move(name);
    j.type = type;
    j.parent = std::move(parent);
    j.child = std::move(child);
    j.X_PJ = X_PJ;
    j.axis = axis.normalized();
    b.add_joint(j);
  };
  joint("base_to_world", model::JointType::fixed, "world", "base", Transform(), Vec3::UnitZ());
  joint("shoulder", model::JointType::revolute, "base", "upper", pose({0, 0, 0.3}, {0, 0, 0.5}),
        Vec3::UnitZ());
  joint("elbow", model::JointType::revolute, "upper", "fore",
        pose({0, 0.05, 0.3}, {0.3, 0.2, -0.1}), Vec3::UnitY());
  joint("slide", model::JointType::prismatic, "fore", "tool", pose({0, 0, 0.25}, {-0.4, 0, 0}),
        Vec3(0.6, 0, 0.8));
  return b.build();
}

TEST(UrdfFile, SpatialArmIsTheArmBuiltInCode) {
  const ModelFile urdf = read_urdf_file(urdf_path("three_link_arm"));
  EXPECT_LT(largest_difference(urdf.model, arm_in_code(), 50), 1e-13);
  // Damping and the limits kept (plastic stops); effort and velocity limits, friction and the
  // transmission listed with their lines.
  EXPECT_EQ(urdf.model.joint(urdf.model.joint_index("elbow")).damping, 0.1);
  for (const auto& [name, lower, upper] :
       {std::tuple{"elbow", -2.0, 2.0}, std::tuple{"slide", 0.0, 0.1}}) {
    const auto& limits = urdf.model.joint(urdf.model.joint_index(name)).limits;
    ASSERT_TRUE(limits.has_value()) << name;
    EXPECT_EQ(limits->lower, lower);
    EXPECT_EQ(limits->upper, upper);
    EXPECT_EQ(limits->restitution, 0.0);
  }
  EXPECT_FALSE(urdf.model.joint(urdf.model.joint_index("shoulder")).limits.has_value());
  std::string notes;
  for (const std::string& n : urdf.notes) notes += n + "\n";
  // In the file's order.
  EXPECT_NE(notes.find(":5: link 'base'"), std::string::npos);
  EXPECT_LT(notes.find(":47: joint 'slide'"), notes.find(":49: <transmission>")) << notes;
  for (const char* expected :
       {":5: link 'base' has no <inertial>: massless",
        ":39: joint 'elbow': its effort (50) and velocity (3) limits are not enforced",
        ":40: the Coulomb friction of joint 'elbow' is not modelled",
        ":47: joint 'slide': its effort (10) and velocity (0.5) limits are not enforced",
        ":49: <transmission>: not used by momenta", ":5: link 'base', the root, is fixed"}) {
    EXPECT_NE(notes.find(expected), std::string::npos) << expected << "\n" << notes;
  }
  // The base's visual cylinder is drawn.
  const std::span<const PartSummary> base = urdf.parts_of(urdf.model.body_index("base"));
  ASSERT_EQ(base.size(), 1u);
  EXPECT_EQ(base[0].kind, "cylinder");
  EXPECT_EQ(base[0].line, 6);
}

// The seven-axis arm as URDF against the MJCF arm it was written from (which MuJoCo agrees with
// to 2e-15): M and ABA's accelerations at 50 random states, to round-off.
TEST(UrdfFile, SevenAxisArmIsItsMjcfTwin) {
  const ModelFile urdf = read_urdf_file(urdf_path("arm7"));
  const ModelFile mjcf = read_mjcf_file(test::source_dir() + "/tests/data/models/mjcf/arm7.xml");
  EXPECT_EQ(urdf.model.nv(), 7);
  EXPECT_LT(largest_difference(urdf.model, mjcf.model, 50), 1e-13);
}

// The humanoid as URDF (a floating base, each ball joint three continuous joints through massless
// links) against the MJCF humanoid: v_urdf = P v_mjcf, P matching joints by name and a ball's
// three rates to its chain's x, y, z joints. Where the balls stand at identity and still (their
// chains at zero, where the chain's axes are the ball's), every other joint anywhere and every
// acceleration random: M and the inverse dynamics agree (the URDF's M = P M Pᵀ, τ = P τ), to the
// issue's 1e-12 relative (round-off here).
TEST(UrdfFile, HumanoidIsItsMjcfTwin) {
  const ModelFile urdf = read_urdf_file(urdf_path("humanoid"));
  const ModelFile mjcf =
      read_mjcf_file(test::source_dir() + "/tests/data/models/mjcf/humanoid.xml");
  const model::Model &a = mjcf.model, &b = urdf.model;
  ASSERT_EQ(a.nv(), b.nv());
  MatX P = MatX::Zero(b.nv(), a.nv());
  for (const model::Joint& ja : a.joints()) {
    for (int k = 0; k < ja.nv(); ++k) {
      const std::string name = ja.type == model::JointType::spherical
                                   ? ja.name + "_" + std::string(1, "xyz"[k])
                                   : ja.name;
      const model::Joint& jb = b.joint(b.joint_index(name));
      P(jb.v_index + (ja.type == model::JointType::spherical ? 0 : k), ja.v_index + k) = 1.0;
    }
  }
  ASSERT_TRUE((P * P.transpose()).isIdentity(0.0)) << "not a permutation";
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  dynamics::Data da(a), db(b);
  double worst = 0.0;
  for (int s = 0; s < 50; ++s) {
    VecX qa = a.initial_q(), va(a.nv()), ddq(a.nv());
    for (int i = 0; i < a.nv(); ++i) {
      va[i] = 3.0 * unit(random);
      ddq[i] = 5.0 * unit(random);
    }
    VecX qb = b.initial_q();
    for (const model::Joint& ja : a.joints()) {
      double* q = qa.data() + ja.q_index;
      if (ja.type == model::JointType::spherical) {
        va.segment(ja.v_index, 3).setZero();  // at identity and still
        continue;
      }
      for (int i = 0; i < ja.nq(); ++i) q[i] = unit(random);
      if (ja.type == model::JointType::free) Eigen::Map<Eigen::Vector4d>(q + 3).normalize();
      const model::Joint& jb = b.joint(b.joint_index(ja.name));
      for (int i = 0; i < ja.nq(); ++i) qb[jb.q_index + i] = q[i];
    }
    const VecX vb = P * va, ddqb = P * ddq;
    const MatX Ma = dynamics::crba(a, da, qa), Mb = dynamics::crba(b, db, qb);
    const VecX ta = dynamics::rnea(a, da, qa, va, ddq), tb = dynamics::rnea(b, db, qb, vb, ddqb);
    ASSERT_TRUE(Ma.allFinite() && Mb.allFinite() && ta.allFinite() && tb.allFinite());
    worst = std::max(
        worst, (Mb - P * Ma * P.transpose()).cwiseAbs().maxCoeff() / Ma.cwiseAbs().maxCoeff());
    worst = std::max(worst, (tb - P * ta).cwiseAbs().maxCoeff() / ta.cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-12);
}

// A robot whose root link is named world floats on a floating joint; a mimic joint is a coupler.
TEST(UrdfFile, WorldRootFloatingBaseAndMimic) {
  const ModelFile f = parse_urdf(R"(<robot name="gripper">
  <link name="world"/>
  <link name="palm"><inertial><mass value="1"/><inertia ixx="1e-3" iyy="1e-3" izz="1e-3"/></inertial></link>
  <link name="a"><inertial><mass value="0.1"/><inertia ixx="1e-5" iyy="1e-5" izz="1e-5"/></inertial></link>
  <link name="b"><inertial><mass value="0.1"/><inertia ixx="1e-5" iyy="1e-5" izz="1e-5"/></inertial></link>
  <joint name="float" type="floating"><parent link="world"/><child link="palm"/></joint>
  <joint name="left" type="prismatic"><parent link="palm"/><child link="a"/><axis xyz="1 0 0"/></joint>
  <joint name="right" type="prismatic"><parent link="palm"/><child link="b"/><axis xyz="1 0 0"/>
    <mimic joint="left" multiplier="-1" offset="0.01"/></joint>
</robot>)",
                                 "gripper.urdf");
  EXPECT_EQ(f.model.num_bodies(), 4);  // the world and three links
  EXPECT_EQ(f.model.joint(0).type, model::JointType::free);
  ASSERT_EQ(f.model.constraints().size(), 1u);
  const auto& coupler = std::get<model::JointCoupler>(f.model.constraints()[0]);
  EXPECT_EQ(coupler.joint_a, "right");
  EXPECT_EQ(coupler.joint_b, "left");
  EXPECT_EQ(coupler.ratio, -1.0);
  EXPECT_EQ(coupler.offset, 0.01);
  EXPECT_TRUE(f.notes.empty());
}

// A <limit> is a pair of plastic stops on a revolute or prismatic joint — a bound a megametre
// away is none — except where it would lock the joint (lower = upper, URDF's default), leaves out
// the robot's start (every q = 0): those are listed as not enforced, with their line. A robot
// whose mimic joints are constraints keeps its stops. A continuous joint's <limit> has no stops.
TEST(UrdfFile, LimitsAreStops) {
  const auto robot = [](const std::string& joints, int links = 5) {
    std::string text = "<robot name=\"r\">\n<link name=\"base\"/>\n";
    for (const char* link : {"a", "b", "c", "d", "e"}) {
      if (links-- == 0) break;
      text += fmt::format(
          "<link name=\"{}\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" iyy=\"1\" "
          "izz=\"1\"/></inertial></link>\n",
          link);
    }
    return text + joints + "</robot>";
  };
  const auto joint = [](const char* name, const char* type, const char* child,
                        const std::string& inside) {
    return fmt::format(
        "<joint name=\"{}\" type=\"{}\"><parent link=\"base\"/><child link=\"{}\"/><axis "
        "xyz=\"0 0 1\"/>{}</joint>\n",
        name, type, child, inside);
  };
  const std::string joints =
      joint("hinge", "revolute", "a", R"(<limit lower="-1" upper="2" effort="0" velocity="0"/>)") +
      joint("locked", "revolute", "b", R"(<limit effort="5" velocity="1"/>)") +
      joint("away", "revolute", "c", R"(<limit lower="0.5" upper="1"/>)") +
      joint("slider", "prismatic", "d", R"(<limit lower="-0.2" upper="1e6"/>)") +
      joint("spin", "continuous", "e", R"(<limit effort="3" velocity="2"/>)");
  const ModelFile f = parse_urdf(robot(joints), "r.urdf");
  const auto limits = [&](const char* name) {
    return f.model.joint(f.model.joint_index(name)).limits;
  };
  ASSERT_TRUE(limits("hinge").has_value());
  EXPECT_EQ(limits("hinge")->lower, -1.0);
  EXPECT_EQ(limits("hinge")->upper, 2.0);
  EXPECT_EQ(limits("hinge")->restitution, 0.0);
  ASSERT_TRUE(limits("slider").has_value());
  EXPECT_EQ(limits("slider")->lower, -0.2);
  EXPECT_EQ(limits("slider")->upper, std::numeric_limits<double>::infinity());
  for (const char* none : {"locked", "away", "spin"}) EXPECT_FALSE(limits(none)) << none;
  std::string notes;
  for (const std::string& n : f.notes) notes += n + "\n";
  for (const char* expected :
       {"r.urdf:9: the limits of joint 'locked' are not enforced: lower = upper = 0 (URDF's "
        "default when they are left out) would lock it; its effort (5) and velocity (1) limits "
        "are not enforced",
        "r.urdf:10: the limits of joint 'away' are not enforced: [0.5, 1] does not hold the "
        "robot's start, where every joint is at 0",
        "r.urdf:12: the <limit> of joint 'spin' (a continuous joint) has no stops: its effort (3) "
        "and velocity (2) limits are not enforced"}) {
    EXPECT_NE(notes.find(expected), std::string::npos) << expected << "\n" << notes;
  }
  EXPECT_EQ(f.notes.size(), 4u) << notes;  // and the root's weld to the world

  // A mimic joint makes the robot constrained; its stops are stops all the same.
  const ModelFile mimic = parse_urdf(
      robot(joint("hinge", "revolute", "a", R"(<limit lower="-1" upper="2"/>)") +
                joint("follower", "revolute", "b",
                      R"(<limit lower="-1" upper="1"/><mimic joint="hinge" multiplier="0.5"/>)"),
            2),
      "r.urdf");
  ASSERT_EQ(mimic.model.constraints().size(), 1u);
  ASSERT_TRUE(mimic.model.joint(mimic.model.joint_index("hinge")).limits.has_value());
  ASSERT_TRUE(mimic.model.joint(mimic.model.joint_index("follower")).limits.has_value());
  EXPECT_EQ(mimic.model.joint(mimic.model.joint_index("follower")).limits->upper, 1.0);
  EXPECT_EQ(mimic.notes.size(), 1u);  // the root's weld

  // Bounds the wrong way round are an error at their line.
  try {
    parse_urdf(robot(joint("hinge", "revolute", "a", R"(<limit lower="1" upper="-1"/>)"), 1),
               "r.urdf");
    ADD_FAILURE() << "no error";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "r.urdf:4: the limits of joint 'hinge': lower 1 is above upper -1"),
              std::string::npos)
        << e.what();
  }
}

// Each problem at its line, with a did-you-mean where a name is close.
std::string error_of(const std::string& text) {
  try {
    parse_urdf(text, "r.urdf");
  } catch (const ParseError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for\n" << text;
  return {};
}

// An <inertial> of zero mass and no inertia is a massless link, as exporters write one (momenta's
// own for the links of a joint chain); zero mass with inertia is still refused.
TEST(UrdfFile, AZeroMassInertialIsAMasslessLink) {
  const auto robot = [](const std::string& inertia) {
    return "<robot name=\"r\">\n<link name=\"base\"/>\n<link name=\"tool\"><inertial><mass "
           "value=\"0\"/>" +
           inertia +
           "</inertial></link>\n<joint name=\"mount\" type=\"fixed\"><parent link=\"base\"/>"
           "<child link=\"tool\"/></joint>\n</robot>";
  };
  const ModelFile f = parse_urdf(robot("<inertia ixx=\"0\" iyy=\"0\" izz=\"0\"/>"), "r.urdf");
  EXPECT_EQ(
      f.model.bodies()[static_cast<std::size_t>(f.model.body_index("tool"))].mass_properties.mass(),
      0.0);
  EXPECT_NE(error_of(robot("<inertia ixx=\"1\" iyy=\"1\" izz=\"1\"/>")).find("r.urdf:3: "),
            std::string::npos);
}

TEST(UrdfFile, ErrorsAreAtTheirLine) {
  const std::string two_links = R"(<robot name="r">
<link name="a"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1"/></inertial></link>
<link name="b"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1"/></inertial></link>
)";
  EXPECT_NE(error_of("<robot><link name='a'>\n</robot>")
                .find("r.urdf:1: not well-formed XML "
                      "(mismatched element)"),
            std::string::npos);
  EXPECT_NE(error_of("").find("r.urdf: the file is empty"), std::string::npos);
  EXPECT_NE(error_of("<model/>").find("root element is <robot>"), std::string::npos);
  EXPECT_NE(
      error_of(
          two_links +
          R"(<joint name="j" type="revolut"><parent link="a"/><child link="b"/></joint></robot>)")
          .find("r.urdf:4: joint 'j': unknown type 'revolut' (did you mean 'revolute'?)"),
      std::string::npos);
  EXPECT_NE(
      error_of(
          two_links +
          R"(<joint name="j" type="fixed"><parent link="a"/><child link="bb"/></joint></robot>)")
          .find("r.urdf:4: unknown link 'bb' (did you mean 'b'?)"),
      std::string::npos);
  EXPECT_NE(error_of(two_links + "</robot>").find("the links form 2 trees, rooted at 'a', 'b'"),
            std::string::npos);
  EXPECT_NE(error_of(R"(<robot name="r">
<link name="a"><inertial><mass value="-1"/></inertial></link></robot>)")
                .find("r.urdf:2: the mass of link 'a' is negative"),
            std::string::npos);
  EXPECT_NE(error_of(R"(<robot name="r">
<link name="a"><inertial><mass value="1"/>
<inertia ixx="1" iyy="1" izz="3"/></inertial></link></robot>)")
                .find("r.urdf:3:"),
            std::string::npos);  // no mass distribution has moments 1, 1, 3
  EXPECT_NE(error_of(R"(<robot name="r"><link name="a">
<inertial><origin xyz="0 0 x"/><mass value="1"/></inertial></link></robot>)")
                .find("r.urdf:2: <origin xyz=\"0 0 x\">: expected three finite numbers"),
            std::string::npos);
  EXPECT_NE(error_of(two_links + R"(<link name="c"/>
<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>
<joint name="k" type="fixed"><parent link="c"/><child link="b"/></joint></robot>)")
                .find("r.urdf:6: link 'b' is the child of joints 'j' and 'k'"),
            std::string::npos);
  // A cycle beside the tree: its links would be left out; refused instead.
  EXPECT_NE(error_of(two_links + R"(<link name="c"/>
<joint name="j" type="fixed"><parent link="b"/><child link="c"/></joint>
<joint name="k" type="fixed"><parent link="c"/><child link="b"/></joint></robot>)")
                .find("r.urdf:3: links 'b', 'c' do not hang from the root 'a': their joints form a "
                      "cycle"),
            std::string::npos);
}

}  // namespace
}  // namespace momenta::io
