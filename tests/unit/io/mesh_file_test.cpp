#include "momenta/io/mesh_file.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/inertia/mesh_mass_properties.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta_test/meshes.hpp"
#include "momenta_test/scratch_dir.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::io {
namespace {

namespace fs = std::filesystem;
using inertia::Amount;
using inertia::MassProperties;
using inertia::TriangleMesh;

// A fresh directory per test for the files it writes, removed afterwards.
class MeshFile : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::make_scratch_dir("mesh_file"); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path file(const std::string& name) const { return dir_ / name; }
  fs::path dir_;
};

// The mesh with its coordinates rounded to float, as an STL file stores them.
TriangleMesh as_floats(TriangleMesh m) {
  // Through a volatile float: at -O2 and above GCC 12 was seen to drop the double → float → double
  // round trip here (and Eigen's cast<float>().cast<double>() with it).
  for (Vec3& p : m.vertices) {
    for (int i = 0; i < 3; ++i) {
      volatile float f = static_cast<float>(p[i]);
      p[i] = f;
    }
  }
  return m;
}

TriangleMesh scaled(TriangleMesh m, double scale) {
  for (Vec3& p : m.vertices) p *= scale;
  return m;
}

// Writes a binary STL: 80-byte header, triangle count, 50 bytes per triangle.
void write_binary_stl(const fs::path& path, const TriangleMesh& m,
                      const std::string& header = "momenta test") {
  std::ofstream out(path, std::ios::binary);
  char head[80] = {};
  std::memcpy(head, header.data(), std::min<std::size_t>(header.size(), 80));
  out.write(head, 80);
  const auto n = static_cast<std::uint32_t>(m.triangles.size());
  out.write(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : m.triangles) {
    const Vec3 normal = (m.vertices[t[1]] - m.vertices[t[0]])
                            .cross(m.vertices[t[2]] - m.vertices[t[0]])
                            .normalized();
    float data[12];
    for (int i = 0; i < 3; ++i) data[i] = static_cast<float>(normal[i]);
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i < 3; ++i) data[3 + 3 * k + i] = static_cast<float>(m.vertices[t[k]][i]);
    }
    out.write(reinterpret_cast<const char*>(data), sizeof data);
    const std::uint16_t attribute = 0;
    out.write(reinterpret_cast<const char*>(&attribute), 2);
  }
}

void write_ascii_stl(const fs::path& path, const TriangleMesh& m, bool close = true) {
  std::ofstream out(path);
  out << "solid test\n";
  for (const auto& t : m.triangles) {
    out << "  facet normal 0 0 0\n    outer loop\n";
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = m.vertices[t[k]];
      out << fmt::format("      vertex {:.9g} {:.9g} {:.9g}\n", static_cast<float>(p.x()),
                         static_cast<float>(p.y()), static_cast<float>(p.z()));
    }
    out << "    endloop\n  endfacet\n";
  }
  if (close) out << "endsolid test\n";
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

template <typename E, typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an exception";
  return {};
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

::testing::AssertionResult same_mass_properties(const MassProperties& a, const MassProperties& b,
                                                double rel) {
  const double scale = b.inertia_about_com().cwiseAbs().maxCoeff();
  if (!test::relatively_near(a.mass(), b.mass(), rel))
    return test::relatively_near(a.mass(), b.mass(), rel);
  auto com = test::matrices_near(a.center_of_mass(), b.center_of_mass(), rel);
  if (!com) return com;
  return test::matrices_near(a.inertia_about_com(), b.inertia_about_com(), rel * scale);
}

