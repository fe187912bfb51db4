// The MJCF reader (io/mjcf_file.hpp): an MJCF file and an independent description of the same
// system give the same dynamics (the double pendulum against its model file); orientations,
// default classes, geoms' mass properties, joints, equality constraints and motors map as
// docs/model-formats.md says, each checked against a value worked out here by another route;
// every problem of a file is an error at its line and column, every element momenta does not use
// a note at its line. The side-by-side with MuJoCo itself is tests/validation/io.

#include "momenta/io/mjcf_file.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <variant>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/constraints.hpp"
#include "momenta/dynamics/force_elements.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta_test/model_comparison.hpp"
#include "momenta_test/tolerance.hpp"

// A namespace of its own: the executable compiles its test files as one unit (unity build).
namespace momenta::io::mjcf_test {
namespace {

constexpr double kPi = std::numbers::pi;

std::string mjcf_path(const std::string& name) {
  return test::source_dir() + "/tests/data/models/mjcf/" + name + ".xml";
}

// A model of one body under the world, placed by `placement` (attributes of <body>), with a
// box geom so that it has mass.
ModelFile one_body(const std::string& compiler, const std::string& placement) {
  return parse_mjcf("<mujoco><compiler " + compiler + "/><worldbody><body name='b' " + placement +
                        "><joint type='hinge'/><geom type='box' size='0.1 0.2 0.3'/></body>"
                        "</worldbody></mujoco>",
                    "m.xml");
}

const model::Joint& joint_of(const ModelFile& file, const std::string& name) {
  return file.model.joints()[static_cast<std::size_t>(file.model.joint_index(name))];
}

TEST(MjcfFile, DoublePendulumIsItsModelFile) {
  const ModelFile mjcf = read_mjcf_file(mjcf_path("double_pendulum"));
  const ModelFile yaml = read_model_file(test::source_dir() + "/examples/double_pendulum.yaml");
  EXPECT_EQ(mjcf.name, "double pendulum");
  EXPECT_EQ(mjcf.model.num_bodies(), 3);
  EXPECT_TRUE(mjcf.notes.empty());
  EXPECT_LT(test::largest_difference(mjcf.model, yaml.model, 20), 1e-14);
  // read_model_file takes *.xml as MJCF.
  EXPECT_EQ(read_model_file(mjcf_path("double_pendulum")).model.nv(), 2);
}

// Every way MJCF gives an orientation, against the rotation built here from its definition.
TEST(MjcfFile, OrientationsAsMuJoCoDefinesThem) {
  const auto R_of = [](const ModelFile& file) { return joint_of(file, "joint0").X_PJ.R; };
  const Vec3 axis = Vec3(1, 2, 3).normalized();
  const Mat3 about = Eigen::AngleAxisd(0.7, axis).toRotationMatrix();
  // quat (w x y z, normalized) and axisangle in degrees (the default) or radians.
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.7, axis));
  EXPECT_MATRIX_NEAR(R_of(one_body("", fmt::format("quat='{} {} {} {}'", 2 * q.w(), 2 * q.x(),
                                                   2 * q.y(), 2 * q.z()))),
                     about, 1e-15);
  EXPECT_MATRIX_NEAR(R_of(one_body("", fmt::format("axisangle='1 2 3 {:.17g}'", 0.7 * 180 / kPi))),
                     about, 1e-15);
  EXPECT_MATRIX_NEAR(R_of(one_body("angle='radian'", "axisangle='1 2 3 0.7'")), about, 1e-15);
  // euler: lower case turns with the frame (R = Rx Ry Rz for "xyz"), upper case about fixed axes
  // (R = Rz Ry Rx for "XYZ") — SciPy's opposite spelling.
  const Vec3 a(0.3, -0.5, 1.1);
  const Mat3 Rx = Eigen::AngleAxisd(a.x(), Vec3::UnitX()).toRotationMatrix();
  const Mat3 Ry = Eigen::AngleAxisd(a.y(), Vec3::UnitY()).toRotationMatrix();
  const Mat3 Rz = Eigen::AngleAxisd(a.z(), Vec3::UnitZ()).toRotationMatrix();
  const std::string angles = fmt::format("euler='{} {} {}'", a.x(), a.y(), a.z());
  EXPECT_MATRIX_NEAR(R_of(one_body("angle='radian'", angles)), Rx * Ry * Rz, 1e-15);
  EXPECT_MATRIX_NEAR(R_of(one_body("angle='radian' eulerseq='XYZ'", angles)), Rz * Ry * Rx, 1e-15);
  EXPECT_MATRIX_NEAR(R_of(one_body("angle='radian' eulerseq='zXy'", angles)),
                     Eigen::AngleAxisd(a.y(), Vec3::UnitX()).toRotationMatrix() *
                         Eigen::AngleAxisd(a.x(), Vec3::UnitZ()).toRotationMatrix() *
                         Eigen::AngleAxisd(a.z(), Vec3::UnitY()).toRotationMatrix(),
                     1e-15);
  // xyaxes: y made perpendicular to x; zaxis: the shortest turn of z onto it.
  Mat3 frame;
  frame.col(0) = Vec3(1, 1, 0).normalized();
  frame.col(1) = Vec3(-1, 1, 0).normalized();
  frame.col(2) = Vec3::UnitZ();
  EXPECT_MATRIX_NEAR(R_of(one_body("", "xyaxes='2 2 0 0 3 0'")), frame, 1e-15);
  const Mat3 tilt = R_of(one_body("", "zaxis='0 1 1'"));
  EXPECT_MATRIX_NEAR(tilt.col(2), Vec3(0, 1, 1).normalized(), 1e-15);
  EXPECT_MATRIX_NEAR(tilt, Eigen::AngleAxisd(-kPi / 4, Vec3::UnitX()).toRotationMatrix(), 1e-15);
}

