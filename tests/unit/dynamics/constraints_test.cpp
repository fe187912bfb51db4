// The constraint rows (dynamics/constraints.hpp) against finite differences, on a model with
// every kind of constraint at random states: G v is the rate of φ, G v̇ + k the rate of G v, and
// the forces add_constraint_forces applies deliver the power λᵀ G v. And the constraint solver's
// two methods (articulated-body factors, dense CRBA) agree on it, without allocating.
//
// Tolerances: central differences of step h = 1e-5 have truncation ~h² ≈ 1e-10 and round-off
// ~ε/h ≈ 1e-11 relative to the rows' scale; 1e-7 leaves room for the second derivatives' size.

#include <gtest/gtest.h>

#include <Eigen/SVD>

#include <algorithm>
#include <optional>
#include <random>
#include <utility>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/constraints.hpp"
#include "momenta/dynamics/contact_geometry.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/hybrid_dynamics.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta/model/model_builder.hpp"
#include "momenta/system/constraint_solver.hpp"
#include "momenta_test/allocation_counter.hpp"
#include "momenta_test/constrained_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta {
namespace {

using model::JointType;

using test::add_tree_of_joint_types;
using test::every_constraint_model;
using test::frame;
using test::random_state;
using test::RandomState;

class ConstraintRowsTest : public ::testing::Test {
 protected:
  model::Model model = every_constraint_model();
  dynamics::Data data{model};
  dynamics::ConstraintRows rows{model};
  std::mt19937 rng{7};

