#include "momenta/io/model_file.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <variant>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta/model/units.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::io {
namespace {

constexpr double kPi = std::numbers::pi;

std::filesystem::path scratch_dir() {
  const auto dir = std::filesystem::temp_directory_path() / "momenta_model_file_test";
  std::filesystem::create_directories(dir);
  return dir;
}

ModelFile parse(const std::string& yaml) { return parse_model_file(yaml, "m.yaml", scratch_dir()); }

// The message of the error `yaml` raises (ParseError, or FileError for a missing file), checked to
// be one line; a failure if it parses.
template <class E = ParseError>
std::string error_of(const std::string& yaml) {
  try {
    parse(yaml);
  } catch (const E& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    return message;
  }
  ADD_FAILURE() << "no error for:\n" << yaml;
  return "";
}

// A message starts with `file:line:` and contains `text`.
#define EXPECT_ERROR_AT(message, prefix, text)                                       \
  do {                                                                               \
    const std::string m_ = (message);                                                \
    EXPECT_EQ(m_.rfind(prefix, 0), 0u) << m_;                                        \
    EXPECT_NE(m_.find(text), std::string::npos) << "no '" << text << "' in: " << m_; \
  } while (0)

// A one-body pendulum the error tests edit: line numbers below count from "name:" = line 1.
const std::string kPendulum = R"(name: p
bodies:
  - name: bob
    mass: 1.0
    com: [0, 0, -1]
joints:
  - name: pivot
    type: revolute
    parent: world
    child: bob
    axis: [0, 1, 0]
)";

// --- examples --------------------------------------------------------------------------------

struct Example {
  const char* file;
  int nq;
  int nv;
  double total_mass;  // kg, the sum of the masses in the file's comments
};

class ExampleTest : public ::testing::TestWithParam<Example> {};

TEST_P(ExampleTest, LoadsAndBuildsWithItsDegreesOfFreedomAndMass) {
  const Example& e = GetParam();
  const ModelFile file = read_model_file(test::source_dir() + "/examples/" + e.file);
  EXPECT_EQ(file.model.nq(), e.nq);
  EXPECT_EQ(file.model.nv(), e.nv);
  // Masses are sums of a few decimal numbers: a relative 1e-14 is round-off.
  EXPECT_REL_NEAR(file.model.total_mass(), e.total_mass, 1e-14);
  EXPECT_FALSE(file.outputs.empty());
  EXPECT_TRUE(file.simulation.duration.has_value());
  EXPECT_TRUE(file.simulation.step.has_value());
  EXPECT_TRUE(file.simulation.integrator.has_value());
  EXPECT_FALSE(file.description.empty());
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleTest,
                         ::testing::Values(Example{"cruise_control.yaml", 1, 1, 1000.0},
                                           Example{"quarter_car.yaml", 3, 3, 396.0},
                                           Example{"satellite_attitude.yaml", 1, 1, 1000.0},
                                           Example{"flexible_satellite.yaml", 2, 2, 110.0},
                                           Example{"pendulum.yaml", 1, 1, 1.0},
                                           Example{"compound_pendulum.yaml", 1, 1, 2.0},
                                           Example{"double_pendulum.yaml", 2, 2, 2.0},
                                           Example{"free_body_tennis_racket.yaml", 7, 6, 1.0},
                                           Example{"heavy_top.yaml", 4, 3, 1.0},
                                           Example{"gyroscope.yaml", 5, 4, 0.55},
                                           Example{"rotating_shaft_bent_rod.yaml", 1, 1, 3.0},
                                           Example{"unbalanced_rotor.yaml", 1, 1, 5.5}),
                         [](const auto& param_info) {
                           std::string name = param_info.param.file;
                           return name.substr(0, name.find('.'));
                         });

// The physical parameters of examples that other tests validate, as the model holds them.
TEST(ModelFileExamples, QuarterCarHoldsFranklinsParameters) {
  const ModelFile file = read_model_file(test::source_dir() + "/examples/quarter_car.yaml");
  const model::Model& m = file.model;
  EXPECT_EQ(m.gravity(), Vec3::Zero());
  EXPECT_EQ(m.body(m.body_index("wheel")).mass_properties.mass(), 20.0);
  EXPECT_EQ(m.body(m.body_index("body")).mass_properties.mass(), 375.0);
  const auto& tyre = std::get<model::LinearSpringDamper>(m.force_elements()[0]);
  const auto& suspension = std::get<model::LinearSpringDamper>(m.force_elements()[1]);
  EXPECT_EQ(tyre.stiffness, 1e6);
  EXPECT_EQ(suspension.stiffness, 130000.0);
  EXPECT_EQ(suspension.damping, 9800.0);
  EXPECT_TRUE(m.joint(m.joint_index("road")).is_prescribed());
  EXPECT_EQ(std::get<model::StepSignal>(m.signals()[0].shape()).rise_time, 0.01);
}

