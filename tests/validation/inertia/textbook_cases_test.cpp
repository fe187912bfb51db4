// Textbook mass properties with their numbers, each found two ways: the primitive or mesh path,
// and a hand derivation written out here.

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Eigenvalues>

#include <gtest/gtest.h>

#include "momenta/inertia/mesh_mass_properties.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta_test/meshes.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::inertia {
namespace {

using test::Tri;

// A slender rod of mass m, length L: about its centre m L²/12, about an end m L²/3
// (Beer & Johnston, Fig. 9.28). Here m = 3 kg, L = 2 m: 1 and 4 kg·m².
TEST(Textbook, RodAboutCentreAndEnd) {
  const MassProperties rod = slender_rod(Amount::mass(3.0), 2.0);
  EXPECT_NEAR(rod.inertia_about_com()(0, 0), 1.0, 1e-15);
  const Mat3 end = rod.inertia_about(Vec3(0, 0, 1.0));
  EXPECT_NEAR(end(0, 0), 4.0, 1e-15);
  EXPECT_NEAR(end(1, 1), 4.0, 1e-15);
  EXPECT_NEAR(end(2, 2), 0.0, 1e-15);
  // By density 0.5 kg/m over 6 m: m = 3 kg, about the end m L²/3 = 36 kg·m².
  EXPECT_NEAR(slender_rod(Amount::density(0.5), 6.0).inertia_about(Vec3(0, 0, -3))(0, 0), 36.0,
              1e-13);
}

// A thin disk (radius r, mass m) about a point Q on its rim (Beer & Johnston Ex. 9.2 setting).
// About the centre: I_diameter = m r²/4, I_axis = m r²/2. At Q = (r, 0, 0), by the parallel-axis
// theorem with d = r:
//   along the diameter through Q (x):         m r²/4          (x is parallel to d: no shift)
//   tangent to the rim at Q (y):              m r²/4 + m r² = 5/4 m r²
//   perpendicular to the disk through Q (z):  m r²/2 + m r² = 3/2 m r²
// Here m = 2 kg, r = 0.5 m: 0.125, 0.625, 0.75 kg·m².
TEST(Textbook, ThinDiskAboutARimPoint) {
  const MassProperties disk = thin_disk(Amount::mass(2.0), 0.5);
  const Mat3 I_Q = disk.inertia_about(Vec3(0.5, 0, 0));
  EXPECT_NEAR(I_Q(0, 0), 0.125, 1e-15);
  EXPECT_NEAR(I_Q(1, 1), 0.625, 1e-15);
  EXPECT_NEAR(I_Q(2, 2), 0.75, 1e-15);
  EXPECT_NEAR(I_Q.cwiseAbs().maxCoeff(), 0.75, 1e-15);  // No products: Q is on a symmetry axis.
  // And through a fine polygonal disk (a shell of 4096 fan triangles), converging as 1/n²:
  // the polygon's relative deficit is (2π/n)²/6 ≈ 4e-7 in area, 8e-7 in the moments.
  TriangleMesh fan;
  const int n = 4096;
  fan.vertices.emplace_back(0, 0, 0);
  for (int j = 0; j < n; ++j) {
    const double phi = 2 * std::numbers::pi * j / n;
    fan.vertices.emplace_back(0.5 * std::cos(phi), 0.5 * std::sin(phi), 0);
  }
  for (int j = 0; j < n; ++j) fan.triangles.push_back(Tri{0, 1 + j, 1 + (j + 1) % n});
  const MassProperties mesh = shell_mesh_mass_properties(fan, Amount::mass(2.0));
  EXPECT_MATRIX_NEAR(mesh.inertia_about(Vec3(0.5, 0, 0)), I_Q, 1e-6 * 0.75);
}

// Products of inertia of an L-shaped plate about its corner O (Beer & Johnston Sample Problem 9.6
// style, with our own numbers). Plate of 1 mm steel, σ = 7.85 kg/m², made of two rectangles:
//   R1: 0 ≤ x ≤ 0.20, 0 ≤ y ≤ 0.04;   R2: 0 ≤ x ≤ 0.04, 0.04 ≤ y ≤ 0.15 (m).
// For a rectangle [x0, x1] × [y0, y1]: ∫xy dA = (x1² − x0²)(y1² − y0²)/4,
//   R1: 0.04 · 0.0016 / 4 = 1.6e-5 m⁴;  R2: 0.0016 · 0.0209 / 4 = 8.36e-6 m⁴;
//   I_xy = σ (1.6e-5 + 8.36e-6) = 7.85 · 2.436e-5 = 1.912260e-4 kg·m²,
// so the tensor entry about O is −1.912260e-4. Moments about O, ∫y² dA = (x1 − x0)(y1³ − y0³)/3:
//   I_x = σ (0.2 · 0.04³ + 0.04 (0.15³ − 0.04³)) / 3 = 7.85 · 4.841333e-5 = 3.800447e-4 kg·m²,
//   I_y = σ (0.04 · 0.2³ + 0.11 · 0.04³) / 3       = 7.85 · 1.090133e-4 = 8.557547e-4 kg·m².
TEST(Textbook, LShapedPlateProductsOfInertiaAboutTheCorner) {
  const double sigma = 7.85;
  const double ixy_by_hand = sigma * (1.6e-5 + 8.36e-6);
  EXPECT_NEAR(ixy_by_hand, 1.912260e-4, 1e-12);
  struct Rect {
    double x0, x1, y0, y1;
  };
  const Rect rects[2] = {{0, 0.20, 0, 0.04}, {0, 0.04, 0.04, 0.15}};
  double ix = 0, iy = 0, ixy = 0, mass = 0;
  for (const Rect& r : rects) {
    ix += sigma * (r.x1 - r.x0) * (std::pow(r.y1, 3) - std::pow(r.y0, 3)) / 3;
    iy += sigma * (r.y1 - r.y0) * (std::pow(r.x1, 3) - std::pow(r.x0, 3)) / 3;
    ixy += sigma * (r.x1 * r.x1 - r.x0 * r.x0) * (r.y1 * r.y1 - r.y0 * r.y0) / 4;
    mass += sigma * (r.x1 - r.x0) * (r.y1 - r.y0);
  }
  EXPECT_NEAR(ixy, ixy_by_hand, 1e-18);
  EXPECT_NEAR(ix, 3.800447e-4, 1e-10);  // The hand values above, to their 7 digits.
  EXPECT_NEAR(iy, 8.557547e-4, 1e-10);

  // Route 1: two thin_rectangular_plate primitives placed at their centres, composed.
  MassProperties plates;
  for (const Rect& r : rects) {
    plates += thin_rectangular_plate(Amount::density(sigma), r.x1 - r.x0, r.y1 - r.y0)
                  .transformed(Mat3::Identity(), Vec3((r.x0 + r.x1) / 2, (r.y0 + r.y1) / 2, 0));
  }
  const Mat3 I_plates = plates.inertia_about(Vec3::Zero());
  // Route 2: the L outline as a shell mesh of four triangles.
  TriangleMesh L;
  L.vertices = {Vec3(0, 0, 0),       Vec3(0.2, 0, 0),     Vec3(0.2, 0.04, 0),
                Vec3(0.04, 0.04, 0), Vec3(0.04, 0.15, 0), Vec3(0, 0.15, 0)};
  L.triangles = {Tri{0, 1, 2}, Tri{0, 2, 3}, Tri{0, 3, 4}, Tri{0, 4, 5}};
  const MassProperties mesh = shell_mesh_mass_properties(L, Amount::density(sigma));
  const Mat3 I_mesh = mesh.inertia_about(Vec3::Zero());

  // Round-off of a few dozen operations on numbers ~1e-4: 1e-15 of the largest entry.
  const double tol = 1e-15 * std::max(ix, iy) * 10;
  for (const Mat3* I : {&I_plates, &I_mesh}) {
    EXPECT_NEAR((*I)(0, 1), -ixy_by_hand, tol);
    EXPECT_NEAR((*I)(1, 0), -ixy_by_hand, tol);
    EXPECT_NEAR((*I)(0, 0), ix, tol);
    EXPECT_NEAR((*I)(1, 1), iy, tol);
    EXPECT_NEAR((*I)(2, 2), ix + iy, tol);  // Perpendicular-axis theorem for a plate.
    EXPECT_NEAR((*I)(0, 2), 0.0, tol);
    EXPECT_NEAR((*I)(1, 2), 0.0, tol);
  }
  EXPECT_NEAR(mesh.mass(), mass, 1e-16);
  // Principal axes in the plane about O: tan 2θ = 2 I_xy / (I_y − I_x) for the product
  // I_xy = ∫xy dm (Beer & Johnston eq. 9.25 with their sign), and the in-plane principal moments
  // (I_x + I_y)/2 ± √(((I_x − I_y)/2)² + I_xy²) are the eigenvalues of the 2 × 2 block.
  const double mean = (ix + iy) / 2;
  const double radius = std::hypot((ix - iy) / 2, ixy);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> in_plane(I_mesh.topLeftCorner<2, 2>());
  EXPECT_NEAR(in_plane.eigenvalues()[0], mean - radius, tol);
  EXPECT_NEAR(in_plane.eigenvalues()[1], mean + radius, tol);
}

// Parallel-axis round trips and rigid-motion invariance on a composite of primitives at random
// poses; composing then moving equals moving then composing.
TEST(Textbook, CompositeOfPrimitivesUnderRigidMotion) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto random_pose = [&] {
    return std::pair{rotation_from_euler("ZYX", Vec3(3 * u(rng), 1.5 * u(rng), 3 * u(rng))),
                     Vec3(u(rng), u(rng), u(rng))};
  };
  const Amount steel = Amount::density(7850);
  const MassProperties parts[] = {box(steel, Vec3(0.1, 0.2, 0.05)),
                                  solid_cylinder(steel, 0.03, 0.4), solid_cone(steel, 0.05, 0.1),
                                  ellipsoid(steel, Vec3(0.05, 0.04, 0.03)),
                                  hollow_sphere(steel, 0.02, 0.03)};
  MassProperties composite;
  std::vector<MassProperties> placed;
  for (const MassProperties& part : parts) {
    const auto [R, p] = random_pose();
    placed.push_back(part.transformed(R, p));
    composite += placed.back();
  }
  ASSERT_NO_THROW(composite.check_physical("composite"));
  const double scale = composite.inertia_about_com().cwiseAbs().maxCoeff();
  for (int trial = 0; trial < 5; ++trial) {
    const auto [R, p] = random_pose();
    MassProperties moved_parts;
    for (const MassProperties& part : placed) moved_parts += part.transformed(R, p);
    const MassProperties moved = composite.transformed(R, p);
    EXPECT_MATRIX_NEAR(moved_parts.center_of_mass(), moved.center_of_mass(), 1e-14);
    EXPECT_MATRIX_NEAR(moved_parts.inertia_about_com(), moved.inertia_about_com(), 1e-13 * scale);
    EXPECT_MATRIX_NEAR(moved.principal_axes().moments, composite.principal_axes().moments,
                       1e-13 * scale);
    // Parallel axis there and back through a random point.
    const Vec3 q(u(rng), u(rng), u(rng));
    const MassProperties back = MassProperties::from_inertia_about(
        moved.mass(), moved.center_of_mass(), moved.inertia_about(q), q);
    EXPECT_MATRIX_NEAR(back.inertia_about_com(), moved.inertia_about_com(), 1e-13 * scale);
  }
}

