// The constraint solver's two ways to M⁻¹ Gᵀ — the articulated-body factors (the default) and
// CRBA with a dense Cholesky factor (the check) — give the same constrained accelerations and
// multipliers: on every bundled constrained example (loops, a prescribed crank, gears, rolling,
// knife edges), a four-bar and a 30-link loop, at their initial states and at states with random
// velocities made consistent. And they project a state moved off the constraints onto the same
// state.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>

#include <fmt/format.h>
#include <Eigen/SVD>

#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/constraints.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/hybrid_dynamics.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/system/constraint_solver.hpp"
#include "momenta_test/allocation_counter.hpp"
#include "momenta_test/closed_chains.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::constraint_methods_test {
namespace {

// The free accelerations (aba, or hybrid_dynamics where joints are prescribed), corrected by a
// solver using `method`: v̇, λ, and the residuals of the equations they solve —
// rnea(q, v, v̇) − τ_free − Gᵀλ on the free coordinates (τ_free = 0 here; an independent
// algorithm) and G v̇ + k.
struct Corrected {
  VecX vdot, lambda;
  double dynamics_residual = 0.0, constraint_residual = 0.0, residual_scale = 0.0;
  double kappa = 1.0;  // of M
};

Corrected correct(const model::Model& model, const VecX& q, const VecX& v,
                  system::AccelerationMethod method) {
  system::ConstraintSolver solver(model);
  solver.set_acceleration_method(method);
  dynamics::Data data(model);
  const VecX zero = VecX::Zero(model.nv());
  VecX vdot = model.has_prescribed_joints()
                  ? dynamics::hybrid_dynamics(model, data, q, v, zero, zero)
                  : dynamics::aba(model, data, q, v, zero);
  EXPECT_TRUE(solver.correct_accelerations(data, q, vdot));
  Corrected out{vdot, solver.multipliers()};
  // G and k formed apart from the solver (whose articulated method reads G v̇₀ + k off the
  // bodies' accelerations and the rows' k from that).
  const VecX tau_total = dynamics::rnea(model, data, q, v, vdot);
  dynamics::ConstraintRows rows(model);
  dynamics::constraint_equations(model, data, q, rows, dynamics::RowTerms::with_velocity_products);
  const VecX generalized = rows.G.transpose() * out.lambda;
  const VecX tau = tau_total - generalized;
  for (const model::Joint& j : model.joints()) {
    if (j.is_prescribed()) continue;
    for (int k = 0; k < j.nv(); ++k)
      out.dynamics_residual = std::max(out.dynamics_residual, std::abs(tau[j.v_index + k]));
  }
  out.constraint_residual = (rows.G * vdot + rows.bias).cwiseAbs().maxCoeff();
  const MatX M = dynamics::crba(model, data, q);
  out.residual_scale = std::max({1.0, M.cwiseAbs().maxCoeff() * vdot.cwiseAbs().maxCoeff(),
                                 generalized.cwiseAbs().maxCoeff(),
                                 rows.G.cwiseAbs().maxCoeff() * vdot.cwiseAbs().maxCoeff()});
  out.kappa = [&] {
    const Eigen::JacobiSVD<MatX> svd(M);
    return svd.singularValues()(0) / svd.singularValues()(svd.singularValues().size() - 1);
  }();
  return out;
}

// (q, v) projected onto the constraints by a solver using `method`.
struct Projected {
  VecX q, v;
  system::ConstraintResiduals residuals;
};

Projected project(const model::Model& model, VecX q, VecX v, system::AccelerationMethod method) {
  system::ConstraintSolver solver(model);
  solver.set_acceleration_method(method);
  dynamics::Data data(model);
  const long before = test::allocation_count();
  solver.project(0.0, data, q, v);
  EXPECT_EQ(test::allocation_count() - before, 0);  // the step's own work: no allocation
  return {q, v, solver.residuals(data, q, v)};
}

// The projection after a step, by both methods, from the consistent state (q, v) moved off the
// constraints as a step leaves it (coordinates by 1e-6 along random tangents, velocities by
// 1e-2). κ: that of M there.
void expect_projections_agree(const model::Model& model, const VecX& q, const VecX& v, double kappa,
                              std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  VecX step(model.nv()), q_off(model.nq()), v_off = v;
  for (const model::Joint& j : model.joints()) {
    for (int k = 0; k < j.nv(); ++k) {
      step[j.v_index + k] = j.is_prescribed() ? 0.0 : 1e-6 * u(rng);
      if (!j.is_prescribed()) v_off[j.v_index + k] += 1e-2 * u(rng);
    }
  }
  model::integrate(model, q, step, 1.0, q_off);
  const Projected articulated =
      project(model, q_off, v_off, system::AccelerationMethod::articulated);
  const Projected dense = project(model, q_off, v_off, system::AccelerationMethod::dense);
  // Both bring the residuals to round-off: Newton stops below 1e-14 or where the residual stops
  // shrinking, the velocities to round-off of their scale.
  const double v_scale = std::max(1.0, v.cwiseAbs().maxCoeff());
  EXPECT_LE(articulated.residuals.position, 1e-14);
  EXPECT_LE(articulated.residuals.velocity, 1e-14 * v_scale);
  // The same steps in the same metric (M at the state the projection starts from): two
  // backward-stable solves, whose corrections Δq and Δv agree to κ(M) ε of their size, 4 κ(M) ε,
  // with a floor of 1e-15 for round-off in q and v themselves. Measured: the examples (κ ≤
  // 2.3e3) ≤ 4.3e-22 in q and 7.5e-17 in v; the 30-link loop (κ = 2.5e6, whose light modes take
  // corrections up to 1.9e-4 rad and 1.0 rad/s) 2.1e-14 and 2.3e-12 against 4.2e-13 and 2.3e-9.
  VecX dq(model.nv());
  model::difference(model, q_off, dense.q, dq);
  const double q_bar = std::max(1e-15, 4 * kappa * 2.2e-16 * dq.cwiseAbs().maxCoeff());
  const double v_bar =
      std::max(1e-15 * v_scale, 4 * kappa * 2.2e-16 * (dense.v - v_off).cwiseAbs().maxCoeff());
  for (int i = 0; i < model.nq(); ++i) EXPECT_NEAR(articulated.q[i], dense.q[i], q_bar);
  EXPECT_MATRIX_NEAR(articulated.v, dense.v, v_bar);
}

void expect_methods_agree(const model::Model& model) {
  dynamics::Data data(model);
  system::ConstraintSolver solver(model);
  std::mt19937 rng(7), moves(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  VecX q = model.initial_q();
  model::normalize(model, q);
  VecX v = model.initial_v();
  const std::vector<char> none(model.num_joints(), 0);
  for (int state = 0; state < 3; ++state) {
    SCOPED_TRACE(fmt::format("state {}", state));
    if (state > 0) {
      for (Eigen::Index i = 0; i < v.size(); ++i) v[i] += u(rng);
    }
    solver.consistent_state(data, q, v, none, none);
    const Corrected articulated = correct(model, q, v, system::AccelerationMethod::articulated);
    const Corrected dense = correct(model, q, v, system::AccelerationMethod::dense);
    // The articulated method solves the equations to round-off (measured ≤ 1e-15 of the scale).
    EXPECT_LE(articulated.dynamics_residual, 1e-13 * articulated.residual_scale);
    EXPECT_LE(articulated.constraint_residual, 1e-13 * articulated.residual_scale);
    // Two backward-stable solves of the same equations differ by κ(M) ε of the results: 1e-12 of
    // their scale (the bar) where κ(M) ≤ ~1e3 — every example and the four-bar — and
    // 4 κ(M) ε where M is worse conditioned (the 30-link loop: κ = 2.5e6, measured 8e-12).
    const double bar = std::max(1e-12, 4 * dense.kappa * 2.2e-16);
    const double a_scale = std::max(1.0, dense.vdot.cwiseAbs().maxCoeff());
    const double l_scale = std::max(1.0, dense.lambda.cwiseAbs().maxCoeff());
    EXPECT_MATRIX_NEAR(articulated.vdot, dense.vdot, bar * a_scale);
    EXPECT_MATRIX_NEAR(articulated.lambda, dense.lambda, bar * l_scale);
    expect_projections_agree(model, q, v, dense.kappa, moves);
  }
}

TEST(ConstraintMethods, ArticulatedEqualsDenseOnEveryConstrainedExample) {
  int examples = 0;
  for (const auto& entry : std::filesystem::directory_iterator("examples/constraints")) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    const io::ModelFile file = io::read_model_file(entry.path().string());
    expect_methods_agree(file.model);
    ++examples;
  }
  EXPECT_GE(examples, 9);
}

TEST(ConstraintMethods, ArticulatedEqualsDenseOnTheFourBarAndTheThirtyLinkLoop) {
  for (const int n : {3, 30}) {
    SCOPED_TRACE(fmt::format("{} links", n));
    const io::ModelFile file = io::parse_model_file(
        n == 3 ? test::four_bar_text() : test::v_loop_text(n), "chain.yaml", ".");
    expect_methods_agree(file.model);
  }
}

}  // namespace
}  // namespace momenta::constraint_methods_test
