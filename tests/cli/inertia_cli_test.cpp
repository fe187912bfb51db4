// `momenta inertia`, run as a user runs it: the built binary (MOMENTA_CLI_PATH, set by CMake), its
// exit codes (0 ok, 1 user error, 2 usage error), its one-line errors and its JSON, checked
// against the library.

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta/io/part_file.hpp"
#include "momenta_test/meshes.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using test::CliRun;
using test::quoted;
using test::slurp;

class InertiaCli : public test::CliTest {
 protected:
  fs::path write_obj(const std::string& name, const inertia::TriangleMesh& mesh) const {
    std::ostringstream out;
    out.precision(17);
    for (const Vec3& v : mesh.vertices)
      out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    for (const auto& t : mesh.triangles)
      out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    return write(name, out.str());
  }

  // A binary STL of `mesh` declaring `declared` triangles (its real count unless told otherwise)
  // and holding the first `written` of them.
  fs::path write_binary_stl(const std::string& name, const inertia::TriangleMesh& mesh,
                            std::uint32_t declared, std::size_t written) const {
    std::string bytes(80, ' ');
    bytes.append(reinterpret_cast<const char*>(&declared), 4);
    for (std::size_t i = 0; i < written; ++i) {
      float data[12] = {0, 0, 0};
      for (int k = 0; k < 3; ++k) {
        const Vec3& p = mesh.vertices[static_cast<std::size_t>(mesh.triangles[i][k])];
        for (int c = 0; c < 3; ++c) data[3 + 3 * k + c] = static_cast<float>(p[c]);
      }
      bytes.append(reinterpret_cast<const char*>(data), sizeof data);
      bytes.append(2, '\0');
    }
    return write(name, bytes);
  }

  // Expects exit code 1 and one line on stderr holding every piece of `pieces`.
  void expect_user_error(const std::string& args, const std::vector<std::string>& pieces) const {
    SCOPED_TRACE(args);
    const CliRun r = momenta(args);
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err;
    EXPECT_EQ(r.err.rfind("momenta: error: ", 0), 0u) << r.err;
    for (const std::string& piece : pieces)
      EXPECT_NE(r.err.find(piece), std::string::npos) << r.err;
  }
};

Vec3 vec(const json& j) {
  return Vec3(j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>());
}

Mat3 mat(const json& j) {
  Mat3 M;
  for (int i = 0; i < 3; ++i) M.row(i) = vec(j.at(i)).transpose();
  return M;
}

constexpr const char* kPlate = R"(name: plate with a bore
units: mm
density: 7850
parts:
  - {name: plate, shape: box, size: [300, 200, 10]}
  - {name: bore, shape: cylinder, radius: 30, length: 10, position: [80, 50, 0], hole: true}
)";

TEST_F(InertiaCli, PartFileJsonMatchesTheLibrary) {
  const fs::path file = write("plate.yaml", kPlate);
  const CliRun r = momenta("inertia " + quoted(file.string()) + " --json --about 0.1 0 0.2");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const json j = json::parse(r.out);
  const io::CompositePart part = io::read_part_file(file);
  const inertia::MassProperties& mp = part.total;
  // JSON doubles print with 17 significant digits and parse back to the same bits.
  EXPECT_EQ(j.at("mass").get<double>(), mp.mass());
  EXPECT_EQ(j.at("volume").get<double>(), mp.volume());
  EXPECT_EQ(vec(j.at("com")), mp.center_of_mass());
  EXPECT_EQ(mat(j.at("inertia_com")), mp.inertia_about_com());
  const inertia::PrincipalAxes principal = mp.principal_axes();
  EXPECT_EQ(vec(j.at("principal_moments")), principal.moments);
  EXPECT_EQ(mat(j.at("principal_axes")), principal.R_BP);
  EXPECT_EQ(vec(j.at("about")), Vec3(0.1, 0, 0.2));
  EXPECT_EQ(mat(j.at("inertia_about")), mp.inertia_about(Vec3(0.1, 0, 0.2)));
  EXPECT_EQ(j.at("name"), "plate with a bore");
  EXPECT_EQ(j.at("frame"), "body");
  ASSERT_EQ(j.at("parts").size(), 2u);
  EXPECT_EQ(j.at("parts")[1].at("name"), "bore");
  EXPECT_EQ(j.at("parts")[1].at("hole"), true);
  EXPECT_EQ(j.at("parts")[1].at("line"), 6);
  // Off-diagonals are minus the products: the bore at (+x, +y) leaves ∫xy dm < 0, entry > 0.
  EXPECT_GT(j.at("inertia_com")[0][1].get<double>(), 0.0);
  // Moments ascending; the axes a proper rotation.
  EXPECT_LE(principal.moments[0], principal.moments[1]);
  EXPECT_LE(principal.moments[1], principal.moments[2]);
  EXPECT_NEAR(mat(j.at("principal_axes")).determinant(), 1.0, 1e-14);
}