TEST(ModelFileExamples, HeavyTopStartsTiltedTwentyDegrees) {
  const ModelFile file = read_model_file(test::source_dir() + "/examples/heavy_top.yaml");
  // q0 from Euler ZXZ (0, 20°, 0) is a rotation of 20° about x: [cos 10°, sin 10°, 0, 0].
  const VecX& q = file.model.initial_q();
  const double h = 10.0 * kPi / 180.0;
  EXPECT_NEAR(q[0], std::cos(h), 1e-15);
  EXPECT_NEAR(q[1], std::sin(h), 1e-15);
  EXPECT_NEAR(q[2], 0.0, 1e-15);
  EXPECT_NEAR(q[3], 0.0, 1e-15);
  // The cone's centre of mass three quarters of the way from the apex (Beer & Johnston table).
  EXPECT_MATRIX_NEAR(file.model.body(1).mass_properties.center_of_mass(), Vec3(0, 0, 0.075), 1e-16);
}

// --- bodies: shape, part, explicit, degrees ---------------------------------------------------

TEST(ModelFileBodies, ShapeEqualsThePrimitivePlacedByItsPose) {
  const ModelFile file = parse(R"(
bodies:
  - {name: drum, shape: cylinder, mass: 3, radius: 0.2, length: 0.5, position: [0.1, 0, 0],
     euler: {sequence: XYZ, angles_deg: [0, 90, 0]}}
joints:
  - {name: j, type: revolute, parent: world, child: drum, axis: [0, 0, 1]}
)");
  const Mat3 R = rotation_from_euler("XYZ", Vec3(0, kPi / 2, 0));
  const inertia::MassProperties expected =
      inertia::solid_cylinder(inertia::Amount::mass(3), 0.2, 0.5).transformed(R, Vec3(0.1, 0, 0));
  const inertia::MassProperties& got = file.model.body(1).mass_properties;
  // The same primitive and the same rotation: identical to round-off of the transform.
  EXPECT_REL_NEAR(got.mass(), expected.mass(), 1e-15);
  EXPECT_MATRIX_NEAR(got.center_of_mass(), expected.center_of_mass(), 1e-16);
  EXPECT_MATRIX_NEAR(got.inertia_about_com(), expected.inertia_about_com(), 1e-16);
}

TEST(ModelFileBodies, ExplicitInertiaAndMasslessBodies) {
  const ModelFile file = parse(R"(
bodies:
  - {name: link, mass: 0}
  - name: tip
    mass: 2
    com: [0, 0, -0.5]
    inertia: [[0.3, 0.01, 0], [0.01, 0.2, 0], [0, 0, 0.4]]
joints:
  - {name: a, type: revolute, parent: world, child: link, axis: [0, 1, 0]}
  - {name: b, type: fixed, parent: link, child: tip}
)");
  EXPECT_EQ(file.model.body_index("link"), 1);
  EXPECT_EQ(file.model.body(1).mass_properties.mass(), 0.0);
  const auto& tip = file.model.body(2).mass_properties;
  EXPECT_EQ(tip.mass(), 2.0);
  EXPECT_EQ(tip.center_of_mass(), Vec3(0, 0, -0.5));
  EXPECT_EQ(tip.inertia_about_com()(0, 1), 0.01);
  EXPECT_EQ(tip.inertia_about_com()(2, 2), 0.4);
}

TEST(ModelFileBodies, InertiaAboutAPointMovesToTheCentreOfMass) {
  // A top given as textbooks give it: m = 2 kg, centre of mass l = 0.3 m above the pivot, I1 about
  // the pivot 0.25 kg·m², I3 0.1 kg·m². About the centre of mass I1 − m l² = 0.07 kg·m².
  const ModelFile file = parse(R"(
bodies:
  - {name: top, mass: 2, com: [0, 0, 0.3], inertia: [0.25, 0.25, 0.1], inertia_about: [0, 0, 0]}
joints:
  - {name: pivot, type: spherical, parent: world, child: top}
)");
  const auto& top = file.model.body(1).mass_properties;
  EXPECT_MATRIX_NEAR(top.inertia_about_com(), Vec3(0.07, 0.07, 0.1).asDiagonal().toDenseMatrix(),
                     1e-15);
  // Moved back to the pivot, it is what the file gave.
  EXPECT_MATRIX_NEAR(top.inertia_about(Vec3::Zero()),
                     Vec3(0.25, 0.25, 0.1).asDiagonal().toDenseMatrix(), 1e-15);
}

TEST(ModelFileErrors, InertiaAboutAPointThatImpliesNoBody) {
  // I1 about the pivot smaller than m l²: about the centre of mass it would be negative.
  EXPECT_ERROR_AT(error_of(R"(bodies:
  - {name: top, mass: 2, com: [0, 0, 0.3], inertia: [0.1, 0.1, 0.1], inertia_about: [0, 0, 0]}
joints:
  - {name: pivot, type: spherical, parent: world, child: top}
)"),
                  "m.yaml:2:53: bodies[0].inertia: ", "parallel-axis theorem");
  EXPECT_ERROR_AT(error_of(R"(bodies:
  - {name: top, mass: 2, inertia_about: [0, 0, 0]}
joints:
  - {name: pivot, type: spherical, parent: world, child: top}
)"),
                  "m.yaml:2:41: bodies[0].inertia_about: ", "needs an 'inertia'");
}

