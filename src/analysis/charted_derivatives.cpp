#include "charted_derivatives.hpp"

#include <algorithm>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "linearize_parts.hpp"
#include "momenta/common/error.hpp"
#include "momenta/dynamics/constraint_derivatives.hpp"

namespace momenta::analysis::detail {
namespace {

// The velocity indices `coordinates` as positions in the free coordinates.
std::vector<int> slots_of(const std::vector<int>& coordinates, const std::vector<int>& free) {
  std::vector<int> slots;
  for (int i : coordinates)
    slots.push_back(static_cast<int>(std::find(free.begin(), free.end(), i) - free.begin()));
  return slots;
}

}  // namespace

MatX charted_state_matrix(ModelResidual& residual, ConstraintChart& chart,
                          const OperatingPoint& p) {
  const model::Model& model = residual.model();
  const std::vector<int>& free = residual.free();
  const int nf = residual.nf();
  const std::vector<int> xi = slots_of(chart.positions(), free);
  const std::vector<int> zeta = slots_of(chart.velocities(), free);
  const std::vector<int> position_dependent = slots_of(chart.dependent_positions(), free);
  const std::vector<int> velocity_dependent = slots_of(chart.dependent_velocities(), free);
  const std::vector<int>& rows = chart.velocity_rows();  // the independent rows
  const auto all = Eigen::all;

  // The tree's residual, the multipliers the solver finds at the point and the rows' derivatives.
  system::MultibodySystem& system = residual.system();
  const VecX& vdot = system.evaluate(p.t, p.q, p.v);
  VecX a_free(nf);
  for (int k = 0; k < nf; ++k) a_free[k] = vdot[free[static_cast<std::size_t>(k)]];
  MatX dr_dq, dr_dv;
  residual.derivatives(p.t, p.q, p.v, a_free, dr_dq, dr_dv);
  dynamics::ConstraintDerivatives rows_d(model);
  residual.constraint_derivatives(system.constraints()->multipliers(), rows_d);
  const MatX G = rows_d.rows.G(rows, free);

  // ∂δ/∂ξ = Q: unit on ξ, the dependent coordinates keeping the holonomic rows (G_h Q = 0).
  MatX Q = MatX::Zero(nf, static_cast<Eigen::Index>(xi.size()));
  for (std::size_t k = 0; k < xi.size(); ++k) Q(xi[k], static_cast<Eigen::Index>(k)) = 1.0;
  if (!position_dependent.empty()) {
    const MatX G_h = rows_d.rows.G(chart.holonomic_rows(), free);
    Q(position_dependent, all) =
        MatX(-G_h(all, position_dependent).partialPivLu().solve(G_h(all, xi)));
  }
  // ∂v/∂δ = P at fixed ζ: the dependent velocities keeping G(q) v = 0.
  MatX P = MatX::Zero(nf, nf);
  const Eigen::PartialPivLU<MatX> G_dependent(G(all, velocity_dependent));
  if (!velocity_dependent.empty())
    P(velocity_dependent, all) = MatX(-G_dependent.solve(rows_d.velocity_dq(rows, free)));

  // ∂v̇ along δ or v from M ∂v̇ − Gᵀ ∂λ = −R, G ∂v̇ = −E: ∂v̇ = d + T y with d on the dependent
  // velocities (G d = −E) and Tᵀ M T y = −Tᵀ (R + M d), T = ∂v_f/∂ζ (G T = 0).
  const MatX T = chart.velocity_map(p.q);
  const MatX M = residual.free_mass(p.t, p.q);
  const Eigen::LLT<MatX> reduced_mass(T.transpose() * M * T);
  if (reduced_mass.info() != Eigen::Success) {
    throw NumericalError(
        "linearize: the reduced mass matrix of the independent coordinates is not positive "
        "definite");
  }
  const auto acceleration_derivative = [&](const MatX& R, const MatX& E) {
    MatX D = MatX::Zero(nf, R.cols());
    if (!velocity_dependent.empty()) D(velocity_dependent, all) = MatX(G_dependent.solve(-E));
    D += T * reduced_mass.solve(-T.transpose() * (R + M * D));
    return D;
  };
  const MatX dvdot_dq =
      acceleration_derivative(dr_dq - rows_d.force_dq(free, free), rows_d.residual_dq(rows, free));
  const MatX dvdot_dv = acceleration_derivative(dr_dv, rows_d.residual_dv(rows, free));

  // ξ̇ = [J_r(δ)⁻¹ v]_ξ and ζ̇ = [v̇]_ζ along the chart.
  const MatX rate_dxi = (rotation_rate_jacobian(model, free, p.v) + P) * Q;
  const MatX vdot_dxi = (dvdot_dq + dvdot_dv * P) * Q;
  const MatX vdot_dzeta = dvdot_dv * T;
  const auto nx = static_cast<Eigen::Index>(xi.size());
  const auto nz = static_cast<Eigen::Index>(zeta.size());
  MatX A(nx + nz, nx + nz);
  A << rate_dxi(xi, all), T(xi, all), vdot_dxi(zeta, all), vdot_dzeta(zeta, all);
  return A;
}

}  // namespace momenta::analysis::detail
