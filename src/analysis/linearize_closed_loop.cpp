// linearize() of a model with controllers (model/controller.hpp): the plant linearized with the
// inputs the controllers drive as inputs, closed by each controller's linear law.
//
//   plant        ẋ = A x + B_d u + B_w w,       y = C x + D_d u + D_w w
//   controllers  ż = A_c z + B_x x + B_r w,      u = C_c z + D_x x + D_r w
// with w the closed loop's inputs (the references and the inputs no controller drives), the
// measured coordinates read from x and a measured output y_m from its row C_m of the plant
// linearized with it as an output (a quantity of the state alone: no D). Then
//   [ẋ; ż] = [A + B_d D_x,  B_d C_c; B_x,  A_c] [x; z] + [B_w + B_d D_r; B_r] w,
//   y      = [C + D_d D_x,  D_d C_c] [x; z] + (D_w + D_d D_r) w.
// Each controller's (A_c, B_x, B_r, C_c, D_x, D_r), in e = r − y_m:
//   pid             states [ki ∫e (where ki ≠ 0), the filter x_f (where kd ≠ 0 and Tf > 0)]:
//                   İ = ki e, ẋ_f = (e − x_f)/Tf, u = kp e + I + kd (e − x_f)/Tf — or, without a
//                   filter, + kd (−ẏ_m) with ẏ_m the measured coordinate's rate state (an
//                   input's own rate ṙ is not an input of the linear model: left out);
//   state_feedback  u = −K x_m (x_ref and u_ff are the point, not perturbations);
//   linear          ż = A z + B e, u = C z + D e.
// Sampled controllers (all at one T): the same interconnection from sample to sample, with the
// plant held and sampled (Φ, Γ = c2d(A, B, T), zero-order hold) in place of (A, B), a block's
// matrices in z, and a pid's discrete form (sampled_pid_law); the result has sample time T.
// A drive that commands a coordinate's acceleration is, in the plant, that acceleration, with the
// coordinate and its rate among the plant's states (linearize.hpp).

#include <algorithm>
#include <optional>

#include <fmt/format.h>

#include "linearize_parts.hpp"
#include "momenta/analysis/discretize.hpp"
#include "momenta/common/error.hpp"
#include "momenta/system/closed_loop_system.hpp"