TEST_F(InertiaCli, PrincipalFrameDiagonalizesTheTensors) {
  const fs::path file = write("plate.yaml", kPlate);
  const CliRun r =
      momenta("inertia " + quoted(file.string()) + " --json --frame principal --about 0 0 0");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  const inertia::MassProperties mp = io::read_part_file(file).total;
  const inertia::PrincipalAxes principal = mp.principal_axes();
  EXPECT_EQ(j.at("frame"), "principal");
  EXPECT_EQ(mat(j.at("inertia_com")), Mat3(principal.moments.asDiagonal()));
  // The tensor about a point, re-expressed: R_BPᵀ I R_BP, to the round-off of two products.
  const Mat3 expected =
      principal.R_BP.transpose() * mp.inertia_about(Vec3::Zero()) * principal.R_BP;
  EXPECT_MATRIX_NEAR(mat(j.at("inertia_about")), expected, 1e-15 * expected.norm());
  EXPECT_EQ(vec(j.at("com")), mp.center_of_mass());  // Still in the file's frame.
}

TEST_F(InertiaCli, TextOutputNamesEveryQuantity) {
  const fs::path file = write("plate.yaml", kPlate);
  const CliRun r = momenta("inertia " + quoted(file.string()) + " --about 0 0 0");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* piece :
       {"plate with a bore", "bore", "cylinder (hole)", "mass ", "volume ", "centre of mass ",
        "inertia about the centre of mass, in body axes", "principal moments",
        "principal axes (columns", "inertia about [0, 0, 0] m"}) {
    EXPECT_NE(r.out.find(piece), std::string::npos) << piece << "\n" << r.out;
  }
}

