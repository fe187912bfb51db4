#include "momenta/io/part_file.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta_test/meshes.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::io {
namespace {

using inertia::MassProperties;
constexpr double kPi = std::numbers::pi;

// Every composite below is a handful of closed-form parts composed by the parallel-axis theorem;
// the hand formulas and the library differ only by the order of a few dozen roundings, so 1e-13
// relative (of the largest entry) is ample and still catches any wrong term.
constexpr double kRel = 1e-13;

CompositePart parse(const std::string& yaml, const PartFileOptions& options = {}) {
  return parse_part_file(yaml, "t.yaml", std::filesystem::temp_directory_path(), options);
}

// The ParseError message for a part file, or a failure if it parses.
std::string error_of(const std::string& yaml, const std::filesystem::path& base_dir =
                                                  std::filesystem::temp_directory_path()) {
  try {
    parse_part_file(yaml, "t.yaml", base_dir);
  } catch (const ParseError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    return message;
  }
  ADD_FAILURE() << "no ParseError for:\n" << yaml;
  return "";
}

void expect_same(const MassProperties& a, const MassProperties& b, double rel = kRel) {
  EXPECT_REL_NEAR(a.mass(), b.mass(), rel);
  EXPECT_REL_NEAR(a.volume(), b.volume(), rel);
  // Centre of mass errors scale with the body: its distance from the origin or its radius of
  // gyration, whichever is larger.
  const double gyration = std::sqrt(b.inertia_about_com().trace() / (2 * b.mass()));
  const double length = std::max(b.center_of_mass().norm(), gyration);
  EXPECT_MATRIX_NEAR(a.center_of_mass(), b.center_of_mass(), rel * length);
  EXPECT_MATRIX_NEAR(a.inertia_about_com(), b.inertia_about_com(),
                     rel * b.inertia_about_com().cwiseAbs().maxCoeff());
}

// A folder of its own for the mesh files a test writes.
std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("momenta_part_file_test_" + name);
  std::filesystem::create_directories(dir);
  return dir;
}

void write_obj(const std::filesystem::path& path, const inertia::TriangleMesh& mesh) {
  std::ofstream out(path);
  out.precision(17);
  for (const Vec3& v : mesh.vertices) out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const auto& t : mesh.triangles) {
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  }
}

TEST(PartFile, BoxByDensityPlacedAndRotated) {
  // A 0.2 × 0.1 × 0.05 m steel box at (1, 2, 3) turned 90° about z: its x edge lies along B's y.
  const CompositePart part = parse(R"(
name: block
parts:
  - shape: box
    size: [0.2, 0.1, 0.05]
    density: 7850
    position: [1, 2, 3]
    euler: {sequence: ZYX, angles_deg: [90, 0, 0]}
)");
  EXPECT_EQ(part.name, "block");
  ASSERT_EQ(part.parts.size(), 1u);
  EXPECT_EQ(part.parts[0].kind, "box");
  EXPECT_EQ(part.parts[0].name, "parts[0]");
  EXPECT_EQ(part.parts[0].line, 4);
  const double a = 0.2, b = 0.1, c = 0.05, m = 7850 * a * b * c;
  // Turned: B's x sees the box's y edge and vice versa.
  const Mat3 I = Vec3(m * (a * a + c * c) / 12, m * (b * b + c * c) / 12, m * (a * a + b * b) / 12)
                     .asDiagonal();
  expect_same(part.total, MassProperties(m, Vec3(1, 2, 3), I, a * b * c));
}

TEST(PartFile, DumbbellAgainstClosedForm) {
  // Two 2 kg spheres (r = 0.05 m) at x = ±0.3 m on a 1 kg rod 0.6 m long along x, the whole
  // dumbbell lifted by 0.5 m along z.
  const CompositePart part = parse(R"(
name: dumbbell
parts:
  - {name: left, shape: sphere, radius: 0.05, mass: 2, position: [-0.3, 0, 0.5]}
  - {name: right, shape: sphere, radius: 0.05, mass: 2, position: [0.3, 0, 0.5]}
  - name: bar
    shape: slender_rod
    length: 0.6
    mass: 1
    position: [0, 0, 0.5]
    euler: {sequence: ZYX, angles_deg: [0, 90, 0]}   # the rod's z axis onto B's x
)");
  const double ms = 2, r = 0.05, d = 0.3, mr = 1, L = 0.6;
  const double axial = 2 * (0.4 * ms * r * r);
  const double transverse = 2 * (0.4 * ms * r * r + ms * d * d) + mr * L * L / 12;
  const double volume = 2 * (4.0 / 3.0 * kPi * r * r * r);  // The rod has none.
  expect_same(part.total, MassProperties(2 * ms + mr, Vec3(0, 0, 0.5),
                                         Vec3(axial, transverse, transverse).asDiagonal(), volume));
  EXPECT_EQ(part.parts[2].name, "bar");
  EXPECT_EQ(part.parts[2].kind, "slender_rod");
}