TEST(ModelFileBodies, MasslessTurntableOnAPrescribedJoint) {
  // A driven turntable carries a bead on a slot: the table's motion is given, so it needs no mass.
  const ModelFile file = parse(R"(
inputs:
  - {name: spin, type: ramp, slope: 2}
bodies:
  - {name: table, mass: 0}
  - {name: bead, mass: 0.1}
joints:
  - {name: drive, type: revolute, parent: world, child: table, axis: [0, 0, 1], prescribed: spin}
  - {name: slot, type: prismatic, parent: table, child: bead, axis: [1, 0, 0]}
)");
  EXPECT_EQ(file.model.nv(), 2);
  EXPECT_EQ(file.model.body(1).mass_properties.mass(), 0.0);
}

// A ball joint is prescribed by its rotation vector (three signals), a free joint by six; the
// count is checked at the key with what the signals stand for.
TEST(ModelFileJoints, BallAndFreeJointsArePrescribedByRotationVectors) {
  const ModelFile file = parse(R"(
inputs:
  - {name: zero, type: constant, value: 0}
  - {name: spin, type: ramp, slope: 3}
bodies:
  - {name: table, mass: 1}
joints:
  - {name: ball, type: ball, parent: world, child: table, prescribed: [zero, zero, spin]}
)");
  EXPECT_TRUE(file.model.joint(0).is_prescribed());
  EXPECT_ERROR_AT(error_of(R"(
inputs:
  - {name: spin, type: ramp, slope: 3}
bodies:
  - {name: table, mass: 1}
joints:
  - {name: ball, type: free, parent: world, child: table, prescribed: [spin, spin, spin]}
)"),
                  "m.yaml:7:", "3 signals given; a free joint needs 6 (its rotation vector");
}

TEST(ModelFileBodies, PartFileIsReadRelativeToTheModel) {
  const auto dir = scratch_dir();
  std::ofstream(dir / "ball.yaml") << "parts:\n  - {shape: sphere, radius: 0.1, mass: 4}\n";
  const ModelFile file = parse(R"(
bodies:
  - {name: ball, part: ball.yaml, position: [0, 0, 1]}
joints:
  - {name: j, type: free, parent: world, child: ball}
)");
  const auto& mp = file.model.body(1).mass_properties;
  EXPECT_EQ(mp.mass(), 4.0);
  EXPECT_EQ(mp.center_of_mass(), Vec3(0, 0, 1));
  // Solid sphere: (2/5) m r² (Beer & Johnston).
  EXPECT_REL_NEAR(mp.inertia_about_com()(0, 0), 0.4 * 4 * 0.01, 1e-15);
}

TEST(ModelFileJoints, DegreesConvertWhereAKeySaysSo) {
  const ModelFile file = parse(R"(
inputs:
  - {name: s, type: sine, amplitude: 1, frequency: 2, phase_deg: 90}
bodies:
  - {name: a, mass: 1, com: [1, 0, 0]}
  - {name: b, mass: 1, com: [1, 0, 0], inertia: [0.1, 0.1, 0.1]}
joints:
  - {name: hinge, type: revolute, parent: world, child: a, q0_deg: 120, v0_deg: -30}
  - name: ball
    type: spherical
    parent: a
    child: b
    in_parent: {euler: {sequence: ZYX, angles_deg: [90, 0, 0]}}
    v0_deg: [180, 0, 0]
forces:
  - {name: k, type: torsional_spring, joint: hinge, stiffness: 1, rest_angle_deg: 45}
)");
  const model::Model& m = file.model;
  EXPECT_NEAR(m.initial_q()[0], 2 * kPi / 3, 1e-15);
  EXPECT_NEAR(m.initial_v()[0], -kPi / 6, 1e-15);
  EXPECT_NEAR(m.initial_v()[1], kPi, 1e-15);
  EXPECT_NEAR(std::get<model::SineSignal>(m.signals()[0].shape()).phase, kPi / 2, 1e-15);
  EXPECT_NEAR(std::get<model::TorsionalSpringDamper>(m.force_elements()[0]).rest_angle, kPi / 4,
              1e-15);
  // 90° about z: x → y.
  EXPECT_MATRIX_NEAR(m.joint(1).X_PJ.R * Vec3::UnitX(), Vec3::UnitY(), 1e-15);
}