// The arm: defaults by class and childclass, geoms' masses, an inertial turned by its quat,
// joints, a spring, motors and the notes.
TEST(MjcfFile, ArmDefaultsMassesJointsMotorsAndNotes) {
  const ModelFile arm = read_mjcf_file(mjcf_path("arm7"));
  EXPECT_EQ(arm.name, "arm7");
  EXPECT_EQ(arm.model.nv(), 7);
  EXPECT_EQ(arm.model.num_bodies(), 9);  // the world, the welded base, seven links
  const auto body = [&](const std::string& name) -> const inertia::MassProperties& {
    return arm.model.bodies()[static_cast<std::size_t>(arm.model.body_index(name))].mass_properties;
  };
  // The base: a 5 kg cylinder 0.0775 m up; link1's capsule (density 2700) is not used beside its
  // <inertial>; link3 is a 3 kg capsule along z from 0 to 0.2155 m.
  EXPECT_REL_NEAR(body("base").mass(), 5.0, 1e-15);
  EXPECT_MATRIX_NEAR(body("base").center_of_mass(), Vec3(0, 0, 0.0775), 1e-17);
  EXPECT_REL_NEAR(body("link1").mass(), 4.0, 1e-15);
  const inertia::MassProperties capsule3 =
      inertia::capsule(inertia::Amount::mass(3.0), 0.065, 0.2155);
  EXPECT_MATRIX_NEAR(body("link3").inertia_about_com(), capsule3.inertia_about_com(), 1e-15);
  EXPECT_MATRIX_NEAR(body("link3").center_of_mass(), Vec3(0, 0, 0.2155 / 2), 1e-16);
  // link4's inertial is turned 30° about x: I = R diag(0.03, 0.03, 0.01) Rᵀ.
  const Mat3 R30 = Eigen::AngleAxisd(kPi / 6, Vec3::UnitX()).toRotationMatrix();
  EXPECT_MATRIX_NEAR(body("link4").inertia_about_com(),
                     Mat3(R30 * Vec3(0.03, 0.03, 0.01).asDiagonal() * R30.transpose()), 1e-8);
  // link7: a cylinder (density 1500 from class wrist, inherited through link6's childclass) and
  // a box turned 30° about z, together.
  const double m_cylinder = 1500 * kPi * 0.04 * 0.04 * 0.045, m_box = 1500 * 0.04 * 0.06 * 0.02;
  EXPECT_REL_NEAR(body("link7").mass(), m_cylinder + m_box, 1e-14);
  // Joint damping from the default classes; a6's anchor; the spring a3 at its springref.
  EXPECT_EQ(joint_of(arm, "a1").damping, 0.5);
  ASSERT_TRUE(joint_of(arm, "a1").limits.has_value());  // range="-170 170" (degrees)
  EXPECT_NEAR(joint_of(arm, "a1").limits->upper, 170.0 * kPi / 180.0, 1e-15);
  EXPECT_EQ(joint_of(arm, "a7").damping, 0.1);
  EXPECT_MATRIX_NEAR(joint_of(arm, "a6").X_CJ.p, Vec3(0, 0, 0.0607), 0.0);
  EXPECT_MATRIX_NEAR(joint_of(arm, "a4").axis, Vec3(0, -1, 0), 0.0);
  const auto& elements = arm.model.force_elements();
  const auto spring = std::find_if(elements.begin(), elements.end(), [](const auto& e) {
    return model::force_element_name(e) == "a3_spring";
  });
  ASSERT_NE(spring, elements.end());
  const auto& torsional = std::get<model::TorsionalSpringDamper>(*spring);
  EXPECT_EQ(torsional.stiffness, 20.0);
  EXPECT_REL_NEAR(torsional.rest_angle, 10 * kPi / 180, 1e-15);
  // Motors: one input each; the generalized force on the joint is gear · gain · u and no other
  // joint feels it (the torque pair's two halves cancel there).
  ASSERT_EQ(arm.model.signals().size(), 7u);
  dynamics::Data data(arm.model);
  VecX q = VecX::LinSpaced(7, 0.3, -0.9), v = VecX::LinSpaced(7, -0.5, 0.5);
  dynamics::forward_kinematics(arm.model, data, q, v);
  std::vector<double> u(7, 0.0);
  VecX tau_zero, tau;
  std::vector<Vec6> f_zero(static_cast<std::size_t>(arm.model.num_bodies())), f_ext = f_zero;
  dynamics::force_element_forces(arm.model, data, u, q, v, tau_zero, f_zero);
  const double gains[7] = {1, 2, 1, 1, 3, 1, 1};
  for (int k = 0; k < 7; ++k) {
    std::fill(u.begin(), u.end(), 0.0);
    u[static_cast<std::size_t>(k)] = 1.5;
    dynamics::force_element_forces(arm.model, data, u, q, v, tau, f_ext);
    // The wrenches' generalized forces: τ_g = −(RNEA with the wrenches − RNEA without).
    const VecX with = dynamics::rnea(arm.model, data, q, v, VecX::Zero(7), f_ext);
    const VecX without = dynamics::rnea(arm.model, data, q, v, VecX::Zero(7), f_zero);
    VecX expected = VecX::Zero(7);
    expected[k] = 1.5 * gains[k];
    EXPECT_MATRIX_NEAR(VecX(without - with), expected, 1e-13) << "motor m" << k + 1;
  }
  // What is not used, at its line.
  const std::vector<std::string> expected_notes = {
      "arm7.xml:8: <option> timestep and integrator",
      "arm7.xml:19: contacts are disabled (<option><flag contact=\"disable\">): the world's "
      "planes hold nothing",
      "arm7.xml:20: <light name=\"sun\">: not used by momenta",
      "arm7.xml:48: <site name=\"flange\"> of body 'link7': not used by momenta",
      "arm7.xml:59: the control and force ranges of actuator 'm1' are not enforced",
      "arm7.xml:67: <sensor> (1 element): not used by momenta"};
  ASSERT_EQ(arm.notes.size(), expected_notes.size());
  for (std::size_t i = 0; i < expected_notes.size(); ++i) {
    EXPECT_NE(arm.notes[i].find(expected_notes[i]), std::string::npos) << arm.notes[i];
  }
}