TEST_F(InertiaCli, MeshFileWithDensityMassScaleOrPerUnitDensity) {
  // A 100 × 60 × 40 mm box drawn in mm: the mesh integrals are exact, so it matches the closed
  // form to round-off.
  const fs::path obj = write_obj("block.obj", test::box_mesh(Vec3(100, 60, 40)));
  const inertia::MassProperties box =
      inertia::box(inertia::Amount::density(2700), Vec3(0.1, 0.06, 0.04));
  const CliRun r =
      momenta("inertia " + quoted(obj.string()) + " --scale 0.001 --density 2700 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const json j = json::parse(r.out);
  EXPECT_REL_NEAR(j.at("mass").get<double>(), box.mass(), 1e-14);
  EXPECT_MATRIX_NEAR(mat(j.at("inertia_com")), box.inertia_about_com(),
                     1e-14 * box.inertia_about_com().norm());
  EXPECT_EQ(j.at("density"), 2700.0);
  EXPECT_EQ(j.at("per_unit_density"), false);
  // And exactly what the library's mesh reader gives.
  const inertia::MassProperties lib =
      io::read_mesh_mass_properties(obj, inertia::Amount::density(2700), 0.001);
  EXPECT_EQ(j.at("mass").get<double>(), lib.mass());
  EXPECT_EQ(mat(j.at("inertia_com")), lib.inertia_about_com());

  // By total mass.
  const CliRun by_mass =
      momenta("inertia " + quoted(obj.string()) + " --scale 0.001 --mass 2 --json");
  ASSERT_EQ(by_mass.code, 0) << by_mass.err;
  EXPECT_REL_NEAR(json::parse(by_mass.out).at("mass").get<double>(), 2.0, 1e-15);

  // No density: per unit density, with a note on stderr (stdout stays clean JSON).
  const CliRun unit = momenta("inertia " + quoted(obj.string()) + " --scale 0.001 --json");
  ASSERT_EQ(unit.code, 0) << unit.err;
  const json u = json::parse(unit.out);
  EXPECT_EQ(u.at("per_unit_density"), true);
  EXPECT_REL_NEAR(u.at("mass").get<double>(), 0.1 * 0.06 * 0.04, 1e-14);
  EXPECT_NE(unit.err.find("per unit density"), std::string::npos) << unit.err;

  // A binary STL of the same box, and the thin-shell reading of a unit cube (I = 5/18 M a²).
  const fs::path stl = write_binary_stl("cube.stl", test::box_mesh(Vec3(1, 1, 1)), 12, 12);
  const CliRun shell = momenta("inertia " + quoted(stl.string()) + " --shell --density 2 --json");
  ASSERT_EQ(shell.code, 0) << shell.err;
  const json s = json::parse(shell.out);
  EXPECT_REL_NEAR(s.at("mass").get<double>(), 12.0, 1e-15);
  EXPECT_MATRIX_NEAR(mat(s.at("inertia_com")), (5.0 / 18.0 * 12.0) * Mat3::Identity(), 1e-14);
  EXPECT_EQ(s.at("volume").get<double>(), 0.0);
}

TEST_F(InertiaCli, DensityOptionReplacesThePartFilesDefault) {
  const fs::path file = write("plate.yaml", kPlate);
  const CliRun r = momenta("inertia " + quoted(file.string()) + " --density 2700 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(json::parse(r.out).at("mass").get<double>(),
            io::read_part_file(file, {.default_density = 2700}).total.mass());
}

TEST_F(InertiaCli, UserErrorsExitOneWithOneLineNamingFileLineAndKey) {
  const std::string d = dir_.string() + "/";
  // Malformed YAML: yaml-cpp's position.
  write("malformed.yaml", "parts:\n  - {shape: box, size: [1, 1, 1}\n");
  expect_user_error("inertia " + quoted(d + "malformed.yaml"),
                    {d + "malformed.yaml:2:", "malformed YAML"});
  // Unknown key, with a suggestion.
  write("unknown.yaml", "parts:\n  - shape: sphere\n    radius: 0.1\n    densty: 1000\n");
  expect_user_error(
      "inertia " + quoted(d + "unknown.yaml"),
      {d + "unknown.yaml:4:5: parts[0]: unknown key 'densty' (did you mean 'density'?)"});
  // Zero and negative masses and sizes.
  write("zero_mass.yaml", "parts:\n  - {shape: sphere, radius: 0.1, mass: 0}\n");
  expect_user_error("inertia " + quoted(d + "zero_mass.yaml"),
                    {d + "zero_mass.yaml:2:40: parts[0].mass: must be positive, got 0"});
  write("negative_mass.yaml", "parts:\n  - inertia: {mass: -1, moments: [1, 1, 1]}\n");
  expect_user_error(
      "inertia " + quoted(d + "negative_mass.yaml"),
      {d + "negative_mass.yaml:2:21: parts[0].inertia.mass: must be positive, got -1"});
  write("negative_size.yaml", "parts:\n  - {shape: box, size: [1, -2, 1], density: 1}\n");
  expect_user_error("inertia " + quoted(d + "negative_size.yaml"),
                    {d + "negative_size.yaml:2:28: parts[0].size[1]: must be positive, got -2"});
  write("zero_size.yaml", "parts:\n  - {shape: cylinder, radius: 0, length: 1, density: 1}\n");
  expect_user_error("inertia " + quoted(d + "zero_size.yaml"),
                    {d + "zero_size.yaml:2:31: parts[0].radius: must be positive, got 0"});
  // A non-physical inertia: moments 1, 1, 3 break A + B >= C.
  write("nonphysical.yaml", "parts:\n  - inertia: {mass: 1, moments: [1, 1, 3]}\n");
  expect_user_error(
      "inertia " + quoted(d + "nonphysical.yaml"),
      {d + "nonphysical.yaml:2:33: parts[0].inertia.moments:", "triangle inequality"});
  // A hole larger than its material.
  write(
      "hole.yaml",
      "parts:\n  - {shape: box, size: [1, 1, 1], mass: 1}\n  - {name: big, shape: sphere, radius: "
      "1, mass: 2, hole: true}\n");
  expect_user_error("inertia " + quoted(d + "hole.yaml"),
                    {d + "hole.yaml:3:5: parts[1]: hole 'big'"});
  // Empty files: part file and mesh.
  write("empty.yaml", "");
  expect_user_error("inertia " + quoted(d + "empty.yaml"), {d + "empty.yaml: ", "empty"});
  write("empty.stl", "");
  expect_user_error("inertia " + quoted(d + "empty.stl"), {d + "empty.stl: ", "empty"});
  // An open mesh, alone and as a part.
  inertia::TriangleMesh open = test::box_mesh(Vec3(1, 1, 1));
  open.triangles.pop_back();
  write_binary_stl("open.stl", open, 11, 11);
  expect_user_error("inertia " + quoted(d + "open.stl") + " --density 1000",
                    {d + "open.stl", "does not bound a solid", "open"});
  write("open_part.yaml", "parts:\n  - {mesh: open.stl, density: 1000}\n");
  expect_user_error("inertia " + quoted(d + "open_part.yaml"),
                    {d + "open_part.yaml:2:12: parts[0].mesh:", "does not bound a solid"});
  // A truncated binary STL: the header declares 12 triangles, 5 are there.
  write_binary_stl("truncated.stl", test::box_mesh(Vec3(1, 1, 1)), 12, 5);
  expect_user_error("inertia " + quoted(d + "truncated.stl") + " --density 1000",
                    {d + "truncated.stl", "12 triangles", "truncated"});
  // Missing files, and a missing mesh named in a part file.
  expect_user_error("inertia " + quoted(d + "absent.yaml"), {d + "absent.yaml: file not found"});
  write("missing_mesh.yaml", "parts:\n  - {mesh: gone.obj, density: 1000}\n");
  expect_user_error(
      "inertia " + quoted(d + "missing_mesh.yaml"),
      {d + "missing_mesh.yaml:2:12: parts[0].mesh:", "gone.obj: mesh file not found"});
  // A file of another kind.
  write("model.step", "ISO-10303-21;\n");
  expect_user_error("inertia " + quoted(d + "model.step"), {"unsupported file extension '.step'"});
}

TEST_F(InertiaCli, UsageErrorsExitTwo) {
  const fs::path file = write("plate.yaml", kPlate);
  const fs::path obj = write_obj("block.obj", test::box_mesh(Vec3(1, 1, 1)));
  const std::string f = quoted(file.string());
  for (const std::string& args : {
           std::string("inertia"),                                       // No FILE.
           "inertia " + f + " --frobnicate",                             // Unknown option.
           "inertia " + f + " --frame sideways",                         // Not a frame.
           "inertia " + f + " --about 1 2",                              // Two coordinates.
           "inertia " + f + " --density -5",                             // Not positive.
           "inertia " + f + " --scale 0.001",                            // Mesh-only option.
           "inertia " + f + " --mass 3",                                 // Mesh-only option.
           "inertia " + quoted(obj.string()) + " --mass 1 --density 2",  // Both.
           std::string("frobnicate"),                                    // No such command.
       }) {
    SCOPED_TRACE(args);
    const CliRun r = momenta(args);
    EXPECT_EQ(r.code, 2) << r.out << r.err;
    EXPECT_FALSE(r.err.empty());
  }
}

TEST_F(InertiaCli, BundledExamplesRun) {
  // Their numbers are checked in tests/validation/io/example_parts_test.cpp; here, that the CLI
  // prints them as JSON equal to the library's.
  for (const char* name : {"flanged_shaft", "bracket", "flywheel", "satellite"}) {
    SCOPED_TRACE(name);
    const std::string file = test::source_dir() + "/examples/parts/" + name + ".yaml";
    const CliRun r = momenta("inertia " + quoted(file) + " --json");
    ASSERT_EQ(r.code, 0) << r.err;
    const json j = json::parse(r.out);
    const inertia::MassProperties mp = io::read_part_file(file).total;
    EXPECT_EQ(j.at("mass").get<double>(), mp.mass());
    EXPECT_EQ(mat(j.at("inertia_com")), mp.inertia_about_com());
  }
}

TEST_F(InertiaCli, HelpShowsAnExample) {
  const CliRun r = momenta("inertia --help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("Examples:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("momenta inertia examples/parts/"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--frame"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace momenta