TEST(ModelFileJoints, NearUnitAxesAreNormalized) {
  const ModelFile file = parse(R"(
bodies:
  - {name: a, mass: 1, com: [1, 0, 0]}
joints:
  - {name: j, type: revolute, parent: world, child: a, axis: [0, 0.7071068, 0.7071068]}
)");
  EXPECT_NEAR(file.model.joint(0).axis.norm(), 1.0, 1e-15);
}

// --- inputs ----------------------------------------------------------------------------------

TEST(ModelFileSignals, TableFromCsvMatchesTheFile) {
  std::ofstream(scratch_dir() / "road.csv") << "time,height\n# comment\n0, 0\n1, 0.1\n\n2, 0.05\n";
  const ModelFile file = parse(kPendulum + R"(inputs:
  - {name: road, type: table, csv: road.csv}
)");
  const auto& table = std::get<model::TableSignal>(file.model.signals()[0].shape());
  EXPECT_EQ(table.times, (std::vector<double>{0, 1, 2}));
  EXPECT_EQ(table.values, (std::vector<double>{0, 0.1, 0.05}));
  EXPECT_DOUBLE_EQ(file.model.signals()[0].value(1.5), 0.075);
}

// --- outputs and simulation settings ---------------------------------------------------------

TEST(ModelFileOutputs, SpecsCarryTargetQuantityComponentAndFrame) {
  const ModelFile file = parse(kPendulum + R"(outputs:
  - {body: bob, quantity: position, point: [0, 0, -1], component: z}
  - {name: rx, joint: pivot, quantity: reaction_force, frame: child, component: x}
  - {joint: pivot, quantity: velocity, component: 0}
simulation: {duration: 2, step: 0.01, integrator: dopri5, rtol: 1e-8, atol: 1e-10, every: 10}
)");
  ASSERT_EQ(file.outputs.size(), 3u);
  EXPECT_EQ(file.outputs[0].name, "bob.position");
  EXPECT_EQ(file.outputs[0].quantity, model::OutputQuantity::body_position);
  EXPECT_EQ(file.outputs[0].point, Vec3(0, 0, -1));
  EXPECT_EQ(file.outputs[0].component, 2);
  EXPECT_EQ(file.outputs[1].name, "rx");
  EXPECT_EQ(file.outputs[1].quantity, model::OutputQuantity::reaction_force);
  EXPECT_EQ(file.outputs[1].frame, model::ReactionFrame::child);
  EXPECT_EQ(file.outputs[2].quantity, model::OutputQuantity::joint_velocity);
  EXPECT_EQ(*file.simulation.integrator, "dopri5");
  EXPECT_EQ(*file.simulation.every, 10);
  EXPECT_EQ(*file.simulation.absolute_tolerance, 1e-10);
}

// A tendon: its joints with their coefficients (1 unless given), its offset, spring and damper;
// its length and tension as outputs, in its first joint's units. Errors at the key.
TEST(ModelFileForces, TendonsListTheirJointsAndCoefficients) {
  const ModelFile file =
      read_model_file(test::source_dir() + "/tests/data/models/tendon_pendulum.yaml");
  const auto& elements = file.model.force_elements();
  ASSERT_EQ(elements.size(), 2u);
  const auto& cord = std::get<model::FixedTendon>(elements[0]);
  ASSERT_EQ(cord.terms.size(), 3u);
  EXPECT_EQ(cord.terms[2].joint, "slide");
  EXPECT_EQ(cord.terms[2].coefficient, 2.0);
  EXPECT_EQ(cord.terms[1].coefficient, -0.5);
  EXPECT_EQ(cord.offset, 0.05);
  EXPECT_EQ(cord.stiffness, 4.0);
  EXPECT_EQ(cord.damping, 0.3);
  EXPECT_EQ(cord.rest_length, 0.1);
  const auto& absolute = std::get<model::FixedTendon>(elements[1]);
  EXPECT_EQ(absolute.terms[1].coefficient, 1.0);
  ASSERT_EQ(file.outputs.size(), 3u);
  EXPECT_EQ(file.outputs[0].quantity, model::OutputQuantity::spring_length);
  EXPECT_EQ(file.outputs[1].quantity, model::OutputQuantity::spring_tension);
  EXPECT_EQ(file.outputs[2].target, "absolute");
  EXPECT_EQ(model::output_unit(file.model, model::OutputQuantity::spring_length, 0, 0), "rad");
  EXPECT_EQ(model::output_unit(file.model, model::OutputQuantity::spring_tension, 0, 0), "N·m");

  const std::string tendon = kPendulum + "forces:\n  - {name: t, type: tendon, joints: ";
  EXPECT_ERROR_AT(error_of(tendon + "[]}\n"), "m.yaml:13:", "at least one");
  EXPECT_ERROR_AT(error_of(tendon + "[{joint: pivot}, {joint: pivot}]}\n"),
                  "m.yaml:13:", "joint 'pivot' is listed twice");
  EXPECT_ERROR_AT(error_of(tendon + "[{joint: pivot, coefficient: 0}]}\n"),
                  "m.yaml:13:", "a coefficient of 0: leave the joint out");
  EXPECT_ERROR_AT(error_of(tendon + "[{joint: pivt}]}\n"), "m.yaml:13:", "did you mean 'pivot'");
  EXPECT_ERROR_AT(error_of(tendon + "[{joint: pivot}], stiffness: -1}\n"),
                  "m.yaml:13:", "stiffness");
  EXPECT_ERROR_AT(error_of(tendon + "[{joint: pivot}]}\noutputs:\n  - {tendon: t, quantity: "
                                    "spring_length}\n"),
                  "m.yaml:15:", "'spring_length' is not a quantity of a tendon");
}

