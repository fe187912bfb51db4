#include "momenta/inertia/primitives.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::inertia {
namespace {

constexpr double kPi = std::numbers::pi;
// Closed forms evaluated two ways in double on O(1)–O(10³) numbers: a few ulps of round-off.
constexpr double kRel = 1e-14;

Mat3 diag(double a, double b, double c) { return Vec3(a, b, c).asDiagonal(); }

// Relative comparison of two inertia tensors against the largest entry of the expected one.
::testing::AssertionResult tensors_near(const Mat3& a, const Mat3& b, double rel) {
  return test::matrices_near(a, b, rel * b.cwiseAbs().maxCoeff());
}

// Each primitive against its textbook closed form (Beer & Johnston, Fig. 9.28; Meriam & Kraige,
// Appendix B), with the mass written out from the density and the size.
TEST(Primitives, ClosedFormsByDensity) {
  const double rho = 7850.0;  // Steel, kg/m³.
  {
    const MassProperties p = solid_sphere(Amount::density(rho), 0.1);
    const double m = rho * 4.0 / 3.0 * kPi * 1e-3;
    EXPECT_REL_NEAR(p.mass(), m, kRel);
    EXPECT_REL_NEAR(p.volume(), 4.0 / 3.0 * kPi * 1e-3, kRel);
    const double i = 2.0 / 5.0 * m * 0.01;
    EXPECT_TRUE(tensors_near(p.inertia_about_com(), diag(i, i, i), kRel));
    EXPECT_MATRIX_NEAR(p.center_of_mass(), Vec3::Zero(), 0.0);
  }
  {
    const MassProperties p = solid_cylinder(Amount::density(rho), 0.05, 0.4);
    const double m = rho * kPi * 0.05 * 0.05 * 0.4;
    EXPECT_REL_NEAR(p.mass(), m, kRel);
    const double ix = m * (3 * 0.05 * 0.05 + 0.4 * 0.4) / 12;
    EXPECT_TRUE(tensors_near(p.inertia_about_com(), diag(ix, ix, m * 0.05 * 0.05 / 2), kRel));
  }
  {
    const MassProperties p = box(Amount::density(rho), Vec3(0.1, 0.2, 0.3));
    const double m = rho * 0.006;
    EXPECT_REL_NEAR(p.mass(), m, kRel);
    EXPECT_TRUE(tensors_near(
        p.inertia_about_com(),
        diag(m * (0.04 + 0.09) / 12, m * (0.01 + 0.09) / 12, m * (0.01 + 0.04) / 12), kRel));
  }
  {
    const MassProperties p = ellipsoid(Amount::density(rho), Vec3(0.3, 0.2, 0.1));
    const double m = rho * 4.0 / 3.0 * kPi * 0.3 * 0.2 * 0.1;
    EXPECT_REL_NEAR(p.mass(), m, kRel);
    EXPECT_TRUE(tensors_near(
        p.inertia_about_com(),
        diag(m * (0.04 + 0.01) / 5, m * (0.09 + 0.01) / 5, m * (0.09 + 0.04) / 5), kRel));
  }
  {
    // Cone: m = ρ π r² h / 3, centroid 3h/4 from the apex, I_axial = 3/10 m r²,
    // I_transverse(centroid) = 3/20 m r² + 3/80 m h², I_transverse(apex) = 3/20 m r² + 3/5 m h².
    const double r = 0.2, h = 0.6;
    const MassProperties p = solid_cone(Amount::density(rho), r, h);
    const double m = rho * kPi * r * r * h / 3;
    EXPECT_REL_NEAR(p.mass(), m, kRel);
    EXPECT_MATRIX_NEAR(p.center_of_mass(), Vec3(0, 0, 0.75 * h), kRel * h);
    const double it = 3.0 / 20 * m * r * r + 3.0 / 80 * m * h * h;
    EXPECT_TRUE(tensors_near(p.inertia_about_com(), diag(it, it, 0.3 * m * r * r), kRel));
    const double it_apex = 3.0 / 20 * m * r * r + 3.0 / 5 * m * h * h;
    EXPECT_TRUE(
        tensors_near(p.inertia_about(Vec3::Zero()), diag(it_apex, it_apex, 0.3 * m * r * r), kRel));
  }
  {
    const double sigma = 2.5;  // kg/m².
    const MassProperties disk = thin_disk(Amount::density(sigma), 0.3);
    const double m = sigma * kPi * 0.09;
    EXPECT_REL_NEAR(disk.mass(), m, kRel);
    EXPECT_TRUE(tensors_near(disk.inertia_about_com(),
                             diag(m * 0.09 / 4, m * 0.09 / 4, m * 0.09 / 2), kRel));
    EXPECT_EQ(disk.volume(), 0.0);
    const MassProperties plate = thin_rectangular_plate(Amount::density(sigma), 0.4, 0.3);
    const double mp = sigma * 0.12;
    EXPECT_TRUE(tensors_near(plate.inertia_about_com(),
                             diag(mp * 0.09 / 12, mp * 0.16 / 12, mp * 0.25 / 12), kRel));
    const MassProperties shell = spherical_shell(Amount::density(sigma), 0.3);
    const double ms = sigma * 4 * kPi * 0.09;
    EXPECT_REL_NEAR(shell.mass(), ms, kRel);
    EXPECT_REL_NEAR(shell.inertia_about_com()(1, 1), 2.0 / 3.0 * ms * 0.09, kRel);
    const MassProperties tube = cylindrical_shell(Amount::density(sigma), 0.1, 0.5);
    const double mt = sigma * 2 * kPi * 0.1 * 0.5;
    EXPECT_TRUE(tensors_near(
        tube.inertia_about_com(),
        diag(mt * 0.01 / 2 + mt * 0.25 / 12, mt * 0.01 / 2 + mt * 0.25 / 12, mt * 0.01), kRel));
  }
  {
    const double lambda = 0.8;  // kg/m.
    const MassProperties ring = thin_ring(Amount::density(lambda), 0.5);
    const double m = lambda * 2 * kPi * 0.5;
    EXPECT_REL_NEAR(ring.mass(), m, kRel);
    EXPECT_TRUE(
        tensors_near(ring.inertia_about_com(), diag(m * 0.25 / 2, m * 0.25 / 2, m * 0.25), kRel));
    const MassProperties rod = slender_rod(Amount::density(lambda), 2.0);
    EXPECT_REL_NEAR(rod.mass(), 1.6, kRel);
    EXPECT_TRUE(tensors_near(rod.inertia_about_com(), diag(1.6 * 4 / 12, 1.6 * 4 / 12, 0), kRel));
  }
  {
    const MassProperties p = point_mass(3.0);
    EXPECT_EQ(p.mass(), 3.0);
    EXPECT_MATRIX_NEAR(p.inertia_about(Vec3(0, 0, 2)), diag(12, 12, 0), 0.0);
  }
}

// Giving the mass instead of the density scales the inertia and keeps the shape.
// A capsule is a cylinder and a sphere whose halves were pulled apart by the cylinder's length:
// the sphere's mass and axial moment unchanged, each half's transverse moment about the capsule's
// centre raised by the parallel-axis terms (m/2)((L/2)² + 2 (L/2)(3r/8)) of the move.
TEST(Primitives, CapsuleIsACylinderAndASpherePulledApart) {
  const double rho = 2700, r = 0.07, L = 0.2;
  const MassProperties capsule_ = capsule(Amount::density(rho), r, L);
  const MassProperties cylinder = solid_cylinder(Amount::density(rho), r, L);
  const MassProperties sphere = solid_sphere(Amount::density(rho), r);
  const double m_s = sphere.mass();
  EXPECT_REL_NEAR(capsule_.mass(), cylinder.mass() + m_s, 1e-15);
  EXPECT_REL_NEAR(capsule_.volume(), cylinder.volume() + sphere.volume(), 1e-15);
  const Mat3 I = capsule_.inertia_about_com();
  const double moved = m_s * (L * L / 4 + 3 * L * r / 8);
  EXPECT_REL_NEAR(I(2, 2), cylinder.inertia_about_com()(2, 2) + sphere.inertia_about_com()(2, 2),
                  1e-15);
  EXPECT_REL_NEAR(I(0, 0),
                  cylinder.inertia_about_com()(0, 0) + sphere.inertia_about_com()(0, 0) + moved,
                  1e-15);
  EXPECT_REL_NEAR(I(1, 1), I(0, 0), 0.0);
  EXPECT_MATRIX_NEAR(capsule_.center_of_mass(), Vec3::Zero(), 0.0);
  // MuJoCo 2.2's capsule (r 0.1, half-length 0.3, water) as it prints it (tests/validation/io
  // compares whole models): m 23.038346126325152, I 1.1006046263076243, 0.11100294042683936.
  const MassProperties mujoco = capsule(Amount::density(1000), 0.1, 0.6);
  EXPECT_REL_NEAR(mujoco.mass(), 23.038346126325152, 1e-15);
  EXPECT_REL_NEAR(mujoco.inertia_about_com()(0, 0), 1.1006046263076243, 1e-15);
  EXPECT_REL_NEAR(mujoco.inertia_about_com()(2, 2), 0.11100294042683936, 1e-15);
  EXPECT_THROW(capsule(Amount::density(rho), 0.0, L), InvalidArgument);
}

TEST(Primitives, ByMassEqualsByDensityWithTheSameMass) {
  const std::function<MassProperties(Amount)> shapes[] = {
      [](Amount a) { return slender_rod(a, 1.3); },
      [](Amount a) { return thin_ring(a, 0.4); },
      [](Amount a) { return thin_disk(a, 0.4); },
      [](Amount a) { return annulus(a, 0.1, 0.4); },
      [](Amount a) { return solid_cylinder(a, 0.1, 0.4); },
      [](Amount a) { return hollow_cylinder(a, 0.05, 0.1, 0.4); },
      [](Amount a) { return cylindrical_shell(a, 0.1, 0.4); },
      [](Amount a) { return solid_sphere(a, 0.2); },
      [](Amount a) { return hollow_sphere(a, 0.1, 0.2); },
      [](Amount a) { return spherical_shell(a, 0.2); },
      [](Amount a) { return box(a, Vec3(0.1, 0.2, 0.3)); },
      [](Amount a) { return thin_rectangular_plate(a, 0.1, 0.2); },
      [](Amount a) { return solid_cone(a, 0.1, 0.3); },
      [](Amount a) { return ellipsoid(a, Vec3(0.1, 0.2, 0.3)); },
  };
  for (const auto& shape : shapes) {
    const MassProperties by_density = shape(Amount::density(1234.0));
    const MassProperties by_mass = shape(Amount::mass(by_density.mass()));
    EXPECT_REL_NEAR(by_mass.mass(), by_density.mass(), kRel);
    EXPECT_TRUE(tensors_near(by_mass.inertia_about_com(), by_density.inertia_about_com(), kRel));
    EXPECT_MATRIX_NEAR(by_mass.center_of_mass(), by_density.center_of_mass(), 1e-15);
    EXPECT_NO_THROW(by_mass.check_physical("primitive"));
  }
}

// Hollow shapes are the outer solid minus the inner one, of the same density (an independent
// route through MassProperties::operator-=).
TEST(Primitives, HollowShapesAreDifferencesOfSolids) {
  const Amount rho = Amount::density(2700.0);
  const MassProperties tube = hollow_cylinder(rho, 0.03, 0.05, 0.2);
  const MassProperties tube_diff = solid_cylinder(rho, 0.05, 0.2) - solid_cylinder(rho, 0.03, 0.2);
  EXPECT_REL_NEAR(tube.mass(), tube_diff.mass(), 1e-14);
  EXPECT_REL_NEAR(tube.volume(), tube_diff.volume(), 1e-14);
  EXPECT_TRUE(tensors_near(tube.inertia_about_com(), tube_diff.inertia_about_com(), 1e-14));

  const MassProperties ball = hollow_sphere(rho, 0.07, 0.1);
  const MassProperties ball_diff = solid_sphere(rho, 0.1) - solid_sphere(rho, 0.07);
  EXPECT_REL_NEAR(ball.mass(), ball_diff.mass(), 1e-14);
  EXPECT_TRUE(tensors_near(ball.inertia_about_com(), ball_diff.inertia_about_com(), 1e-14));

  const Amount sigma = Amount::density(3.0);
  const MassProperties washer = annulus(sigma, 0.02, 0.06);
  const MassProperties washer_diff = thin_disk(sigma, 0.06) - thin_disk(sigma, 0.02);
  EXPECT_REL_NEAR(washer.mass(), washer_diff.mass(), 1e-14);
  EXPECT_TRUE(tensors_near(washer.inertia_about_com(), washer_diff.inertia_about_com(), 1e-14));

  // Inner radius 0: the solid itself.
  EXPECT_TRUE(tensors_near(hollow_cylinder(rho, 0.0, 0.05, 0.2).inertia_about_com(),
                           solid_cylinder(rho, 0.05, 0.2).inertia_about_com(), kRel));
  EXPECT_TRUE(tensors_near(hollow_sphere(rho, 0.0, 0.1).inertia_about_com(),
                           solid_sphere(rho, 0.1).inertia_about_com(), kRel));
}

// Thin shapes are limits of thick ones: a wall of thickness t changes the moments by a relative
// O(t/r) (the wall's own thickness), so at t/r = 1e-6 they agree to about 1e-6.
TEST(Primitives, ThinShapesAreLimitsOfThickOnes) {
  const double t = 1e-7;
  const double r = 0.1;
  // Spherical shell vs a hollow sphere of wall t, mass given (the factored form keeps digits).
  const MassProperties shell = spherical_shell(Amount::mass(2.0), r);
  const MassProperties thick = hollow_sphere(Amount::mass(2.0), r - t / 2, r + t / 2);
  EXPECT_TRUE(tensors_near(shell.inertia_about_com(), thick.inertia_about_com(), 1e-12));
  // Cylindrical shell vs a thin tube; thin ring vs a thin tube of tiny length.
  EXPECT_TRUE(tensors_near(
      cylindrical_shell(Amount::mass(2.0), r, 0.3).inertia_about_com(),
      hollow_cylinder(Amount::mass(2.0), r - t / 2, r + t / 2, 0.3).inertia_about_com(), 1e-12));
  EXPECT_TRUE(tensors_near(
      thin_ring(Amount::mass(2.0), r).inertia_about_com(),
      hollow_cylinder(Amount::mass(2.0), r - t / 2, r + t / 2, t).inertia_about_com(), 1e-11));
  // Thin disk vs a cylinder of length t: the m t²/12 term is a relative (t/r)²/3.
  EXPECT_TRUE(tensors_near(thin_disk(Amount::mass(2.0), r).inertia_about_com(),
                           solid_cylinder(Amount::mass(2.0), r, t).inertia_about_com(), 1e-11));
  // Plate vs a box of thickness t; rod vs a box of cross-section t × t.
  EXPECT_TRUE(tensors_near(thin_rectangular_plate(Amount::mass(2.0), 0.3, 0.2).inertia_about_com(),
                           box(Amount::mass(2.0), Vec3(0.3, 0.2, t)).inertia_about_com(), 1e-11));
  EXPECT_TRUE(tensors_near(slender_rod(Amount::mass(2.0), 0.3).inertia_about_com(),
                           box(Amount::mass(2.0), Vec3(t, t, 0.3)).inertia_about_com(), 1e-11));
  // Sphere = ellipsoid with equal semi-axes.
  EXPECT_TRUE(tensors_near(solid_sphere(Amount::mass(2.0), r).inertia_about_com(),
                           ellipsoid(Amount::mass(2.0), Vec3(r, r, r)).inertia_about_com(), kRel));
}

// The cone against a stack of thin disks, integrated by 3-point Gauss–Legendre along the axis,
// exact for the polynomial integrands here (degree ≤ 4 in z) up to round-off.
TEST(Primitives, ConeAgainstAStackOfDisks) {
  const double rho = 1500.0, R = 0.25, h = 0.8;
  const double nodes[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const double weights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  double m = 0, mz = 0, i_axial = 0, i_transverse_apex = 0;
  for (int k = 0; k < 3; ++k) {
    const double z = h / 2 * (1 + nodes[k]);
    const double w = h / 2 * weights[k];
    const double r = R * z / h;
    const double dm = rho * kPi * r * r * w;  // A disk of radius r(z) and thickness dz.
    m += dm;
    mz += dm * z;
    i_axial += dm * r * r / 2;
    i_transverse_apex += dm * (r * r / 4 + z * z);  // Disk about its diameter, shifted to apex.
  }
  const MassProperties cone = solid_cone(Amount::density(rho), R, h);
  EXPECT_REL_NEAR(cone.mass(), m, 1e-14);
  EXPECT_REL_NEAR(cone.center_of_mass().z(), mz / m, 1e-14);
  const Mat3 I_apex = cone.inertia_about(Vec3::Zero());
  EXPECT_REL_NEAR(I_apex(2, 2), i_axial, 1e-14);
  EXPECT_REL_NEAR(I_apex(0, 0), i_transverse_apex, 1e-14);
  EXPECT_REL_NEAR(I_apex(1, 1), i_transverse_apex, 1e-14);
  // About the centroid: the apex value less m (3h/4)².
  EXPECT_REL_NEAR(cone.inertia_about_com()(0, 0), i_transverse_apex - m * (mz / m) * (mz / m),
                  1e-13);
}

// Every bad size is rejected, and the message names the shape and the value.
TEST(Primitives, RejectBadSizesNamingShapeAndValue) {
  const Amount rho = Amount::density(1000.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const auto expect_message = [](const std::function<void()>& f, const std::string& shape,
                                 const std::string& value) {
    try {
      f();
      ADD_FAILURE() << "expected InvalidArgument from " << shape;
    } catch (const InvalidArgument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(shape), std::string::npos) << what;
      EXPECT_NE(what.find(value), std::string::npos) << what;
    }
  };
  expect_message([&] { solid_sphere(rho, -0.5); }, "solid_sphere", "-0.5");
  expect_message([&] { solid_cylinder(rho, 0.1, 0.0); }, "solid_cylinder", "length 0");
  expect_message([&] { box(rho, Vec3(1, nan, 1)); }, "box", "nan");
  expect_message([&] { ellipsoid(rho, Vec3(1, 1, inf)); }, "ellipsoid", "inf");
  expect_message([&] { solid_cone(rho, 0.1, -2.0); }, "solid_cone", "-2");
  expect_message([&] { hollow_cylinder(rho, 0.2, 0.1, 1.0); }, "hollow_cylinder", "0.2");
  expect_message([&] { hollow_sphere(rho, 0.1, 0.1); }, "hollow_sphere", "not below");
  expect_message([&] { annulus(rho, -0.1, 0.3); }, "annulus", "-0.1");
  expect_message([&] { thin_ring(rho, 0.0); }, "thin_ring", "radius 0");
  expect_message([&] { thin_disk(rho, nan); }, "thin_disk", "nan");
  expect_message([&] { slender_rod(rho, -1.0); }, "slender_rod", "-1");
  expect_message([&] { cylindrical_shell(rho, 0.1, inf); }, "cylindrical_shell", "inf");
  expect_message([&] { spherical_shell(rho, -3.0); }, "spherical_shell", "-3");
  expect_message([&] { thin_rectangular_plate(rho, 1.0, 0.0); }, "thin_rectangular_plate", "0");
  expect_message([&] { point_mass(0.0); }, "point_mass", "0");
  expect_message([&] { solid_sphere(Amount::mass(-2.0), 0.1); }, "solid_sphere", "mass -2");
  expect_message([&] { solid_sphere(Amount::density(nan), 0.1); }, "solid_sphere", "density nan");
}

}  // namespace
}  // namespace momenta::inertia
