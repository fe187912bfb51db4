// The bundled example parts (examples/parts/*.yaml) against hand calculations: every part's mass
// and inertia from its textbook formula, written out here, summed about B's origin with the
// parallel-axis theorem, and only then moved to the centre of mass — a different route from the
// library's, which composes about the running centre of mass with its own primitives.

#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "momenta/io/part_file.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::io {
namespace {

constexpr double kPi = std::numbers::pi;

// The files give lengths to 16 digits (mm converted to m costs one rounding each) and the hand
// sums and the library's take different roundings; the composites cancel by at most a factor of a
// few (inertia about the origin vs about the centre of mass). Measured: 1.2e-15 of the largest
// entry at worst (flanged shaft). 1e-13 leaves a factor of 80 and still catches any wrong term (the
// smallest part, a bolt hole, moves the inertia by 1e-4 of it).
constexpr double kRel = 1e-13;

// A body by hand: mass, first moment and inertia about B's origin.
struct Hand {
  double mass = 0;
  Vec3 first_moment = Vec3::Zero();
  Mat3 I_Bo = Mat3::Zero();
  double volume = 0;

  // Adds (sign +1) or removes (−1) a part of mass m, centre c (in B), inertia I_c about its centre
  // already expressed in B's axes.
  void add(double m, const Vec3& c, const Mat3& I_c, double v = 0, double sign = 1) {
    Mat3 shift;  // m (|c|² 1 − c cᵀ), written out.
    shift << c.y() * c.y() + c.z() * c.z(), -c.x() * c.y(), -c.x() * c.z(),  //
        -c.x() * c.y(), c.x() * c.x() + c.z() * c.z(), -c.y() * c.z(),       //
        -c.x() * c.z(), -c.y() * c.z(), c.x() * c.x() + c.y() * c.y();
    mass += sign * m;
    first_moment += sign * m * c;
    I_Bo += sign * (I_c + m * shift);
    volume += sign * v;
  }
  void remove(double m, const Vec3& c, const Mat3& I_c, double v) { add(m, c, I_c, v, -1); }

