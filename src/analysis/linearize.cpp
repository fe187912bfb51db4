#include "momenta/analysis/linearize.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string_view>
#include <utility>
#include <variant>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <Eigen/Cholesky>

#include "linearize_parts.hpp"
#include "model_residual.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/model/units.hpp"
#include "momenta/system/closed_loop_system.hpp"
#include "momenta/system/output_set.hpp"

namespace momenta::analysis {
namespace {

using detail::Input;
using detail::Jacobians;
using detail::kExactStep;
using detail::ModelResidual;
using detail::OutputRow;
using detail::rotation_rate_jacobian;

void check_arguments(const OperatingPoint& point, const LinearizationOptions& options) {
  if (!std::isfinite(point.t)) {
    throw InvalidArgument(
        fmt::format("linearize: operating point time t = {} is not finite", point.t));
  }
  if (options.angle_step < 0.0 || options.length_step < 0.0 || !std::isfinite(options.angle_step) ||
      !std::isfinite(options.length_step)) {
    throw InvalidArgument(fmt::format(
        "linearize: angle_step = {} and length_step = {} must be finite and ≥ 0 (0: automatic)",
        options.angle_step, options.length_step));
  }
}

// What linearize differentiates: g(q, v) = [r_f; the output columns] at the operating point's
// time with its free accelerations held, and the steps of the differences.
struct Differentiated {
  const model::Model& model;
  ModelResidual& residual;
  const system::OutputSet& outputs;
  double t;
  VecX q0, v0, a_free;
  int nf, columns;
  const detail::DifferenceSteps& steps;
  mutable VecX r_work;

