// articulated_solve against M⁻¹ from crba and a dense Cholesky factor: every joint type, with and
// without prescribed joints (M_ff⁻¹ over the free coordinates), zero columns, wrong sizes.
#include "momenta/dynamics/articulated_solve.hpp"

#include <limits>
#include <random>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/hybrid_dynamics.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/point_kinematics.hpp"
#include "momenta_test/multibody_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics::articulated_solve_test {
namespace {

// Random generalized forces, five columns, the third all zero.
MatX random_columns(int nv, std::mt19937& rng) {
  MatX X(nv, 5);
  for (int k = 0; k < 5; ++k) X.col(k) = test::random_vector(nv, rng, 3.0);
  X.col(2).setZero();
  return X;
}

TEST(ArticulatedSolve, EqualsTheInverseMassMatrixOnRandomTreesOfEveryJointType) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE(fmt::format("seed {}", seed));
    const Model m = test::random_tree(14, seed);
    std::mt19937 rng(seed + 300);
    const VecX q = test::random_configuration(m, rng);
    const VecX v = test::random_vector(m.nv(), rng, 2.0);
    const VecX tau = test::random_vector(m.nv(), rng, 3.0);
    Data data(m), work(m);
    aba(m, data, q, v, tau);
    const MatX X = random_columns(m.nv(), rng);
    MatX Y = X;
    articulated_solve(m, data, {}, Y);

    // Two independent references: the dense solve, and M Y = X. The solve's error is κ(M) ε
    // times |Y| (κ up to ~1e3 on these trees); the residual is round-off of |M| |Y| (measured
    // ≤ 2e-15 of it).
    const MatX M = crba(m, work, q);
    const MatX reference = M.llt().solve(X);
    const double scale = std::max(1.0, reference.cwiseAbs().maxCoeff());
    EXPECT_MATRIX_NEAR(Y, reference, 1e-11 * scale);
    EXPECT_MATRIX_NEAR(M * Y, X, 1e-13 * M.cwiseAbs().maxCoeff() * scale);
    EXPECT_TRUE(Y.col(2).isZero(0.0));  // a zero column is left alone, exactly
    // aba's results are untouched: the solve has its own workspace.
    EXPECT_MATRIX_NEAR(data.vdot, aba(m, work, q, v, tau), 0.0);
  }
}

TEST(ArticulatedSolve, HoldsPrescribedJointsAndSolvesTheFreeBlock) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE(fmt::format("seed {}", seed));
    const Model m = test::random_tree(14, seed);
    std::mt19937 rng(seed + 400);
    const VecX q = test::random_configuration(m, rng);
    const VecX v = test::random_vector(m.nv(), rng, 2.0);
    const VecX a = test::random_vector(m.nv(), rng, 3.0);
    std::vector<char> prescribed(m.num_joints(), 0);
    for (int j = 0; j < m.num_joints(); j += 3) prescribed[j] = 1;  // roots and inner joints
    Data data(m), work(m);
    hybrid_dynamics(m, data, prescribed, q, v, a, a);
    const MatX X = random_columns(m.nv(), rng);
    MatX Y = X;
    articulated_solve(m, data, prescribed, Y);

    // M_ff⁻¹ X_f over the free coordinates; zero on the held ones.
    std::vector<int> free;
    for (int j = 0; j < m.num_joints(); ++j) {
      if (prescribed[j]) continue;
      for (int k = 0; k < m.joint(j).nv(); ++k) free.push_back(m.joint(j).v_index + k);
    }
    const int nf = static_cast<int>(free.size());
    ASSERT_GT(nf, 0);
    ASSERT_LT(nf, m.nv());
    const MatX M = crba(m, work, q);
    MatX M_ff(nf, nf), X_f(nf, X.cols());
    for (int r = 0; r < nf; ++r) {
      X_f.row(r) = X.row(free[r]);
      for (int c = 0; c < nf; ++c) M_ff(r, c) = M(free[r], free[c]);
    }
    const MatX reference = M_ff.llt().solve(X_f);
    const double scale = std::max(1.0, reference.cwiseAbs().maxCoeff());
    MatX expected = MatX::Zero(m.nv(), X.cols());
    for (int r = 0; r < nf; ++r) expected.row(free[r]) = reference.row(r);
    EXPECT_MATRIX_NEAR(Y, expected, 1e-11 * scale);
  }
}