  Vec3 com() const { return first_moment / mass; }
  Mat3 I_com() const {
    const Vec3 c = com();
    return I_Bo - mass * (c.squaredNorm() * Mat3::Identity() - c * c.transpose());
  }
};

Mat3 diag(double a, double b, double c) { return Vec3(a, b, c).asDiagonal(); }

// Solid cylinder (radius r, length L) about its centre, axis along z.
Mat3 cylinder_z(double m, double r, double L) {
  return diag(m * (3 * r * r + L * L) / 12, m * (3 * r * r + L * L) / 12, m * r * r / 2);
}
// Tube (radii a < b, length L) about its centre, axis along z.
Mat3 tube_z(double m, double a, double b, double L) {
  const double s = a * a + b * b;
  return diag(m * (3 * s + L * L) / 12, m * (3 * s + L * L) / 12, m * s / 2);
}
// Box with edges (a, b, c) about its centre.
Mat3 box(double m, double a, double b, double c) {
  return diag(m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12);
}

void expect_matches(const CompositePart& part, const Hand& hand) {
  const inertia::MassProperties& mp = part.total;
  EXPECT_REL_NEAR(mp.mass(), hand.mass, kRel);
  EXPECT_REL_NEAR(mp.volume(), hand.volume, kRel);
  const double size = std::sqrt(hand.I_com().trace() / hand.mass);  // ~ radius of gyration.
  EXPECT_MATRIX_NEAR(mp.center_of_mass(), hand.com(), kRel * std::max(size, hand.com().norm()));
  EXPECT_MATRIX_NEAR(mp.inertia_about_com(), hand.I_com(),
                     kRel * hand.I_com().cwiseAbs().maxCoeff());
  EXPECT_NO_THROW(mp.check_physical("example"));
}

CompositePart example(const std::string& name) {
  return read_part_file(test::source_dir() + "/examples/parts/" + name);
}

TEST(ExampleParts, FlangedShaft) {
  const double rho = 7850;
  Hand h;
  // Shaft Ø40 × 300 from z = 0; flange ring Ø40/Ø120 × 15 at the bottom.
  const double ms = rho * kPi * 0.02 * 0.02 * 0.3;
  h.add(ms, Vec3(0, 0, 0.15), cylinder_z(ms, 0.02, 0.3), kPi * 0.02 * 0.02 * 0.3);
  const double vf = kPi * (0.06 * 0.06 - 0.02 * 0.02) * 0.015;
  h.add(rho * vf, Vec3(0, 0, 0.0075), tube_z(rho * vf, 0.02, 0.06, 0.015), vf);
  // Six Ø10 holes on the 45 mm radius, every 60°.
  const double vh = kPi * 0.005 * 0.005 * 0.015;
  for (int k = 0; k < 6; ++k) {
    const double t = k * kPi / 3;
    h.remove(rho * vh, Vec3(0.045 * std::cos(t), 0.045 * std::sin(t), 0.0075),
             cylinder_z(rho * vh, 0.005, 0.015), vh);
  }
  const CompositePart part = example("flanged_shaft.yaml");
  EXPECT_EQ(part.name, "flanged shaft");
  EXPECT_EQ(part.parts.size(), 8u);
  expect_matches(part, h);
  // Six-fold symmetry: a symmetric top about z with its centre of mass on the axis.
  EXPECT_REL_NEAR(part.total.inertia_about_com()(0, 0), part.total.inertia_about_com()(1, 1),
                  1e-14);
}

TEST(ExampleParts, BracketWithAMeshPart) {
  const double rho = 2700;
  Hand h;
  // The L mesh is two boxes: base 80 × 40 × 6 and upright 6 × 40 × 60 on its x = 0 end.
  const double vb = 0.08 * 0.04 * 0.006, vu = 0.006 * 0.04 * 0.06;
  h.add(rho * vb, Vec3(0.04, 0, 0.003), box(rho * vb, 0.08, 0.04, 0.006), vb);
  h.add(rho * vu, Vec3(0.003, 0, 0.036), box(rho * vu, 0.006, 0.04, 0.06), vu);
  // Two Ø9 holes through the base, one Ø22 along x through the upright.
  const double vh = kPi * 0.0045 * 0.0045 * 0.006;
  for (double x : {0.035, 0.065}) {
    h.remove(rho * vh, Vec3(x, 0, 0.003), cylinder_z(rho * vh, 0.0045, 0.006), vh);
  }
  const double vs = kPi * 0.011 * 0.011 * 0.006, ms = rho * vs;
  const double across = ms * (3 * 0.011 * 0.011 + 0.006 * 0.006) / 12;
  h.remove(ms, Vec3(0.003, 0, 0.04), diag(ms * 0.011 * 0.011 / 2, across, across), vs);
  // The motor, axis along −x: its centre 25 mm out, its axial moment about B's x.
  h.add(0.35, Vec3(-0.025, 0, 0.04), diag(3.0e-5, 8.0e-5, 8.0e-5));
  const CompositePart part = example("bracket.yaml");
  expect_matches(part, h);
  EXPECT_EQ(part.parts[0].kind, "mesh");
  // Everything lies on y = 0's plane of symmetry: only the xz product survives, and it is nonzero.
  const Mat3& I = part.total.inertia_about_com();
  // (The mesh's ±y halves cancel to round-off, about 1e-17 of the largest entry.)
  EXPECT_LE(std::abs(I(0, 1)), 1e-15 * I.maxCoeff());
  EXPECT_LE(std::abs(I(1, 2)), 1e-15 * I.maxCoeff());
  EXPECT_GT(std::abs(I(0, 2)), 0.1 * I(0, 0));
}

TEST(ExampleParts, Flywheel) {
  const double rho = 7200;
  Hand h;
  const auto ring = [&](double a, double b, double L) {
    const double v = kPi * (b * b - a * a) * L;
    h.add(rho * v, Vec3::Zero(), tube_z(rho * v, a, b, L), v);
  };
  ring(0.150, 0.180, 0.060);  // Rim.
  ring(0.040, 0.150, 0.020);  // Web.
  ring(0.015, 0.040, 0.050);  // Hub.
  const double v = kPi * 0.03 * 0.03 * 0.02, p = 0.095 / std::sqrt(2.0);
  for (const auto& [sx, sy] : {std::pair{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}) {
    h.remove(rho * v, Vec3(sx * p, sy * p, 0), cylinder_z(rho * v, 0.03, 0.02), v);
  }
  expect_matches(example("flywheel.yaml"), h);
}

TEST(ExampleParts, Satellite) {
  Hand h;
  h.add(180, Vec3(0, 0, 0.625), box(180, 1.0, 0.75, 1.25), 1.0 * 0.75 * 1.25);  // Bus mesh.
  // Panels: the plate's normal on B's x, its width (2 m) along B's y, its height along B's z.
  for (double y : {1.475, -1.475}) {
    h.add(12, Vec3(0, y, 0.625), diag(12 * (4.0 + 1.0) / 12, 12 * 1.0 / 12, 12 * 4.0 / 12));
  }
  h.add(60, Vec3(0, 0, 0.5), 0.4 * 60 * 0.25 * 0.25 * Mat3::Identity(),
        4.0 / 3.0 * kPi * 0.25 * 0.25 * 0.25);  // Tank.
  Mat3 payload;
  payload << 1.2, -0.05, 0.02, -0.05, 0.9, 0.0, 0.02, 0.0, 1.1;
  h.add(25, Vec3(0.3, 0, 1.35), payload);
  h.add(3, Vec3(1.25, 0, 1.0), diag(0, 3 * 1.5 * 1.5 / 12, 3 * 1.5 * 1.5 / 12));  // Boom along x.
  expect_matches(example("satellite.yaml"), h);
}

}  // namespace
}  // namespace momenta::io
