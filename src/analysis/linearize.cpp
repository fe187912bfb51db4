#include "momenta/analysis/linearize.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <span>
#include <string_view>
#include <utility>
#include <variant>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <Eigen/Cholesky>

#include "model_residual.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"

namespace momenta::analysis {
namespace {

using detail::ModelResidual;

// Automatic steps: angles in rad, lengths as a fraction of the characteristic length (both near
// ε^(1/5), the best step of a Richardson-extrapolated central difference).
constexpr double kRelativeStep = 1e-3;
// Steps of the exact differences (velocity, prescribed rate and acceleration, in their units):
// any step is exact for a quadratic, and a large one keeps round-off (ε·|r|/h) small.
constexpr double kExactStep = 1.0;
// Tangent step for ∂δ̇/∂δ: exact for any |h| < π (J_r(δ)⁻¹ beyond its linear term is even in δ).
constexpr double kRotationRateStep = 0.5;

// How a signal is used: by applied loads and/or prescribed joints.
struct SignalUse {
  bool load = false;
  bool prescribed = false;
};

std::vector<SignalUse> signal_uses(const model::Model& model) {
  std::vector<SignalUse> use(model.signals().size());
  for (const model::ForceElement& element : model.force_elements()) {
    if (const auto* f = std::get_if<model::AppliedForce>(&element); f && f->signal_index >= 0) {
      use[static_cast<std::size_t>(f->signal_index)].load = true;
    }
    if (const auto* m = std::get_if<model::AppliedTorque>(&element); m && m->signal_index >= 0) {
      use[static_cast<std::size_t>(m->signal_index)].load = true;
    }
  }
  for (const model::Joint& j : model.joints()) {
    for (int s : j.prescribed_signal_indices) use[static_cast<std::size_t>(s)].prescribed = true;
  }
  return use;
}

// One input: the signal perturbed and the name it goes by.
struct Input {
  std::string name;
  int signal = -1;
  bool prescribed = false;  // drives a prescribed joint (value by Richardson; rate, acceleration)
};

std::vector<Input> resolve_inputs(const model::Model& model,
                                  const std::vector<std::string>& names) {
  const std::vector<SignalUse> use = signal_uses(model);
  std::vector<Input> inputs;
  // Default: every signal something reads.
  if (names.empty()) {
    for (std::size_t s = 0; s < use.size(); ++s) {
      if (!use[s].load && !use[s].prescribed) continue;
      inputs.push_back({model.signals()[s].name(), static_cast<int>(s), use[s].prescribed});
    }
    return inputs;
  }
  // By name: a signal, or a prescribed coordinate standing for its signal.
  std::set<std::string> seen;
  for (const std::string& name : names) {
    if (!seen.insert(name).second) {
      throw InvalidArgument(fmt::format("linearize: input '{}' is named twice", name));
    }
    std::optional<int> signal = model.find_signal(name);
    if (!signal) {
      for (const model::Joint& j : model.joints()) {
        for (int k = 0; k < static_cast<int>(j.prescribed_signal_indices.size()); ++k) {
          if (model.q_name(j.q_index + k) == name) signal = j.prescribed_signal_indices[k];
        }
      }
    }
    if (!signal) {
      std::vector<std::string> candidates;
      for (const model::Signal& s : model.signals()) candidates.push_back(s.name());
      for (const model::Joint& j : model.joints()) {
        for (int k = 0; k < static_cast<int>(j.prescribed_signal_indices.size()); ++k)
          candidates.push_back(model.q_name(j.q_index + k));
      }
      const std::vector<std::string_view> views(candidates.begin(), candidates.end());
      throw InvalidArgument(fmt::format(
          "linearize: no input named '{}'{}; inputs are the model's signals and prescribed "
          "coordinates: {}",
          name, did_you_mean(name, views),
          candidates.empty() ? std::string("(none)")
                             : fmt::format("{}", fmt::join(candidates, ", "))));
    }
    const SignalUse& u = use[static_cast<std::size_t>(*signal)];
    if (!u.load && !u.prescribed) {
      throw InvalidArgument(fmt::format(
          "linearize: input '{}': signal '{}' scales no applied load and drives no prescribed "
          "joint, so it has no effect",
          name, model.signals()[static_cast<std::size_t>(*signal)].name()));
    }
    inputs.push_back({name, *signal, u.prescribed});
  }
  return inputs;
}

// Tangent-coordinate names of velocity coordinate i's configuration.
std::string tangent_name(const model::Model& model, int i) {
  const model::Joint& j = model.joint(model.joint_of_v(i));
  const int k = i - j.v_index;
  static constexpr const char* kRotation[] = {"rx", "ry", "rz"};
  static constexpr const char* kFree[] = {"rx", "ry", "rz", "x", "y", "z"};
  if (j.type == model::JointType::spherical) return j.name + "." + kRotation[k];
  if (j.type == model::JointType::free) return j.name + "." + kFree[k];
  return model.q_name(j.q_index + k);
}

// An output row: a state read directly, or a column of the OutputSet by finite differences.
struct OutputRow {
  std::string name;
  int state = -1;   // ≥ 0: C row = e_state
  int column = -1;  // ≥ 0: column of the OutputSet
};

// Resolves the output names; appends to `specs` the coordinate outputs it synthesizes.
std::vector<OutputRow> resolve_outputs(const model::Model& model,
                                       const std::vector<std::string>& state_names,
                                       const LinearizationOptions& options,
                                       std::vector<model::OutputSpec>& specs) {
  specs = options.output_specs;
  const std::vector<std::string> columns = system::OutputSet(model, specs).column_names();
  const std::size_t nf = state_names.size() / 2;

  std::vector<std::string> names = options.outputs;
  if (names.empty()) {
    names = columns.empty() ? std::vector<std::string>(state_names.begin(),
                                                       state_names.begin() + static_cast<long>(nf))
                            : columns;
  }

  std::vector<OutputRow> rows;
  std::set<std::string> seen;
  int synthesized = 0;
  for (const std::string& name : names) {
    if (!seen.insert(name).second) {
      throw InvalidArgument(fmt::format("linearize: output '{}' is named twice", name));
    }
    // A model output column.
    if (const auto c = std::find(columns.begin(), columns.end(), name); c != columns.end()) {
      rows.push_back({name, -1, static_cast<int>(c - columns.begin())});
      continue;
    }
    // A state.
    if (const auto s = std::find(state_names.begin(), state_names.end(), name);
        s != state_names.end()) {
      rows.push_back({name, static_cast<int>(s - state_names.begin()), -1});
      continue;
    }
    // Any model coordinate: a joint-position or joint-velocity output of one component.
    std::optional<model::OutputSpec> spec;
    for (int i = 0; i < model.nq() && !spec; ++i) {
      if (model.q_name(i) != name) continue;
      const model::Joint& j = model.joint(model.joint_of_q(i));
      spec = model::OutputSpec{name, model::OutputQuantity::joint_position, j.name, Vec3::Zero(),
                               i - j.q_index};
    }
    for (int i = 0; i < model.nv() && !spec; ++i) {
      if (model.v_name(i) != name) continue;
      const model::Joint& j = model.joint(model.joint_of_v(i));
      spec = model::OutputSpec{name, model::OutputQuantity::joint_velocity, j.name, Vec3::Zero(),
                               i - j.v_index};
    }
    if (spec) {
      specs.push_back(*spec);
      rows.push_back({name, -1, static_cast<int>(columns.size()) + synthesized++});
      continue;
    }
    std::vector<std::string_view> candidates(columns.begin(), columns.end());
    candidates.insert(candidates.end(), state_names.begin(), state_names.end());
    for (int i = 0; i < model.nq(); ++i) candidates.push_back(model.q_name(i));
    for (int i = 0; i < model.nv(); ++i) candidates.push_back(model.v_name(i));
    throw InvalidArgument(fmt::format(
        "linearize: no output named '{}'{}; outputs are the model's output columns ({}), the "
        "states ({}) and the joint coordinates",
        name, did_you_mean(name, candidates),
        columns.empty() ? std::string("none") : fmt::format("{}", fmt::join(columns, ", ")),
        fmt::join(state_names, ", ")));
  }
  return rows;
}

// Throws NumericalError naming the first non-finite entry of a derivative.
void check_derivative_finite(const MatX& X, const char* what) {
  for (Eigen::Index j = 0; j < X.cols(); ++j)
    for (Eigen::Index i = 0; i < X.rows(); ++i)
      if (!std::isfinite(X(i, j)))
        throw NumericalError(
            fmt::format("linearize: {}({}, {}) = {} is not finite", what, i, j, X(i, j)));
}

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
  double angle_step;   // rad
  double length;       // characteristic length, m
  double length_step;  // m, or 0: relative to the length and the coordinate
  mutable VecX r_work;