// The mesh path composes like the primitives: a mesh of two boxes at random poses (two closed
// components) equals the composite of the two box primitives moved there.
TEST(Textbook, TwoBoxMeshEqualsCompositeOfBoxes) {
  const Mat3 R1 = rotation_from_euler("XYZ", Vec3(0.3, 0.7, -1.2));
  const Mat3 R2 = rotation_from_euler("ZYX", Vec3(-2.0, 0.1, 0.4));
  const Vec3 p1(0.5, -0.2, 0.1), p2(-0.3, 0.4, 0.9);
  const TriangleMesh a = test::moved(test::box_mesh(Vec3(0.2, 0.1, 0.3)), R1, p1);
  const TriangleMesh b = test::moved(test::box_mesh(Vec3(0.05, 0.4, 0.1)), R2, p2);
  TriangleMesh both = a;
  const auto base = static_cast<std::int32_t>(both.vertices.size());
  both.vertices.insert(both.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (const auto& t : b.triangles)
    both.triangles.push_back(Tri{t[0] + base, t[1] + base, t[2] + base});
  ASSERT_FALSE(prepare_solid_mesh(both, "two boxes"));
  const Amount rho = Amount::density(2700);
  const MassProperties mesh = solid_mesh_mass_properties(both, rho);
  const MassProperties exact = box(rho, Vec3(0.2, 0.1, 0.3)).transformed(R1, p1) +
                               box(rho, Vec3(0.05, 0.4, 0.1)).transformed(R2, p2);
  EXPECT_REL_NEAR(mesh.mass(), exact.mass(), 1e-14);
  EXPECT_MATRIX_NEAR(mesh.center_of_mass(), exact.center_of_mass(), 1e-14);
  EXPECT_MATRIX_NEAR(mesh.inertia_about_com(), exact.inertia_about_com(),
                     1e-13 * exact.inertia_about_com().cwiseAbs().maxCoeff());
}

}  // namespace
}  // namespace momenta::inertia