TEST(ModelFileOutputs, EulerAnglesTakeASequenceAndNumberedComponents) {
  const ModelFile file = parse(kPendulum + R"(outputs:
  - {body: bob, quantity: euler_angles}
  - {name: yaw_rate, body: bob, quantity: euler_rates, sequence: zyx, component: 0}
)");
  ASSERT_EQ(file.outputs.size(), 2u);
  EXPECT_EQ(file.outputs[0].name, "bob.euler_angles");
  EXPECT_EQ(file.outputs[0].quantity, model::OutputQuantity::body_euler_angles);
  EXPECT_EQ(file.outputs[0].sequence, "ZXZ");  // the default: precession, nutation, spin
  EXPECT_EQ(file.outputs[1].quantity, model::OutputQuantity::body_euler_rates);
  EXPECT_EQ(file.outputs[1].sequence, "zyx");
  EXPECT_EQ(file.outputs[1].component, 0);
  EXPECT_ERROR_AT(
      error_of(kPendulum + "outputs:\n  - {body: bob, quantity: euler_angles, sequence: ZZX}\n"),
      "m.yaml:13:51: outputs[0].sequence: ", "Euler sequence 'ZZX' is not one of the 12");
  EXPECT_ERROR_AT(
      error_of(kPendulum + "outputs:\n  - {body: bob, quantity: position, sequence: ZYX}\n"),
      "m.yaml:13:", "only euler_angles and euler_rates take a 'sequence'");
  EXPECT_ERROR_AT(
      error_of(kPendulum + "outputs:\n  - {body: bob, quantity: euler_rates, component: 3}\n"),
      "m.yaml:13:", "component 3 of the Euler angles must be 0, 1 or 2");
}

// --- the live page's numbers ------------------------------------------------------------------

TEST(ModelFileLive, ListsPathsInOrderWithTheirRanges) {
  const ModelFile file = parse(kPendulum + R"(    damping: 0.2
live:
  - joints.pivot.damping
  - {path: bodies.bob.mass, min: 0.5, max: 4}
  - {path: bodies.0.com.2, max: 0}
)");
  ASSERT_EQ(file.live_numbers.size(), 3u);
  EXPECT_EQ(file.live_numbers[0].path, "joints.pivot.damping");
  EXPECT_FALSE(file.live_numbers[0].min || file.live_numbers[0].max);
  EXPECT_EQ(file.live_numbers[0].line, 14);
  EXPECT_EQ(file.live_numbers[1].path, "bodies.bob.mass");
  EXPECT_EQ(file.live_numbers[1].min, 0.5);
  EXPECT_EQ(file.live_numbers[1].max, 4.0);
  EXPECT_EQ(file.live_numbers[2].path, "bodies.0.com.2");
  EXPECT_FALSE(file.live_numbers[2].min);
  EXPECT_EQ(file.live_numbers[2].max, 0.0);
  EXPECT_TRUE(parse(kPendulum).live_numbers.empty());
}

TEST(ModelFileErrors, LiveNumbersThatAreNoNumbersOfTheFile) {
  EXPECT_ERROR_AT(error_of(kPendulum + "live:\n  - bodies.bobb.mass\n"),
                  "m.yaml:13:5:", "did you mean 'bob'?");
  EXPECT_ERROR_AT(error_of(kPendulum + "live:\n  - joints.pivot.damping\n"),
                  "m.yaml:13:5:", "names no number this file writes");
  EXPECT_ERROR_AT(error_of(kPendulum + "live:\n  - joints.pivot.type\n"),
                  "m.yaml:13:5:", "something other than a number");
  EXPECT_ERROR_AT(error_of(kPendulum + "live:\n  - {path: bodies.bob.mass, min: 2, max: 1}\n"),
                  "m.yaml:13:5:", "min 2 must be less than max 1");
  EXPECT_ERROR_AT(error_of(kPendulum + "live:\n  - bodies.bob.mass\n  - bodies.bob.mass\n"),
                  "m.yaml:14:5:", "listed twice (line 13)");
  EXPECT_ERROR_AT(error_of(kPendulum + "live:\n  - {path: bodies.bob.mass, mn: 2}\n"),
                  "m.yaml:13:", "did you mean 'min'?");
  EXPECT_ERROR_AT(error_of(kPendulum + "live: bodies.bob.mass\n"),
                  "m.yaml:12:7:", "a list of the numbers the live report offers to change");
}

