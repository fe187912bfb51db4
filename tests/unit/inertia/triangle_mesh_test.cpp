#include "momenta/inertia/triangle_mesh.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta_test/meshes.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::inertia {
namespace {

using test::Tri;

// The message of the MeshError `f` throws (fails the test if it throws none).
template <typename F>
std::string mesh_error(F&& f) {
  try {
    f();
  } catch (const MeshError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected MeshError";
  return {};
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(WeldVertices, UnweldedMeshWeldsBackToItsTopology) {
  const TriangleMesh sphere = test::uv_ellipsoid(Vec3(1, 1, 1), 8, 12);
  const TriangleMesh soup = test::unwelded(sphere);
  ASSERT_EQ(soup.vertices.size(), 3 * sphere.triangles.size());
  const TriangleMesh welded = weld_vertices(soup, 0.0);
  EXPECT_EQ(welded.vertices.size(), sphere.vertices.size());
  EXPECT_EQ(welded.triangles.size(), sphere.triangles.size());
  // Same triangles, as coordinates.
  for (std::size_t t = 0; t < sphere.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(welded.vertices[welded.triangles[t][k]], sphere.vertices[sphere.triangles[t][k]]);
    }
  }
  EXPECT_TRUE(analyze_topology(welded).is_closed_manifold());
  EXPECT_FALSE(analyze_topology(soup).is_closed_manifold());
}

TEST(WeldVertices, ToleranceMergesNearbyVerticesAcrossCells) {
  TriangleMesh soup = test::unwelded(test::box_mesh(Vec3(1, 2, 3)));
  // Jitter every copy by up to 1e-9 m in every direction, so copies straddle grid cells.
  for (std::size_t i = 0; i < soup.vertices.size(); ++i) {
    const double j = 1e-9 * std::sin(1.7 * static_cast<double>(i));
    soup.vertices[i] += Vec3(j, -j, 0.5 * j);
  }
  EXPECT_EQ(weld_vertices(soup, 1e-6).vertices.size(), 8u);
  EXPECT_TRUE(analyze_topology(weld_vertices(soup, 1e-6)).is_closed_manifold());
  // Below the jitter nothing merges but exact repeats.
  EXPECT_GT(weld_vertices(soup, 1e-12).vertices.size(), 8u);
  // The first occurrence's coordinates are kept.
  EXPECT_EQ(weld_vertices(soup, 1e-6).vertices[0], soup.vertices[0]);
}

TEST(WeldVertices, DropsTrianglesThatCollapseAndRejectsBadInput) {
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1e-9, 0, 0)};
  m.triangles = {Tri{0, 1, 2}, Tri{0, 3, 2}};
  // 3 merges into 0 at 1e-6: the second triangle repeats a vertex and goes.
  const TriangleMesh w = weld_vertices(m, 1e-6);
  EXPECT_EQ(w.vertices.size(), 3u);
  EXPECT_EQ(w.triangles.size(), 1u);
  EXPECT_THROW(weld_vertices(m, -1.0), InvalidArgument);
  EXPECT_THROW(weld_vertices(m, std::numeric_limits<double>::quiet_NaN()), InvalidArgument);
  TriangleMesh bad_index = m;
  bad_index.triangles.push_back(Tri{0, 1, 4});
  EXPECT_TRUE(contains(mesh_error([&] { weld_vertices(bad_index, 0.0); }), "vertex 4"));
  TriangleMesh bad_vertex = m;
  bad_vertex.vertices[2].y() = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(contains(mesh_error([&] { weld_vertices(bad_vertex, 0.0); }), "vertex 2"));
}

TEST(AnalyzeTopology, ClosedMeshesAndTheirVolume) {
  const TriangleMesh box = test::box_mesh(Vec3(1, 2, 3));
  const MeshTopology t = analyze_topology(box);
  EXPECT_TRUE(t.is_closed_manifold());
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.degenerate_triangles, 0u);
  EXPECT_TRUE(t.example.empty());
  EXPECT_NEAR(t.signed_volume, 6.0, 1e-14);
  EXPECT_NEAR(analyze_topology(test::flipped(box)).signed_volume, -6.0, 1e-14);
  // Each generated shape is closed, consistent and outward.
  for (const TriangleMesh& m :
       {test::uv_ellipsoid(Vec3(1, 2, 3), 6, 9), test::cylinder_mesh(1, 2, 7),
        test::cone_mesh(1, 2, 5), test::torus_mesh(2, 0.5, 9, 7)}) {
    const MeshTopology mt = analyze_topology(m);
    EXPECT_TRUE(mt.is_closed_manifold()) << mt.example;
    EXPECT_GT(mt.signed_volume, 0.0);
    EXPECT_EQ(mt.components, 1u);
  }
}

