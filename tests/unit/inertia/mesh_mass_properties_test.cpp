#include "momenta/inertia/mesh_mass_properties.hpp"

#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta_test/allocation_counter.hpp"
#include "momenta_test/meshes.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::inertia {
namespace {

using test::Tri;

::testing::AssertionResult tensors_near(const Mat3& a, const Mat3& b, double rel) {
  return test::matrices_near(a, b, rel * b.cwiseAbs().maxCoeff());
}

// A random proper rotation (uniform unit quaternion) and offset.
std::pair<Mat3, Vec3> random_pose(std::mt19937& rng, double reach) {
  std::normal_distribution<double> normal;
  const Quat q = Quat(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
  std::uniform_real_distribution<double> offset(-reach, reach);
  return {q.toRotationMatrix(), Vec3(offset(rng), offset(rng), offset(rng))};
}

// A box is a polyhedron: its mesh gives the closed form to round-off (a few ulps of ~100 flops
// per triangle on 12 triangles).
TEST(SolidMesh, BoxIsExact) {
  const Vec3 size(0.5, 0.25, 0.125);
  const MassProperties mesh = solid_mesh_mass_properties(test::box_mesh(size), Amount::density(8));
  const MassProperties exact = box(Amount::density(8), size);
  EXPECT_REL_NEAR(mesh.mass(), exact.mass(), 1e-15);
  EXPECT_REL_NEAR(mesh.volume(), exact.volume(), 1e-15);
  EXPECT_MATRIX_NEAR(mesh.center_of_mass(), Vec3::Zero(), 1e-16);
  EXPECT_TRUE(tensors_near(mesh.inertia_about_com(), exact.inertia_about_com(), 1e-15));
}

// Far from the origin (1e4 m away, box 0.5 m: coordinates exactly representable) the reference
// point at the bounding-box centre keeps the digits: integrating about the origin would lose
// (1e4 / 0.5)² ≈ 4e8 of them to cancellation in the parallel-axis shift.
TEST(SolidMesh, FarFromTheOriginKeepsItsDigits) {
  const Vec3 size(0.5, 0.25, 0.125);
  const Vec3 far(1e4, -2e4, 3e4);
  const MassProperties mesh = solid_mesh_mass_properties(
      test::moved(test::box_mesh(size), Mat3::Identity(), far), Amount::mass(3));
  const MassProperties exact = box(Amount::mass(3), size);
  EXPECT_MATRIX_NEAR(mesh.center_of_mass(), far, 1e-15 * far.norm());
  EXPECT_TRUE(tensors_near(mesh.inertia_about_com(), exact.inertia_about_com(), 1e-14));
  EXPECT_REL_NEAR(mesh.volume(), exact.volume(), 1e-15);
}

// Moving the mesh rigidly moves its mass properties: same principal moments, the centre of mass
// carried along, the tensor rotated (a random rotation and offset, repeated).
TEST(SolidMesh, RigidMotionCommutesWithIntegration) {
  std::mt19937 rng(7);
  const TriangleMesh body = test::torus_mesh(0.3, 0.1, 24, 16);
  const MassProperties here = solid_mesh_mass_properties(body, Amount::density(1000));
  for (int trial = 0; trial < 10; ++trial) {
    const auto [R, p] = random_pose(rng, 2.0);
    const MassProperties there =
        solid_mesh_mass_properties(test::moved(body, R, p), Amount::density(1000));
    const MassProperties expected = here.transformed(R, p);
    // Round-off of rotating ~800 vertices and the sums over them: ~1e-14 relative.
    EXPECT_REL_NEAR(there.mass(), here.mass(), 1e-13);
    EXPECT_MATRIX_NEAR(there.center_of_mass(), expected.center_of_mass(), 1e-13);
    EXPECT_TRUE(tensors_near(there.inertia_about_com(), expected.inertia_about_com(), 1e-13));
    EXPECT_TRUE(test::matrices_near(there.principal_axes().moments, here.principal_axes().moments,
                                    1e-13 * here.principal_axes().moments.maxCoeff()));
  }
}

// A mesh of two bodies integrates to the composite of the two integrated apart, and the composite
// moved equals the moved parts composed.
TEST(SolidMesh, CompositeMeshEqualsCompositeOfParts) {
  const Mat3 R = rotation_from_euler("ZYX", Vec3(0.3, -0.4, 1.1));
  const TriangleMesh a = test::moved(test::box_mesh(Vec3(0.2, 0.3, 0.4)), R, Vec3(1, 0, 0));
  const TriangleMesh b = test::cone_mesh(0.1, 0.3, 32);
  TriangleMesh both = a;
  const auto base = static_cast<std::int32_t>(both.vertices.size());
  both.vertices.insert(both.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (const auto& t : b.triangles)
    both.triangles.push_back(Tri{t[0] + base, t[1] + base, t[2] + base});
  const Amount rho = Amount::density(2700);
  const MassProperties whole = solid_mesh_mass_properties(both, rho);
  const MassProperties parts =
      solid_mesh_mass_properties(a, rho) + solid_mesh_mass_properties(b, rho);
  EXPECT_REL_NEAR(whole.mass(), parts.mass(), 1e-14);
  EXPECT_MATRIX_NEAR(whole.center_of_mass(), parts.center_of_mass(), 1e-14);
  EXPECT_TRUE(tensors_near(whole.inertia_about_com(), parts.inertia_about_com(), 1e-13));
}

// Reversed winding: integration alone reports it; prepare_solid_mesh repairs it to the same result.
TEST(SolidMesh, InsideOutMeshIsRejectedThenRepaired) {
  const TriangleMesh sphere = test::uv_ellipsoid(Vec3(0.1, 0.1, 0.1), 16, 32);
  TriangleMesh inside_out = test::flipped(sphere);
  EXPECT_THROW(solid_mesh_mass_properties(inside_out, Amount::density(1)), MeshError);
  EXPECT_TRUE(prepare_solid_mesh(inside_out, "sphere"));
  const MassProperties repaired = solid_mesh_mass_properties(inside_out, Amount::density(1));
  const MassProperties original = solid_mesh_mass_properties(sphere, Amount::density(1));
  EXPECT_REL_NEAR(repaired.mass(), original.mass(), 1e-15);
  EXPECT_TRUE(tensors_near(repaired.inertia_about_com(), original.inertia_about_com(), 1e-15));
  TriangleMesh bad = sphere;
  bad.triangles[7][2] = 100000;
  EXPECT_THROW(solid_mesh_mass_properties(bad, Amount::density(1)), MeshError);
}

// The regular-polygon prism is a polyhedron with closed forms: area (n/2) r² sin θ and polar
// moment n r⁴ sin θ (2 + cos θ)/12, θ = 2π/n; the mesh path matches them to round-off.
TEST(SolidMesh, PolygonPrismMatchesItsClosedForm) {
  const int n = 7;
  const double r = 0.2, length = 0.5, rho = 1000;
  const double theta = 2 * std::numbers::pi / n;
  const double area = n / 2.0 * r * r * std::sin(theta);
  const double polar = n * std::pow(r, 4) * std::sin(theta) * (2 + std::cos(theta)) / 12;
  const MassProperties mesh =
      solid_mesh_mass_properties(test::cylinder_mesh(r, length, n), Amount::density(rho));
  EXPECT_REL_NEAR(mesh.volume(), area * length, 1e-15);
  EXPECT_REL_NEAR(mesh.inertia_about_com()(2, 2), rho * length * polar, 1e-14);
  // A regular polygon's in-plane moments are equal (n ≥ 3): each half the polar moment.
  const double transverse = rho * length * polar / 2 + mesh.mass() * length * length / 12;
  EXPECT_REL_NEAR(mesh.inertia_about_com()(0, 0), transverse, 1e-14);
  EXPECT_REL_NEAR(mesh.inertia_about_com()(1, 1), transverse, 1e-14);
}

TEST(SolidMesh, DoesNotAllocate) {
  const TriangleMesh sphere = test::uv_ellipsoid(Vec3(1, 1, 1), 32, 64);
  const long before = test::allocation_count();
  const MassProperties p = solid_mesh_mass_properties(sphere, Amount::density(1));
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_GT(p.mass(), 0.0);
}

// A thin-shell box surface is the composite of its six plates (thin_rectangular_plate moved into
// place): exact to round-off.
TEST(ShellMesh, BoxSurfaceIsSixPlates) {
  const Vec3 s(0.3, 0.2, 0.1);
  const double sigma = 7.85;  // 1 mm steel sheet, kg/m².
  const MassProperties shell =
      shell_mesh_mass_properties(test::box_mesh(s), Amount::density(sigma));
  const Amount a = Amount::density(sigma);
  const Mat3 to_x = rotation_from_euler("ZYX", Vec3(0, std::numbers::pi / 2, 0));  // z → x
  const Mat3 to_y = rotation_from_euler("ZYX", Vec3(0, 0, std::numbers::pi / 2));  // z → −y
  MassProperties plates;
  for (const double side : {-1.0, 1.0}) {
    plates += thin_rectangular_plate(a, s.x(), s.y())
                  .transformed(Mat3::Identity(), Vec3(0, 0, side * s.z() / 2));
    plates +=
        thin_rectangular_plate(a, s.z(), s.y()).transformed(to_x, Vec3(side * s.x() / 2, 0, 0));
    plates +=
        thin_rectangular_plate(a, s.x(), s.z()).transformed(to_y, Vec3(0, side * s.y() / 2, 0));
  }
  EXPECT_REL_NEAR(shell.mass(), plates.mass(), 1e-15);
  EXPECT_EQ(shell.volume(), 0.0);
  EXPECT_MATRIX_NEAR(shell.center_of_mass(), Vec3::Zero(), 1e-16);
  EXPECT_TRUE(tensors_near(shell.inertia_about_com(), plates.inertia_about_com(), 1e-14));
}

// One right triangle with legs b (x) and h (y): ∫x y dA = b²h²/24 about the right angle
// (Beer & Johnston, Sample Problem 9.6), so the tensor entry −I_xy about that corner is −σ b²h²/24;
// its area moments about the corner are ∫y² dA = b h³/12 and ∫x² dA = b³h/12.
TEST(ShellMesh, RightTriangleProductOfInertia) {
  const double b = 0.3, h = 0.2, sigma = 10;
  TriangleMesh t;
  t.vertices = {Vec3(0, 0, 0), Vec3(b, 0, 0), Vec3(0, h, 0)};
  t.triangles = {Tri{0, 1, 2}};
  const MassProperties p = shell_mesh_mass_properties(t, Amount::density(sigma));
  const Mat3 I = p.inertia_about(Vec3::Zero());
  EXPECT_REL_NEAR(p.mass(), sigma * b * h / 2, 1e-15);
  EXPECT_MATRIX_NEAR(p.center_of_mass(), Vec3(b / 3, h / 3, 0), 1e-16);
  EXPECT_REL_NEAR(I(0, 1), -sigma * b * b * h * h / 24, 1e-14);
  EXPECT_REL_NEAR(I(0, 0), sigma * b * h * h * h / 12, 1e-14);
  EXPECT_REL_NEAR(I(1, 1), sigma * b * b * b * h / 12, 1e-14);
  EXPECT_REL_NEAR(I(2, 2), sigma * (b * h * h * h + b * b * b * h) / 12, 1e-14);
  EXPECT_NEAR(I(0, 2), 0.0, 1e-18);
  EXPECT_NEAR(I(1, 2), 0.0, 1e-18);
  // Winding does not matter for a sheet.
  const MassProperties back = shell_mesh_mass_properties(test::flipped(t), Amount::density(sigma));
  EXPECT_TRUE(tensors_near(back.inertia_about_com(), p.inertia_about_com(), 1e-15));
}

TEST(ShellMesh, RejectsAZeroAreaMesh) {
  TriangleMesh t;
  t.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
  t.triangles = {Tri{0, 1, 2}};
  EXPECT_THROW(shell_mesh_mass_properties(t, Amount::density(1)), MeshError);
  EXPECT_THROW(shell_mesh_mass_properties(TriangleMesh{}, Amount::density(1)), MeshError);
}

}  // namespace
}  // namespace momenta::inertia