// Several joints in one body: a chain of massless bodies whose frames coincide with the body's,
// as MuJoCo applies them one after the other; a free joint starts where the file draws the body.
TEST(MjcfFile, HumanoidJointChainsAndFloatingBase) {
  const ModelFile human = read_mjcf_file(mjcf_path("humanoid"));
  EXPECT_EQ(human.model.nv(), 6 + 4 * 3 + 32);  // free, four balls, 32 hinges and slides
  const model::Joint& root = joint_of(human, "root");
  EXPECT_EQ(root.type, model::JointType::free);
  const Eigen::Quaterniond q_WB(0.9950042, 0, 0, 0.0998334);
  ASSERT_EQ(root.q0.size(), 7);
  EXPECT_MATRIX_NEAR(root.q0.head<3>(), Vec3(0, 0, 1), 0.0);
  EXPECT_NEAR(root.q0[3], q_WB.normalized().w(), 1e-15);
  // The left hip's three hinges: x on the pelvis, then y and z on massless links.
  EXPECT_EQ(joint_of(human, "left_hip_x").child, "left_thigh_left_hip_x");
  EXPECT_EQ(joint_of(human, "left_hip_y").parent, "left_thigh_left_hip_x");
  EXPECT_EQ(joint_of(human, "left_hip_z").child, "left_thigh");
  EXPECT_EQ(joint_of(human, "left_thumb_slide").type, model::JointType::prismatic);
  // Masses as given: 70 kg in all (Winter's fractions sum to 1).
  double total = 0.0;
  for (const auto& b : human.model.bodies()) total += b.mass_properties.mass();
  EXPECT_NEAR(total, 70.0, 1e-12);
}

// Equality constraints: a four-bar closed by connect assembles where the file draws it; weld and
// joint (a coupler) take their partner's pose and the polynomial's linear part.
TEST(MjcfFile, EqualityConstraintsCloseLoopsWhereTheFileDrawsThem) {
  const ModelFile bar = parse_mjcf(R"(<mujoco><compiler angle="radian"/>
<worldbody>
  <body name="crank"><joint name="crank_pin" axis="0 0 1"/>
    <geom type="capsule" fromto="0 0 0 0.1 0 0" size="0.01"/>
    <body name="coupler" pos="0.1 0 0" euler="0 0 1.2"><joint name="coupler_pin" axis="0 0 1"/>
      <geom type="capsule" fromto="0 0 0 0.3 0 0" size="0.01"/></body></body>
  <body name="rocker" pos="0.3 0 0" euler="0 0 1.9"><joint name="rocker_pin" axis="0 0 1"/>
    <geom type="capsule" fromto="0 0 0 0.25 0 0" size="0.01"/></body>
  <body name="tip" pos="1 0 0"><joint name="slide" type="slide" axis="1 0 0"/>
    <geom type="sphere" size="0.05"/></body>
  <body name="follower" pos="2 0 0"><joint name="follow" type="slide" axis="1 0 0"/>
    <geom type="sphere" size="0.05"/></body>
</worldbody>
<equality>
  <connect name="closure" body1="coupler" body2="rocker" anchor="0.3 0 0"/>
  <weld name="glue" body1="tip"/>
  <joint name="gear" joint1="follow" joint2="slide" polycoef="0.1 -2 0 0 0"/>
</equality></mujoco>)",
                                   "bar.xml");
  ASSERT_EQ(bar.model.constraints().size(), 3u);
  const auto& closure = std::get<model::LoopClosure>(bar.model.constraints()[0]);
  EXPECT_EQ(closure.type, model::LoopType::point);
  EXPECT_EQ(closure.b.body, "coupler");
  EXPECT_EQ(closure.a.body, "rocker");
  // The anchor's point on the rocker, worked out by hand: the coupler's end in the world, then
  // into the rocker's frame.
  const Vec3 coupler_end =
      Vec3(0.1, 0, 0) + Eigen::AngleAxisd(1.2, Vec3::UnitZ()) * Vec3(0.3, 0, 0);
  const Vec3 on_rocker = Eigen::AngleAxisd(-1.9, Vec3::UnitZ()) * (coupler_end - Vec3(0.3, 0, 0));
  EXPECT_MATRIX_NEAR(closure.a.X_BF.p, on_rocker, 1e-15);
  // At the drawn configuration every position row is satisfied.
  dynamics::Data data(bar.model);
  dynamics::ConstraintRows rows(bar.model);
  const VecX q0 = bar.model.initial_q();
  dynamics::forward_kinematics(bar.model, data, q0);
  dynamics::constraint_equations(bar.model, data, q0, rows);
  ASSERT_EQ(rows.count, 3 + 6 + 1);
  ASSERT_TRUE(rows.position.allFinite());
  EXPECT_LT(rows.position.head(9).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_EQ(rows.position[9], -0.1);  // the coupler's offset: follow = 0.1 − 2 slide
  const auto& glue = std::get<model::LoopClosure>(bar.model.constraints()[1]);
  EXPECT_EQ(glue.type, model::LoopType::weld);
  EXPECT_EQ(glue.a.body, "world");
  EXPECT_MATRIX_NEAR(glue.a.X_BF.p, Vec3(1, 0, 0), 0.0);
  const auto& gear = std::get<model::JointCoupler>(bar.model.constraints()[2]);
  EXPECT_EQ(gear.joint_a, "follow");
  EXPECT_EQ(gear.ratio, -2.0);
  EXPECT_EQ(gear.offset, 0.1);
}