// A sphere drawn in millimetres, written as binary STL and read with scale 0.001, welds back to
// its own topology and integrates to exactly what the same float coordinates give in memory.
TEST_F(MeshFile, BinaryStlInMillimetres) {
  const TriangleMesh sphere_mm = test::uv_ellipsoid(Vec3(50, 50, 50), 24, 48);
  write_binary_stl(file("sphere.stl"), sphere_mm);
  TriangleMesh read = read_mesh_file(file("sphere.stl"), 0.001);
  EXPECT_EQ(read.vertices.size(), sphere_mm.vertices.size());
  EXPECT_EQ(read.triangles.size(), sphere_mm.triangles.size());
  EXPECT_FALSE(inertia::prepare_solid_mesh(read, "sphere.stl"));
  const MassProperties from_file = inertia::solid_mesh_mass_properties(read, Amount::density(7850));
  const MassProperties in_memory = inertia::solid_mesh_mass_properties(
      scaled(as_floats(sphere_mm), 0.001), Amount::density(7850));
  // Same coordinates, same arithmetic up to the summation order of the welded mesh: ~1e-15.
  EXPECT_TRUE(same_mass_properties(from_file, in_memory, 1e-14));
  // And the sphere itself, r = 0.05 m, to the tessellation's O(h²) error (0.7% at 24 × 48).
  const MassProperties exact = inertia::solid_sphere(Amount::density(7850), 0.05);
  EXPECT_TRUE(test::relatively_near(from_file.mass(), exact.mass(), 1e-2));
}

// Binary files often begin with "solid" too; their size tells them apart from ASCII.
TEST_F(MeshFile, BinaryStlWhoseHeaderSaysSolid) {
  const TriangleMesh box = test::box_mesh(Vec3(1, 2, 3));
  write_binary_stl(file("box.stl"), box, "solid exported by a CAD system");
  TriangleMesh read = read_mesh_file(file("box.stl"));
  EXPECT_EQ(read.vertices.size(), 8u);
  EXPECT_EQ(read.triangles.size(), 12u);
  inertia::prepare_solid_mesh(read, "box.stl");
  EXPECT_NEAR(inertia::solid_mesh_mass_properties(read, Amount::density(1)).volume(), 6.0, 1e-14);
}

TEST_F(MeshFile, AsciiStl) {
  const TriangleMesh ellipsoid = test::uv_ellipsoid(Vec3(0.3, 0.2, 0.1), 12, 24);
  write_ascii_stl(file("ellipsoid.STL"), ellipsoid);
  TriangleMesh read = read_mesh_file(file("ellipsoid.STL"));
  EXPECT_EQ(read.vertices.size(), ellipsoid.vertices.size());
  EXPECT_FALSE(inertia::prepare_solid_mesh(read, "ellipsoid.STL"));
  // Nine significant digits of a float, parsed back: a relative 1e-7 at worst.
  EXPECT_TRUE(same_mass_properties(
      inertia::solid_mesh_mass_properties(read, Amount::mass(2)),
      inertia::solid_mesh_mass_properties(as_floats(ellipsoid), Amount::mass(2)), 1e-6));
}