namespace momenta::analysis::detail {
namespace {

using model::ControllerKind;

// The linear law of one controller over (x, w), as the file comment writes it.
struct Law {
  MatX A_c, B_x, B_r, C_c, D_x, D_r;
  std::vector<std::string> states;
};

// The row of x holding model coordinate `index` (into [q; v]): the state of that name (states are
// named as the coordinates are, Model::q_name / v_name).
int state_row(const model::Model& model, const LinearModel& plant, int index,
              const std::string& controller) {
  const std::string& name =
      index < model.nq() ? model.q_name(index) : model.v_name(index - model.nq());
  const std::vector<std::string>& states = plant.system.state_names();
  const auto at = std::find(states.begin(), states.end(), name);
  if (at == states.end()) {
    throw InvalidArgument(fmt::format(
        "linearize: controller '{}' measures '{}', which is not a state of the linear model "
        "(a prescribed or constrained coordinate, or a quaternion's component)",
        controller, name));
  }
  return static_cast<int>(at - states.begin());
}

// The loop's sample time: 0 when every controller is continuous, else the one T all share.
double loop_sample_time(const model::Model& model) {
  double T = 0.0;
  const model::ResolvedController* continuous = nullptr;
  const model::ResolvedController* sampled = nullptr;
  for (const model::ResolvedController& c : model.controllers()) {
    if (!c.spec.discrete()) {
      continuous = &c;
      continue;
    }
    if (sampled != nullptr && c.spec.sample_time != T) {
      throw InvalidArgument(fmt::format(
          "linearize: controllers '{}' and '{}' are sampled every {} s and {} s; a sampled linear "
          "model has one sample time",
          sampled->spec.name, c.spec.name, T, c.spec.sample_time));
    }
    sampled = &c;
    T = c.spec.sample_time;
  }
  if (sampled != nullptr && continuous != nullptr) {
    throw InvalidArgument(fmt::format(
        "linearize: controller '{}' is sampled every {} s and '{}' is continuous; linearize the "
        "plant alone (the controllers open) and close the loops on it",
        sampled->spec.name, T, continuous->spec.name));
  }
  return T;
}

// The rows of the measured outputs over x (C of the plant with them as its outputs), every
// controller's in order; empty without any.
MatX measured_output_rows(const model::Model& model, const OperatingPoint& point,
                          const LinearizationOptions& open) {
  LinearizationOptions measuring = open;
  measuring.outputs.clear();
  measuring.output_specs.clear();
  for (const model::ResolvedController& c : model.controllers()) {
    for (const model::OutputSpec& spec : c.spec.measured_outputs) {
      measuring.outputs.push_back(spec.name);
      measuring.output_specs.push_back(spec);
    }
  }
  if (measuring.outputs.empty()) return MatX();
  return linearize(model, point, measuring).system.C();
}

// A sampled pid's law from sample to sample (ClosedLoopSystem::take_sample, Åström & Murray):
// with a = Tf/(Tf + T), b = kd/(Tf + T), states ξ = [I, D_(k−1), e_(k−1)] where used,
//   u_k = kp e_k + I_k + D_k,  D_k = a D_(k−1) + b (e_k − e_(k−1)),  I_(k+1) = I_k + ki T e_k,
// so ξ_(k+1) = A_ξ ξ_k + B_e e_k, u_k = C_ξ ξ_k + D_e e_k, with e = R w − S x.
Law sampled_pid_law(const model::Controller& s, const MatX& S, const MatX& R) {
  const model::PidGains& g = s.pid;
  const double T = s.sample_time, Tf = g.derivative_filter;
  const double a = Tf / (Tf + T), b = g.kd / (Tf + T);
  const int integral = g.ki != 0.0 ? 0 : -1;
  const int derivative = g.kd != 0.0 && Tf > 0.0 ? integral + 1 : -1;
  const int last_error = g.kd != 0.0 ? std::max(integral, derivative) + 1 : -1;
  const Eigen::Index nz = std::max({integral, derivative, last_error}) + 1;
  MatX A = MatX::Zero(nz, nz), B = MatX::Zero(nz, 1), C = MatX::Zero(1, nz);
  Law law;
  if (integral >= 0) {
    A(integral, integral) = 1.0;
    B(integral, 0) = g.ki * T;
    C(0, integral) = 1.0;
    law.states.push_back(s.name + ".integral");
  }
  if (derivative >= 0) {
    A(derivative, derivative) = a;
    A(derivative, last_error) = -b;
    B(derivative, 0) = b;
    C(0, derivative) = a;
    law.states.push_back(s.name + ".derivative");
  }
  if (last_error >= 0) {
    B(last_error, 0) = 1.0;
    C(0, last_error) = -b;
    law.states.push_back(s.name + ".last_error");
  }
  const double D = g.kp + b;
  law.A_c = A;
  law.B_x = -B * S;
  law.B_r = B * R;
  law.C_c = C;
  law.D_x = -D * S;
  law.D_r = D * R;
  return law;
}

Law law_of(const model::Model& model, const model::ResolvedController& c, const LinearModel& plant,
           const MatX& output_rows, int first_output, int reference_column, int n, int nw) {
  const model::Controller& s = c.spec;
  const auto m = static_cast<Eigen::Index>(c.drives.size());
  // S x: the measured coordinates, and the measured outputs' rows.
  MatX S = MatX::Zero(static_cast<Eigen::Index>(c.measured.size()), n);
  const int coordinates = model.nq() + model.nv();
  for (std::size_t i = 0; i < c.measured.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    if (c.measured[i] < coordinates)
      S(row, state_row(model, plant, c.measured[i], s.name)) = 1.0;
    else
      S.row(row) = output_rows.row(first_output + c.measured[i] - coordinates);
  }
  // R w: the reference's column (none for a constant setpoint, or a reference not asked for).
  MatX R = MatX::Zero(1, nw);
  if (reference_column >= 0) R(0, reference_column) = 1.0;

  Law law;
  switch (s.kind) {
    case ControllerKind::pid: {
      if (s.discrete()) return sampled_pid_law(s, S, R);
      const model::PidGains& g = s.pid;
      const double Tf = g.derivative_filter;
      const bool integral = g.ki != 0.0, filter = g.kd != 0.0 && Tf > 0.0;
      const Eigen::Index nz = (integral ? 1 : 0) + (filter ? 1 : 0);
      law.A_c = MatX::Zero(nz, nz);
      law.B_x = MatX::Zero(nz, n);
      law.B_r = MatX::Zero(nz, nw);
      law.C_c = MatX::Zero(1, nz);
      // u's gain on e: kp, plus kd/Tf through a filter.
      const double on_e = g.kp + (filter ? g.kd / Tf : 0.0);
      law.D_x = -on_e * S;
      law.D_r = on_e * R;
      Eigen::Index k = 0;
      if (integral) {
        law.B_x.row(k) = -g.ki * S;
        law.B_r.row(k) = g.ki * R;
        law.C_c(0, k) = 1.0;
        law.states.push_back(s.name + ".integral");
        ++k;
      }
      if (filter) {
        law.A_c(k, k) = -1.0 / Tf;
        law.B_x.row(k) = -S / Tf;
        law.B_r.row(k) = R / Tf;
        law.C_c(0, k) = -g.kd / Tf;
        law.states.push_back(s.name + ".filter");
      } else if (g.kd != 0.0) {
        law.D_x(0, state_row(model, plant, model.nq() + c.measured_rate, s.name)) -= g.kd;
      }
      return law;
    }
    case ControllerKind::state_feedback:
      law.A_c = MatX::Zero(0, 0);
      law.B_x = MatX::Zero(0, n);
      law.B_r = MatX::Zero(0, nw);
      law.C_c = MatX::Zero(m, 0);
      law.D_x = -s.gain * S;
      law.D_r = MatX::Zero(m, nw);
      return law;
    case ControllerKind::linear:
      law.A_c = s.block.A;
      law.B_x = -s.block.B * S;
      law.B_r = s.block.B * R;
      law.C_c = s.block.C;
      law.D_x = -s.block.D * S;
      law.D_r = s.block.D * R;
      for (Eigen::Index i = 0; i < s.block.A.rows(); ++i)
        law.states.push_back(fmt::format("{}.z{}", s.name, i + 1));
      return law;
    case ControllerKind::external:
      break;  // refused by linearize_closed_loop
  }
  return law;
}

}  // namespace

LinearModel linearize_closed_loop(const model::Model& model, const OperatingPoint& point,
                                  const LinearizationOptions& options) {
  // The closed loop's inputs: those asked for, else every input no controller drives.
  std::vector<std::string> inputs = options.inputs;
  if (inputs.empty()) {
    for (int s = 0; s < static_cast<int>(model.signals().size()); ++s) {
      if (!model.is_driven(s))
        inputs.push_back(model.signals()[static_cast<std::size_t>(s)].name());
    }
  }
  for (const model::ResolvedController& c : model.controllers()) {
    if (c.spec.kind == ControllerKind::external) {
      throw InvalidArgument(fmt::format(
          "linearize: controller '{}' is a function; its law has no linear model here — "
          "linearize the plant alone (the controllers open) and close the loop on the result",
          c.spec.name));
    }
    if (c.spec.sensor.delay > 0) {
      throw InvalidArgument(fmt::format(
          "linearize: controller '{}' reads through a delay of {} samples, which the linear model "
          "leaves out; linearize without it (a delay adds a state per sample and quantity)",
          c.spec.name, c.spec.sensor.delay));
    }
    for (int s : c.drives) {
      const std::string& name = model.signals()[static_cast<std::size_t>(s)].name();
      for (const std::string& input : inputs) {
        if (input == name) {
          throw InvalidArgument(fmt::format(
              "linearize: input '{}' is driven by controller '{}'; the closed loop's inputs are "
              "its references and the inputs no controller drives (or linearize the plant alone)",
              name, c.spec.name));
        }
      }
    }
  }

  // Sampled controllers make the loop a sampled system: every one at one sample time T, none
  // continuous beside them; the plant is then held (zero-order hold) and sampled at T.
  const double T = loop_sample_time(model);

  // The controllers' outputs at the point (their states as a run from it starts them): the
  // plant is linearized with its driven inputs there.
  LinearizationOptions open = options;
  open.close_loops = false;
  open.inputs.clear();
  {
    system::MultibodySystem plant_system(model);
    system::ClosedLoopSystem loop(plant_system);
    const integrate::State start = loop.start(point.t, point.q, point.v);
    std::vector<double> columns(loop.column_names().size());
    loop.record(point.t, start.q, start.v, columns);
    open.driven_values.assign(model.signals().size(), 0.0);
    for (int s = 0; s < static_cast<int>(model.signals().size()); ++s) {
      if (model.is_driven(s))
        open.driven_values[static_cast<std::size_t>(s)] = plant_system.driven_value(s);
    }
  }
  std::vector<int> driven_column;  // per controller, its first driven column
  for (const model::ResolvedController& c : model.controllers()) {
    driven_column.push_back(static_cast<int>(open.inputs.size()));
    for (int s : c.drives)
      open.inputs.push_back(model.signals()[static_cast<std::size_t>(s)].name());
  }
  const int nd = static_cast<int>(open.inputs.size());
  // The closed loop's inputs that act on the plant (a reference alone acts on a controller).
  std::vector<int> acting;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const std::optional<int> s = model.find_signal(inputs[i]);
    if (!s || signal_has_effect(model, *s)) {
      acting.push_back(static_cast<int>(i));
      open.inputs.push_back(inputs[i]);
    } else {
      bool reference = false;
      for (const model::ResolvedController& c : model.controllers()) reference |= c.reference == *s;
      if (!reference) {
        throw InvalidArgument(fmt::format(
            "linearize: input '{}' scales no applied load, drives no prescribed joint and is no "
            "controller's reference, so it has no effect",
            inputs[i]));
      }
    }
  }
  const LinearModel plant = linearize(model, point, open);
  // Sampled: x_(k+1) = Φ x_k + Γ u_k, the inputs held over each sample.
  const StateSpace P = T > 0.0 ? c2d(plant.system, T) : plant.system;
  const auto n = P.A().rows();
  const auto nw = static_cast<Eigen::Index>(inputs.size());
  const MatX B_d = P.B().leftCols(nd), D_d = P.D().leftCols(nd);
  MatX B_w = MatX::Zero(n, nw), D_w = MatX::Zero(P.C().rows(), nw);
  for (std::size_t k = 0; k < acting.size(); ++k) {
    B_w.col(acting[k]) = P.B().col(nd + static_cast<Eigen::Index>(k));
    D_w.col(acting[k]) = P.D().col(nd + static_cast<Eigen::Index>(k));
  }

