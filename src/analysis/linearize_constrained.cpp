// linearize() for models with constraints: the motion in independent coordinates (see
// linearize.hpp, "Models with constraints") differentiated as a first-order system.
#include <algorithm>
#include <cmath>
#include <span>

#include <fmt/format.h>
#include <Eigen/Cholesky>

#include "charted_derivatives.hpp"
#include "constraint_chart.hpp"
#include "linearize_parts.hpp"
#include "model_residual.hpp"
#include "momenta/common/error.hpp"
#include "momenta/system/output_set.hpp"

namespace momenta::analysis::detail {
namespace {

// g(ξ, ζ) = [ξ̇; ζ̇; the output columns] at the operating point's time.
class ChartedMotion {
 public:
  ChartedMotion(ModelResidual& residual, ConstraintChart& chart, const system::OutputSet& outputs,
                double t)
      : model_(residual.model()),
        system_(residual.system()),
        chart_(chart),
        outputs_(outputs),
        t_(t),
        nx_(static_cast<int>(chart.positions().size())),
        nz_(static_cast<int>(chart.velocities().size())) {}

  int states() const { return nx_ + nz_; }

  void evaluate(const VecX& xi, const VecX& zeta, VecX& out) {
    chart_.configuration(xi, q_, delta_);
    chart_.velocity(q_, zeta, v_);
    const VecX& vdot = system_.evaluate(t_, q_, v_);
    const auto columns = static_cast<int>(outputs_.size());
    out.resize(nx_ + nz_ + columns);
    for (int k = 0; k < nz_; ++k)
      out[nx_ + k] = vdot[chart_.velocities()[static_cast<std::size_t>(k)]];
    model::local_coordinate_rate(model_, delta_, v_, delta_rate_);
    for (int k = 0; k < nx_; ++k)
      out[k] = delta_rate_[chart_.positions()[static_cast<std::size_t>(k)]];
    if (columns > 0)
      outputs_.evaluate(system_, t_, q_, v_, std::span<double>(out.data() + nx_ + nz_, columns));
  }