// --- errors: every class at its file:line ----------------------------------------------------

TEST(ModelFileErrors, MalformedYaml) {
  EXPECT_ERROR_AT(error_of("bodies:\n  - {name: a, mass: 1\n"), "m.yaml:", "malformed YAML");
}

TEST(ModelFileErrors, UnknownKeyWithSuggestion) {
  std::string yaml = kPendulum;
  yaml.replace(yaml.find("    axis:"), 9, "    axes:");
  EXPECT_ERROR_AT(error_of(yaml),
                  "m.yaml:11:5: joints[0]: ", "unknown key 'axes' (did you mean 'axis'?)");
  EXPECT_ERROR_AT(error_of("gravty: [0, 0, 0]\n" + kPendulum),
                  "m.yaml:1:1:", "did you mean 'gravity'?");
}

TEST(ModelFileErrors, UnknownBodyWithSuggestionAtTheReference) {
  std::string yaml = kPendulum;
  yaml.replace(yaml.find("child: bob"), 10, "child: bop");
  EXPECT_ERROR_AT(error_of(yaml),
                  "m.yaml:10:12: joints[0].child: ", "unknown body 'bop' (did you mean 'bob'?)");
  EXPECT_ERROR_AT(error_of(kPendulum + "forces:\n  - {name: f, type: force, body: bop, vector: "
                                       "[1, 0, 0]}\n"),
                  "m.yaml:13:", "unknown body 'bop' (did you mean 'bob'?)");
  EXPECT_ERROR_AT(error_of(kPendulum + "outputs:\n  - {joint: pivt, quantity: position}\n"),
                  "m.yaml:13:", "unknown joint 'pivt' (did you mean 'pivot'?)");
}

TEST(ModelFileErrors, UnknownSignalWithSuggestion) {
  EXPECT_ERROR_AT(error_of(kPendulum + R"(inputs:
  - {name: torque, type: constant, value: 1}
forces:
  - {name: m, type: torque, body: bob, vector: [0, 1, 0], signal: torqe}
)"),
                  "m.yaml:15:", "unknown signal 'torqe' (did you mean 'torque'?)");
}

TEST(ModelFileErrors, CycleAtTheJointThatClosesIt) {
  EXPECT_ERROR_AT(error_of(R"(bodies:
  - {name: a, mass: 1}
  - {name: b, mass: 1}
joints:
  - {name: ab, type: fixed, parent: a, child: b}
  - {name: ba, type: fixed, parent: b, child: a}
)"),
                  "m.yaml:", "the joints form a cycle");
  // The message names the bodies on the cycle, from the one the walk met first.
  EXPECT_NE(error_of(R"(bodies:
  - {name: a, mass: 1}
  - {name: b, mass: 1}
joints:
  - {name: ab, type: fixed, parent: a, child: b}
  - {name: ba, type: fixed, parent: b, child: a}
)")
                .find("a <- b <- a"),
            std::string::npos);
}

TEST(ModelFileErrors, BodyWithoutJointAtTheBody) {
  EXPECT_ERROR_AT(error_of(R"(bodies:
  - {name: a, mass: 1, com: [1, 0, 0]}
  - {name: loose, mass: 1}
joints:
  - {name: j, type: revolute, parent: world, child: a}
)"),
                  "m.yaml:3:5: bodies[1]: ", "body 'loose' is not attached to anything");
}

TEST(ModelFileErrors, MasslessLeafAtItsJoint) {
  // From ModelBuilder::build(), mapped to the line of the joint it names.
  EXPECT_ERROR_AT(error_of(R"(bodies:
  - {name: a, mass: 1, com: [1, 0, 0]}
  - {name: ghost, mass: 0}
joints:
  - {name: j, type: revolute, parent: world, child: a}
  - {name: k, type: revolute, parent: a, child: ghost}
)"),
                  "m.yaml:6:5: joints[1]: ", "joint 'k' carries only massless bodies");
}

TEST(ModelFileErrors, MasslessBodyOnAFreeJointIsStillRefused) {
  EXPECT_ERROR_AT(error_of(R"(bodies:
  - {name: table, mass: 0}
joints:
  - {name: drive, type: revolute, parent: world, child: table, axis: [0, 0, 1]}
)"),
                  "m.yaml:4:5: joints[0]: ", "joint 'drive' carries only massless bodies");
}