TEST(PartFile, PlateWithAHoleAgainstClosedForm) {
  // A 300 × 200 × 10 mm steel plate with a 30 mm radius hole through it at (80, 50) mm.
  const CompositePart part = parse(R"(
units: mm
density: 7850
parts:
  - {name: plate, shape: box, size: [300, 200, 10]}
  - {name: bore, shape: cylinder, radius: 30, length: 10, position: [80, 50, 0], hole: true}
)");
  const double rho = 7850, w = 0.3, h = 0.2, t = 0.01, r = 0.03, a = 0.08, b = 0.05;
  const double M1 = rho * w * h * t, M2 = rho * kPi * r * r * t, M = M1 - M2;
  // Inertia about the plate's centre O, by hand: plate minus the hole moved by (a, b, 0).
  Mat3 I1 = Vec3(M1 * (h * h + t * t) / 12, M1 * (w * w + t * t) / 12, M1 * (w * w + h * h) / 12)
                .asDiagonal();
  Mat3 I2 = Mat3::Zero();
  I2(0, 0) = M2 * (3 * r * r + t * t) / 12 + M2 * b * b;
  I2(1, 1) = M2 * (3 * r * r + t * t) / 12 + M2 * a * a;
  I2(2, 2) = M2 * r * r / 2 + M2 * (a * a + b * b);
  I2(0, 1) = I2(1, 0) = -M2 * a * b;  // Minus the product ∫xy dm.
  const Vec3 c = -M2 * Vec3(a, b, 0) / M;
  const Mat3 I_O = I1 - I2;
  Mat3 I_com = I_O;
  I_com(0, 0) -= M * c.y() * c.y();
  I_com(1, 1) -= M * c.x() * c.x();
  I_com(2, 2) -= M * (c.x() * c.x() + c.y() * c.y());
  I_com(0, 1) += M * c.x() * c.y();
  I_com(1, 0) += M * c.x() * c.y();
  // mm → m in the file's lengths costs one rounding per length: still within kRel·10.
  expect_same(part.total, MassProperties(M, c, I_com, w * h * t - kPi * r * r * t), 10 * kRel);
  ASSERT_EQ(part.parts.size(), 2u);
  EXPECT_TRUE(part.parts[1].hole);
  EXPECT_REL_NEAR(part.parts[1].mass_properties.mass(), M2, 10 * kRel);
}

TEST(PartFile, SheetPlateWithAHoleUsesSurfaceDensity) {
  // 2 mm aluminium sheet as a thin plate (σ = 2700 · 0.002 kg/m²) with a thin-disk hole.
  const CompositePart part = parse(R"(
parts:
  - {shape: thin_plate, width: 0.4, height: 0.3, density: 5.4}
  - {shape: thin_disk, radius: 0.05, density: 5.4, position: [-0.1, 0, 0], hole: true}
)");
  const double s = 5.4, w = 0.4, h = 0.3, r = 0.05, a = -0.1;
  const double M1 = s * w * h, M2 = s * kPi * r * r, M = M1 - M2;
  const double cx = -M2 * a / M;
  const double Ixx = M1 * h * h / 12 - M2 * r * r / 4;
  const double Iyy = M1 * w * w / 12 - (M2 * r * r / 4 + M2 * a * a) - M * cx * cx;
  const double Izz = M1 * (w * w + h * h) / 12 - (M2 * r * r / 2 + M2 * a * a) - M * cx * cx;
  expect_same(part.total, MassProperties(M, Vec3(cx, 0, 0), Vec3(Ixx, Iyy, Izz).asDiagonal(), 0));
}