  void rows_at(const VecX& q, const VecX& v) {
    dynamics::forward_kinematics(model, data, q, v);
    dynamics::constraint_equations(model, data, q, rows,
                                   dynamics::RowTerms::with_velocity_products);
  }
};

TEST_F(ConstraintRowsTest, SizesAndNames) {
  EXPECT_EQ(rows.count, 6 + 3 + 5 + 5 + 1 + 3 + 3 + 1 + 1);
  EXPECT_EQ(model.num_constraint_rows(), rows.count);
  EXPECT_EQ(rows.names[6], "ball.x");
  EXPECT_EQ(rows.names[21], "wheel.longitudinal");
  int position_rows = 0;
  for (char h : rows.holonomic) position_rows += h;
  EXPECT_EQ(position_rows, rows.count - 2 - 2 - 1);
}

TEST_F(ConstraintRowsTest, JacobianIsTheRateOfThePositionRows) {
  const double h = 1e-5;
  for (int trial = 0; trial < 20; ++trial) {
    const RandomState s = random_state(model, rng);
    rows_at(s.q, s.v);
    const VecX Gv = rows.G * s.v;
    dynamics::forward_kinematics(model, data, model::integrate(model, s.q, s.v, h));
    dynamics::constraint_equations(model, data, model::integrate(model, s.q, s.v, h), rows);
    const VecX plus = rows.position;
    dynamics::forward_kinematics(model, data, model::integrate(model, s.q, s.v, -h));
    dynamics::constraint_equations(model, data, model::integrate(model, s.q, s.v, -h), rows);
    const VecX rate = (plus - rows.position) / (2 * h);
    for (int i = 0; i < rows.count; ++i) {
      if (!rows.holonomic[i]) continue;
      EXPECT_NEAR(Gv[i], rate[i], 1e-7 * (1 + std::abs(Gv[i])))
          << rows.names[i] << " trial " << trial;
    }
  }
}

TEST_F(ConstraintRowsTest, VelocityProductTermIsTheRateOfTheVelocityRows) {
  const double h = 1e-5;
  for (int trial = 0; trial < 20; ++trial) {
    const RandomState s = random_state(model, rng);
    rows_at(s.q, s.v);
    const VecX accel = rows.G * s.vdot + rows.bias;
    // G v along the motion q(t) = q ⊕ (t v + ½ t² v̇), v(t) = v + t v̇.
    const auto Gv_at = [&](double t) {
      const VecX q = model::integrate(model, s.q, t * s.v + 0.5 * t * t * s.vdot, 1.0);
      const VecX v = s.v + t * s.vdot;
      rows_at(q, v);
      return VecX(rows.G * v);
    };
    const VecX rate = (Gv_at(h) - Gv_at(-h)) / (2 * h);
    for (int i = 0; i < rows.count; ++i) {
      EXPECT_NEAR(accel[i], rate[i], 1e-7 * (1 + std::abs(accel[i])))
          << rows.names[i] << " trial " << trial;
    }
  }
}

// The solver's right-hand side read off the bodies' accelerations of aba or hybrid_dynamics
// (RowTerms::with_acceleration_residual) is G v̇ + k formed from G and k: both are sums of the
// same few products, so they agree to round-off of the largest term (measured ≤ 5.8e-16 of
// it; a wrong term would show at O(1)).
TEST_F(ConstraintRowsTest, AccelerationResidualIsGTimesTheAccelerationsPlusK) {
  std::vector<char> prescribed(model.num_joints(), 0);
  prescribed[0] = prescribed[3] = 1;  // j1 and j4: the gear's two joints, driven
  for (int trial = 0; trial < 20; ++trial) {
    const RandomState s = random_state(model, rng);
    const VecX tau = 5.0 * s.vdot.reverse();
    const bool hybrid = trial % 2 == 1;
    const VecX vdot =
        hybrid ? dynamics::hybrid_dynamics(model, data, prescribed, s.q, s.v, s.vdot, tau)
               : dynamics::aba(model, data, s.q, s.v, tau);
    dynamics::constraint_equations(model, data, s.q, rows,
                                   dynamics::RowTerms::with_acceleration_residual);
    const VecX residual = rows.bias;
    rows_at(s.q, s.v);
    const VecX expected = rows.G * vdot + rows.bias;
    const double scale = std::max({1.0, rows.G.cwiseAbs().maxCoeff() * vdot.cwiseAbs().maxCoeff(),
                                   rows.bias.cwiseAbs().maxCoeff()});
    ASSERT_TRUE(residual.allFinite());
    EXPECT_MATRIX_NEAR(residual, expected, 1e-14 * scale) << "trial " << trial;
  }
}

TEST_F(ConstraintRowsTest, ForcesDeliverThePowerOfTheirMultipliers) {
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 10; ++trial) {
    const RandomState s = random_state(model, rng);
    rows_at(s.q, s.v);
    const VecX lambda = VecX::NullaryExpr(rows.count, [&] { return u(rng); });
    std::vector<Vec6> f_ext(model.num_bodies(), Vec6::Zero());
    VecX tau = VecX::Zero(model.nv());
    dynamics::add_constraint_forces(model, data, rows, lambda, f_ext, tau);
    double power = tau.dot(s.v);
    for (int b = 1; b < model.num_bodies(); ++b) power += f_ext[b].dot(data.V_WB_B[b]);
    EXPECT_NEAR(power, lambda.dot(rows.G * s.v), 1e-12 * (1 + std::abs(power)));
  }
}