  void evaluate(const VecX& q, const VecX& v, VecX& out) const {
    residual.residual(t, q, v, a_free, r_work);
    out.resize(nf + columns);
    out.head(nf) = r_work;
    if (columns > 0) {
      outputs.evaluate(residual.system(), t, q, v, std::span<double>(out.data() + nf, columns));
    }
  }
  // The output columns alone at (q, v).
  void evaluate_outputs(const VecX& q, const VecX& v, VecX& out) const {
    out.resize(columns);
    outputs.evaluate(residual.system(), t, q, v, std::span<double>(out.data(), columns));
  }
  double configuration_step(int i) const { return steps.configuration(i, q0); }
  // The smallest configuration step of the coordinates a prescribed signal drives.
  double prescribed_step(int signal) const {
    double h = std::numeric_limits<double>::infinity();
    for (const model::Joint& joint : model.joints()) {
      for (int k = 0; k < static_cast<int>(joint.prescribed_signal_indices.size()); ++k) {
        if (joint.prescribed_signal_indices[static_cast<std::size_t>(k)] != signal) continue;
        const int i = joint.v_index + k;
        // A free joint's position signals (k ≥ 3) move q_index + k − 3; the others q_index + k.
        const int position = joint.q_index + (joint.type == model::JointType::free ? k - 3 : k);
        h = std::min(h, detail::is_angle_coordinate(model, i) ? steps.angle_step
                                                              : steps.of_length(q0[position]));
      }
    }
    return h;
  }
};

// ∂g/∂δq and ∂g/∂v: the equations of motion analytically (ModelResidual::derivatives), the output
// columns by differences — Richardson-extrapolated on δq, exact central ones on v. With
// `differences`, the equations' rows by the same differences as the outputs (the check).
void differentiate_state(const Differentiated& f, const std::vector<int>& free, bool differences,
                         Jacobians& J) {
  J.dq.resize(f.nf + f.columns, f.nf);
  J.dv.resize(f.nf + f.columns, f.nf);
  MatX dr_dq, dr_dv;
  f.residual.derivatives(f.t, f.q0, f.v0, f.a_free, dr_dq, dr_dv);
  J.dq.topRows(f.nf) = dr_dq;
  J.dv.topRows(f.nf) = dr_dv;
  if (f.columns == 0 && !differences) return;
  const auto evaluate = [&](const VecX& q, const VecX& v, VecX& out) {
    if (differences) {
      f.evaluate(q, v, out);
    } else {
      f.evaluate_outputs(q, v, out);
    }
  };
  const int first = differences ? 0 : f.nf;  // the first row the differences fill
  VecX plus, minus, coarse, d, tangent, q_step, v_step;
  for (int k = 0; k < f.nf; ++k) {
    const int i = free[static_cast<std::size_t>(k)];
    detail::richardson_difference(
        [&](double s, VecX& out) {
          detail::displace(f.model, f.q0, i, s, tangent, q_step);
          evaluate(q_step, f.v0, out);
        },
        f.configuration_step(i), plus, minus, coarse, d);
    J.dq.col(k).tail(f.nf + f.columns - first) = d;
    detail::central_difference(
        [&](double s, VecX& out) {
          v_step = f.v0;
          v_step[i] += s;
          evaluate(f.q0, v_step, out);
        },
        kExactStep, plus, minus, d);
    J.dv.col(k).tail(f.nf + f.columns - first) = d;
  }
}

// The velocity coordinates whose value a signal sets one to one (a prescribed joint's coordinate,
// a free joint's position), when that is all the signal does: then ∂r_f/∂u is the sum of their
// columns of ∂r_f/∂δq. Nothing when it also turns a ball or free joint (its rotation is no sum of
// tangents) or drives a load.
std::optional<std::vector<int>> coordinates_set_by(const model::Model& model, int signal) {
  for (const model::ForceElement& element : model.force_elements()) {
    const int used = std::visit(
        [](const auto& e) {
          if constexpr (requires { e.signal_index; }) return e.signal_index;
          return -1;
        },
        element);
    if (used == signal) return std::nullopt;
  }
  std::vector<int> coordinates;
  for (const model::Joint& joint : model.joints()) {
    const auto& signals = joint.prescribed_signal_indices;
    for (int k = 0; k < static_cast<int>(signals.size()); ++k) {
      if (signals[static_cast<std::size_t>(k)] != signal) continue;
      const bool turns = joint.type == model::JointType::spherical ||
                         (joint.type == model::JointType::free && k < 3);
      if (turns) return std::nullopt;
      coordinates.push_back(joint.v_index + k);
    }
  }
  return coordinates;
}

// ∂g/∂u: value, rate and acceleration offsets of each input's signal.
void differentiate_inputs(const Differentiated& f, const std::vector<Input>& inputs,
                          bool differences, Jacobians& J) {
  const int m = static_cast<int>(inputs.size());
  J.du0 = MatX::Zero(f.nf + f.columns, m);
  J.du1 = MatX::Zero(f.nf + f.columns, m);
  J.du2 = MatX::Zero(f.nf + f.columns, m);
  VecX plus, minus, coarse, d;
  for (int j = 0; j < m; ++j) {
    const Input& input = inputs[static_cast<std::size_t>(j)];
    const auto perturbed = [&](double value, double rate, double acceleration) {
      return [&, value, rate, acceleration](double s, VecX& out) {
        f.residual.set_offset(input.signal, s * value, s * rate, s * acceleration);
        f.evaluate(f.q0, f.v0, out);
      };
    };
    if (input.prescribed) {
      // The value moves prescribed coordinates: nonlinear, as the configuration. The equations'
      // rows analytically where the signal sets coordinates one to one (differentiate_state left
      // ∂r_f/∂δq of every coordinate), the output columns by differences.
      detail::richardson_difference(perturbed(1, 0, 0), f.prescribed_step(input.signal), plus,
                                    minus, coarse, d);
      if (const auto set = differences ? std::nullopt : coordinates_set_by(f.model, input.signal)) {
        d.head(f.nf).setZero();
        for (int i : *set) d.head(f.nf) += f.residual.dr_dq_all().col(i);
      }
      J.du0.col(j) = d;
      detail::central_difference(perturbed(0, 1, 0), kExactStep, plus, minus, d);
      J.du1.col(j) = d;
      detail::central_difference(perturbed(0, 0, 1), kExactStep, plus, minus, d);
      J.du2.col(j) = d;
    } else {
      // Loads are linear in their signal: one exact central difference.
      const double u0 = f.model.signals()[static_cast<std::size_t>(input.signal)].value(f.t);
      detail::central_difference(perturbed(1, 0, 0), std::max(1.0, std::abs(u0)), plus, minus, d);
      J.du0.col(j) = d;
    }
    f.residual.clear_offsets();
  }
}

// A = [T 1; −M⁻¹ K  −M⁻¹ C_v] and the input columns B = [0; −M⁻¹ ∂r_f/∂u] of each kind.
MatX state_matrix(LinearModel& result, const MatX& T, const Eigen::LLT<MatX>& llt,
                  const Jacobians& J, int nf) {
  const int n = 2 * nf;
  const auto m = J.du0.cols();
  MatX A = MatX::Zero(n, n);
  A.topLeftCorner(nf, nf) = T;
  A.topRightCorner(nf, nf).setIdentity();
  A.bottomLeftCorner(nf, nf) = -llt.solve(result.stiffness);
  A.bottomRightCorner(nf, nf) = -llt.solve(result.damping);
  const auto input_rows = [&](const MatX& dg_du) {
    MatX B = MatX::Zero(n, m);
    if (m > 0 && nf > 0) B.bottomRows(nf) = -llt.solve(dg_du.topRows(nf));
    return B;
  };
  result.input_value = input_rows(J.du0);
  result.input_rate = input_rows(J.du1);
  result.input_acceleration = input_rows(J.du2);
  return A;
}

}  // namespace

OperatingPoint initial_operating_point(const model::Model& model) {
  return {0.0, model.initial_q(), model.initial_v()};
}

double characteristic_length(const model::Model& model) {
  double L = 0.0;
  for (const model::Joint& j : model.joints()) {
    L = std::max({L, j.X_PJ.p.norm(), j.X_CJ.p.norm()});
  }
  for (const model::Body& b : model.bodies()) {
    const inertia::MassProperties& mp = b.mass_properties;
    L = std::max(L, mp.center_of_mass().norm());
    if (mp.mass() > 0.0)
      L = std::max(L, std::sqrt(mp.inertia_about_com().trace() / (2 * mp.mass())));
  }
  for (const model::ForceElement& element : model.force_elements()) {
    if (const auto* s = std::get_if<model::LinearSpringDamper>(&element)) {
      L = std::max({L, s->free_length, s->a.p_BoP_B.norm(), s->b.p_BoP_B.norm()});
    } else if (const auto* f = std::get_if<model::AppliedForce>(&element)) {
      L = std::max(L, f->at.p_BoP_B.norm());
    }
  }
  return L > 0.0 && std::isfinite(L) ? L : 1.0;
}

void check_linearization_names(const model::Model& model, const LinearizationOptions& options) {
  detail::resolve_inputs(model, options.inputs);
  std::vector<model::OutputSpec> specs;
  detail::resolve_outputs(model, linear_state_names(model), 0, options, specs);
}

std::vector<std::string> linear_state_names(const model::Model& model) {
  std::vector<std::string> position, velocity;
  for (const model::Joint& j : model.joints()) {
    if (j.is_prescribed()) continue;
    for (int k = 0; k < j.nv(); ++k) {
      position.push_back(detail::tangent_name(model, j.v_index + k));
      velocity.push_back(model.v_name(j.v_index + k));
    }
  }
  position.insert(position.end(), velocity.begin(), velocity.end());
  return position;
}

namespace {

// What a state, input or output of a linearization is, by its name: each of the model's
// coordinate (and tangent) names, signals, outputs and controller columns with its unit.
StateSpace::Units units_by_name(const model::Model& model,
                                const std::vector<model::OutputSpec>& outputs,
                                const StateSpace& system) {
  std::map<std::string, std::string, std::less<>> unit;
  for (int i = 0; i < model.nq(); ++i) unit.emplace(model.q_name(i), model::q_unit(model, i));
  for (int i = 0; i < model.nv(); ++i) {
    const std::string rate = model::v_unit(model, i);
    unit.emplace(model.v_name(i), rate);
    // A tangent coordinate (a rotation vector's component, a length) is its rate's integral.
    unit.emplace(detail::tangent_name(model, i),
                 rate.ends_with("/s") ? rate.substr(0, rate.size() - 2) : std::string());
  }
  for (int s = 0; s < static_cast<int>(model.signals().size()); ++s)
    unit.emplace(model.signals()[static_cast<std::size_t>(s)].name(), model::signal_unit(model, s));
  const system::OutputSet output_set(model, outputs);
  for (std::size_t k = 0; k < output_set.column_names().size(); ++k)
    unit.emplace(output_set.column_names()[k], output_set.column_units()[k]);
  if (model.has_controllers()) {
    system::MultibodySystem plant(model);
    const system::ClosedLoopSystem loop(plant);
    for (std::size_t k = 0; k < loop.column_names().size(); ++k)
      unit.emplace(loop.column_names()[k], loop.column_units()[k]);
  }
  const auto of = [&](const std::vector<std::string>& names) {
    std::vector<std::string> units;
    for (const std::string& name : names) {
      const auto found = unit.find(name);
      units.push_back(found != unit.end() ? found->second : std::string());
    }
    return units;
  };
  return {of(system.state_names()), of(system.input_names()), of(system.output_names())};
}

LinearModel linearize_any(const model::Model& model, const OperatingPoint& point,
                          const LinearizationOptions& options);

}  // namespace

LinearModel linearize(const model::Model& model, const OperatingPoint& point,
                      const LinearizationOptions& options) {
  LinearModel result = linearize_any(model, point, options);
  result.system =
      result.system.with_units(units_by_name(model, options.output_specs, result.system));
  return result;
}

namespace {

LinearModel linearize_any(const model::Model& model, const OperatingPoint& point,
                          const LinearizationOptions& options) {
  check_arguments(point, options);
  if (model.has_controllers() && options.close_loops)
    return detail::linearize_closed_loop(model, point, options);
  if (model.has_constraints()) return detail::linearize_constrained(model, point, options);
  ModelResidual residual(model);
  detail::set_driven_values(model, options, residual.system());
  system::MultibodySystem& system = residual.system();
  const double t = point.t;
  const int nf = residual.nf();
  const std::vector<int>& free = residual.free();

  // The operating point, its prescribed coordinates from their signals.
  LinearModel result;
  VecX q0 = detail::checked_configuration(model, point.q, point.v, "linearize: operating point");
  VecX v0 = point.v;
  system.apply_prescribed_motion(t, q0, v0);
  result.point = {t, q0, v0};
  result.acceleration = system.evaluate(t, q0, v0);
  result.coordinates = free;
  result.velocity_coordinates = free;
  VecX a_free(nf);
  for (int k = 0; k < nf; ++k) a_free[k] = result.acceleration[free[static_cast<std::size_t>(k)]];

  // Names, inputs and outputs.
  const std::vector<std::string> state_names = linear_state_names(model);
  const std::vector<Input> inputs = detail::resolve_inputs(model, options.inputs);
  std::vector<model::OutputSpec> specs;
  const std::vector<OutputRow> rows =
      detail::resolve_outputs(model, state_names, nf, options, specs);
  const system::OutputSet output_set(model, specs);
  std::vector<std::string> output_names, input_names;
  for (const OutputRow& row : rows) output_names.push_back(row.name);
  for (const Input& input : inputs) input_names.push_back(input.name);

  // Everything differentiated at once: g = [r_f; the output columns] at (q, v).
  const detail::DifferenceSteps steps(model, options);
  const Differentiated f{
      model, residual, output_set, t, q0, v0, a_free, nf, static_cast<int>(output_set.size()),
      steps, {}};
  VecX g0;
  f.evaluate(q0, v0, g0);
  Jacobians J;
  const bool differences = options.derivatives == LinearizationOptions::Derivatives::differences;
  differentiate_state(f, free, differences, J);
  differentiate_inputs(f, inputs, differences, J);
  detail::check_jacobians_finite(J);

  // M_ff and its Cholesky factor: ∂a/∂(·) = −M⁻¹ ∂r/∂(·).
  result.mass = residual.free_mass(t, q0);
  const Eigen::LLT<MatX> llt(result.mass);
  if (llt.info() != Eigen::Success) {
    throw NumericalError(fmt::format(
        "linearize: the mass matrix of the free coordinates ({}) is not positive definite",
        fmt::join(state_names.begin(), state_names.begin() + nf, ", ")));
  }
  result.stiffness = J.dq.topRows(nf);
  result.damping = J.dv.topRows(nf);

  MatX A = state_matrix(result, rotation_rate_jacobian(model, free, v0), llt, J, nf);
  // A configuration state reads 0 at the point (δq = 0 there); a velocity state reads v₀.
  VecX state_values = VecX::Zero(2 * nf);
  for (int k = 0; k < nf; ++k) state_values[nf + k] = v0[free[static_cast<std::size_t>(k)]];
  MatX C = detail::output_matrix(result, rows, J, g0, nf, state_values);
  MatX B, D;
  detail::fold_input_rates(result, A, C, inputs, output_names, B, D);
  result.system = StateSpace(std::move(A), std::move(B), std::move(C), std::move(D), state_names,
                             std::move(input_names), std::move(output_names));
  detail::add_commanded_states(model, inputs, result);
  return result;
}

}  // namespace

double largest_acceleration(const LinearModel& linear) {
  double worst = 0.0;
  for (const int i : linear.coordinates) worst = std::max(worst, std::abs(linear.acceleration[i]));
  return worst;
}

double largest_speed(const LinearModel& linear) {
  double fastest = 0.0;
  for (const int i : linear.coordinates) fastest = std::max(fastest, std::abs(linear.point.v[i]));
  return fastest;
}

NormalModes undamped_modes(const LinearModel& linear) {
  if (const double speed = largest_speed(linear); speed > kAtRestSpeed) {
    throw InvalidArgument(OptionMessage{fmt::format(
        "undamped_modes: the point moves (largest speed {:.4g}): its gyroscopic and velocity terms "
        "couple the coordinates, which K φ = ω² M φ leaves out — use the modes of A, or the "
        "steady motion's (‹about=steady›)",
        speed)});
  }
  if (linear.stiffness.size() == 0 && linear.system.A().rows() > 0) {
    throw InvalidArgument(
        "undamped_modes: nonholonomic constraints leave fewer velocity than configuration "
        "states, so there is no second-order form M δq̈ + K δq = 0 — use the modes of A");
  }
  const MatX& K = linear.stiffness;
  const Eigen::Index nf = K.rows();
  const double scale = nf == 0 ? 0.0 : K.cwiseAbs().maxCoeff();
  Eigen::Index i = 0, j = 0;
  const double asymmetry = nf == 0 ? 0.0 : (K - K.transpose()).cwiseAbs().maxCoeff(&i, &j);
  const std::vector<std::string>& states = linear.system.state_names();
  const std::vector<std::string> names(states.begin(), states.begin() + nf);
  if (asymmetry > 1e-6 * scale) {
    throw InvalidArgument(fmt::format(
        "undamped_modes: the stiffness ∂r/∂q is not symmetric: K({0}, {1}) − K({1}, {0}) = {2:.6g} "
        "against largest |K| = {3:.6g} (coordinates '{4}', '{5}'); a non-conservative load or a "
        "point that is not an equilibrium has no undamped normal modes — use the modes of A",
        i, j, K(i, j) - K(j, i), scale, names[static_cast<std::size_t>(i)],
        names[static_cast<std::size_t>(j)]));
  }
  const MatX K_sym = 0.5 * (K + K.transpose());
  const MatX M_sym = 0.5 * (linear.mass + linear.mass.transpose());
  // K's entries are differences of the generalized forces M q̈ at the point (gravity's, the
  // springs'): an ω² at the round-off of those over the mass is zero (the double pendulum laid
  // flat has K = 0 to 1e-15, which would otherwise print ω² = 3.5e-16).
  double frequency_scale = 0.0;
  if (static_cast<Eigen::Index>(linear.coordinates.size()) == nf) {
    VecX free_acceleration(nf);
    for (Eigen::Index k = 0; k < nf; ++k) {
      free_acceleration[k] = linear.acceleration[linear.coordinates[static_cast<std::size_t>(k)]];
    }
    const VecX forces = M_sym * free_acceleration;
    for (Eigen::Index k = 0; k < nf; ++k) {
      frequency_scale = std::max(frequency_scale, std::abs(forces[k]) / M_sym(k, k));
    }
  }
  return normal_modes(M_sym, K_sym, names, frequency_scale);
}

}  // namespace momenta::analysis