TEST(ModelFileSimulation, EventsAreConditionsOrMapsWithANameAndAnAction) {
  const ModelFile file = parse(kPendulum + R"(simulation:
  events:
    - pivot.angle = 0
    - {name: up, when: "pivot.angle_rate > 2.5", action: stop}
    - {when: energy_kinetic < 1e-3, action: record}
)");
  const auto& events = file.simulation.events;
  ASSERT_EQ(events.size(), 3u);
  EXPECT_EQ(events[0].name, "pivot.angle = 0");
  EXPECT_EQ(events[0].quantity, "pivot.angle");
  EXPECT_EQ(events[0].direction, model::EventDirection::either);
  EXPECT_EQ(events[0].action, model::EventAction::record);
  EXPECT_EQ(events[1].name, "up");
  EXPECT_EQ(events[1].direction, model::EventDirection::rising);
  EXPECT_EQ(events[1].value, 2.5);
  EXPECT_EQ(events[1].action, model::EventAction::stop);
  EXPECT_EQ(events[2].quantity, "energy_kinetic");
  EXPECT_EQ(events[2].value, 1e-3);
  ASSERT_EQ(file.simulation.event_positions.size(), 3u);
  EXPECT_EQ(file.simulation.event_positions[1].line, 15);
}

TEST(ModelFileSimulation, ABadEventIsReportedAtItsLine) {
  EXPECT_ERROR_AT(error_of(kPendulum + "simulation:\n  events:\n    - pivot.angle\n"),
                  "m.yaml:14:7: simulation.events[0]: ", "no comparison (<, > or =)");
  EXPECT_ERROR_AT(
      error_of(kPendulum + "simulation:\n  events:\n    - {when: x < 1, action: halt}\n"),
      "m.yaml:14:", "'halt' is not an action: record (write a row and go on) or stop");
  EXPECT_ERROR_AT(
      error_of(kPendulum + "simulation:\n  events:\n    - {when: x < 1, acton: stop}\n"),
      "m.yaml:14:", "did you mean 'action'");
  EXPECT_ERROR_AT(error_of(kPendulum + "simulation:\n  events:\n    - x < 1\n    - x < 1\n"),
                  "m.yaml:15:", "a second event named 'x < 1'");
  EXPECT_ERROR_AT(error_of(kPendulum + "simulation:\n  events: {when: x < 1}\n"),
                  "m.yaml:13:", "a list of events");
}

TEST(ModelFileSimulation, EveryRegisteredIntegratorIsAcceptedByName) {
  for (const char* name :
       {"rk4", "symplectic_euler", "dopri5", "splitting", "splitting4", "lie_group", "exact"}) {
    const ModelFile file = parse(fmt::format(R"(
bodies:
  - {{name: b, mass: 1, inertia: [1, 2, 3]}}
joints:
  - {{name: f, type: free, parent: world, child: b}}
simulation: {{integrator: {}}}
)",
                                             name));
    EXPECT_EQ(*file.simulation.integrator, name);
  }
  EXPECT_ERROR_AT(error_of(R"(bodies:
  - {name: b, mass: 1, inertia: [1, 2, 3]}
joints:
  - {name: f, type: free, parent: world, child: b}
simulation: {integrator: exactt}
)"),
                  "m.yaml:5:26: simulation.integrator: ",
                  "unknown integrator 'exactt' (did you mean 'exact'?); known: rk4, "
                  "symplectic_euler, dopri5, bdf, sdirk3, splitting, splitting4, lie_group, exact");
}

TEST(ModelFile, LocatesAnErrorAboutAnItemAtItsDeclaration) {
  const ModelFile file = parse(R"(bodies:
  - {name: a, mass: 1, com: [1, 0, 0]}
joints:
  - {name: j, type: revolute, parent: world, child: a}
)");
  InvalidArgument about_joint("something about j");
  about_joint.about(ModelItemRef::Kind::joint, "j");
  const auto located = file.locate(about_joint);
  ASSERT_TRUE(located.has_value());
  EXPECT_EQ(std::string(located->what()), "m.yaml:4:5: something about j");
  InvalidArgument about_nothing("no item");
  EXPECT_FALSE(file.locate(about_nothing).has_value());
  InvalidArgument about_other("other");
  about_other.about(ModelItemRef::Kind::body, "j");
  EXPECT_FALSE(file.locate(about_other).has_value());
}

TEST(ModelFileErrors, NonUnitQuaternionAndAxis) {
  EXPECT_ERROR_AT(error_of(R"(bodies:
  - {name: a, mass: 1, com: [1, 0, 0]}
joints:
  - name: j
    type: revolute
    parent: world
    child: a
    in_parent: {quaternion: [1, 0.1, 0, 0]}
)"),
                  "m.yaml:8:29: joints[0].in_parent.quaternion: ", "unit");
  EXPECT_ERROR_AT(error_of(R"(bodies:
  - {name: a, mass: 1, inertia: [1, 1, 1]}
joints:
  - {name: j, type: spherical, parent: world, child: a, q0: [1, 0, 0.5, 0]}
)"),
                  "m.yaml:4:61: joints[0].q0: ", "unit");
  EXPECT_ERROR_AT(
      error_of(R"(bodies:
  - {name: a, mass: 1, com: [1, 0, 0]}
joints:
  - {name: j, type: revolute, parent: world, child: a, axis: [1, 1, 0]}
)"),
      "m.yaml:4:62: joints[0].axis: ", "must be a unit vector (its norm is 1.41421356)");
}