// Contacts (model::Contact), switched on as a run switches them on: a point with friction on a
// tilted ground plane, a sphere with friction on another body's plane (both turning and moving),
// two spheres with friction, and a disk's rim with friction on each plane. Their rows against
// finite differences as above: G v the rate of each gap, and G v̇ + k the rate of every row's G v
// (the tangent rows: the slip along the plane's tangents). The gap's second rate the run's locator
// takes (contact_gap_acceleration, from the bodies' accelerations) is the first row's G v̇ + k.
TEST(ConstraintRows, ContactRowsSwitchedOnAreTheRatesOfTheirGapsAndSlips) {
  model::ModelBuilder b;
  add_tree_of_joint_types(b);
  const Transform X(Eigen::AngleAxisd(0.7, Vec3(-1, 2, 1).normalized()).toRotationMatrix(),
                    Vec3(0.05, 0.1, -0.2));
  model::Contact ground;
  ground.name = "floor";
  ground.frame = frame("b3", X);
  ground.plane_normal = Vec3(0, 0.6, 0.8);
  ground.plane_point = Vec3(0, 0, -0.1);
  ground.static_friction = 0.5;
  ground.kinetic_friction = 0.4;
  model::Contact on_body = ground;
  on_body.name = "on_body";
  on_body.frame = frame("b2", X);
  on_body.radius = 0.05;
  on_body.other = frame("b4", {});
  on_body.other_plane = true;
  on_body.plane_normal = Vec3(0.48, 0.6, 0.64);
  on_body.plane_point = Vec3(0.1, 0.2, 0.3);
  model::Contact spheres;
  spheres.name = "spheres";
  spheres.frame = frame("b5", X);
  spheres.radius = 0.1;
  spheres.other = frame("b1", X.inverse());
  spheres.other_radius = 0.2;
  spheres.static_friction = 0.3;  // its tangents turn with the line of centres
  spheres.kinetic_friction = 0.2;
  model::Contact disk_on_ground = ground;
  disk_on_ground.name = "disk_on_ground";
  disk_on_ground.frame = frame("b4", X);
  disk_on_ground.shape = model::ContactShape::disk;
  disk_on_ground.radius = 0.15;
  model::Contact disk_on_body = on_body;
  disk_on_body.name = "disk_on_body";
  disk_on_body.frame = frame("b1", X.inverse());
  disk_on_body.other = frame("b3", {});
  disk_on_body.shape = model::ContactShape::disk;
  disk_on_body.radius = 0.1;
  // A disk against a ball: one so wide that the ball is always over its face, one so narrow
  // that it is always beside its rim.
  model::Contact disk_face_ball = spheres;
  disk_face_ball.name = "disk_face_ball";
  disk_face_ball.frame = frame("b2", X);
  disk_face_ball.shape = model::ContactShape::disk;
  disk_face_ball.radius = 10.0;
  disk_face_ball.other = frame("b5", X.inverse());
  model::Contact disk_rim_ball = disk_face_ball;
  disk_rim_ball.name = "disk_rim_ball";
  disk_rim_ball.radius = 0.01;
  disk_rim_ball.other = frame("b3", X);
  const std::vector<model::Contact> contacts{
      ground, on_body, spheres, disk_on_ground, disk_on_body, disk_face_ball, disk_rim_ball};
  for (const model::Contact& c : contacts) b.add_constraint(c);
  const model::Model model = b.build();
  dynamics::Data data(model);
  dynamics::ConstraintRows rows(model);
  ASSERT_EQ(rows.count, 3 * 7);
  EXPECT_EQ(rows.names[4], "on_body.tangent_1");
  std::fill(rows.enabled.begin(), rows.enabled.end(), 1);
  const auto rows_at = [&](const VecX& q, const VecX& v) {
    dynamics::forward_kinematics(model, data, q, v);
    dynamics::constraint_equations(model, data, q, rows,
                                   dynamics::RowTerms::with_velocity_products);
  };
  std::mt19937 rng(11);
  const double h = 1e-5;
  for (int trial = 0; trial < 20; ++trial) {
    const RandomState s = random_state(model, rng);
    rows_at(s.q, s.v);
    const VecX Gv = rows.G * s.v;
    const VecX accel = rows.G * s.vdot + rows.bias;
    const auto position_at = [&](double t) {
      rows_at(model::integrate(model, s.q, s.v, t), s.v);
      return VecX(rows.position);
    };
    const VecX rate = (position_at(h) - position_at(-h)) / (2 * h);
    const auto Gv_at = [&](double t) {
      const VecX q = model::integrate(model, s.q, t * s.v + 0.5 * t * t * s.vdot, 1.0);
      const VecX v = s.v + t * s.vdot;
      rows_at(q, v);
      return VecX(rows.G * v);
    };
    const VecX Gv_rate = (Gv_at(h) - Gv_at(-h)) / (2 * h);
    for (int i = 0; i < rows.count; ++i) {
      if (rows.holonomic[i]) {
        EXPECT_NEAR(Gv[i], rate[i], 1e-7 * (1 + std::abs(Gv[i])))
            << rows.names[i] << " trial " << trial;
      }
      EXPECT_NEAR(accel[i], Gv_rate[i], 1e-7 * (1 + std::abs(accel[i])))
          << rows.names[i] << " trial " << trial;
    }
    // Two sums of the same products by different routes: round-off of the largest term.
    dynamics::forward_kinematics(model, data, s.q, s.v, s.vdot);
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      const double gap_acceleration = dynamics::contact_gap_acceleration(
          std::get<model::Contact>(model.constraints()[k]), data);
      const int first = rows.first_row[k];
      EXPECT_NEAR(gap_acceleration, accel[first], 1e-12 * (1 + std::abs(accel[first])))
          << rows.names[first] << " trial " << trial;
    }
  }
}