// Rows by hand on a random tree: wrenches (random, in W about Wo) between random bodies, the
// world among them, G_r = w_rᵀ (J_b − J_a) from frame_jacobian; a coupler-like row (G written
// directly, a = b = 0); and a row of zeros.
ConstraintRows random_rows(const Model& m, const Data& kinematics, std::mt19937& rng) {
  const int count = 7;
  ConstraintRows rows(m);
  rows.count = count;
  rows.G = MatX::Zero(count, m.nv());
  rows.wrench_W.assign(count, Vec6::Zero());
  rows.body_a.assign(count, 0);
  rows.body_b.assign(count, 0);
  std::uniform_int_distribution<int> body(1, m.num_bodies() - 1);
  MatX J(6, m.nv());
  const auto jacobian_about_Wo = [&](int b) {
    frame_jacobian(m, kinematics, b, kinematics.X_WB[b].inverse().p, J);
    return J;
  };
  for (int r = 0; r < 5; ++r) {
    const int b = body(rng);
    int a = r == 0 ? 0 : body(rng);
    if (a == b) a = 0;
    rows.body_a[r] = a;
    rows.body_b[r] = b;
    rows.wrench_W[r] = test::random_vector(6, rng, 1.0);
    rows.G.row(r) = rows.wrench_W[r].transpose() * jacobian_about_Wo(b);
    if (a != 0) rows.G.row(r) -= rows.wrench_W[r].transpose() * jacobian_about_Wo(a);
  }
  rows.G(5, 0) = 1.0;  // a coupler's row: q₀ − 1.7 q_last
  rows.G(5, m.nv() - 1) = -1.7;
  return rows;  // row 6: zero
}

// articulated_row_factors after aba_articulate, against dense references on random trees of
// every joint type (roots that are free, fixed and revolute; bodies under external wrenches):
// (L Gᵀ)ᵀ D⁻¹ (L Gᵀ) = G M⁻¹ Gᵀ by crba's Cholesky; the rows' accelerations at aba's v̇₀,
// w·(A_b − A_a) from forward_kinematics(q, v, v̇₀) (world-aligned, gravity included) and G v̇₀
// for the coupler's row; and one pass 3 with (L Gᵀ) λ = aba(…) + M⁻¹ Gᵀ λ. Errors are κ(M) ε
// of the results (κ up to ~1e3 on these trees).
TEST(ArticulatedRowFactors, GiveTheRowsMetricAccelerationsAndCorrectionOfTheDenseSolve) {
  using model::JointType;
  const std::vector<std::vector<JointType>> roots = {
      {JointType::revolute, JointType::free, JointType::prismatic, JointType::spherical,
       JointType::cylindrical, JointType::universal, JointType::fixed, JointType::planar},
      {JointType::fixed, JointType::revolute, JointType::spherical, JointType::prismatic},
      {JointType::free, JointType::universal, JointType::revolute, JointType::fixed,
       JointType::cylindrical}};
  for (unsigned seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE(fmt::format("seed {}", seed));
    const Model m = test::random_tree(14, seed, roots[seed % roots.size()]);
    std::mt19937 rng(seed + 500);
    const VecX q = test::random_configuration(m, rng);
    const VecX v = test::random_vector(m.nv(), rng, 2.0);
    const VecX tau = test::random_vector(m.nv(), rng, 3.0);
    std::vector<Vec6> f_ext(m.num_bodies());
    for (Vec6& f : f_ext) f = test::random_vector(6, rng, 2.0);
    Data data(m), work(m);
    const VecX vdot0 = aba(m, work, q, v, tau, f_ext);
    forward_kinematics(m, work, q, v, vdot0);
    const ConstraintRows rows = random_rows(m, work, rng);
    aba_articulate(m, data, q, v, tau, f_ext);
    data.X_WB = work.X_WB;  // as constraint_equations leaves them
    const double nan = std::numeric_limits<double>::quiet_NaN();
    MatX LGt = MatX::Constant(m.nv(), rows.count, nan), Dinv_LGt = LGt;
    VecX acceleration(rows.count);
    std::vector<int> active(rows.count);
    EXPECT_EQ(articulated_row_factors(m, data, rows, LGt, Dinv_LGt, acceleration, active), 6);
    for (int r = 0; r < 6; ++r) EXPECT_EQ(active[r], r);
    // The zero row's columns are not written (they are zero); every other column is, whole.
    EXPECT_TRUE(LGt.col(6).array().isNaN().all());
    EXPECT_TRUE(Dinv_LGt.col(6).array().isNaN().all());
    EXPECT_TRUE(LGt.leftCols(6).allFinite());
    EXPECT_TRUE(Dinv_LGt.leftCols(6).allFinite());
    EXPECT_EQ(acceleration[6], 0.0);
    LGt.col(6).setZero();
    Dinv_LGt.col(6).setZero();

    const MatX M = crba(m, work, q);
    const Eigen::LLT<MatX> llt(M);
    const MatX metric = rows.G * llt.solve(rows.G.transpose());
    EXPECT_MATRIX_NEAR(LGt.transpose() * Dinv_LGt, metric, 1e-12 * metric.cwiseAbs().maxCoeff());

    VecX expected(rows.count);
    double scale = 0.0;
    for (int r = 0; r < rows.count; ++r) {
      if (rows.body_a[r] == rows.body_b[r]) {  // the coupler's and the zero row
        expected[r] = rows.G.row(r).dot(vdot0);
      } else {
        const auto A_W = [&](int b) -> Vec6 {  // world-aligned at Wo: W about Wo
          if (b == 0) return Vec6::Zero();
          return work.X_WB[b].act_motion(work.A_WB_B[b]);
        };
        expected[r] = rows.wrench_W[r].dot(A_W(rows.body_b[r]) - A_W(rows.body_a[r]));
      }
      scale = std::max(scale, rows.G.row(r).cwiseAbs().dot(vdot0.cwiseAbs()));
    }
    EXPECT_MATRIX_NEAR(acceleration, expected, 1e-12 * scale);

    const VecX lambda = test::random_vector(rows.count, rng, 1.0);
    const VecX corrected = vdot0 + llt.solve(rows.G.transpose() * lambda);
    const VecX du = LGt * lambda;
    EXPECT_MATRIX_NEAR(aba_accelerate(m, data, du), corrected,
                       1e-11 * std::max(1.0, corrected.cwiseAbs().maxCoeff()));
    // data.u is read, not changed: without du, pass 3 gives aba's accelerations again.
    EXPECT_MATRIX_NEAR(aba_accelerate(m, data), vdot0, 0.0);
  }
}