TEST(PartFile, ThreeWaysToWriteOneRotation) {
  // 30° about the unit axis (1, 1, 1)/√3, as a matrix, a quaternion and extrinsic xyz angles.
  const Vec3 axis = Vec3(1, 1, 1).normalized();
  const double angle = kPi / 6;
  const Mat3 R = rotation_from_axis_angle(axis, angle);
  const Quat q(Eigen::AngleAxisd(angle, axis));
  const Vec3 xyz = R.eulerAngles(2, 1, 0).reverse();  // R = Rz(c) Ry(b) Rx(a) → extrinsic xyz.
  const std::string body = "  - {shape: ellipsoid, semi_axes: [0.3, 0.2, 0.1], mass: 4, ";
  const auto with = [&](const std::string& pose) {
    return parse("parts:\n" + body + pose + "}\n").total;
  };
  const MassProperties expected =
      inertia::ellipsoid(inertia::Amount::mass(4), Vec3(0.3, 0.2, 0.1)).re_expressed(R);
  expect_same(with(fmt::format("rotation: [[{:.17g}, {:.17g}, {:.17g}], [{:.17g}, {:.17g}, "
                               "{:.17g}], [{:.17g}, {:.17g}, {:.17g}]]",
                               R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0),
                               R(2, 1), R(2, 2))),
              expected, 1e-14);
  expect_same(with(fmt::format("quaternion: [{:.17g}, {:.17g}, {:.17g}, {:.17g}]", q.w(), q.x(),
                               q.y(), q.z())),
              expected, 1e-14);
  expect_same(with(fmt::format("euler: {{sequence: xyz, angles: [{:.17g}, {:.17g}, {:.17g}]}}",
                               xyz[0], xyz[1], xyz[2])),
              expected, 1e-14);
}

TEST(PartFile, HandWrittenRotationIsAcceptedToSixDigitsAndMadeExact) {
  // cos 45° to 7 digits: off by 2e-8, accepted and replaced by the nearest rotation.
  const CompositePart part = parse(R"(
parts:
  - shape: box
    size: [1, 2, 3]
    mass: 1
    rotation: [[0.7071068, -0.7071068, 0], [0.7071068, 0.7071068, 0], [0, 0, 1]]
)");
  const MassProperties expected =
      inertia::box(inertia::Amount::mass(1), Vec3(1, 2, 3))
          .re_expressed(rotation_from_axis_angle(Vec3::UnitZ(), kPi / 4));
  expect_same(part.total, expected, 1e-14);
}

TEST(PartFile, ExplicitInertiaPart) {
  // A motor given by its datasheet: 1.5 kg, centre of mass 20 mm up, its own inertia tensor.
  const CompositePart part = parse(R"(
units: mm
parts:
  - name: motor
    inertia:
      mass: 1.5
      com: [0, 0, 20]
      tensor: [[2e-3, -1e-4, 0], [-1e-4, 3e-3, 0], [0, 0, 1.5e-3]]
    position: [100, 0, 0]
)");
  Mat3 I;
  I << 2e-3, -1e-4, 0, -1e-4, 3e-3, 0, 0, 0, 1.5e-3;
  expect_same(part.total, MassProperties(1.5, Vec3(0.1, 0, 0.02), I, 0), 1e-15);
  EXPECT_EQ(part.parts[0].kind, "inertia");
  const CompositePart diagonal = parse("parts:\n  - inertia: {mass: 2, moments: [1, 2, 2.5]}\n");
  expect_same(diagonal.total, MassProperties(2, Vec3::Zero(), Vec3(1, 2, 2.5).asDiagonal(), 0), 0);
}

TEST(PartFile, DefaultDensityAndItsOverride) {
  const std::string yaml = "density: 1000\nparts:\n  - {shape: sphere, radius: 0.1}\n";
  const double volume = 4.0 / 3.0 * kPi * 1e-3;
  EXPECT_REL_NEAR(parse(yaml).total.mass(), 1000 * volume, 1e-15);
  EXPECT_REL_NEAR(parse(yaml, {.default_density = 2700}).total.mass(), 2700 * volume, 1e-15);
  // Without any density the solid needs one.
  EXPECT_NE(error_of("parts:\n  - {shape: sphere, radius: 0.1}\n")
                .find("t.yaml:2:5: parts[0]: sphere needs a 'mass' (kg) or a 'density' (kg/m³)"),
            std::string::npos);
  // A thin shape never takes the solids' default.
  EXPECT_NE(error_of("density: 1000\nparts:\n  - {shape: thin_disk, radius: 0.1}\n")
                .find("thin_disk is thin: it needs a 'mass' (kg) or its own 'density' (kg/m²)"),
            std::string::npos);
  EXPECT_THROW(parse(yaml, {.default_density = -1}), InvalidArgument);
}