TEST(ConstraintRows, DegenerateDirectionIsNamed) {
  model::ModelBuilder b;
  b.add_body("arm", inertia::box(inertia::Amount::mass(1.0), Vec3(0.1, 0.2, 0.3)));
  model::Joint j;
  j.name = "hinge";
  j.parent = "world";
  j.child = "arm";
  b.add_joint(j);
  b.add_constraint(model::DistanceLink{"tie", {"world", {}, -1}, {"arm", {}, -1}, 1.0});
  const model::Model model = b.build();
  dynamics::Data data(model);
  dynamics::ConstraintRows rows(model);
  const VecX q = model.initial_q();
  dynamics::forward_kinematics(model, data, q);
  try {
    dynamics::constraint_equations(model, data, q, rows);
    FAIL() << "coincident points accepted";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("constraint 'tie': its two points coincide"),
              std::string::npos)
        << e.what();
  }
}

// --- The constraint solver's two methods on every row kind and joint type -----------------------

// The free accelerations of (q, v, τ) corrected by a solver using `method`: v̇ and λ, or nothing
// where the rows there are fewer than at the model's initial configuration.
std::optional<std::pair<VecX, VecX>> corrected(const model::Model& model, const RandomState& s,
                                               const VecX& tau, system::AccelerationMethod method) {
  system::ConstraintSolver solver(model);
  solver.set_acceleration_method(method);
  dynamics::Data data(model);
  VecX vdot = dynamics::aba(model, data, s.q, s.v, tau);
  if (!solver.correct_accelerations(data, s.q, vdot)) return std::nullopt;
  return std::make_pair(vdot, solver.multipliers());
}

// The same tree with one constraint of each kind that leaves the rows independent at random
// states (nine rows on fourteen coordinates): a ball joint, a wire, a rolling sphere, a knife
// edge and a gear coupler. (every_constraint_model's 28 rows are mostly dependent there, and
// which of two nearly dependent rows carries the force is decided by round-off.)
model::Model independent_constraints_model() {
  model::ModelBuilder b;
  add_tree_of_joint_types(b);
  const Transform X(Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()).toRotationMatrix(),
                    Vec3(0.1, -0.2, 0.05));
  b.add_constraint(
      model::LoopClosure{"ball", model::LoopType::point, frame("b1", X), frame("b3", X)});
  b.add_constraint(model::DistanceLink{"wire", frame("b2", X), frame("world", {}), 0.5});
  b.add_constraint(model::RollingContact{"ball_roll", frame("b2", X), model::RollingShape::sphere,
                                         0.1, Vec3::UnitZ(), Vec3::Zero()});
  b.add_constraint(model::KnifeEdge{"blade", frame("b5", X), Vec3::UnitZ()});
  b.add_constraint(model::JointCoupler{"gear", "j1", "j4", -1.7, 0.2});
  return b.build();
}