TEST(AnalyzeTopology, CountsComponents) {
  TriangleMesh two = test::box_mesh(Vec3(1, 1, 1));
  const TriangleMesh other = test::moved(two, Mat3::Identity(), Vec3(5, 0, 0));
  const auto base = static_cast<std::int32_t>(two.vertices.size());
  two.vertices.insert(two.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (const auto& t : other.triangles)
    two.triangles.push_back(Tri{t[0] + base, t[1] + base, t[2] + base});
  const MeshTopology t = analyze_topology(two);
  EXPECT_EQ(t.components, 2u);
  EXPECT_TRUE(t.is_closed_manifold());
  EXPECT_NEAR(t.signed_volume, 2.0, 1e-14);
}

TEST(AnalyzeTopology, FindsEachDefect) {
  // Open: one triangle removed leaves a hole of 3 boundary edges.
  TriangleMesh open = test::box_mesh(Vec3(1, 1, 1));
  open.triangles.pop_back();
  const MeshTopology o = analyze_topology(open);
  EXPECT_EQ(o.boundary_edges, 3u);
  EXPECT_EQ(o.non_manifold_edges, 0u);
  EXPECT_EQ(o.inconsistent_edges, 0u);
  EXPECT_TRUE(contains(o.example, "used by triangle")) << o.example;

  // Inconsistent: one triangle wound the other way disagrees with its 3 neighbours.
  TriangleMesh twisted = test::box_mesh(Vec3(1, 1, 1));
  std::swap(twisted.triangles[3][1], twisted.triangles[3][2]);
  const MeshTopology i = analyze_topology(twisted);
  EXPECT_EQ(i.inconsistent_edges, 3u);
  EXPECT_EQ(i.boundary_edges, 0u);
  EXPECT_TRUE(contains(i.example, "same direction")) << i.example;

  // Non-manifold: a fin on an existing edge (0, 4) makes it shared by 3 triangles and adds 2
  // boundary edges.
  TriangleMesh fin = test::box_mesh(Vec3(1, 1, 1));
  fin.vertices.emplace_back(-1.5, -1.5, 0);
  fin.triangles.push_back(Tri{0, 4, 8});
  const MeshTopology n = analyze_topology(fin);
  EXPECT_EQ(n.non_manifold_edges, 1u);
  EXPECT_EQ(n.boundary_edges, 2u);
  EXPECT_TRUE(contains(n.example, "shared by 3 triangles")) << n.example;

  // Degenerate: a repeated index is counted and its edges ignored.
  TriangleMesh degenerate = test::box_mesh(Vec3(1, 1, 1));
  degenerate.triangles.push_back(Tri{0, 0, 1});
  const MeshTopology d = analyze_topology(degenerate);
  EXPECT_EQ(d.degenerate_triangles, 1u);
  EXPECT_TRUE(d.is_closed_manifold());
  EXPECT_TRUE(contains(d.example, "degenerate triangle 12")) << d.example;

  TriangleMesh bad = test::box_mesh(Vec3(1, 1, 1));
  bad.triangles[5][1] = -1;
  EXPECT_TRUE(contains(mesh_error([&] { analyze_topology(bad); }), "triangle 5"));
}

TEST(PrepareSolidMesh, AcceptsClosedFlipsInsideOut) {
  TriangleMesh box = test::unwelded(test::box_mesh(Vec3(1, 2, 3)));
  EXPECT_FALSE(prepare_solid_mesh(box, "box"));
  EXPECT_EQ(box.vertices.size(), 8u);  // Welded.
  TriangleMesh inside_out = test::flipped(test::box_mesh(Vec3(1, 2, 3)));
  EXPECT_TRUE(prepare_solid_mesh(inside_out, "inside-out box"));
  EXPECT_NEAR(analyze_topology(inside_out).signed_volume, 6.0, 1e-14);
}

TEST(PrepareSolidMesh, NamesTheMeshAndTheDefect) {
  TriangleMesh open = test::box_mesh(Vec3(1, 1, 1));
  open.triangles.pop_back();
  std::string what = mesh_error([&] { prepare_solid_mesh(open, "bracket.stl"); });
  EXPECT_TRUE(contains(what, "bracket.stl")) << what;
  EXPECT_TRUE(contains(what, "3 open boundary edges")) << what;
  EXPECT_TRUE(contains(what, "edge between vertices")) << what;

  TriangleMesh twisted = test::box_mesh(Vec3(1, 1, 1));
  std::swap(twisted.triangles[3][1], twisted.triangles[3][2]);
  what = mesh_error([&] { prepare_solid_mesh(twisted, "twisted"); });
  EXPECT_TRUE(contains(what, "3 inconsistently oriented edges")) << what;

  TriangleMesh fin = test::box_mesh(Vec3(1, 1, 1));
  fin.vertices.emplace_back(-1.5, -1.5, 0);
  fin.triangles.push_back(Tri{0, 4, 8});
  what = mesh_error([&] { prepare_solid_mesh(fin, "fin"); });
  EXPECT_TRUE(contains(what, "1 non-manifold edges")) << what;
  EXPECT_TRUE(contains(what, "2 open boundary edges")) << what;

  // Closed but flat: a triangle and its reverse enclose nothing.
  TriangleMesh flat;
  flat.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  flat.triangles = {Tri{0, 1, 2}, Tri{0, 2, 1}};
  what = mesh_error([&] { prepare_solid_mesh(flat, "flat"); });
  EXPECT_TRUE(contains(what, "encloses no volume")) << what;

  TriangleMesh empty;
  EXPECT_TRUE(contains(mesh_error([&] { prepare_solid_mesh(empty, "empty"); }), "no triangles"));
  TriangleMesh collapsed;
  collapsed.vertices = {Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, 0, 0)};
  collapsed.triangles = {Tri{0, 1, 2}};
  EXPECT_TRUE(contains(mesh_error([&] { prepare_solid_mesh(collapsed, "c"); }), "degenerate"));
  TriangleMesh nan_vertex = test::box_mesh(Vec3(1, 1, 1));
  nan_vertex.vertices[3].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(contains(mesh_error([&] { prepare_solid_mesh(nan_vertex, "nan"); }), "'nan'"));
}

}  // namespace
}  // namespace momenta::inertia
