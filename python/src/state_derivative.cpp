// Model.dynamics(t, x, u): the mechanism's state derivative ẋ = f(t, x, u) as scipy's solve_ivp
// and a hand-written integrator want it, and Model.input_names, the inputs u holds.
//
// x = [q; v] (nq + nv entries, as model.q_names then model.v_names), ẋ = [q̇; v̇] with q̇ the
// configuration's rate (½ q ⊗ [0; ω] on a quaternion, v elsewhere) and v̇ the simulator's own
// accelerations (force elements, prescribed joints, constraints: system/multibody_system.hpp).
// Without u the inputs follow their signals of time; with u every input takes u's value.

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>

#include "bindings.hpp"
#include "model_handle.hpp"
#include "momenta/system/multibody_system.hpp"

namespace momenta::python {

// The systems one model's dynamics() evaluates, made at its first call and kept with the model.
struct StateDerivative {
  explicit StateDerivative(std::shared_ptr<const io::ModelFile> f)
      : file(std::move(f)),
        timed(file->model),
        driven(file->model),
        q(VecX::Zero(file->model.nq())),
        v(VecX::Zero(file->model.nv())),
        vdot(VecX::Zero(file->model.nv())),
        qdot(VecX::Zero(file->model.nq())) {
    const model::Model& model = file->model;
    for (int s = 0; s < static_cast<int>(model.signals().size()); ++s) {
      if (!is_input(model, s)) continue;
      inputs.push_back(s);
      if (!commanded(model, s)) driven.drive_signal(s);  // a commanded one is driven already
    }
  }

  // A commanded signal: one a controller drives that prescribes a joint's coordinate, whose
  // value is then that coordinate's acceleration (model/controller.hpp).
  static bool commanded(const model::Model& model, int s) {
    return model.is_driven(s) && model.prescribed_coordinate(s).has_value();
  }
  // What u holds: every signal but those that are a joint's motion of time.
  static bool is_input(const model::Model& model, int s) {
    return !model.joint_prescribed_by(s) || commanded(model, s);
  }

  std::shared_ptr<const io::ModelFile> file;  // first: the systems refer to its model
  system::MultibodySystem timed;              // inputs from their signals of time
  system::MultibodySystem driven;             // every input set from u
  std::vector<int> inputs;                    // the signals u holds, in model order
  VecX q, v, vdot, qdot;
};

namespace {

std::vector<std::string> input_names(const model::Model& model) {
  std::vector<std::string> names;
  for (int s = 0; s < static_cast<int>(model.signals().size()); ++s) {
    if (StateDerivative::is_input(model, s))
      names.push_back(model.signals()[static_cast<std::size_t>(s)].name());
  }
  return names;
}

py::array_t<double> state_derivative(const ModelHandle& h, double t, const py::handle& x,
                                     const py::object& u) {
  if (!h.state_derivative) h.state_derivative = std::make_shared<StateDerivative>(h.file);
  StateDerivative& d = *h.state_derivative;
  const model::Model& model = h.model();
  const int nq = model.nq(), nv = model.nv();
  if (!std::isfinite(t)) throw InvalidArgument(fmt::format("dynamics: t = {} is not finite", t));
  ArgStorage sx;
  const auto state = vector_arg(x, "x", nq + nv, "the model's nq + nv: [q; v]", sx);
  d.q = state.head(nq);
  d.v = state.tail(nv);
  system::MultibodySystem* system = &d.timed;
  if (!u.is_none()) {
    const auto n = static_cast<Eigen::Index>(d.inputs.size());
    // Any shape holding n numbers: -K @ x of a (1, n) K is (1,), [-K @ x] is (1, 1).
    const auto array = as_float_array(u, "u");
    if (array.size() != n) {
      throw py::value_error(fmt::format(
          "u: expected {} number{} ({}), got {}", n, n == 1 ? "" : "s",
          n == 0 ? std::string("the model has no inputs")
                 : fmt::format("one per input: {}", fmt::join(input_names(model), ", ")),
          array.size()));
    }
    const Eigen::Map<const VecX> values(array.data(), n);
    for (Eigen::Index i = 0; i < n; ++i) {
      if (!std::isfinite(values[i])) {
        throw InvalidArgument(fmt::format("dynamics: u[{}] ({}) is {}", i,
                                          input_names(model)[static_cast<std::size_t>(i)],
                                          values[i]));
      }
      d.driven.set_driven_value(d.inputs[static_cast<std::size_t>(i)], values[i]);
    }
    system = &d.driven;
  }
  system->acceleration(t, d.q, d.v, d.vdot);
  model::configuration_rate(model, d.q, d.v, d.qdot);
  py::array_t<double> out = new_float_array(nq + nv);
  Eigen::Map<VecX> xdot(out.mutable_data(), nq + nv);
  xdot.head(nq) = d.qdot;
  xdot.tail(nv) = d.vdot;
  return out;
}

}  // namespace

void bind_state_derivative(py::module_& m) {
  auto model = py::reinterpret_borrow<py::class_<ModelHandle>>(m.attr("Model"));
  model.def_property_readonly(
      "input_names", [](const ModelHandle& h) { return input_names(h.model()); },
      "The inputs u holds in dynamics(t, x, u), in order: the model's signals that no joint "
      "follows (a prescribed joint's signal is a motion, not an input) — but a joint a controller "
      "commands takes its acceleration from u.");
  model.def("dynamics", &state_derivative, py::arg("t"), py::arg("x"), py::arg("u") = py::none(),
            R"doc(The state derivative ẋ = f(t, x, u), for scipy.integrate.solve_ivp:
x = [q; v] (nq + nv numbers, model.q_names then model.v_names), ẋ = [q̇; v̇] — q̇ the
configuration's rate (½ q ⊗ [0; ω] on a ball or free joint's quaternion, v elsewhere), v̇ the
accelerations `simulate` integrates (gravity, force elements, prescribed joints, constraint
forces). u: None, and every input follows its signal of time at t (an input a controller of the
model drives is then 0: this is the plant, the loop open); or one number per model.input_names,
which the inputs take instead. solve_ivp keeps neither a quaternion's unit norm nor a loop's
constraints: normalize, or use simulate. Raises ValueError for a wrong size, InvalidArgument
for a value that is not finite.)doc");
}

}  // namespace momenta::python