TEST(ConstraintSolverMethods, ArticulatedEqualsDenseOnEveryRowKindAndJointType) {
  // Revolute, spherical, free, prismatic and planar joints; wrench rows of every form (loop,
  // distance, rolling, knife edge) and a coupler's joint-space row. The equations hold at any
  // state, assembled or not.
  const model::Model model = independent_constraints_model();
  std::mt19937 rng(11);
  int compared = 0;
  for (int trial = 0; trial < 12; ++trial) {
    SCOPED_TRACE(trial);
    const RandomState s = random_state(model, rng);
    const VecX tau = s.vdot;  // random generalized forces
    const auto articulated = corrected(model, s, tau, system::AccelerationMethod::articulated);
    const auto dense = corrected(model, s, tau, system::AccelerationMethod::dense);
    ASSERT_EQ(articulated.has_value(), dense.has_value());
    if (!dense) continue;
    ++compared;
    // Two backward-stable solves differ by the conditioning of G M⁻¹ Gᵀ (κ(M) ≈ 240 here, κ of
    // G M⁻¹ Gᵀ 7e2 – 4e6 over these states: random states put rows near dependence): 1e-12
    // relative, or 4 κ ε where that is larger (measured 0.1 – 0.4 κ ε).
    system::ConstraintSolver rows_of(model);
    dynamics::Data data(model);
    VecX vdot = dynamics::aba(model, data, s.q, s.v, tau);
    rows_of.correct_accelerations(data, s.q, vdot);
    const MatX& G = rows_of.rows().G;
    const MatX M = dynamics::crba(model, data, s.q);
    const Eigen::JacobiSVD<MatX> svd(G * M.llt().solve(G.transpose()));
    const VecX& sigma = svd.singularValues();
    int rank = 0;
    while (rank < sigma.size() && sigma[rank] > 1e-10 * sigma[0]) ++rank;
    const double bar = std::max(1e-12, 4 * sigma[0] / sigma[rank - 1] * 2.2e-16);
    const double a_scale = std::max(1.0, dense->first.cwiseAbs().maxCoeff());
    const double l_scale = std::max(1.0, dense->second.cwiseAbs().maxCoeff());
    EXPECT_MATRIX_NEAR(articulated->first, dense->first, bar * a_scale);
    EXPECT_MATRIX_NEAR(articulated->second, dense->second, bar * l_scale);
  }
  EXPECT_GE(compared, 6);
}

// Both methods leave the rows' k in rows().bias: the dense one as formed, the articulated one as
// (G v̇₀ + k) − G v̇₀ with G v̇₀ = G v̇ − (G M⁻¹ Gᵀ) λ (it never forms k). Against k formed
// apart (RowTerms::with_velocity_products): the dense method's exactly; the articulated one's to
// round-off of the terms that cancel, |G| |v̇| and |G| |M⁻¹ Gᵀ λ|, through the articulated
// passes (measured ≤ 2.9e-14 of them at these states).
TEST(ConstraintSolverMethods, BothLeaveTheRowsVelocityProductTerm) {
  const model::Model model = independent_constraints_model();
  std::mt19937 rng(13);
  for (int trial = 0; trial < 12; ++trial) {
    SCOPED_TRACE(trial);
    const RandomState s = random_state(model, rng);
    dynamics::Data data(model);
    dynamics::ConstraintRows rows(model);
    dynamics::forward_kinematics(model, data, s.q, s.v);
    dynamics::constraint_equations(model, data, s.q, rows,
                                   dynamics::RowTerms::with_velocity_products);
    for (const auto method :
         {system::AccelerationMethod::articulated, system::AccelerationMethod::dense}) {
      system::ConstraintSolver solver(model);
      solver.set_acceleration_method(method);
      VecX vdot = dynamics::aba(model, data, s.q, s.v, s.vdot);
      if (!solver.correct_accelerations(data, s.q, vdot)) continue;
      const VecX generalized = rows.G.transpose() * solver.multipliers();
      const VecX Gvdot_terms = rows.G.cwiseAbs() * vdot.cwiseAbs();
      const MatX M = dynamics::crba(model, data, s.q);
      const VecX A_lambda = rows.G.cwiseAbs() * M.llt().solve(generalized).cwiseAbs();
      const double scale = std::max(
          {1.0, rows.bias.cwiseAbs().maxCoeff(), Gvdot_terms.maxCoeff(), A_lambda.maxCoeff()});
      EXPECT_MATRIX_NEAR(solver.rows().bias, rows.bias, 1e-13 * scale);
    }
  }
}

TEST(ConstraintSolverMethods, CorrectingAccelerationsDoesNotAllocate) {
  const model::Model model = every_constraint_model();
  std::mt19937 rng(5);
  const RandomState s = random_state(model, rng);
  for (const auto method :
       {system::AccelerationMethod::articulated, system::AccelerationMethod::dense}) {
    system::ConstraintSolver solver(model);
    solver.set_acceleration_method(method);
    dynamics::Data data(model);
    VecX vdot = dynamics::aba(model, data, s.q, s.v, s.vdot);
    const long before = test::allocation_count();
    solver.correct_accelerations(data, s.q, vdot);
    EXPECT_EQ(test::allocation_count() - before, 0);
  }
}

}  // namespace
}  // namespace momenta