TEST(PartFile, EveryPrimitiveMatchesTheLibrary) {
  namespace in = inertia;
  using in::Amount;
  const Amount m = Amount::mass(3);
  const struct {
    std::string yaml;
    MassProperties expected;
  } cases[] = {
      {"shape: point_mass", in::point_mass(3)},
      {"shape: slender_rod, length: 2", in::slender_rod(m, 2)},
      {"shape: thin_ring, radius: 0.5", in::thin_ring(m, 0.5)},
      {"shape: thin_disk, radius: 0.5", in::thin_disk(m, 0.5)},
      {"shape: annulus, inner_radius: 0.2, outer_radius: 0.5", in::annulus(m, 0.2, 0.5)},
      {"shape: cylinder, radius: 0.5, length: 2", in::solid_cylinder(m, 0.5, 2)},
      {"shape: hollow_cylinder, inner_radius: 0, outer_radius: 0.5, length: 2",
       in::hollow_cylinder(m, 0, 0.5, 2)},
      {"shape: cylindrical_shell, radius: 0.5, length: 2", in::cylindrical_shell(m, 0.5, 2)},
      {"shape: sphere, radius: 0.5", in::solid_sphere(m, 0.5)},
      {"shape: hollow_sphere, inner_radius: 0.4, outer_radius: 0.5",
       in::hollow_sphere(m, 0.4, 0.5)},
      {"shape: spherical_shell, radius: 0.5", in::spherical_shell(m, 0.5)},
      {"shape: box, size: [1, 2, 3]", in::box(m, Vec3(1, 2, 3))},
      {"shape: thin_plate, width: 1, height: 2", in::thin_rectangular_plate(m, 1, 2)},
      {"shape: cone, radius: 0.5, height: 2", in::solid_cone(m, 0.5, 2)},
      {"shape: ellipsoid, semi_axes: [1, 2, 3]", in::ellipsoid(m, Vec3(1, 2, 3))},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.yaml);
    expect_same(parse("parts:\n  - {mass: 3, " + c.yaml + "}\n").total, c.expected, 0);
  }
}

TEST(PartFile, MeshPartsSolidShellAndScaled) {
  const auto dir = scratch_dir("mesh");
  // A 100 × 60 × 40 mm box drawn in millimetres.
  write_obj(dir / "block.obj", test::box_mesh(Vec3(100, 60, 40)));
  const auto read = [&](const std::string& yaml) {
    return parse_part_file(yaml, (dir / "p.yaml").string(), dir).total;
  };
  // Solid, by density, scale from the file's units: the mesh's integrals are exact, so only the
  // float storage of the OBJ coordinates (exact here: integers) and round-off remain.
  expect_same(read("units: mm\nparts:\n  - {mesh: block.obj, density: 2700}\n"),
              inertia::box(inertia::Amount::density(2700), Vec3(0.1, 0.06, 0.04)), 1e-13);
  // An explicit scale wins over the units; mass instead of density.
  expect_same(read("parts:\n  - {mesh: block.obj, scale: 0.001, mass: 2, position: [0, 0, 1]}\n"),
              inertia::box(inertia::Amount::mass(2), Vec3(0.1, 0.06, 0.04))
                  .transformed(Mat3::Identity(), Vec3(0, 0, 1)),
              1e-13);
  // A thin shell over a cube's surface: 6 plates, I = 5/18 M a² about every axis (by hand: the
  // two faces normal to an axis give 2 · m a²/6, the four others 4 · (m a²/12 + m a²/4)).
  write_obj(dir / "cube.obj", test::box_mesh(Vec3(1, 1, 1)));
  const MassProperties shell = read("parts:\n  - {mesh: cube.obj, shell: true, density: 2}\n");
  const double M = 6 * 2.0;
  expect_same(shell, MassProperties(M, Vec3::Zero(), (5.0 / 18.0 * M) * Mat3::Identity(), 0),
              1e-14);
}