  // Every controller's law, stacked: z in controller order, u in driven-column order.
  const MatX output_rows = measured_output_rows(model, point, open);
  int first_output = 0;
  std::vector<Law> laws;
  Eigen::Index nz = 0;
  for (const model::ResolvedController& c : model.controllers()) {
    int reference_column = -1;
    if (c.reference >= 0) {
      const std::string& r = model.signals()[static_cast<std::size_t>(c.reference)].name();
      for (std::size_t i = 0; i < inputs.size(); ++i) {
        if (inputs[i] == r) reference_column = static_cast<int>(i);
      }
    }
    laws.push_back(law_of(model, c, plant, output_rows, first_output, reference_column,
                          static_cast<int>(n), static_cast<int>(nw)));
    first_output += static_cast<int>(c.spec.measured_outputs.size());
    nz += laws.back().A_c.rows();
  }
  MatX A_c = MatX::Zero(nz, nz), B_x = MatX::Zero(nz, n), B_r = MatX::Zero(nz, nw);
  MatX C_c = MatX::Zero(nd, nz), D_x = MatX::Zero(nd, n), D_r = MatX::Zero(nd, nw);
  std::vector<std::string> states = P.state_names();
  Eigen::Index z = 0;
  for (std::size_t i = 0; i < laws.size(); ++i) {
    const Law& l = laws[i];
    const Eigen::Index k = l.A_c.rows(), u = driven_column[i], m = l.D_x.rows();
    A_c.block(z, z, k, k) = l.A_c;
    B_x.middleRows(z, k) = l.B_x;
    B_r.middleRows(z, k) = l.B_r;
    C_c.block(u, z, m, k) = l.C_c;
    D_x.middleRows(u, m) = l.D_x;
    D_r.middleRows(u, m) = l.D_r;
    states.insert(states.end(), l.states.begin(), l.states.end());
    z += k;
  }

  // The interconnection.
  MatX A(n + nz, n + nz), B(n + nz, nw), C(P.C().rows(), n + nz);
  A << P.A() + B_d * D_x, B_d * C_c, B_x, A_c;
  B << B_w + B_d * D_r, B_r;
  C << P.C() + D_d * D_x, D_d * C_c;
  const MatX D = D_w + D_d * D_r;
  LinearModel result = plant;
  result.system = StateSpace(A, B, C, D, states, inputs, P.output_names(), T);
  result.input_value = B;
  result.input_rate = MatX::Zero(n + nz, nw);
  result.input_acceleration = MatX::Zero(n + nz, nw);
  result.feedthrough_value = D;
  result.feedthrough_rate = MatX::Zero(D.rows(), nw);
  result.feedthrough_acceleration = MatX::Zero(D.rows(), nw);
  return result;
}

}  // namespace momenta::analysis::detail