// A hinge's or slide's range, where `limited` (or `auto` with <compiler autolimits>, MuJoCo's
// default) makes it one, is a pair of plastic stops on momenta's coordinate qpos − ref, in the
// compiler's angle unit; a bound a megametre away is none. Not enforced, each said at its line:
// a ball's range (its cone) and a range that leaves out the start (qpos = ref); a model with
// <equality> constraints keeps its stops. An empty range is an error at its line.
TEST(MjcfFile, RangesAreStops) {
  const auto model = [](const std::string& compiler, const std::string& joints,
                        const std::string& after = "") {
    std::string text = "<mujoco><compiler " + compiler + "/>\n<worldbody>\n";
    // One body of the world per line of `joints`, each on its line's joint.
    int k = 0;
    for (std::size_t start = 0; start < joints.size(); ++k) {
      const std::size_t end = joints.find('\n', start);
      text += fmt::format(
          "<body name=\"b{}\" pos=\"{} 0 0\">{}<geom type=\"sphere\" "
          "size=\"0.1\"/></body>\n",
          k, k, joints.substr(start, end - start));
      start = end + 1;
    }
    return text + "</worldbody>\n" + after + "</mujoco>";
  };
  const std::string joints =
      "<joint name=\"hinge\" range=\"-30 60\" ref=\"10\"/>\n"
      "<joint name=\"slide\" type=\"slide\" range=\"-0.5 1e6\"/>\n"
      "<joint name=\"loose\" range=\"-30 60\" limited=\"false\"/>\n"
      "<joint name=\"ball\" type=\"ball\" range=\"0 45\"/>\n"
      "<joint name=\"away\" range=\"20 60\"/>\n";
  const ModelFile f = parse_mjcf(model("angle=\"degree\"", joints), "m.xml");
  const double degree = kPi / 180.0;
  const auto& hinge = joint_of(f, "hinge").limits;
  ASSERT_TRUE(hinge.has_value());
  EXPECT_NEAR(hinge->lower, -40.0 * degree, 1e-15);  // qpos − ref
  EXPECT_NEAR(hinge->upper, 50.0 * degree, 1e-15);
  EXPECT_EQ(hinge->restitution, 0.0);
  const auto& slide = joint_of(f, "slide").limits;
  ASSERT_TRUE(slide.has_value());
  EXPECT_EQ(slide->lower, -0.5);
  EXPECT_EQ(slide->upper, std::numeric_limits<double>::infinity());
  for (const char* none : {"loose", "ball", "away"}) {
    EXPECT_FALSE(joint_of(f, none).limits.has_value()) << none;
  }
  std::string notes;
  for (const std::string& n : f.notes) notes += n + "\n";
  for (const char* expected :
       {"m.xml:6: the range of joint 'ball' (a ball joint's cone) is not enforced",
        "m.xml:7: the limits of joint 'away' are not enforced: its start (qpos = ref = 0) is "
        "outside its range [20, 60]"}) {
    EXPECT_NE(notes.find(expected), std::string::npos) << expected << "\n" << notes;
  }
  // Without autolimits a range alone limits nothing; limited="true" still does.
  const ModelFile manual =
      parse_mjcf(model("autolimits=\"false\"",
                       "<joint name=\"a\" range=\"-1 1\"/>\n<joint name=\"b\" range=\"-1 1\" "
                       "limited=\"true\"/>\n"),
                 "m.xml");
  EXPECT_FALSE(joint_of(manual, "a").limits.has_value());
  ASSERT_TRUE(joint_of(manual, "b").limits.has_value());
  EXPECT_EQ(joint_of(manual, "b").limits->upper, std::numbers::pi / 180.0);
  // A constrained model keeps its stops.
  const ModelFile constrained =
      parse_mjcf(model("angle=\"radian\"",
                       "<joint name=\"a\" range=\"-1 1\"/>\n<joint name=\"b\" range=\"-1 1\"/>\n",
                       "<equality><joint joint1=\"a\" joint2=\"b\"/></equality>\n"),
                 "m.xml");
  EXPECT_TRUE(constrained.model.has_constraints());
  ASSERT_TRUE(joint_of(constrained, "a").limits.has_value());
  EXPECT_EQ(joint_of(constrained, "a").limits->upper, 1.0);
  for (const std::string& n : constrained.notes)
    EXPECT_EQ(n.find("limits"), std::string::npos) << n;
  // An empty range, at its line.
  try {
    parse_mjcf(model("", "<joint name=\"a\"/>\n<joint name=\"b\" range=\"1 1\"/>\n"), "m.xml");
    ADD_FAILURE() << "no error";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("m.xml:4"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("the range of joint 'b' [1, 1] is empty"),
              std::string::npos)
        << e.what();
  }
}