TEST(PartFile, MeshErrorsNameTheMeshKey) {
  const auto dir = scratch_dir("mesh_errors");
  inertia::TriangleMesh open = test::box_mesh(Vec3(1, 1, 1));
  open.triangles.pop_back();
  write_obj(dir / "open.obj", open);
  const std::string missing = error_of("parts:\n  - {mesh: nothere.stl, density: 1}\n", dir);
  EXPECT_NE(missing.find("t.yaml:2:12: parts[0].mesh: "), std::string::npos) << missing;
  EXPECT_NE(missing.find("nothere.stl: mesh file not found"), std::string::npos) << missing;
  const std::string open_error = error_of("parts:\n  - {mesh: open.obj, density: 1}\n", dir);
  EXPECT_NE(open_error.find("t.yaml:2:12: parts[0].mesh: "), std::string::npos) << open_error;
  EXPECT_NE(open_error.find("open"), std::string::npos) << open_error;
  // An open mesh is fine as a shell.
  EXPECT_NO_THROW(
      parse_part_file("parts:\n  - {mesh: open.obj, shell: true, mass: 1}\n", "t.yaml", dir));
}

TEST(PartFile, ErrorsNameFileLineAndKey) {
  struct Case {
    std::string yaml;
    std::string expected;  // A piece of the message, from its file:line:column on.
  };
  const Case cases[] = {
      {"parts: [1, 2\n", "t.yaml:2:1: malformed YAML"},
      {"", "t.yaml: the file holds no YAML document"},
      {"parts:\n  - {shape: box, sise: [1, 1, 1], mass: 1}\n",
       "t.yaml:2:18: parts[0]: unknown key 'sise' (did you mean 'size'?)"},
      {"parts:\n  - {shap: box, size: [1, 1, 1], mass: 1}\n",
       "t.yaml:2:6: parts[0]: unknown key 'shap' (did you mean 'shape'?)"},
      {"name: x\nprts: []\n", "t.yaml:2:1: unknown key 'prts' (did you mean 'parts'?)"},
      {"parts:\n  - {shape: cylnder, radius: 1, length: 1, mass: 1}\n",
       "t.yaml:2:13: parts[0].shape: unknown shape 'cylnder' (did you mean 'cylinder'?)"},
      {"parts:\n  - {shape: sphere, radius: 0.1, mass: 0}\n",
       "t.yaml:2:40: parts[0].mass: must be positive, got 0"},
      {"parts:\n  - {shape: sphere, radius: 0.1, mass: -2}\n",
       "t.yaml:2:40: parts[0].mass: must be positive, got -2"},
      {"parts:\n  - {shape: sphere, radius: 0, mass: 1}\n",
       "t.yaml:2:29: parts[0].radius: must be positive, got 0"},
      {"parts:\n  - {shape: box, size: [1, -1, 1], mass: 1}\n",
       "t.yaml:2:28: parts[0].size[1]: must be positive, got -1"},
      {"parts:\n  - {shape: sphere, radius: 0.1, density: -7850}\n",
       "parts[0].density: must be positive, got -7850"},
      {"parts:\n  - {shape: sphere, radius: 0.1, mass: 1, density: 2}\n",
       "t.yaml:2:43: parts[0]: give only one of 'mass', 'density'"},
      {"parts:\n  - {shape: annulus, inner_radius: 0.5, outer_radius: 0.5, mass: 1}\n",
       "parts[0].inner_radius: inner_radius 0.5 must be below outer_radius 0.5"},
      {"parts:\n  - {shape: box, size: [1, 1, 1], mass: 1, rotation: [[1, 0, 0], [0, 1, 0], [0, 0, "
       "2]]}\n",
       "t.yaml:2:54: parts[0].rotation: this matrix is not a rotation matrix"},
      {"parts:\n  - {shape: box, size: [1, 1, 1], mass: 1, quaternion: [1, 0, 0, 0.1]}\n",
       "t.yaml:2:56: parts[0].quaternion: this quaternion [1, 0, 0, 0.1] has norm"},
      {"parts:\n  - {shape: box, size: [1, 1, 1], mass: 1, euler: {sequence: XYW, angles: [0, 0, "
       "0]}}\n",
       "parts[0].euler.sequence:"},
      {"parts:\n  - {shape: box, size: [1, 1, 1], mass: 1, euler: {sequence: XYZ}}\n",
       "parts[0].euler: missing required key 'angles' (radians) or 'angles_deg' (degrees)"},
      {"parts:\n  - inertia: {mass: 1, tensor: [[1, 0, 0], [0, 1, 0], [0, 0, 3]]}\n",
       "t.yaml:2:32: parts[0].inertia.tensor: explicit inertia: principal moments 1, 1, 3 kg·m² "
       "violate the "
       "triangle inequality"},
      {"parts:\n  - inertia: {mass: 1, tensor: [[1, 2, 0], [2, 1, 0], [0, 0, 1]]}\n",
       "parts[0].inertia.tensor: explicit inertia: inertia"},
      {"parts:\n  - inertia: {mass: 0, moments: [1, 1, 1]}\n",
       "parts[0].inertia.mass: must be positive, got 0"},
      {"parts:\n  - {shape: box, size: [1, 1, 1], mass: 1}\n  - {shape: box, size: [2, 2, 2], "
       "mass: "
       "2, hole: true}\n",
       "t.yaml:3:5: parts[1]: hole 'parts[1]' leaves no physical body"},
      {"parts:\n  - {shape: box, size: [1, 1, 1], mass: 1, hole: true}\n",
       "t.yaml:2:3: parts: every part is a hole"},
      {"parts: []\n", "t.yaml:1:8: parts: the list of parts is empty"},
      {"units: inch\nparts: []\n", "t.yaml:1:8: units: unknown length unit 'inch'"},
      {"parts:\n  - {size: [1, 1, 1], mass: 1}\n",
       "t.yaml:2:5: parts[0]: a part needs one of 'shape' (a primitive), 'mesh' (a mesh file) or "
       "'inertia'"},
      {"parts:\n  - {shape: point_mass, density: 3}\n",
       "parts[0].density: a point mass has no size: give its 'mass' instead"},
      {"parts:\n  - {shape: sphere, radius: 1, length: 2, mass: 1}\n",
       "parts[0]: unknown key 'length'"},
      {"parts:\n  - {shape: box, size: [1, 1, 1], mass: 1, hole: maybe}\n",
       "parts[0].hole: expected true or false, got 'maybe'"},
      {"- a\n- b\n", "t.yaml:1:1: expected a part file: a map with a 'parts' list, got a list"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.yaml);
    const std::string message = error_of(c.yaml);
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
}

TEST(PartFile, HoleThatBreaksTheBodyIsNamed) {
  // Two holes: the first fits; the second, 0.5 kg of the 0.99 kg left but 2 m outside the disk,
  // leaves a positive mass (0.49 kg) with negative moments of inertia about its centre of mass.
  const std::string message = error_of(R"(
parts:
  - {name: disk, shape: cylinder, radius: 0.1, length: 0.01, mass: 1}
  - {name: pin, shape: cylinder, radius: 0.01, length: 0.01, mass: 0.01, hole: true}
  - {name: ghost, shape: sphere, radius: 0.01, mass: 0.5, position: [2, 0, 0], hole: true}
)");
  EXPECT_NE(message.find("t.yaml:5:5: parts[2]: hole 'ghost' leaves no physical body"),
            std::string::npos)
      << message;
}

TEST(PartFile, ReadsFilesAndResolvesMeshesBesideThem) {
  const auto dir = scratch_dir("file");
  write_obj(dir / "unit.obj", test::box_mesh(Vec3(1, 1, 1)));
  {
    std::ofstream out(dir / "p.yaml");
    out << "parts:\n  - {mesh: unit.obj, mass: 6}\n";
  }
  const CompositePart part = read_part_file(dir / "p.yaml");
  EXPECT_EQ(part.name, "p");
  expect_same(part.total, MassProperties(6, Vec3::Zero(), Mat3::Identity(), 1), 1e-15);
  EXPECT_THROW(read_part_file(dir / "absent.yaml"), FileError);
}

}  // namespace
}  // namespace momenta::io