TEST(ArticulatedRowFactors, WrongSizesAreRefusedByName) {
  const Model m = test::random_tree(5, 2);
  Data data(m);
  ConstraintRows rows(m);
  rows.count = 2;
  rows.G = MatX::Ones(2, m.nv());
  rows.body_a.assign(2, 0);
  rows.body_b.assign(2, 0);
  rows.wrench_W.assign(2, Vec6::Zero());
  MatX X = MatX::Ones(m.nv(), 2), Z = MatX::Ones(m.nv(), 2), wide = MatX::Ones(m.nv(), 3);
  VecX r(2), long_r(3);
  std::vector<int> active(2), short_active(1);
  EXPECT_THROW(articulated_row_factors(m, data, rows, X, wide, r, active), InvalidArgument);
  EXPECT_THROW(articulated_row_factors(m, data, rows, wide, Z, r, active), InvalidArgument);
  EXPECT_THROW(articulated_row_factors(m, data, rows, X, Z, long_r, active), InvalidArgument);
  EXPECT_THROW(articulated_row_factors(m, data, rows, X, Z, r, short_active), InvalidArgument);
  EXPECT_THROW(aba_accelerate(m, data, VecX::Ones(m.nv() + 1)), InvalidArgument);
}

TEST(ArticulatedSolve, WrongSizesAreRefusedByName) {
  const Model m = test::random_tree(5, 2);
  const Model other = test::random_tree(7, 2);
  Data data(m), other_data(other);
  MatX X = MatX::Ones(m.nv() + 1, 2);
  EXPECT_THROW(articulated_solve(m, data, {}, X), InvalidArgument);
  MatX Y = MatX::Ones(m.nv(), 2);
  EXPECT_THROW(articulated_solve(m, other_data, {}, Y), InvalidArgument);
  const std::vector<char> mask(m.num_joints() + 1, 0);
  EXPECT_THROW(articulated_solve(m, data, mask, Y), InvalidArgument);
  try {
    articulated_solve(m, data, {}, X);
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("articulated_solve"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace momenta::dynamics::articulated_solve_test