TEST(ModelFileErrors, NegativeMass) {
  std::string yaml = kPendulum;
  yaml.replace(yaml.find("mass: 1.0"), 9, "mass: -1.0");
  EXPECT_ERROR_AT(error_of(yaml),
                  "m.yaml:4:11: bodies[0].mass: ", "must not be negative, got -1.0");
  EXPECT_ERROR_AT(error_of(R"(bodies:
  - {name: a, shape: sphere, radius: 0.1, mass: -2}
joints:
  - {name: j, type: free, parent: world, child: a}
)"),
                  "m.yaml:2:49: bodies[0].mass: ", "must be positive, got -2");
}

TEST(ModelFileErrors, TableTimesNotIncreasing) {
  EXPECT_ERROR_AT(
      error_of(kPendulum + R"(inputs:
  - {name: r, type: table, times: [0, 1, 1], values: [0, 1, 2]}
)"),
      "m.yaml:13:42: inputs[0].times[2]: ", "times must increase: 1 does not come after 1");
  std::ofstream(scratch_dir() / "bad.csv") << "0,0\n2,1\n1,2\n";
  const std::string csv = (scratch_dir() / "bad.csv").string();
  EXPECT_ERROR_AT(error_of(kPendulum + "inputs:\n  - {name: r, type: table, csv: bad.csv}\n"),
                  csv + ":3: ", "times must increase: 1 does not come after 2");
}

TEST(ModelFileErrors, MissingCsvFileAtTheReference) {
  EXPECT_ERROR_AT(
      error_of<FileError>(kPendulum + "inputs:\n  - {name: r, type: table, csv: nowhere.csv}\n"),
      "m.yaml:13:33: inputs[0].csv: ", "cannot read the CSV file");
}

TEST(ModelFileErrors, BadOutputTarget) {
  EXPECT_ERROR_AT(
      error_of(kPendulum + "outputs:\n  - {body: bob, quantity: spring_length}\n"),
      "m.yaml:13:27: outputs[0].quantity: ", "'spring_length' is not a quantity of a body");
  EXPECT_ERROR_AT(
      error_of(kPendulum + "outputs:\n  - {joint: pivot, quantity: position, "
                           "component: 1}\n"),
      "m.yaml:13:", "coordinate 1 is out of range: joint 'pivot' has 1: 0 (pivot.angle)");
  EXPECT_ERROR_AT(error_of(kPendulum + R"(inputs:
  - {name: u, type: constant, value: 1}
forces:
  - {name: push, type: force, body: bob, vector: [1, 0, 0], signal: u}
outputs:
  - {spring: push, quantity: spring_length}
)"),
                  "m.yaml:17:", "force element 'push' is not a spring_damper");
}

TEST(ModelFileErrors, BuilderErrorsAreReportedAtWhatTheyName) {
  // Parallel universal axes: found by ModelBuilder::build(), reported at the joint.
  EXPECT_ERROR_AT(error_of(R"(bodies:
  - {name: a, mass: 1, com: [1, 0, 0], inertia: [1, 1, 1]}
joints:
  - {name: u, type: universal, parent: world, child: a, axis: [0, 0, 1], axis2: [0, 0, 1]}
)"),
                  "m.yaml:4:5: joints[0]: ", "joint 'u': universal axes");
}

TEST(ModelFileErrors, RepeatedNamesAndMisplacedKeys) {
  EXPECT_ERROR_AT(
      error_of(R"(bodies:
  - {name: a, mass: 1, com: [1, 0, 0]}
  - {name: a, mass: 1, com: [1, 0, 0]}
joints:
  - {name: j, type: revolute, parent: world, child: a}
)"),
      "m.yaml:3:12: bodies[1].name: ", "a second body named 'a' (the first is at line 2)");
  EXPECT_ERROR_AT(error_of(R"(bodies:
  - {name: a, mass: 1, com: [1, 0, 0]}
joints:
  - {name: j, type: prismatic, parent: world, child: a, q0_deg: 10}
)"),
                  "m.yaml:4:", "degrees are not allowed here");
  EXPECT_ERROR_AT(error_of(R"(bodies:
  - {name: a, mass: 1, inertia: [1, 1, 1]}
joints:
  - {name: j, type: ball, parent: world, child: a, axis: [0, 0, 1]}
)"),
                  "m.yaml:4:", "a spherical joint has no 'axis'");
}

TEST(ModelFileErrors, MissingFiles) {
  EXPECT_THROW(read_model_file(scratch_dir() / "no_such_model.yaml"), FileError);
  EXPECT_ERROR_AT(error_of<FileError>(R"(bodies:
  - {name: a, part: missing_part.yaml}
joints:
  - {name: j, type: free, parent: world, child: a}
)"),
                  "m.yaml:2:21: bodies[0].part: ", "file not found");
}

}  // namespace
}  // namespace momenta::io