// OBJ with quads: assimp triangulates them; a unit cube offset by (1, 2, 3).
TEST_F(MeshFile, ObjWithQuads) {
  write_text(file("cube.obj"),
             "# unit cube\n"
             "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
             "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  TriangleMesh read = read_mesh_file(file("cube.obj"), 2.0);
  EXPECT_EQ(read.triangles.size(), 12u);
  EXPECT_EQ(read.vertices.size(), 8u);
  EXPECT_FALSE(inertia::prepare_solid_mesh(read, "cube.obj"));
  const MassProperties p = inertia::solid_mesh_mass_properties(read, Amount::density(1));
  const MassProperties exact = inertia::box(Amount::density(1), Vec3(2, 2, 2));
  EXPECT_NEAR(p.volume(), 8.0, 1e-14);
  EXPECT_MATRIX_NEAR(p.center_of_mass(), Vec3(1, 1, 1), 1e-15);
  EXPECT_MATRIX_NEAR(p.inertia_about_com(), exact.inertia_about_com(), 1e-14);
}

// OBJ and ASCII STL are read in double precision: coordinates written with 17 significant digits
// come back bit for bit, so the mass properties equal those of the mesh in memory exactly. (Read
// through single precision, as before, the 7-decimal tetrahedron below was 6.7e-8 off in volume.)
TEST_F(MeshFile, TextFormatsKeepEveryDigit) {
  TriangleMesh tetra;
  tetra.vertices = {Vec3(0.1234567, 0.2345678, 0.3456789), Vec3(1.9876543, 0.1111111, 0.2222222),
                    Vec3(0.3333333, 1.4444444, 0.5555555), Vec3(0.6666666, 0.7777777, 1.8888888)};
  tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  const TriangleMesh body =
      test::moved(test::uv_ellipsoid(Vec3(0.3, 0.2, 0.1), 12, 24),
                  rotation_from_axis_angle(Vec3(1, 2, 3), 0.7), Vec3(0.1, -0.2, 0.3));
  for (const TriangleMesh* mesh : {static_cast<const TriangleMesh*>(&tetra), &body}) {
    std::string obj, stl = "solid exact\n";
    for (const Vec3& p : mesh->vertices)
      obj += fmt::format("v {:.17g} {:.17g} {:.17g}\n", p.x(), p.y(), p.z());
    for (const auto& t : mesh->triangles) {
      obj += fmt::format("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
      stl += "facet normal 0 0 0\nouter loop\n";
      for (int k = 0; k < 3; ++k) {
        const Vec3& p = mesh->vertices[t[k]];
        stl += fmt::format("vertex {:.17g} {:.17g} {:.17g}\n", p.x(), p.y(), p.z());
      }
      stl += "endloop\nendfacet\n";
    }
    stl += "endsolid exact\n";
    write_text(file("exact.obj"), obj);
    write_text(file("exact.stl"), stl);
    const MassProperties expected = inertia::solid_mesh_mass_properties(*mesh, Amount::density(1));
    for (const char* name : {"exact.obj", "exact.stl"}) {
      const TriangleMesh read = read_mesh_file(file(name));
      // (STL welds its repeated corners in order of appearance; OBJ keeps its own order.)
      if (std::string(name) == "exact.obj") {
        EXPECT_EQ(read.vertices, mesh->vertices);
      }
      const MassProperties got = inertia::solid_mesh_mass_properties(read, Amount::density(1));
      EXPECT_EQ(got.volume(), expected.volume()) << name;
      EXPECT_MATRIX_NEAR(got.center_of_mass(), expected.center_of_mass(), 0.0);
      EXPECT_MATRIX_NEAR(got.inertia_about_com(), expected.inertia_about_com(), 0.0);
    }
  }
  // The tetrahedron's volume against the determinant formula |det[b−a, c−a, d−a]| / 6.
  Mat3 edges;
  for (int k = 0; k < 3; ++k) edges.col(k) = tetra.vertices[k + 1] - tetra.vertices[0];
  const TriangleMesh tetra_read = [&] {
    std::string obj;
    for (const Vec3& p : tetra.vertices)
      obj += fmt::format("v {:.7f} {:.7f} {:.7f}\n", p.x(), p.y(), p.z());
    obj += "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
    write_text(file("tetra7.obj"), obj);
    return read_mesh_file(file("tetra7.obj"));
  }();
  EXPECT_TRUE(test::relatively_near(
      inertia::solid_mesh_mass_properties(tetra_read, Amount::density(1)).volume(),
      std::abs(edges.determinant()) / 6.0, 4 * test::kEps));
}

// A concave polygon face is ear-clipped in its plane: an L-shaped prism (three unit squares,
// depth 1) has volume 3 and surface area 2·3 + 8 = 14 exactly. (A fan from the first vertex
// would cover part of the L twice with opposite signs: right volume, wrong area.)
TEST_F(MeshFile, ConcavePolygonFacesAreEarClipped) {
  write_text(file("l.obj"),
             "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\n"
             "v 0 0 1\nv 2 0 1\nv 2 1 1\nv 1 1 1\nv 1 2 1\nv 0 2 1\n"
             "f 4 3 2 1 6 5\n"     // bottom, outward −z, starting at the reflex corner
             "f 7 8 9 10 11 12\n"  // top, +z
             "f 1 2 8 7\nf 2 3 9 8\nf 3 4 10 9\nf 4 5 11 10\nf 5 6 12 11\nf 6 1 7 12\n");
  TriangleMesh read = read_mesh_file(file("l.obj"));
  EXPECT_EQ(read.triangles.size(), 4u + 4u + 12u);
  EXPECT_FALSE(inertia::prepare_solid_mesh(read, "l.obj"));
  EXPECT_NEAR(inertia::solid_mesh_mass_properties(read, Amount::density(1)).volume(), 3.0, 1e-15);
  EXPECT_NEAR(inertia::shell_mesh_mass_properties(read, Amount::density(1)).mass(), 14.0, 1e-14);
}

// Text files that break their grammar are refused at the line and column of the fault.
TEST_F(MeshFile, TextFileErrorsNameTheLineAndColumn) {
  const auto error = [&](const std::string& name, const std::string& text) {
    write_text(file(name), text);
    return error_of<ParseError>([&] { read_mesh_file(file(name)); });
  };
  std::string e = error("v.obj", "v x y z\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_TRUE(contains(e, "v.obj:1:3: expected a number, got 'x'")) << e;
  e = error("f.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 5\n");
  EXPECT_TRUE(contains(e, "f.obj:4:7: face refers to vertex 5, but 3 vertices are defined")) << e;
  e = error("two.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n");
  EXPECT_TRUE(contains(e, "two.obj:3:")) << e;
  EXPECT_TRUE(contains(e, "at least 3 vertices")) << e;
  e = error("nan.stl",
            "solid a\nfacet normal 0 0 0\nouter loop\nvertex 0 0 nan\nvertex 1 0 0\n"
            "vertex 0 1 0\nendloop\nendfacet\nendsolid\n");
  EXPECT_TRUE(contains(e, "nan.stl:4:12: the coordinate 'nan' is not a finite double")) << e;
  e = error("word.stl",
            "solid a\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
            "endloop\nendfacet\nendsolid\n");
  EXPECT_TRUE(contains(e, "word.stl:6:1: expected 'vertex', got 'endloop'")) << e;
  // Negative references count back from the last vertex.
  write_text(file("neg.obj"),
             "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf -4 -2 -3\nf -4 -3 -1\n"
             "f -3 -2 -1\nf -4 -1 -2\n");
  TriangleMesh tetra = read_mesh_file(file("neg.obj"));
  EXPECT_FALSE(inertia::prepare_solid_mesh(tetra, "neg.obj"));
  EXPECT_NEAR(inertia::solid_mesh_mass_properties(tetra, Amount::density(1)).volume(), 1.0 / 6,
              1e-16);
}

// An inside-out file is repaired by prepare_solid_mesh to the same result; an open one is
// rejected with the file's name.
TEST_F(MeshFile, InsideOutAndOpenFiles) {
  const TriangleMesh box = test::box_mesh(Vec3(0.5, 0.25, 0.125));
  write_binary_stl(file("inside_out.stl"), test::flipped(box));
  TriangleMesh read = read_mesh_file(file("inside_out.stl"));
  EXPECT_TRUE(inertia::prepare_solid_mesh(read, "inside_out.stl"));
  EXPECT_TRUE(same_mass_properties(inertia::solid_mesh_mass_properties(read, Amount::density(3)),
                                   inertia::box(Amount::density(3), Vec3(0.5, 0.25, 0.125)),
                                   1e-15));
  TriangleMesh open = box;
  open.triangles.pop_back();
  write_binary_stl(file("open.stl"), open);
  TriangleMesh open_read = read_mesh_file(file("open.stl"));
  const std::string what = error_of<MeshError>(
      [&] { inertia::prepare_solid_mesh(open_read, file("open.stl").string()); });
  EXPECT_TRUE(contains(what, "open.stl")) << what;
  EXPECT_TRUE(contains(what, "3 open boundary edges")) << what;
}

TEST_F(MeshFile, TruncatedOrPaddedBinaryStlGivesBothNumbers) {
  const TriangleMesh box = test::box_mesh(Vec3(1, 1, 1));
  write_binary_stl(file("full.stl"), box);
  ASSERT_EQ(fs::file_size(file("full.stl")), 84u + 50u * 12u);
  // Cut off the last 20 bytes.
  fs::copy_file(file("full.stl"), file("truncated.stl"));
  fs::resize_file(file("truncated.stl"), 84 + 50 * 12 - 20);
  std::string what = error_of<ParseError>([&] { read_mesh_file(file("truncated.stl")); });
  EXPECT_TRUE(contains(what, "truncated.stl")) << what;
  EXPECT_TRUE(contains(what, "declares 12 triangles")) << what;
  EXPECT_TRUE(contains(what, "684 bytes")) << what;
  EXPECT_TRUE(contains(what, "664 bytes")) << what;
  // Trailing garbage: assimp alone would read this silently.
  fs::copy_file(file("full.stl"), file("padded.stl"));
  fs::resize_file(file("padded.stl"), 84 + 50 * 12 + 7);
  what = error_of<ParseError>([&] { read_mesh_file(file("padded.stl")); });
  EXPECT_TRUE(contains(what, "691 bytes")) << what;
  EXPECT_TRUE(contains(what, "too long")) << what;
  // Shorter than the header.
  write_text(file("tiny.stl"), std::string(40, '\x01'));
  what = error_of<ParseError>([&] { read_mesh_file(file("tiny.stl")); });
  EXPECT_TRUE(contains(what, "40 bytes")) << what;
}

TEST_F(MeshFile, TruncatedAsciiStl) {
  write_ascii_stl(file("cut.stl"), test::box_mesh(Vec3(1, 1, 1)), /*close=*/false);
  const std::string what = error_of<ParseError>([&] { read_mesh_file(file("cut.stl")); });
  EXPECT_TRUE(contains(what, "cut.stl")) << what;
  EXPECT_TRUE(contains(what, "endsolid")) << what;
}

// COLLADA through assimp: the mesh arm's hand, a 50 x 80 x 30 mm box written in millimetres with
// <unit meter="0.001"> and <up_axis>Z_UP: read in metres, its axes as written (not turned to y
// up), a closed solid of the box's volume to single precision (assimp keeps the unit as a float:
// two roundings of 2^-24 per length, three lengths: 4e-7).
TEST_F(MeshFile, ColladaInItsUnitAndAxes) {
  TriangleMesh hand = read_mesh_file(std::filesystem::path(test::source_dir()) /
                                     "tests/data/models/urdf/packages/mesh_arm/meshes/hand.dae");
  EXPECT_EQ(hand.vertices.size(), 8u);
  EXPECT_EQ(hand.triangles.size(), 12u);
  Vec3 extent = Vec3::Zero();
  for (const Vec3& v : hand.vertices) extent = extent.cwiseMax(v.cwiseAbs());
  EXPECT_TRUE(test::matrices_near(extent, Vec3(0.025, 0.04, 0.015), 1.2e-7 * 0.04)) << extent;
  EXPECT_FALSE(inertia::prepare_solid_mesh(hand, "hand.dae"));
  EXPECT_TRUE(
      test::relatively_near(inertia::solid_mesh_mass_properties(hand, Amount::density(1.0)).mass(),
                            0.05 * 0.08 * 0.03, 4e-7));
  // Not COLLADA inside: assimp's complaint, with the file's name.
  write_text(file("broken.dae"), "<COLLADA><library_geometries>");
  const std::string what = error_of<ParseError>([&] { read_mesh_file(file("broken.dae")); });
  EXPECT_TRUE(contains(what, "broken.dae")) << what;
  EXPECT_TRUE(contains(what, "cannot read the COLLADA file")) << what;
}

TEST_F(MeshFile, MissingEmptyAndUnsupportedFiles) {
  std::string what = error_of<FileError>([&] { read_mesh_file(file("nowhere.stl")); });
  EXPECT_TRUE(contains(what, "nowhere.stl")) << what;
  EXPECT_TRUE(contains(what, "not found")) << what;
  write_text(file("empty.stl"), "");
  what = error_of<FileError>([&] { read_mesh_file(file("empty.stl")); });
  EXPECT_TRUE(contains(what, "empty.stl")) << what;
  EXPECT_TRUE(contains(what, "empty")) << what;
  write_text(file("empty.obj"), "");
  EXPECT_THROW(read_mesh_file(file("empty.obj")), FileError);
  EXPECT_THROW(read_mesh_file(dir_), FileError);
  write_text(file("part.step"), "ISO-10303-21;");
  what = error_of<ParseError>([&] { read_mesh_file(file("part.step")); });
  EXPECT_TRUE(contains(what, "'.step'")) << what;
  // An OBJ with vertices but no faces holds no triangles.
  write_text(file("points.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  EXPECT_THROW(read_mesh_file(file("points.obj")), ParseError);
  write_binary_stl(file("box.stl"), test::box_mesh(Vec3(1, 1, 1)));
  EXPECT_THROW(read_mesh_file(file("box.stl"), 0.0), InvalidArgument);
  EXPECT_THROW(read_mesh_file(file("box.stl"), -1e-3), InvalidArgument);
}

}  // namespace
}  // namespace momenta::io