std::string error_of(const std::string& body) {
  try {
    parse_mjcf(body, "m.xml");
  } catch (const ParseError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for\n" << body;
  return {};
}

std::string in_world(const std::string& body) {
  return "<mujoco>\n<worldbody>\n" + body + "\n</worldbody>\n</mujoco>";
}

TEST(MjcfFile, ErrorsAreAtTheirLineAndColumn) {
  const auto has = [](const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos ? ::testing::AssertionSuccess()
                                                : ::testing::AssertionFailure() << text;
  };
  EXPECT_TRUE(has(error_of("<mujoco><worldbody>\n</mujoco>"),
                  "m.xml:1: not well-formed XML (mismatched element)"));
  EXPECT_TRUE(has(error_of(""), "m.xml: the file is empty"));
  EXPECT_TRUE(has(error_of("<robot/>"), "root element is <mujoco> (a URDF <robot>"));
  EXPECT_TRUE(has(error_of(in_world("<body><joint type='hinge' axs='0 0 1'/></body>")),
                  "m.xml:3:27: <joint>: unknown attribute 'axs' (did you mean 'axis'?)"));
  EXPECT_TRUE(has(error_of(in_world("<body><joint type='slid'/><geom size='1'/></body>")),
                  "m.xml:3:14: <joint type=\"slid\">: not one of hinge, slide, ball, free (did you "
                  "mean 'slide'?)"));
  EXPECT_TRUE(has(error_of(in_world("<body><jiont/></body>")),
                  "m.xml:3:7: <jiont> in body 'body1': not an element of a body (did you mean "
                  "'joint'?)"));
  EXPECT_TRUE(has(error_of(in_world("<body><geom size='0.1 x'/></body>")),
                  "m.xml:3:13: <geom size=\"0.1 x\">: not a list of finite numbers"));
  EXPECT_TRUE(has(error_of(in_world("<body><geom type='box' size='0.1 0.2'/></body>")),
                  "a geom of body 'body1' (a box) needs 3 sizes, the file gives 2"));
  EXPECT_TRUE(has(error_of(in_world("<body><geom class='wide' size='1'/></body>")),
                  "unknown class 'wide'"));
  EXPECT_TRUE(has(error_of(in_world("<body><geom type='mesh' mesh='m'/></body>")),
                  "m.xml:3:25: unknown mesh 'm'"));
  EXPECT_TRUE(has(error_of(in_world("<body><geom type='plane' size='1 1 1'/></body>")),
                  "is a plane: momenta cannot find its mass; give body 'body1' an <inertial>"));
  EXPECT_TRUE(has(error_of(in_world("<body quat='1 0 0 0' euler='0 0 1'><geom size='1'/></body>")),
                  "<body> gives its orientation twice ('quat' and 'euler')"));
  EXPECT_TRUE(has(
      error_of(in_world("<body><geom size='1'/><body><freejoint/><geom size='1'/></body></body>")),
      "a free joint is the only joint of a body of the world"));
  EXPECT_TRUE(has(error_of(in_world("<body><inertial mass='1' diaginertia='1 1 3'/></body>")),
                  "m.xml:3:26: body 'body1': principal moments 1, 1, 3"));
  EXPECT_TRUE(has(error_of("<mujoco><compiler settotalmass='5'/><worldbody/></mujoco>"),
                  "<compiler settotalmass>: momenta takes the masses as the file gives them"));
  EXPECT_TRUE(has(error_of("<mujoco><default><default class='main'/></default></mujoco>"),
                  "a second default class named 'main'"));
  EXPECT_TRUE(has(error_of("<mujoco><worldbdy/></mujoco>"),
                  "<worldbdy>: not an element of <mujoco> (did you mean 'worldbody'?)"));
  EXPECT_TRUE(has(error_of("<mujoco><worldbody><body name='a'><joint/><geom size='1'/></body>"
                           "</worldbody>\n<equality><connect body1='b' anchor='0 0 0'/></equality>"
                           "</mujoco>"),
                  "m.xml:2:20: unknown body 'b' (did you mean 'a'?)"));
  // A massless body on a joint: the builder's error, at the body's line.
  EXPECT_TRUE(has(error_of(in_world("<body name='a'>\n<joint/></body>")),
                  "m.xml:4:1: joint 'joint0' carries only massless bodies"));
}

// Fixed tendons without MuJoCo at hand (side by side: FixedTendonsAreMuJoCos,
// TendonEqualitiesAreCouplersWhereMuJoCosHold): what momenta does not enforce or model is a note
// — a range, dry friction, a spatial tendon, an equality over more than two joints — and a
// missing coef, a joint that is not 1-dof or an unknown tendon in an equality an error at its line.
TEST(MjcfFile, FixedTendonsSayWhatTheyDoNotModel) {
  const std::string two_hinges =
      "<mujoco><worldbody><body><joint name='a'/><geom size='0.1'/><body><joint name='b'/>"
      "<geom size='0.1'/><body><joint name='c'/><geom size='0.1'/></body></body></body>"
      "</worldbody>\n";
  const ModelFile f = parse_mjcf(two_hinges + R"(<tendon>
<fixed name="t" range="-1 1" frictionloss="0.2"><joint joint="a" coef="1"/><joint joint="b" coef="2"/></fixed>
<fixed name="all"><joint joint="a" coef="1"/><joint joint="b" coef="1"/><joint joint="c" coef="1"/></fixed>
<spatial name="cable"/>
</tendon>
<equality><tendon name="three" tendon1="all"/></equality></mujoco>)",
                                 "m.xml", ".");
  ASSERT_EQ(f.notes.size(), 4u) << ::testing::PrintToString(f.notes);
  EXPECT_EQ(f.notes[0], "m.xml:3: the range of tendon 't' is not enforced");
  EXPECT_EQ(f.notes[1], "m.xml:3: the dry friction of tendon 't' is not modelled");
  EXPECT_EQ(f.notes[2],
            "m.xml:5: <spatial> tendon 'cable': not modelled (momenta reads fixed "
            "tendons)");
  EXPECT_EQ(f.notes[3],
            "m.xml:7: tendon equality 'three': not modelled (momenta couples two "
            "joints: one tendon of two joints, or two tendons of one joint each)");
  EXPECT_TRUE(f.model.constraints().empty());
  EXPECT_EQ(f.model.force_elements().size(), 2u);
  ASSERT_EQ(f.outputs.size(), 2u);
  EXPECT_EQ(f.outputs[0].name, "t_length");

  EXPECT_NE(error_of(two_hinges + "<tendon><fixed><joint joint='a'/></fixed></tendon></mujoco>")
                .find("m.xml:2:16: <joint> needs the attribute 'coef'"),
            std::string::npos);
  EXPECT_NE(error_of("<mujoco><worldbody><body><joint type='ball'/><geom size='0.1'/></body>"
                     "</worldbody>\n<tendon><fixed name='t'><joint joint='joint0' coef='1'/>"
                     "</fixed></tendon></mujoco>")
                .find("joint 'joint0' is spherical with 3 degrees of freedom; a tendon's joints "
                      "are 1-dof"),
            std::string::npos);
  EXPECT_NE(error_of(two_hinges + "<tendon><fixed name='t'><joint joint='a' coef='1'/></fixed>"
                                  "</tendon><equality><tendon tendon1='s'/></equality></mujoco>")
                .find("unknown fixed tendon 's' (did you mean 't'?)"),
            std::string::npos);
}

