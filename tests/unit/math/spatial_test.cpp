// Spatial algebra: the inline transform actions and cross products against their 6×6 matrices
// (Featherstone 2008, eqs. 2.24–2.32), duality of motion and force, and spatial inertia.
#include "momenta/math/spatial.hpp"
#include "momenta/inertia/mass_properties.hpp"

#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "momenta_test/tolerance.hpp"

namespace momenta {
namespace {

Transform some_transform() {
  return {rotation_from_axis_angle(Vec3(1, -2, 0.5), 0.9), Vec3(0.3, -0.7, 1.1)};
}

TEST(Spatial, TransformActionsMatchMatrices) {
  const Transform X = some_transform();
  const Vec6 m = (Vec6() << 0.1, -0.2, 0.3, 1.0, 2.0, -3.0).finished();
  // Round-off of O(1) products: 1e-15.
  EXPECT_MATRIX_NEAR(X.act_motion(m), X.motion_matrix() * m, 1e-15);
  EXPECT_MATRIX_NEAR(X.act_force(m), X.force_matrix() * m, 1e-15);
  EXPECT_MATRIX_NEAR(X.act_motion_inverse(m), X.inverse().motion_matrix() * m, 1e-15);
  EXPECT_MATRIX_NEAR(X.act_force_inverse(m), X.inverse().force_matrix() * m, 1e-15);
  // ᴬX_B* = (ᴮX_A)ᵀ, and the power f·m does not depend on the frame.
  EXPECT_MATRIX_NEAR(X.force_matrix(), X.inverse().motion_matrix().transpose(), 1e-15);
  const Vec6 f = (Vec6() << 2.0, 0.5, -1.0, 0.3, 0.2, 0.1).finished();
  EXPECT_NEAR(X.act_force(f).dot(X.act_motion(m)), f.dot(m), 1e-14);
  // Composition and inverse.
  const Transform Y(rotation_from_axis_angle(Vec3(0, 1, 1), -0.4), Vec3(-1, 0.2, 0.3));
  EXPECT_MATRIX_NEAR((X * Y).motion_matrix(), X.motion_matrix() * Y.motion_matrix(), 1e-14);
  EXPECT_TRUE((X * X.inverse()).isApprox(Transform::identity()));
  EXPECT_MATRIX_NEAR(X.apply(Vec3(1, 2, 3)), X.R * Vec3(1, 2, 3) + X.p, 1e-15);
}

TEST(Spatial, TransformsAgainstFeatherstoneWrittenOut) {
  // Featherstone 2008, eq. 2.24: ᴮX_A = [E 0; −E r× E] with E = R_ABᵀ and r = p_AoBo_A, its
  // blocks typed here entry by entry (no library matrix helper involved).
  const Transform X = some_transform();
  const Mat3 E = X.R.transpose();
  const Vec3 r = X.p;
  Mat3 r_cross;
  r_cross << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
  Mat6 B_X_A;
  B_X_A << E, Mat3::Zero(), -E * r_cross, E;
  const Vec6 m = (Vec6() << 0.1, -0.2, 0.3, 1.0, 2.0, -3.0).finished();
  EXPECT_MATRIX_NEAR(X.act_motion_inverse(m), B_X_A * m, 1e-15);
  // ᴬX_B = (ᴮX_A)⁻¹ = [Eᵀ 0; r× Eᵀ Eᵀ]; ᴬX_B* = [Eᵀ r× Eᵀ; 0 Eᵀ] (eq. 2.25–2.26).
  Mat6 A_X_B, A_X_B_force;
  A_X_B << E.transpose(), Mat3::Zero(), r_cross * E.transpose(), E.transpose();
  A_X_B_force << E.transpose(), r_cross * E.transpose(), Mat3::Zero(), E.transpose();
  EXPECT_MATRIX_NEAR(X.act_motion(m), A_X_B * m, 1e-15);
  EXPECT_MATRIX_NEAR(X.act_force(m), A_X_B_force * m, 1e-15);
  EXPECT_MATRIX_NEAR(A_X_B * B_X_A, Mat6::Identity(), 1e-15);

  // By hand: B turned 90° about z and 1 m along x from A.
  const Transform Z(rotation_from_axis_angle(Vec3::UnitZ(), std::numbers::pi / 2), Vec3(1, 0, 0));
  // Spinning about Bo's z at 1 rad/s: Ao, 1 m from the axis, moves at p × ω = (0, −1, 0).
  const Vec6 spin = (Vec6() << 0, 0, 1, 0, 0, 0).finished();
  EXPECT_MATRIX_NEAR(Z.act_motion(spin), (Vec6() << 0, 0, 1, 0, -1, 0).finished(), 1e-16);
  // A 1 N force along B's x at Bo is along A's y, with moment p × f = (0, 0, 1) N·m about Ao.
  const Vec6 push = (Vec6() << 0, 0, 0, 1, 0, 0).finished();
  EXPECT_MATRIX_NEAR(Z.act_force(push), (Vec6() << 0, 0, 1, 0, 1, 0).finished(), 1e-16);
  // And back.
  EXPECT_MATRIX_NEAR(Z.act_force_inverse(Z.act_force(push)), push, 1e-16);
  EXPECT_MATRIX_NEAR(Z.act_motion_inverse(Z.act_motion(spin)), spin, 1e-16);
}

// The half-cost forms for a rotation about one coordinate axis (a revolute joint's) against the
// general kernels, for each axis.
template <int K>
void check_about_axis(double angle) {
  const Vec3 p(0.3, -0.7, 1.1);
  const Mat3 R = rotation_from_axis_angle(Vec3::Unit(K), angle);
  const Vec6 m = (Vec6() << 0.1, -0.2, 0.3, 1.0, 2.0, -3.0).finished();
  Vec6 fast, general;
  kernel::motion_inverse_about_axis<K>(std::cos(angle), std::sin(angle), p, m.data(), fast.data());
  kernel::motion_inverse(R, p, m.data(), general.data());
  EXPECT_MATRIX_NEAR(fast, general, 1e-15);
  kernel::force_about_axis<K>(std::cos(angle), std::sin(angle), p, m.data(), fast.data());
  kernel::force(R, p, m.data(), general.data());
  EXPECT_MATRIX_NEAR(fast, general, 1e-15);
  // Cross product with a basis vector, against the general one.
  Vec6 e = Vec6::Zero();
  e[K] = 2.5;
  Vec6 basis = Vec6::Zero(), full = Vec6::Zero();
  kernel::add_cross_motion_axis<K>(m.data(), 2.5, basis.data());
  kernel::add_cross_motion(m.data(), e.data(), full.data());
  EXPECT_MATRIX_NEAR(basis, full, 0.0);
}

TEST(Spatial, InertiaColumnsAreTheMatrixColumns) {
  const SpatialInertia I(
      2.5, Vec3(0.3, -0.4, 0.5),
      (Mat3() << 0.4, -0.01, 0.02, -0.01, 0.5, 0.03, 0.02, 0.03, 0.6).finished());
  for (int k = 0; k < 6; ++k) {
    Vec6 column;
    kernel::inertia_column(I.mass, I.h, I.I_O, k, column.data());
    EXPECT_MATRIX_NEAR(column, I.matrix().col(k), 0.0) << k;
  }
}

TEST(Spatial, KernelsAboutACoordinateAxisMatchTheGeneralOnes) {
  check_about_axis<0>(0.8);
  check_about_axis<1>(-2.1);
  check_about_axis<2>(2.9);
}

TEST(Spatial, CrossProducts) {
  const Vec6 v = (Vec6() << 0.4, -1.0, 0.7, 2.0, 0.1, -0.5).finished();
  const Vec6 m = (Vec6() << 1.0, 2.0, 3.0, -1.0, 0.5, 0.25).finished();
  EXPECT_MATRIX_NEAR(cross_motion(v, m), crm(v) * m, 1e-15);
  EXPECT_MATRIX_NEAR(cross_force(v, m), crf(v) * m, 1e-15);
  EXPECT_MATRIX_NEAR(crf(v), -crm(v).transpose(), 0.0);
  // v ×m v = 0 exactly in exact arithmetic; a fused multiply-add keeps one product unrounded,
  // leaving at most an ulp of |v|² ≈ 5 (8.9e-16).
  EXPECT_MATRIX_NEAR(cross_motion(v, v), Vec6::Zero(), 8.9e-16);
}

TEST(Spatial, InertiaFromMassPropertiesAndTransformed) {
  const Mat3 R = rotation_from_axis_angle(Vec3(1, 1, 0), 0.6);
  const inertia::MassProperties mp(2.5, Vec3(0.1, -0.2, 0.3),
                                   R * Vec3(0.02, 0.03, 0.04).asDiagonal() * R.transpose());
  const SpatialInertia I = mp.spatial_inertia();
  EXPECT_MATRIX_NEAR(I.I_O, mp.inertia_about(Vec3::Zero()), 1e-15);
  EXPECT_MATRIX_NEAR(I.center_of_mass(), mp.center_of_mass(), 1e-15);
  const Vec6 V = (Vec6() << 0.4, -1.0, 0.7, 2.0, 0.1, -0.5).finished();
  EXPECT_MATRIX_NEAR(I * V, I.matrix() * V, 1e-15);
  // In A: ᴬX_B* I ᴮX_A (Featherstone eq. 2.66), against the mass properties moved to A.
  const Transform X = some_transform();
  const SpatialInertia IA = I.transformed(X);
  const Mat6 expected = X.force_matrix() * I.matrix() * X.inverse().motion_matrix();
  EXPECT_MATRIX_NEAR(IA.matrix(), expected, 1e-14);
  const inertia::MassProperties moved = mp.transformed(X.R, X.p);
  EXPECT_MATRIX_NEAR(IA.I_O, moved.inertia_about(Vec3::Zero()), 1e-14);
  // Kinetic energy is frame independent.
  EXPECT_NEAR(IA.kinetic_energy(X.act_motion(V)), I.kinetic_energy(V), 1e-14);
}

}  // namespace
}  // namespace momenta