  void evaluate(const VecX& q, const VecX& v, VecX& out) const {
    residual.residual(t, q, v, a_free, r_work);
    out.resize(nf + columns);
    out.head(nf) = r_work;
    if (columns > 0) {
      outputs.evaluate(residual.system(), t, q, v, std::span<double>(out.data() + nf, columns));
    }
  }
  double step_of_length(double value) const {
    return length_step > 0.0 ? length_step : kRelativeStep * std::max(length, std::abs(value));
  }
  // The configuration step of velocity coordinate i: an angle or a length.
  double configuration_step(int i) const {
    if (detail::is_angle_coordinate(model, i)) return angle_step;
    const model::Joint& j = model.joint(model.joint_of_v(i));
    const int k = i - j.v_index;
    const int iq = j.type == model::JointType::free ? j.q_index + k - 3 : j.q_index + k;
    return step_of_length(q0[iq]);
  }
  // The smallest configuration step of the coordinates a prescribed signal drives.
  double prescribed_step(int signal) const {
    double h = std::numeric_limits<double>::infinity();
    for (const model::Joint& joint : model.joints()) {
      for (int k = 0; k < static_cast<int>(joint.prescribed_signal_indices.size()); ++k) {
        if (joint.prescribed_signal_indices[static_cast<std::size_t>(k)] != signal) continue;
        const int i = joint.v_index + k;
        h = std::min(h, detail::is_angle_coordinate(model, i)
                            ? angle_step
                            : step_of_length(q0[joint.q_index + k]));
      }
    }
    return h;
  }
};

// ∂g/∂δq, ∂g/∂v and ∂g/∂u by the input signal's value, rate and acceleration.
struct Jacobians {
  MatX dq, dv, du0, du1, du2;
};

// ∂g/∂δq by Richardson-extrapolated central differences; ∂g/∂v by exact central differences.
void differentiate_state(const Differentiated& f, const std::vector<int>& free, Jacobians& J) {
  J.dq.resize(f.nf + f.columns, f.nf);
  J.dv.resize(f.nf + f.columns, f.nf);
  VecX plus, minus, coarse, d, tangent, q_step, v_step;
  for (int k = 0; k < f.nf; ++k) {
    const int i = free[static_cast<std::size_t>(k)];
    detail::richardson_difference(
        [&](double s, VecX& out) {
          detail::displace(f.model, f.q0, i, s, tangent, q_step);
          f.evaluate(q_step, f.v0, out);
        },
        f.configuration_step(i), plus, minus, coarse, d);
    J.dq.col(k) = d;
    detail::central_difference(
        [&](double s, VecX& out) {
          v_step = f.v0;
          v_step[i] += s;
          f.evaluate(f.q0, v_step, out);
        },
        kExactStep, plus, minus, d);
    J.dv.col(k) = d;
  }
}

// ∂g/∂u: value, rate and acceleration offsets of each input's signal.
void differentiate_inputs(const Differentiated& f, const std::vector<Input>& inputs, Jacobians& J) {
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
      // The value moves prescribed coordinates: nonlinear, as the configuration.
      detail::richardson_difference(perturbed(1, 0, 0), f.prescribed_step(input.signal), plus,
                                    minus, coarse, d);
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

void check_jacobians_finite(const Jacobians& J) {
  check_derivative_finite(J.dq, "∂(r, y)/∂q");
  check_derivative_finite(J.dv, "∂(r, y)/∂v");
  check_derivative_finite(J.du0, "∂(r, y)/∂u");
  check_derivative_finite(J.du1, "∂(r, y)/∂u̇");
  check_derivative_finite(J.du2, "∂(r, y)/∂ü");
}

// T = ∂δ̇/∂δ from δ̇ = J_r(δ)⁻¹ ω (zero unless a ball or free joint turns).
MatX rotation_rate_jacobian(const model::Model& model, const std::vector<int>& free,
                            const VecX& v0) {
  const int nf = static_cast<int>(free.size());
  MatX T = MatX::Zero(nf, nf);
  VecX tangent(model.nv()), rate_plus(model.nv()), rate_minus(model.nv());
  for (int k = 0; k < nf; ++k) {
    const int i = free[static_cast<std::size_t>(k)];
    tangent.setZero();
    tangent[i] = kRotationRateStep;
    model::local_coordinate_rate(model, tangent, v0, rate_plus);
    tangent[i] = -kRotationRateStep;
    model::local_coordinate_rate(model, tangent, v0, rate_minus);
    for (int a = 0; a < nf; ++a) {
      const int ia = free[static_cast<std::size_t>(a)];
      T(a, k) = (rate_plus[ia] - rate_minus[ia]) / (2 * kRotationRateStep);
    }
  }
  return T;
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

// Output rows: a state directly, or a column of g by its differences. Sets the feedthroughs and
// output values of `result`; returns C.
MatX output_matrix(LinearModel& result, const std::vector<OutputRow>& rows, const Jacobians& J,
                   const VecX& g0, const std::vector<int>& free, int nf, const VecX& v0) {
  const auto p = static_cast<Eigen::Index>(rows.size());
  const auto m = J.du0.cols();
  MatX C = MatX::Zero(p, 2 * nf);
  result.feedthrough_value = MatX::Zero(p, m);
  result.feedthrough_rate = MatX::Zero(p, m);
  result.feedthrough_acceleration = MatX::Zero(p, m);
  result.output_values = VecX::Zero(p);
  for (Eigen::Index r = 0; r < p; ++r) {
    const OutputRow& row = rows[static_cast<std::size_t>(r)];
    if (row.state >= 0) {
      C(r, row.state) = 1.0;
      const int i = free[static_cast<std::size_t>(row.state % nf)];
      // A configuration state reads 0 at the point (δq = 0 there); a velocity state reads v₀.
      result.output_values[r] = row.state < nf ? 0.0 : v0[i];
      continue;
    }
    const int c = nf + row.column;
    C.block(r, 0, 1, nf) = J.dq.row(c);
    C.block(r, nf, 1, nf) = J.dv.row(c);
    result.feedthrough_value.row(r) = J.du0.row(c);
    result.feedthrough_rate.row(r) = J.du1.row(c);
    result.feedthrough_acceleration.row(r) = J.du2.row(c);
    result.output_values[r] = g0[c];
  }
  return C;
}

// Folds each prescribed input's rate and acceleration into its position (header comment):
// w = x − E₁ u − E₂ u̇, E₂ = B₂, E₁ = A E₂ + B₁; B = B₀ + A E₁, D = D₀ + C E₁. Throws when an
// output feels a rate or acceleration that no state shift absorbs (an improper transfer).
void fold_input_rates(LinearModel& result, const MatX& A, const MatX& C,
                      const std::vector<Input>& inputs,
                      const std::vector<std::string>& output_names, MatX& B, MatX& D) {
  B = result.input_value;
  D = result.feedthrough_value;
  const auto p = C.rows();
  for (Eigen::Index j = 0; j < B.cols(); ++j) {
    const VecX E2 = result.input_acceleration.col(j);
    const VecX E1 = A * E2 + result.input_rate.col(j);
    if (E1.isZero(0.0) && E2.isZero(0.0) && result.feedthrough_rate.col(j).isZero(0.0) &&
        result.feedthrough_acceleration.col(j).isZero(0.0)) {
      continue;
    }
    result.states_shifted = result.states_shifted || !E1.isZero(0.0) || !E2.isZero(0.0);
    B.col(j) += A * E1;
    D.col(j) += C * E1;
    // The terms in u̇ and ü that a state shift cannot absorb must vanish (to round-off).
    const VecX rate_term = C * E2 + result.feedthrough_rate.col(j);
    for (Eigen::Index r = 0; r < p; ++r) {
      const double floor =
          1e-8 *
          (C.row(r).cwiseAbs().maxCoeff() * (E1.cwiseAbs().maxCoeff() + E2.cwiseAbs().maxCoeff()) +
           std::abs(result.feedthrough_value(r, j)) + std::abs(result.feedthrough_rate(r, j)) +
           std::abs(result.output_values[r]));
      const double direct[2] = {rate_term[r], result.feedthrough_acceleration(r, j)};
      static constexpr const char* kWhat[2] = {"rate", "acceleration"};
      for (int w = 0; w < 2; ++w) {
        if (std::abs(direct[w]) > floor) {
          const std::string& input = inputs[static_cast<std::size_t>(j)].name;
          throw InvalidArgument(fmt::format(
              "linearize: output '{}' feels the {} of prescribed input '{}' directly ({:.6g} per "
              "unit), so its transfer function from '{}' is improper; choose a position output, "
              "or a body's absolute velocity instead of a coordinate carried by the prescribed "
              "joint",
              output_names[static_cast<std::size_t>(r)], kWhat[w], input, direct[w], input));
        }
      }
    }
  }
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

std::vector<std::string> linear_state_names(const model::Model& model) {
  std::vector<std::string> position, velocity;
  for (const model::Joint& j : model.joints()) {
    if (j.is_prescribed()) continue;
    for (int k = 0; k < j.nv(); ++k) {
      position.push_back(tangent_name(model, j.v_index + k));
      velocity.push_back(model.v_name(j.v_index + k));
    }
  }
  position.insert(position.end(), velocity.begin(), velocity.end());
  return position;
}

LinearModel linearize(const model::Model& model, const OperatingPoint& point,
                      const LinearizationOptions& options) {
  check_arguments(point, options);
  if (model.has_constraints()) {
    // The tree's linearization would ignore the constraints: refuse rather than mislead.
    throw InvalidArgument(fmt::format(
        "linearization of a model with constraints ('{}', ...) is not available yet: it needs "
        "the independent coordinates of the constraint Jacobian's null space (docs/constraints.md)",
        model::constraint_name(model.constraints().front())));
  }
  ModelResidual residual(model);
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
  VecX a_free(nf);
  for (int k = 0; k < nf; ++k) a_free[k] = result.acceleration[free[static_cast<std::size_t>(k)]];

  // Names, inputs and outputs.
  const std::vector<std::string> state_names = linear_state_names(model);
  const std::vector<Input> inputs = resolve_inputs(model, options.inputs);
  std::vector<model::OutputSpec> specs;
  const std::vector<OutputRow> rows = resolve_outputs(model, state_names, options, specs);
  const system::OutputSet output_set(model, specs);
  std::vector<std::string> output_names, input_names;
  for (const OutputRow& row : rows) output_names.push_back(row.name);
  for (const Input& input : inputs) input_names.push_back(input.name);

  // Everything differentiated at once: g = [r_f; the output columns] at (q, v).
  const Differentiated f{model,
                         residual,
                         output_set,
                         t,
                         q0,
                         v0,
                         a_free,
                         nf,
                         static_cast<int>(output_set.size()),
                         options.angle_step > 0.0 ? options.angle_step : kRelativeStep,
                         characteristic_length(model),
                         options.length_step,
                         {}};
  VecX g0;
  f.evaluate(q0, v0, g0);
  Jacobians J;
  differentiate_state(f, free, J);
  differentiate_inputs(f, inputs, J);
  check_jacobians_finite(J);

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
  MatX C = output_matrix(result, rows, J, g0, free, nf, v0);
  MatX B, D;
  fold_input_rates(result, A, C, inputs, output_names, B, D);
  result.system = StateSpace(std::move(A), std::move(B), std::move(C), std::move(D), state_names,
                             std::move(input_names), std::move(output_names));
  return result;
}

NormalModes undamped_modes(const LinearModel& linear) {
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
  return normal_modes(M_sym, K_sym, names);
}

}  // namespace momenta::analysis