// Keyframes without MuJoCo at hand (side by side with it: tests/validation/io/mjcf_mujoco_test.cpp,
// KeyframesAreMuJoCosStates): a hinge's q is qpos − ref (in radians, whatever the compiler's
// angle), a free joint's speeds turn from [v; ω] to [ω; v]; what momenta has no use for is a note;
// a key of the wrong size, an unknown element or a second key of one name an error at its line.
TEST(MjcfFile, KeyframesAreNamedStatesInMomentasLayout) {
  const std::string body = R"(<mujoco>
<worldbody>
<body name="box" pos="0 0 1"><freejoint name="root"/><geom type="box" size="1 1 1"/>
<body name="arm"><joint name="hinge" axis="0 1 0" ref="90"/><geom size="0.1" pos="0 0 -1"/></body>
</body>
</worldbody>
<keyframe>
<key name="tilted" qpos="1 2 3 1 0 0 0 2" qvel="1 2 3 4 5 6 7" act="1"/>
</keyframe>
)";
  const ModelFile f = parse_mjcf(body + "</mujoco>", "m.xml");
  ASSERT_EQ(f.keyframes.size(), 1u);
  const Keyframe& key = f.keyframe("tilted");
  EXPECT_EQ(key.line, 8);
  EXPECT_EQ(key.q.head<7>(), (VecX(7) << 1, 2, 3, 1, 0, 0, 0).finished());
  EXPECT_NEAR(key.q[7], 2.0 - std::numbers::pi / 2, 1e-15);
  EXPECT_EQ(key.v, (VecX(7) << 4, 5, 6, 1, 2, 3, 7).finished());
  std::string notes;
  for (const std::string& n : f.notes) notes += n + "\n";
  EXPECT_NE(notes.find("m.xml:8: key 'tilted': act not used by momenta"), std::string::npos)
      << notes;
  const auto has = [](const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos ? ::testing::AssertionSuccess()
                                                : ::testing::AssertionFailure() << text;
  };
  EXPECT_TRUE(has(error_of(body + "<keyframe><key qpos='1 2'/></keyframe></mujoco>"),
                  "m.xml:10:16: <key qpos=\"1 2\">: expected 8 numbers, found 2"));
  EXPECT_TRUE(has(error_of(body + "<keyframe><kye/></keyframe></mujoco>"),
                  "m.xml:10:11: <kye> in <keyframe>: its elements are <key>"));
  EXPECT_TRUE(has(error_of(body + "<keyframe><key name='tilted'/></keyframe></mujoco>"),
                  "a second key named 'tilted' (the first is at line 8)"));
  // A file of another format has none to ask for.
  EXPECT_THROW(
      {
        try {
          read_model_file(test::source_dir() + "/examples/pendulum.yaml").keyframe("a");
        } catch (const InvalidArgument& e) {
          EXPECT_TRUE(has(e.what(), "examples/pendulum.yaml has no keyframes"));
          throw;
        }
      },
      InvalidArgument);
}

