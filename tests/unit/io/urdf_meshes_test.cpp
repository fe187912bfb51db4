// A URDF's geometry (io/urdf_file.hpp): the mesh arm's links weighed from their meshes — an ASCII
// STL hexagonal prism, a binary STL unit cube scaled per axis, a binary STL box, a COLLADA box in
// millimetres — against the closed forms of those solids; what is drawn; package:// found on
// the package path, in ROS_PACKAGE_PATH and a few levels down a workspace; and every problem an
// error at its line naming the link.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta/io/model_export.hpp"
#include "momenta/io/urdf_file.hpp"
#include "momenta_test/scratch_dir.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::io::urdf_meshes_test {
namespace {

namespace fs = std::filesystem;

constexpr double kAluminium = 2700.0;  // kg/m³

fs::path packages() { return fs::path(test::source_dir()) / "tests/data/models/urdf/packages"; }
fs::path mesh_arm() { return packages() / "mesh_arm/urdf/mesh_arm.urdf"; }

ModelFile weighed_mesh_arm() {
  ModelFileOptions options;
  options.package_path = {packages()};
  options.link_density = kAluminium;
  return read_urdf_file(mesh_arm(), options);
}

const inertia::MassProperties& body_mass(const ModelFile& f, const std::string& name) {
  return f.model.bodies()[static_cast<std::size_t>(f.model.body_index(name))].mass_properties;
}

// The largest difference of mass, centre of mass and inertia, each relative to its own scale
// (the mass, the reference's largest length from the origin or 1 mm, its largest moment).
double relative_difference(const inertia::MassProperties& a, const inertia::MassProperties& b) {
  const double length = std::max(b.center_of_mass().norm(), 1e-3);
  const double moment = b.inertia_about_com().cwiseAbs().maxCoeff();
  return std::max({std::abs(a.mass() - b.mass()) / b.mass(),
                   (a.center_of_mass() - b.center_of_mass()).cwiseAbs().maxCoeff() / length,
                   (a.inertia_about_com() - b.inertia_about_com()).cwiseAbs().maxCoeff() / moment});
}

// A uniform regular hexagonal prism (circumradius r, length l) along x, centred at `centre`: a
// regular hexagon's polar moment of area is (5/12) r² times its area, so m·5r²/12 about the prism's
// axis; half of it about each axis across, plus m l²/12 for the length.
inertia::MassProperties hexagonal_prism_along_x(double density, double r, double l,
                                                const Vec3& centre) {
  const double mass = density * 1.5 * std::sqrt(3.0) * r * r * l;
  const double axial = mass * 5.0 * r * r / 12.0;
  const double across = mass * (5.0 * r * r / 24.0 + l * l / 12.0);
  return {mass, centre, Vec3(axial, across, across).asDiagonal()};
}

inertia::MassProperties box_at(const Vec3& size, const Vec3& centre) {
  return inertia::box(inertia::Amount::density(kAluminium), size)
      .transformed(Mat3::Identity(), centre);
}

// Every link's mass properties from its mesh, as the closed form of the solid it bounds. The
// STL coordinates arrive exactly (17 digits in text; binary fractions in single precision), so
// only the integration's round-off remains: 1e-14. The COLLADA hand is scaled by assimp with
// <unit meter="0.001"> stored in single precision (relative error up to 2^-24 per length, so
// ~5 length⁵ factors in an inertia: 3e-7): 1e-6.
TEST(UrdfMeshes, MeshArmLinksWeighAsTheirSolids) {
  const ModelFile f = weighed_mesh_arm();
  EXPECT_LT(relative_difference(body_mass(f, "base"),
                                box_at(Vec3(0.25, 0.25, 0.125), Vec3(0, 0, 0.0625))),
            1e-14);
  EXPECT_LT(
      relative_difference(body_mass(f, "upper_arm"),
                          hexagonal_prism_along_x(kAluminium, 0.04, 0.375, Vec3(0.1875, 0, 0))),
      1e-14);
  EXPECT_LT(relative_difference(body_mass(f, "forearm"),
                                box_at(Vec3(0.3125, 0.0625, 0.0625), Vec3(0.15625, 0, 0))),
            1e-14);
  EXPECT_LT(
      relative_difference(body_mass(f, "hand"), box_at(Vec3(0.05, 0.08, 0.03), Vec3(0.025, 0, 0))),
      1e-6);
  // The payload keeps its own <inertial>.
  EXPECT_EQ(body_mass(f, "payload").mass(), 0.5);
  EXPECT_EQ(body_mass(f, "payload").inertia_about_com()(1, 1), 1.8e-4);
}

// Without a density the links without <inertial> are massless (URDF's meaning), and a note says
// how to weigh them; the mesh arm still moves (the payload carries mass along every joint).
TEST(UrdfMeshes, WithoutADensityLinksAreMasslessAndNoted) {
  ModelFileOptions options;
  options.package_path = {packages()};
  const ModelFile f = read_urdf_file(mesh_arm(), options);
  EXPECT_EQ(body_mass(f, "upper_arm").mass(), 0.0);
  std::string notes;
  for (const std::string& n : f.notes) notes += n + "\n";
  // The option is marked for each front end to spell (--link-density, link_density=).
  EXPECT_NE(notes.find(":28: link 'upper_arm' has no <inertial>: massless (a link density, "
                       "‹link_density›, would give it the mass of its geometry)"),
            std::string::npos)
      << notes;
  EXPECT_NE(notes.find(":33: <collision> of link 'upper_arm': not used by momenta"),
            std::string::npos)
      << notes;
  EXPECT_NE(notes.find(":12: <material> in the <visual> of link 'base': not used by momenta"),
            std::string::npos)
      << notes;
}

// What the report draws: each link's visual geometry in its frame, meshes in metres.
TEST(UrdfMeshes, VisualsAreDrawnInTheLinkFrame) {
  const ModelFile f = weighed_mesh_arm();
  const auto parts = [&](const std::string& body) { return f.parts_of(f.model.body_index(body)); };
  ASSERT_EQ(parts("upper_arm").size(), 1u);
  const PartSummary& upper = parts("upper_arm")[0];
  EXPECT_EQ(upper.kind, "mesh");
  EXPECT_EQ(upper.name, "visual[0]");
  EXPECT_EQ(upper.line, 29);
  ASSERT_TRUE(upper.mesh);
  EXPECT_EQ(upper.mesh->vertices.size(), 12u);  // the STL's corners welded
  EXPECT_EQ(upper.mesh->triangles.size(), 20u);
  EXPECT_EQ(upper.p_BoSo_B, Vec3(0.1875, 0, 0));
  EXPECT_LT((upper.R_BS * Vec3::UnitZ() - Vec3::UnitX()).norm(), 1e-15);  // the prism along x
  // The forearm's unit cube scaled per axis.
  const PartSummary& fore = parts("forearm")[0];
  Vec3 extent = Vec3::Zero();
  for (const Vec3& v : fore.mesh->vertices) extent = extent.cwiseMax(v.cwiseAbs());
  EXPECT_EQ(extent, Vec3(0.15625, 0.03125, 0.03125));
  // The COLLADA hand in metres, its z axis kept (its <up_axis> is Z_UP); to two roundings in
  // single precision (the unit 0.001 and the product as assimp stores them: 2^-23).
  extent.setZero();
  for (const Vec3& v : parts("hand")[0].mesh->vertices) extent = extent.cwiseMax(v.cwiseAbs());
  const Vec3 hand(0.025, 0.04, 0.015);
  EXPECT_LT((extent - hand).cwiseQuotient(hand).cwiseAbs().maxCoeff(), 1.2e-7) << extent;
  // A primitive: the payload's sphere, drawn though its mass is its <inertial>'s.
  ASSERT_EQ(parts("payload").size(), 1u);
  EXPECT_EQ(parts("payload")[0].kind, "sphere");
  EXPECT_EQ(parts("payload")[0].sizes,
            (std::vector<std::pair<std::string, double>>{{"radius", 0.03}}));
}

// Written out, the meshes are named as not drawn (their mass stays in each link's inertial); the
// payload's sphere is drawn.
TEST(UrdfMeshes, MeshesWrittenOutAreNamedAsNotDrawn) {
  const ModelFile f = weighed_mesh_arm();
  for (const ExportedModel& written : {write_mjcf(f, model::neutral(f.model)), write_urdf(f)}) {
    std::string lost;
    for (const std::string& l : written.not_written) lost += l + "\n";
    EXPECT_NE(lost.find("the mesh 'visual[0]' of body 'upper_arm', not drawn (the body's "
                        "inertial keeps its mass)"),
              std::string::npos)
        << lost;
    EXPECT_EQ(std::count(lost.begin(), lost.end(), '\n'), 4) << lost;  // base, arm, fore, hand
    EXPECT_NE(written.text.find("0.03"), std::string::npos);           // the payload's sphere
  }
}

ModelFile parse(const std::string& text, const ModelFileOptions& options = {},
                const fs::path& base = packages() / "mesh_arm/urdf") {
  return parse_urdf(text, "robot.urdf", options, base);
}

std::string one_link(const std::string& geometry, const std::string& inertial = "") {
  return R"(<robot name="r">
  <link name="base"/>
  <joint name="hinge" type="continuous">
    <parent link="base"/><child link="arm"/><axis xyz="0 1 0"/>
  </joint>
  <link name="arm">)" +
         inertial + geometry + R"(
  </link>
</robot>)";
}

