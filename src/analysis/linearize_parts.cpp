#include "linearize_parts.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string_view>
#include <variant>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "model_residual.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/system/output_set.hpp"

namespace momenta::analysis::detail {
namespace {

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

}  // namespace

bool signal_has_effect(const model::Model& model, int s) {
  const SignalUse use = signal_uses(model)[static_cast<std::size_t>(s)];
  return use.load || use.prescribed;
}

void set_driven_values(const model::Model& model, const LinearizationOptions& options,
                       system::MultibodySystem& system) {
  if (options.driven_values.empty()) return;
  if (options.driven_values.size() != model.signals().size()) {
    throw InvalidArgument(fmt::format("linearize: {} driven values for {} signals",
                                      options.driven_values.size(), model.signals().size()));
  }
  for (int s = 0; s < static_cast<int>(model.signals().size()); ++s) {
    if (model.is_driven(s))
      system.set_driven_value(s, options.driven_values[static_cast<std::size_t>(s)]);
  }
}

namespace {

// The name that stands for a prescribed joint's k-th signal as an input: its coordinate, or for a
// ball or free joint (whose signals are a rotation vector, and a position) its velocity
// coordinate.
std::string prescribed_input_name(const model::Model& model, const model::Joint& j, int k) {
  return j.nq() == j.nv() ? model.q_name(j.q_index + k) : model.v_name(j.v_index + k);
}

}  // namespace

std::vector<Input> resolve_inputs(const model::Model& model,
                                  const std::vector<std::string>& names) {
  const std::vector<SignalUse> use = signal_uses(model);
  std::vector<Input> inputs;
  // Default: every signal something reads.
  if (names.empty()) {
    for (std::size_t s = 0; s < use.size(); ++s) {
      if (!use[s].load && !use[s].prescribed) continue;
      inputs.push_back({model.signals()[s].name(), static_cast<int>(s), use[s].prescribed,
                        use[s].prescribed && model.is_driven(static_cast<int>(s))});
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
          if (prescribed_input_name(model, j, k) == name) signal = j.prescribed_signal_indices[k];
        }
      }
    }
    if (!signal) {
      std::vector<std::string> candidates;
      for (const model::Signal& s : model.signals()) candidates.push_back(s.name());
      for (const model::Joint& j : model.joints()) {
        for (int k = 0; k < static_cast<int>(j.prescribed_signal_indices.size()); ++k)
          candidates.push_back(prescribed_input_name(model, j, k));
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
    inputs.push_back({name, *signal, u.prescribed, u.prescribed && model.is_driven(*signal)});
  }
  return inputs;
}

std::string tangent_name(const model::Model& model, int i) {
  const model::Joint& j = model.joint(model.joint_of_v(i));
  const int k = i - j.v_index;
  static constexpr const char* kRotation[] = {"rx", "ry", "rz"};
  static constexpr const char* kFree[] = {"rx", "ry", "rz", "x", "y", "z"};
  if (j.type == model::JointType::spherical) return j.name + "." + kRotation[k];
  if (j.type == model::JointType::free) return j.name + "." + kFree[k];
  return model.q_name(j.q_index + k);
}

std::vector<OutputRow> resolve_outputs(const model::Model& model,
                                       const std::vector<std::string>& state_names,
                                       int configuration_states,
                                       const LinearizationOptions& options,
                                       std::vector<model::OutputSpec>& specs) {
  specs = options.output_specs;
  const std::vector<std::string> columns = system::OutputSet(model, specs).column_names();

  std::vector<std::string> names = options.outputs;
  if (names.empty()) {
    names = columns.empty() ? std::vector<std::string>(state_names.begin(),
                                                       state_names.begin() + configuration_states)
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
      spec = model::OutputSpec{
          name,          model::OutputQuantity::joint_position, j.name, Vec3::Zero(),
          i - j.q_index, model::ReactionFrame::world,           ""};
    }
    for (int i = 0; i < model.nv() && !spec; ++i) {
      if (model.v_name(i) != name) continue;
      const model::Joint& j = model.joint(model.joint_of_v(i));
      spec = model::OutputSpec{
          name,          model::OutputQuantity::joint_velocity, j.name, Vec3::Zero(),
          i - j.v_index, model::ReactionFrame::world,           ""};
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

DifferenceSteps::DifferenceSteps(const model::Model& m, const LinearizationOptions& options)
    : model(m),
      angle_step(options.angle_step > 0.0 ? options.angle_step : kRelativeStep),
      length(characteristic_length(m)),
      length_step(options.length_step) {}

double DifferenceSteps::of_length(double value) const {
  return length_step > 0.0 ? length_step : kRelativeStep * std::max(length, std::abs(value));
}

double DifferenceSteps::configuration(int i, const VecX& q0) const {
  if (is_angle_coordinate(model, i)) return angle_step;
  const model::Joint& j = model.joint(model.joint_of_v(i));
  const int k = i - j.v_index;
  const int iq = j.type == model::JointType::free ? j.q_index + k - 3 : j.q_index + k;
  return of_length(q0[iq]);
}

void check_derivative_finite(const MatX& X, const char* what) {
  for (Eigen::Index j = 0; j < X.cols(); ++j)
    for (Eigen::Index i = 0; i < X.rows(); ++i)
      if (!std::isfinite(X(i, j)))
        throw NumericalError(
            fmt::format("linearize: {}({}, {}) = {} is not finite", what, i, j, X(i, j)));
}

void check_jacobians_finite(const Jacobians& J) {
  check_derivative_finite(J.dq, "∂(r, y)/∂q");
  check_derivative_finite(J.dv, "∂(r, y)/∂v");
  check_derivative_finite(J.du0, "∂(r, y)/∂u");
  check_derivative_finite(J.du1, "∂(r, y)/∂u̇");
  check_derivative_finite(J.du2, "∂(r, y)/∂ü");
}

MatX output_matrix(LinearModel& result, const std::vector<OutputRow>& rows, const Jacobians& J,
                   const VecX& g0, int rows_before_outputs, const VecX& state_values) {
  const auto p = static_cast<Eigen::Index>(rows.size());
  const auto m = J.du0.cols();
  const auto nx = J.dq.cols(), nz = J.dv.cols();
  MatX C = MatX::Zero(p, nx + nz);
  result.feedthrough_value = MatX::Zero(p, m);
  result.feedthrough_rate = MatX::Zero(p, m);
  result.feedthrough_acceleration = MatX::Zero(p, m);
  result.output_values = VecX::Zero(p);
  for (Eigen::Index r = 0; r < p; ++r) {
    const OutputRow& row = rows[static_cast<std::size_t>(r)];
    if (row.state >= 0) {
      C(r, row.state) = 1.0;
      result.output_values[r] = state_values[row.state];
      continue;
    }
    const int c = rows_before_outputs + row.column;
    C.block(r, 0, 1, nx) = J.dq.row(c);
    C.block(r, nx, 1, nz) = J.dv.row(c);
    result.feedthrough_value.row(r) = J.du0.row(c);
    result.feedthrough_rate.row(r) = J.du1.row(c);
    result.feedthrough_acceleration.row(r) = J.du2.row(c);
    result.output_values[r] = g0[c];
  }
  return C;
}

void fold_input_rates(LinearModel& result, const MatX& A, const MatX& C,
                      const std::vector<Input>& inputs,
                      const std::vector<std::string>& output_names, MatX& B, MatX& D) {
  B = result.input_value;
  D = result.feedthrough_value;
  const auto p = C.rows();
  for (Eigen::Index j = 0; j < B.cols(); ++j) {
    if (inputs[static_cast<std::size_t>(j)].commanded) continue;  // the closed loop's states
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

void add_commanded_states(const model::Model& model, const std::vector<Input>& inputs,
                          LinearModel& result) {
  std::vector<Eigen::Index> columns;  // the commanded inputs'
  for (std::size_t j = 0; j < inputs.size(); ++j) {
    if (inputs[j].commanded) columns.push_back(static_cast<Eigen::Index>(j));
  }
  if (columns.empty()) return;
  if (result.states_shifted) {
    throw InvalidArgument(fmt::format(
        "linearize: input '{}' commands an acceleration, which cannot be linearized beside a "
        "prescribed motion whose rates enter (its states shifted); linearize with that motion "
        "held",
        inputs[static_cast<std::size_t>(columns.front())].name));
  }
  const StateSpace& S = result.system;
  const Eigen::Index n = S.A().rows(), m = S.B().cols(), p = S.C().rows();
  const auto c = static_cast<Eigen::Index>(columns.size());
  MatX A = MatX::Zero(n + 2 * c, n + 2 * c), B = MatX::Zero(n + 2 * c, m);
  MatX C(p, n + 2 * c), D = S.D();
  A.topLeftCorner(n, n) = S.A();
  B.topRows(n) = S.B();
  C.leftCols(n) = S.C();
  std::vector<std::string> states = S.state_names();
  std::vector<std::string> rates;
  for (Eigen::Index k = 0; k < c; ++k) {
    const Eigen::Index j = columns[static_cast<std::size_t>(k)];
    A.col(n + k).head(n) = result.input_value.col(j);
    A.col(n + c + k).head(n) = result.input_rate.col(j);
    A(n + k, n + c + k) = 1.0;
    B.col(j).head(n) = result.input_acceleration.col(j);
    B(n + c + k, j) = 1.0;
    C.col(n + k) = result.feedthrough_value.col(j);
    C.col(n + c + k) = result.feedthrough_rate.col(j);
    D.col(j) = result.feedthrough_acceleration.col(j);
    const auto coordinate = model.prescribed_coordinate(inputs[static_cast<std::size_t>(j)].signal);
    states.push_back(model.q_name(coordinate->q));
    rates.push_back(model.v_name(coordinate->v));
  }
  states.insert(states.end(), rates.begin(), rates.end());
  result.system =
      StateSpace(A, B, C, D, states, S.input_names(), S.output_names(), S.sample_time());
}

// Tangent step for ∂δ̇/∂δ: exact for any |h| < π (J_r(δ)⁻¹ beyond its linear term is even in δ).
constexpr double kRotationRateStep = 0.5;

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

}  // namespace momenta::analysis::detail