// The contacts MuJoCo would find against the world's planes, as momenta's rigid ones: a sphere
// as itself, a capsule as its end spheres, a cylinder as its faces' rims, a box as its eight
// corners (points), on a tilted plane
// through a point; MuJoCo's contype/conaffinity filter, its friction (the larger,
// or the higher priority's; condim 1 frictionless); a body welded to the world and one excluded
// from it have none; the shapes momenta does not pose (an ellipsoid) and condim 6's extra
// friction noted.
TEST(MjcfFile, GeomsTouchTheWorldsPlanes) {
  const std::string text = R"(<mujoco>
<compiler angle="radian"/>
<worldbody>
<geom name="slope" type="plane" size="1 1 0.1" pos="0 0 -1" euler="0.3 0 0" friction="0.5"/>
<geom name="post" type="box" size="0.1 0.1 0.1" pos="3 0 0"/>
<body name="base"><geom name="plinth" type="sphere" size="0.2"/>
<body name="arm" pos="0 0 1"><joint name="j1" axis="0 1 0"/>
<geom name="ball" type="sphere" size="0.1" pos="0.5 0 0" friction="0.7" condim="6"/>
<geom name="rod" type="capsule" fromto="0 0 0 0 0 -0.4" size="0.05" condim="1" priority="2"/>
<geom name="drum" type="cylinder" size="0.2 0.1" pos="0 1 0" priority="1" friction="0.2"/>
<geom name="brick" type="box" size="0.1 0.2 0.3" pos="1 0 0" euler="0 0 0.5"/>
<geom name="egg" type="ellipsoid" size="0.1 0.2 0.3"/>
<geom name="ghost" type="sphere" size="0.1" contype="0" conaffinity="0"/>
<geom name="other" type="sphere" size="0.1" contype="2" conaffinity="2"/>
</body>
<body name="tail" pos="0 0 2"><joint name="j2"/><geom type="sphere" size="0.1"/></body>
</body>
</worldbody>
<contact><exclude body1="world" body2="tail"/><pair geom1="ball" geom2="rod"/></contact>
</mujoco>)";
  const ModelFile f = parse_mjcf(text, "m.xml");
  std::vector<std::string> names;
  for (const model::Constraint& c : f.model.constraints())
    names.push_back(model::constraint_name(c));
  std::vector<std::string> expected_names{"ball_slope", "rod_end1_slope", "rod_end2_slope",
                                          "drum_rim1_slope", "drum_rim2_slope"};
  for (int k = 1; k <= 8; ++k) expected_names.push_back(fmt::format("brick_corner{}_slope", k));
  EXPECT_EQ(names, expected_names);
  const auto contact = [&](std::size_t k) -> const model::Contact& {
    return std::get<model::Contact>(f.model.constraints()[k]);
  };
  // The plane: its frame's z through its pos, the geom's euler (x by 0.3 rad).
  const Vec3 n(0.0, -std::sin(0.3), std::cos(0.3));
  for (std::size_t k = 0; k < names.size(); ++k) {
    EXPECT_MATRIX_NEAR(contact(k).plane_normal, n, 1e-16);
    EXPECT_MATRIX_NEAR(contact(k).plane_point, Vec3(0, 0, -1), 0.0);
    EXPECT_TRUE(contact(k).on_ground());
    EXPECT_EQ(contact(k).restitution, 0.0);
    EXPECT_EQ(contact(k).frame.body, "arm");
  }
  EXPECT_EQ(contact(0).shape, model::ContactShape::sphere);
  EXPECT_EQ(contact(0).radius, 0.1);
  EXPECT_MATRIX_NEAR(contact(0).frame.X_BF.p, Vec3(0.5, 0, 0), 0.0);
  EXPECT_EQ(contact(0).static_friction, 0.7);  // the larger of 0.7 and the plane's 0.5
  EXPECT_EQ(contact(0).kinetic_friction, 0.7);
  // The capsule's ends, from and to; condim 1 (its priority's): frictionless.
  EXPECT_EQ(contact(1).radius, 0.05);
  EXPECT_MATRIX_NEAR(contact(1).frame.X_BF.p, Vec3(0, 0, 0), 1e-16);
  EXPECT_MATRIX_NEAR(contact(2).frame.X_BF.p, Vec3(0, 0, -0.4), 1e-16);
  EXPECT_EQ(contact(1).static_friction, 0.0);
  // The cylinder's rims about its axis (z), at ±its half-length; its priority gives 0.2.
  EXPECT_EQ(contact(3).shape, model::ContactShape::disk);
  EXPECT_EQ(contact(3).radius, 0.2);
  EXPECT_MATRIX_NEAR(contact(3).frame.X_BF.p, Vec3(0, 1, -0.1), 1e-16);
  EXPECT_MATRIX_NEAR(contact(4).frame.X_BF.p, Vec3(0, 1, 0.1), 1e-16);
  EXPECT_MATRIX_NEAR(Vec3(contact(4).frame.X_BF.R.col(2)), Vec3::UnitZ(), 1e-16);
  EXPECT_EQ(contact(3).static_friction, 0.2);
  // The box's corners: (±0.1, ±0.2, ±0.3) turned 0.5 rad about z, at (1, 0, 0) — x's sign first,
  // then y's, then z's; points (radius 0), with MuJoCo's default friction 1 (the larger).
  const Mat3 R = Eigen::AngleAxisd(0.5, Vec3::UnitZ()).toRotationMatrix();
  for (int k = 0; k < 8; ++k) {
    const model::Contact& corner = contact(5 + static_cast<std::size_t>(k));
    const Vec3 p_GC((k & 1) ? 0.1 : -0.1, (k & 2) ? 0.2 : -0.2, (k & 4) ? 0.3 : -0.3);
    EXPECT_MATRIX_NEAR(corner.frame.X_BF.p, Vec3(Vec3(1, 0, 0) + R * p_GC), 1e-15) << k;
    EXPECT_EQ(corner.shape, model::ContactShape::sphere);
    EXPECT_EQ(corner.radius, 0.0);
    EXPECT_EQ(corner.static_friction, 1.0);
  }
  // What is not posed, at its line; the <contact> elements.
  const std::vector<std::string> expected_notes = {
      "m.xml:5: <geom name=\"post\"> in the world (a box): contacts are with the world's planes "
      "only",
      "m.xml:8: geom 'ball' on plane <geom name=\"slope\">: condim 6 — its torsional and rolling "
      "friction is not modelled",
      "m.xml:12: geom 'egg' (an ellipsoid) passes through plane <geom name=\"slope\">",
      "m.xml:19: <pair> of <contact>: not used"};
  for (const std::string& expected : expected_notes) {
    EXPECT_TRUE(std::any_of(f.notes.begin(), f.notes.end(), [&](const std::string& note) {
      return note.find(expected) != std::string::npos;
    })) << expected;
  }
  // Contacts disabled: none, and a note says so.
  std::string disabled = text;
  disabled.replace(disabled.find("<worldbody>"), 11,
                   "<option><flag contact=\"disable\"/></option><worldbody>");
  const ModelFile off = parse_mjcf(disabled, "m.xml");
  EXPECT_TRUE(off.model.constraints().empty());
  EXPECT_TRUE(std::any_of(off.notes.begin(), off.notes.end(), [](const std::string& note) {
    return note.find("contacts are disabled") != std::string::npos;
  }));
  // An exclude naming an unknown body is an error at its line.
  std::string unknown = text;
  unknown.replace(unknown.find("body2=\"tail\""), 12, "body2=\"tale\"");
  const std::string error = error_of(unknown);
  EXPECT_NE(error.find("m.xml:19:"), std::string::npos) << error;
  EXPECT_NE(error.find("unknown body 'tale'"), std::string::npos) << error;
}