std::string error_of(const std::string& text, const ModelFileOptions& options = {},
                     const fs::path& base = packages() / "mesh_arm/urdf") {
  try {
    parse(text, options, base);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

// A link without <inertial> on a moving joint: refused at the joint's line, naming the link and
// how to weigh it; with a density, its collision geometry (not its visual) gives its mass.
TEST(UrdfMeshes, AMasslessLinkIsRefusedNamingItAndADensityWeighsItsCollision) {
  const std::string text = one_link(R"(
    <visual><geometry><box size="1 1 1"/></geometry></visual>
    <collision><origin xyz="0 0 -0.5"/><geometry><cylinder radius="0.1" length="1"/></geometry></collision>)");
  const std::string refused = error_of(text);
  EXPECT_NE(refused.find("robot.urdf:3: joint 'hinge' carries only massless bodies"),
            std::string::npos)
      << refused;
  EXPECT_NE(refused.find("(link 'arm' has no <inertial>: give it one, or a link density "
                         "(link_density) to take its mass from its collision or visual geometry)"),
            std::string::npos)
      << refused;
  ModelFileOptions options;
  options.link_density = 1000.0;
  const ModelFile f = parse(text, options);
  const inertia::MassProperties cylinder =
      inertia::solid_cylinder(inertia::Amount::density(1000.0), 0.1, 1.0)
          .transformed(Mat3::Identity(), Vec3(0, 0, -0.5));
  EXPECT_LT(relative_difference(body_mass(f, "arm"), cylinder), 1e-15);
  // The visual box is what is drawn.
  ASSERT_EQ(f.parts_of(f.model.body_index("arm")).size(), 1u);
  EXPECT_EQ(f.parts_of(f.model.body_index("arm"))[0].kind, "box");
}

// Several solids add; a mirroring scale keeps the mass positive (the winding turned back).
TEST(UrdfMeshes, SolidsAddAndAMirroredMeshWeighsTheSame) {
  ModelFileOptions options;
  options.link_density = kAluminium;
  const ModelFile f = parse(one_link(R"(
    <collision><geometry><mesh filename="../meshes/box.stl" scale="-0.5 0.25 0.125"/></geometry></collision>
    <collision><origin xyz="1 0 0"/><geometry><sphere radius="0.1"/></geometry></collision>)"),
                            options);
  inertia::MassProperties expected = box_at(Vec3(0.5, 0.25, 0.125), Vec3::Zero());
  expected += inertia::solid_sphere(inertia::Amount::density(kAluminium), 0.1)
                  .transformed(Mat3::Identity(), Vec3(1, 0, 0));
  EXPECT_LT(relative_difference(body_mass(f, "arm"), expected), 1e-14);
}

// package:// is found as a folder on the path, as a folder holding it, a few levels down a
// workspace beside its package.xml, and on ROS_PACKAGE_PATH; file:// and relative paths too.
TEST(UrdfMeshes, MeshFileNamesAreFound) {
  const auto weighs = [&](const std::string& file_name, const ModelFileOptions& given) {
    ModelFileOptions options = given;
    options.link_density = kAluminium;
    const ModelFile f = parse(one_link("<collision><geometry><mesh filename=\"" + file_name +
                                       "\"/></geometry></collision>"),
                              options);
    return body_mass(f, "arm").mass();
  };
  const double cube = kAluminium;  // the unit cube
  const std::string uri = "package://mesh_arm/meshes/box.stl";
  ModelFileOptions options;
  options.package_path = {packages()};
  EXPECT_EQ(weighs(uri, options), cube);
  options.package_path = {packages() / "mesh_arm"};
  EXPECT_EQ(weighs(uri, options), cube);
  options.package_path = {"/nonexistent", fs::path(test::source_dir()) / "tests/data/models"};
  EXPECT_EQ(weighs(uri, options), cube);  // models/urdf/packages/mesh_arm: three levels down
  EXPECT_EQ(weighs("file://" + (packages() / "mesh_arm/meshes/box.stl").string(), {}), cube);
  EXPECT_EQ(weighs("../meshes/box.stl", {}), cube);
  ASSERT_EQ(::setenv("ROS_PACKAGE_PATH", ("/nonexistent:" + packages().string()).c_str(), 1), 0);
  EXPECT_EQ(weighs(uri, {}), cube);
  ::unsetenv("ROS_PACKAGE_PATH");
}

// Where a link is weighed from its mesh (no <inertial>, a density given), a mesh that cannot be
// had is an error at the line that names it.
TEST(UrdfMeshes, MeshFileNamesThatLeadNowhereAreErrorsAtTheirLineWhereTheMeshIsWeighed) {
  const auto error = [&](const std::string& file_name, ModelFileOptions options = {}) {
    options.link_density = 2700.0;
    return error_of(
        one_link("\n<visual><geometry><mesh filename=\"" + file_name + "\"/></geometry></visual>"),
        options);
  };
  ::unsetenv("ROS_PACKAGE_PATH");
  EXPECT_EQ(error("package://mesh_arm/meshes/box.stl"),
            "robot.urdf:7: 'package://mesh_arm/meshes/box.stl' names package 'mesh_arm', and no "
            "package path is given: give the folder that holds it with package_path or "
            "ROS_PACKAGE_PATH");
  ModelFileOptions options;
  options.package_path = {"/nonexistent"};
  EXPECT_EQ(error("package://mesh_arm/meshes/box.stl", options),
            "robot.urdf:7: package 'mesh_arm' of 'package://mesh_arm/meshes/box.stl' is not found "
            "in /nonexistent (neither a folder of that name nor one holding it): give the folder "
            "that holds it with package_path");
  EXPECT_EQ(error("package://mesh_arm"),
            "robot.urdf:7: 'package://mesh_arm' is not package://PACKAGE/path/to/mesh");
  EXPECT_EQ(error("https://example.org/arm.stl"),
            "robot.urdf:7: 'https://example.org/arm.stl': momenta reads meshes from package://, "
            "file:// or a path relative to the URDF's folder, not https://");
  const std::string missing = error("../meshes/nothing.stl");
  EXPECT_NE(missing.find("robot.urdf:7: mesh '../meshes/nothing.stl': "), std::string::npos)
      << missing;
  EXPECT_NE(missing.find("nothing.stl: mesh file not found"), std::string::npos) << missing;
  EXPECT_NE(error("../package.xml")
                .find("unsupported mesh file extension '.xml': expected .stl, "
                      ".obj or .dae"),
            std::string::npos);
}

// Most URDFs arrive without their mesh packages (the URDF tutorial's R2-D2 names
// package://pr2_description): where every link has its <inertial>, nothing needs a mesh, so one
// that cannot be found or read is a note at its line, and the part is not drawn.
TEST(UrdfMeshes, AMeshOnlyDrawnThatCannotBeHadIsANoteAndTheModelLoads) {
  ::unsetenv("ROS_PACKAGE_PATH");
  const std::string inertial =
      "<inertial><mass value=\"2\"/><inertia ixx=\"0.1\" iyy=\"0.2\" izz=\"0.3\"/></inertial>";
  const std::string text = one_link(R"(
<visual><geometry><mesh filename="package://pr2_description/meshes/base.dae"/></geometry></visual>
<collision><geometry><mesh filename="package://pr2_description/meshes/base.dae"/></geometry></collision>
<visual><geometry><mesh filename="../meshes/nothing.stl"/></geometry></visual>
<visual><geometry><box size="0.1 0.2 0.3"/></geometry></visual>)",
                                    inertial);
  const ModelFile f = parse(text);
  EXPECT_EQ(body_mass(f, "arm").mass(), 2.0);
  std::string notes;
  for (const std::string& n : f.notes) notes += n + "\n";
  EXPECT_NE(notes.find("robot.urdf:7: not drawn: 'package://pr2_description/meshes/base.dae' "
                       "names package 'pr2_description', and no package path is given: give the "
                       "folder that holds it with ‹package_path› or ROS_PACKAGE_PATH\n"),
            std::string::npos)
      << notes;
  EXPECT_NE(notes.find("robot.urdf:9: not drawn: mesh '../meshes/nothing.stl': "),
            std::string::npos)
      << notes;
  // The box is drawn; the collision mesh (neither drawn nor weighed) is noted as unused.
  const auto drawn = f.parts_of(f.model.body_index("arm"));
  ASSERT_EQ(drawn.size(), 1u);
  EXPECT_EQ(drawn[0].kind, "box");
  EXPECT_NE(notes.find("robot.urdf:8: <collision> of link 'arm': not used"), std::string::npos)
      << notes;
}

// A mesh that bounds no solid cannot weigh its link: refused naming the link and the mesh; drawn
// alone (no density) it is accepted.
TEST(UrdfMeshes, AnOpenMeshCannotWeighItsLink) {
  const fs::path dir = test::make_scratch_dir("urdf_meshes");
  std::ofstream(dir / "open.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\n"
                                     "f 1 4 3\n";  // a tetrahedron missing a face
  const std::string text =
      one_link("\n<visual><geometry><mesh filename=\"open.obj\"/></geometry></visual>",
               "<inertial><mass value=\"1\"/><inertia ixx=\"1\" iyy=\"1\" izz=\"1\"/></inertial>");
  EXPECT_NO_THROW(parse(text, {}, dir));
  const std::string weighed =
      one_link("\n<visual><geometry><mesh filename=\"open.obj\"/></geometry></visual>");
  ModelFileOptions options;
  options.link_density = 1000.0;
  const std::string refused = error_of(weighed, options, dir);
  EXPECT_NE(refused.find("robot.urdf:7: link 'arm' has no <inertial>, and its visual mesh cannot "
                         "give its mass: "),
            std::string::npos)
      << refused;
  EXPECT_NE(refused.find("open.obj"), std::string::npos) << refused;
  fs::remove_all(dir);
}

TEST(UrdfMeshes, MalformedGeometryIsAnErrorAtItsLine) {
  EXPECT_EQ(error_of(one_link("\n<visual><origin xyz=\"0 0 1\"/></visual>")),
            "robot.urdf:7: the <visual> of link 'arm' needs a <geometry>");
  EXPECT_EQ(error_of(one_link("\n<visual><geometry><capsule radius=\"1\" length=\"2\"/>"
                              "</geometry></visual>")),
            "robot.urdf:7: <capsule> in the <geometry> of the <visual> of link 'arm': URDF's "
            "shapes are <box>, <cylinder>, <sphere> and <mesh>");
  EXPECT_EQ(error_of(one_link("\n<collision><geometry><sphere radius=\"-1\"/>"
                              "</geometry></collision>")),
            "robot.urdf:7: the radius of the collision sphere of link 'arm' is -1 m: it must be "
            "positive");
  EXPECT_EQ(error_of(one_link("\n<visual><geometry><box size=\"1 0 1\"/></geometry></visual>")),
            "robot.urdf:7: the size of the visual box of link 'arm' must be three positive "
            "lengths (m)");
  EXPECT_EQ(error_of(one_link("\n<visual><geometry/></visual>")),
            "robot.urdf:7: the <geometry> of the <visual> of link 'arm' holds one of <box>, "
            "<cylinder>, <sphere> or <mesh>");
  EXPECT_EQ(error_of(one_link("\n<visual><geometry><mesh filename=\"../meshes/box.stl\" "
                              "scale=\"1 0 1\"/></geometry></visual>")),
            "robot.urdf:7: the scale of the visual mesh of link 'arm' has a zero factor");
  ModelFileOptions options;
  options.link_density = -1.0;
  EXPECT_EQ(error_of(one_link(""), options),
            "robot.urdf: the link density -1 kg/m³ is not positive and finite");
}

}  // namespace
}  // namespace momenta::io::urdf_meshes_test