 private:
  const model::Model& model_;
  system::MultibodySystem& system_;
  ConstraintChart& chart_;
  const system::OutputSet& outputs_;
  double t_;
  int nx_, nz_;
  VecX q_, v_, delta_, delta_rate_;
};

// The reduced second-order form of a holonomic model (linearize.hpp): mass = Tᵀ M_ff T with
// T = ∂v_f/∂ζ, stiffness = −mass ∂ζ̇/∂ξ, damping = −mass ∂ζ̇/∂ζ.
void reduced_second_order_form(LinearModel& result, ModelResidual& residual, ConstraintChart& chart,
                               const MatX& A) {
  const auto nz = static_cast<Eigen::Index>(chart.velocities().size());
  const OperatingPoint& p = result.point;
  const MatX T = chart.velocity_map(p.q);
  const MatX M = residual.free_mass(p.t, p.q);
  result.mass = T.transpose() * M * T;
  if (Eigen::LLT<MatX>(result.mass).info() != Eigen::Success) {
    throw NumericalError(
        "linearize: the reduced mass matrix of the independent coordinates is "
        "not positive definite");
  }
  result.stiffness = -result.mass * A.block(nz, 0, nz, nz);
  result.damping = -result.mass * A.block(nz, nz, nz, nz);
}

}  // namespace

LinearModel linearize_constrained(const model::Model& model, const OperatingPoint& point,
                                  const LinearizationOptions& options) {
  ModelResidual residual(model);
  detail::set_driven_values(model, options, residual.system());
  system::MultibodySystem& system = residual.system();
  const double t = point.t;

  // By default the load signals only: a prescribed motion stays at its signal's value.
  std::vector<Input> inputs = resolve_inputs(model, options.inputs);
  if (options.inputs.empty())
    std::erase_if(inputs, [](const Input& input) { return input.prescribed; });
  for (const Input& input : inputs) {
    if (input.prescribed) {
      throw InvalidArgument(fmt::format(
          "linearize: input '{}' drives a prescribed joint of a model with constraints; "
          "prescribed-motion inputs move the constraint manifold and are not supported there — "
          "use an applied load as the input",
          input.name));
    }
  }

  // The operating point, made consistent as a simulation's first state is.
  LinearModel result;
  VecX q0 = checked_configuration(model, point.q, point.v, "linearize: operating point");
  VecX v0 = point.v;
  system.make_consistent(t, q0, v0);
  result.point = {t, q0, v0};
  result.acceleration = system.evaluate(t, q0, v0);

  // The independent coordinates and the names of the states.
  ConstraintChart chart(model, residual.free(), q0, v0, options.independent);
  const std::vector<int>& positions = chart.positions();
  const std::vector<int>& velocities = chart.velocities();
  const int nx = static_cast<int>(positions.size()), nz = static_cast<int>(velocities.size());
  result.coordinates = positions;
  result.velocity_coordinates = velocities;
  result.dependent_coordinates = chart.dependent_positions();
  result.dependent_velocities = chart.dependent_velocities();
  std::vector<std::string> state_names;
  for (int i : positions) state_names.push_back(tangent_name(model, i));
  for (int i : velocities) state_names.push_back(model.v_name(i));

  std::vector<model::OutputSpec> specs;
  const std::vector<OutputRow> rows = resolve_outputs(model, state_names, nx, options, specs);
  const system::OutputSet output_set(model, specs);
  std::vector<std::string> output_names, input_names;
  for (const OutputRow& row : rows) output_names.push_back(row.name);
  for (const Input& input : inputs) input_names.push_back(input.name);

  // g = [ξ̇; ζ̇; outputs] at ξ = 0, ζ = ζ₀: its state rows differentiated analytically, the
  // output columns by differences (Richardson on ξ, exact on ζ; the state rows too with
  // Derivatives::differences), the loads by exact differences.
  ChartedMotion motion(residual, chart, output_set, t);
  const DifferenceSteps steps(model, options);
  const VecX xi0 = VecX::Zero(nx);
  VecX zeta0(nz);
  for (int k = 0; k < nz; ++k) zeta0[k] = v0[velocities[static_cast<std::size_t>(k)]];
  VecX g0, plus, minus, coarse, d, xi, zeta;
  motion.evaluate(xi0, zeta0, g0);
  const int n = nx + nz;
  const auto rows_g = g0.size();
  const auto m = static_cast<Eigen::Index>(inputs.size());
  Jacobians J{MatX(rows_g, nx), MatX(rows_g, nz), MatX::Zero(rows_g, m), MatX::Zero(rows_g, m),
              MatX::Zero(rows_g, m)};
  const bool differences = options.derivatives == LinearizationOptions::Derivatives::differences;
  if (rows_g > n || differences) {
    for (int k = 0; k < nx; ++k) {
      richardson_difference(
          [&](double s, VecX& out) {
            xi = xi0;
            xi[k] += s;
            motion.evaluate(xi, zeta0, out);
          },
          steps.configuration(positions[static_cast<std::size_t>(k)], q0), plus, minus, coarse, d);
      J.dq.col(k) = d;
    }
    for (int k = 0; k < nz; ++k) {
      central_difference(
          [&](double s, VecX& out) {
            zeta = zeta0;
            zeta[k] += s;
            motion.evaluate(xi0, zeta, out);
          },
          kExactStep, plus, minus, d);
      J.dv.col(k) = d;
    }
  }
  if (!differences) {
    const MatX state_rows = charted_state_matrix(residual, chart, result.point);
    J.dq.topRows(n) = state_rows.leftCols(nx);
    J.dv.topRows(n) = state_rows.rightCols(nz);
  }
  for (Eigen::Index j = 0; j < m; ++j) {
    // Loads are linear in their signal: one exact central difference.
    const int signal = inputs[static_cast<std::size_t>(j)].signal;
    const double u0 = model.signals()[static_cast<std::size_t>(signal)].value(t);
    central_difference(
        [&](double s, VecX& out) {
          residual.set_offset(signal, s, 0.0, 0.0);
          motion.evaluate(xi0, zeta0, out);
        },
        std::max(1.0, std::abs(u0)), plus, minus, d);
    J.du0.col(j) = d;
    residual.clear_offsets();
  }
  check_jacobians_finite(J);

  MatX A(n, n);
  A << J.dq.topRows(n), J.dv.topRows(n);
  result.input_value = J.du0.topRows(n);
  result.input_rate = MatX::Zero(n, m);
  result.input_acceleration = MatX::Zero(n, m);
  VecX state_values = VecX::Zero(n);
  state_values.tail(nz) = zeta0;
  MatX C = output_matrix(result, rows, J, g0, n, state_values);
  MatX B, D;
  fold_input_rates(result, A, C, inputs, output_names, B, D);
  if (chart.dependent_velocities() == chart.dependent_positions()) {
    reduced_second_order_form(result, residual, chart, A);
  }
  result.system = StateSpace(std::move(A), std::move(B), std::move(C), std::move(D), state_names,
                             std::move(input_names), std::move(output_names));
  return result;
}

}  // namespace momenta::analysis::detail