// Mesh geoms: each mesh in its file's coordinates, placed by the geom and weighed as the solid it
// bounds — the cube scaled per axis against the box's closed form (±0.5 is exact in the binary
// STL's floats: 1e-15), the prism against the regular hexagonal prism (its corners rounded to
// single precision in the file: 1e-7), the wedge by the geom's mass.
TEST(MjcfFile, MeshGeomsWeighAsTheirSolids) {
  const ModelFile arm = read_mjcf_file(mjcf_path("mesh_arm"));
  const auto body = [&](const std::string& name) {
    return arm.model.bodies()[static_cast<std::size_t>(arm.model.body_index(name))].mass_properties;
  };
  const inertia::MassProperties cube =
      inertia::box(inertia::Amount::density(2700), Vec3(0.3, 0.06, 0.06))
          .transformed(Mat3::Identity(), Vec3(0.15, 0, 0));
  EXPECT_NEAR(body("fore").mass(), cube.mass(), 1e-15 * cube.mass());
  EXPECT_MATRIX_NEAR(body("fore").inertia_about_com(), cube.inertia_about_com(), 1e-15 * 0.03);
  const double r = 0.04, l = 0.375, prism = 2700 * 1.5 * std::sqrt(3.0) * r * r * l;
  EXPECT_NEAR(body("upper").mass(), prism, 1e-7 * prism);
  EXPECT_NEAR(body("upper").inertia_about_com()(0, 0), prism * 5 * r * r / 12, 1e-7 * 0.003);
  EXPECT_MATRIX_NEAR(body("upper").center_of_mass(), Vec3(0.1875, 0, 0), 1e-9);
  // The wedge's 0.4 kg beside a water sphere of radius 2 cm.
  EXPECT_NEAR(body("hand").mass(), 0.4 + 1000 * 4.0 / 3.0 * std::numbers::pi * 8e-6, 1e-15);
  // Drawn as meshes in the body frame; the note says what MuJoCo's default would do otherwise.
  const std::span<const PartSummary> hand = arm.parts_of(arm.model.body_index("hand"));
  ASSERT_EQ(hand.size(), 2u);
  EXPECT_EQ(hand[0].kind, "mesh");
  EXPECT_EQ(hand[0].mesh->triangles.size(), 8u);
  EXPECT_EQ(arm.notes.size(), 1u);  // the <material> asset; exactmeshinertia is set
  const std::string unset = R"(<mujoco><asset><mesh file="box.stl"/></asset><worldbody>
<body><joint type="hinge"/><geom type="mesh" mesh="box"/></body></worldbody></mujoco>)";
  const ModelFile f = parse_mjcf(unset, "m.xml",
                                 test::source_dir() +
                                     "/tests/data/models/urdf/packages/mesh_arm/"
                                     "meshes");
  ASSERT_EQ(f.notes.size(), 1u);
  EXPECT_NE(f.notes[0].find("m.xml:2: mesh geoms are weighed as the solids they bound; MuJoCo 2.2 "
                            "does so with <compiler exactmeshinertia=\"true\">"),
            std::string::npos)
      << f.notes[0];
  EXPECT_NEAR(f.model.bodies()[1].mass_properties.mass(), 1000.0, 1e-12);
}

TEST(MjcfFile, MeshErrorsAreAtTheirLine) {
  const auto error = [](const std::string& asset, const std::string& geom) {
    try {
      parse_mjcf("<mujoco>\n<asset>" + asset + "</asset>\n<worldbody>\n<body><joint/>" + geom +
                     "</body>\n</worldbody>\n</mujoco>",
                 "m.xml", test::source_dir() + "/tests/data/models/urdf/packages/mesh_arm/meshes");
    } catch (const ParseError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string box = "<mesh name='box' file='box.stl'/>";
  EXPECT_EQ(error(box, "<geom type='mesh' mesh='bx'/>"),
            "m.xml:4:33: unknown mesh 'bx' (did you mean 'box'?)");
  EXPECT_EQ(error(box, "<geom type='mesh'/>"),
            "m.xml:4:15: a geom of body 'body1' is a mesh and names none (mesh=\"...\")");
  EXPECT_EQ(error(box, "<geom type='mesh' mesh='box' fromto='0 0 0 1 0 0'/>"),
            "m.xml:4:44: a geom of body 'body1' is a mesh: fromto gives the axis of a capsule, "
            "cylinder, box or ellipsoid (as MuJoCo requires)");
  EXPECT_EQ(error(box + "\n" + box, ""),
            "m.xml:3:7: a second mesh named 'box' (the first is at line 2)");
  EXPECT_EQ(error("<mesh vertex='0 0 0 1 0 0 0 1 0 0 0 1'/>", ""),
            "m.xml:2:14: <mesh vertex=...>: momenta reads meshes from files (STL, OBJ)");
  EXPECT_EQ(error("<mesh file='box.stl' refpos='0 0 1'/>", ""),
            "m.xml:2:29: <mesh refpos>: momenta reads a mesh in the coordinates of its file");
  const std::string missing =
      error("<mesh file='nothing.stl'/>", "<geom type='mesh' mesh='nothing'/>");
  EXPECT_NE(missing.find("m.xml:2:14: mesh 'nothing': "), std::string::npos) << missing;
  EXPECT_NE(missing.find("nothing.stl: mesh file not found"), std::string::npos) << missing;
  EXPECT_EQ(error("<mesh file='box.stl' scale='1 0 1'/>", "<geom type='mesh' mesh='box'/>"),
            "m.xml:2:29: the scale of mesh 'box' has a zero factor");
}

// A mesh that only draws — its body has an <inertial> — may be missing: the file loads, the mesh
// is a note at its geom's line and is not drawn. Where the mesh gives the body its mass it stays
// an error (MeshErrorsAreAtTheirLine).
TEST(MjcfFile, AMissingMeshThatOnlyDrawsIsANote) {
  const ModelFile f = parse_mjcf(R"(<mujoco><asset><mesh file="gone.stl"/></asset><worldbody>
<body><joint type="hinge"/><inertial pos="0 0 0" mass="2" diaginertia="1 1 1"/>
<geom name="shell" type="mesh" mesh="gone"/><geom type="sphere" size="0.1"/></body>
</worldbody></mujoco>)",
                                 "m.xml", test::source_dir());
  EXPECT_EQ(f.model.total_mass(), 2.0);
  ASSERT_EQ(f.notes.size(), 1u);
  EXPECT_NE(f.notes[0].find("m.xml:3: not drawn: geom 'shell': mesh 'gone', file "),
            std::string::npos)
      << f.notes[0];
  EXPECT_NE(f.notes[0].find("gone.stl not found"), std::string::npos) << f.notes[0];
  ASSERT_EQ(f.parts_of(1).size(), 1u);  // the sphere alone
  EXPECT_EQ(f.parts_of(1)[0].kind, "sphere");
}

}  // namespace
}  // namespace momenta::io::mjcf_test
