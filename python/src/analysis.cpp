// Linear analysis from Python: linearize a model about an operating point, find an equilibrium,
// and the modes, transfer functions, Bode data and step / impulse responses of a StateSpace.

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/complex.h>
#include <pybind11/stl.h>
#include <Eigen/Eigenvalues>

#include "bindings.hpp"
#include "model_handle.hpp"
#include "momenta/analysis/equilibrium.hpp"
#include "momenta/analysis/frequency_response.hpp"
#include "momenta/analysis/joint_steady_motion.hpp"
#include "momenta/analysis/linearize.hpp"
#include "momenta/analysis/modes.hpp"
#include "momenta/analysis/modes_text.hpp"
#include "momenta/analysis/nyquist.hpp"
#include "momenta/analysis/operating_point.hpp"
#include "momenta/analysis/rolling_steady_motion.hpp"
#include "momenta/analysis/stability_margins.hpp"
#include "momenta/analysis/state_space.hpp"
#include "momenta/analysis/steady_motion.hpp"
#include "momenta/analysis/step_info.hpp"
#include "momenta/analysis/time_response.hpp"
#include "momenta/analysis/transfer_function.hpp"
#include "momenta/common/number_text.hpp"

namespace momenta::python {
namespace {

using namespace analysis;

py::array_t<std::complex<double>> complex_array(const std::vector<Complex>& z) {
  py::array_t<std::complex<double>> out(static_cast<py::ssize_t>(z.size()));
  std::copy(z.begin(), z.end(), out.mutable_data());
  return out;
}

}  // namespace

std::string matrix_table(const char* name, const MatX& M, const std::vector<std::string>& rows,
                         const std::vector<std::string>& columns) {
  std::string text = fmt::format("{} =\n", name);
  if (M.rows() == 0 || M.cols() == 0) return text + "  (empty)\n";
  std::size_t width = 0;
  for (const std::string& r : rows) width = std::max(width, r.size());
  std::vector<std::size_t> widths;  // each column as wide as its name, at least 12
  for (const std::string& c : columns) widths.push_back(std::max<std::size_t>(12, c.size()));
  text += fmt::format("  {:<{}}", "", width);
  for (std::size_t j = 0; j < columns.size(); ++j)
    text += fmt::format(" {:>{}}", columns[j], widths[j]);
  text += "\n";
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    text += fmt::format("  {:<{}}", rows[static_cast<std::size_t>(i)], width);
    for (Eigen::Index j = 0; j < M.cols(); ++j) {
      text += fmt::format(" {:>{}}", number_text(M(i, j), 6), widths[static_cast<std::size_t>(j)]);
    }
    text += "\n";
  }
  return text;
}

namespace {

// An input or output given by name (str) or index (int).
std::size_t input_arg(const StateSpace& s, const py::handle& input) {
  if (py::isinstance<py::str>(input)) return s.input_index(input.cast<std::string>());
  return input.cast<std::size_t>();
}
std::size_t output_arg(const StateSpace& s, const py::handle& output) {
  if (py::isinstance<py::str>(output)) return s.output_index(output.cast<std::string>());
  return output.cast<std::size_t>();
}

}  // namespace

StateSpace state_space_arg(const py::handle& object) {
  if (py::isinstance<StateSpace>(object)) return object.cast<StateSpace>();
  if (py::isinstance<LinearModel>(object)) return object.cast<const LinearModel&>().system;
  // scipy.signal's TransferFunction and ZerosPolesGain (lti or dlti) through their to_ss().
  py::object system = py::reinterpret_borrow<py::object>(object);
  if (!py::hasattr(system, "A") && py::hasattr(system, "to_ss")) system = system.attr("to_ss")();
  if (!py::hasattr(system, "A") || !py::hasattr(system, "B") || !py::hasattr(system, "C") ||
      !py::hasattr(system, "D")) {
    throw py::type_error(fmt::format(
        "system: expected a momenta.StateSpace, a LinearModel, or a state space with A, B, C, D "
        "(scipy.signal.StateSpace, python-control's StateSpace); got {}",
        py::str(py::type::of(object).attr("__name__")).cast<std::string>()));
  }
  const MatX a = matrix_arg(system.attr("A"), "A", -1, -1);
  const MatX b = matrix_arg(system.attr("B"), "B", a.rows(), -1);
  const MatX c = matrix_arg(system.attr("C"), "C", -1, a.rows());
  const MatX d = matrix_arg(system.attr("D"), "D", c.rows(), b.cols());
  // scipy: dt None for continuous; python-control: 0 continuous, True "discrete, unspecified".
  double dt = 0.0;
  if (py::hasattr(system, "dt")) {
    const py::object t = system.attr("dt");
    if (py::isinstance<py::bool_>(t) && t.cast<bool>()) {
      throw py::value_error("system: a discrete system with an unspecified sample time (dt=True)");
    }
    if (!t.is_none() && !py::isinstance<py::bool_>(t)) dt = t.cast<double>();
  }
  return StateSpace(a, b, c, d, {}, {}, {}, dt);
}

namespace {

TimeGrid grid_of(std::optional<double> final_time, std::optional<std::size_t> samples) {
  TimeGrid grid;
  grid.final_time = final_time.value_or(0.0);
  grid.samples = samples.value_or(0);
  return grid;
}

// The operating point: the model's initial state unless q / v are given.
OperatingPoint point_of(const ModelHandle& h, const py::object& q, const py::object& v, double t) {
  OperatingPoint p = initial_operating_point(h.model());
  ArgStorage storage;
  if (!q.is_none()) p.q = vector_arg(q, "q", h.model().nq(), "the model's nq", storage);
  if (!v.is_none()) p.v = vector_arg(v, "v", h.model().nv(), "the model's nv", storage);
  p.t = t;
  return p;
}

// The operating points of a batched linearize: one per row of q, an (N, nq) array, and/or of v,
// an (N, nv) one (a vector, or None for the initial state's, is used for every row); empty when
// neither has rows.
std::vector<OperatingPoint> points_of_rows(const ModelHandle& h, const py::object& q,
                                           const py::object& v, double t) {
  const auto rows_of = [](const py::object& x, const char* name) -> py::ssize_t {
    if (x.is_none()) return -1;
    const auto a = as_float_array(x, name);
    return a.ndim() == 2 ? a.shape(0) : -1;
  };
  const py::ssize_t nq_rows = rows_of(q, "q"), nv_rows = rows_of(v, "v");
  if (nq_rows < 0 && nv_rows < 0) return {};
  if (nq_rows >= 0 && nv_rows >= 0 && nq_rows != nv_rows) {
    throw py::value_error(
        fmt::format("linearize: q has {} rows and v {}; one operating point per row of each",
                    nq_rows, nv_rows));
  }
  const py::ssize_t n = std::max(nq_rows, nv_rows);
  const model::Model& model = h.model();
  const MatX Q = nq_rows >= 0 ? matrix_arg(q, "q", -1, model.nq()) : MatX();
  const MatX V = nv_rows >= 0 ? matrix_arg(v, "v", -1, model.nv()) : MatX();
  std::vector<OperatingPoint> points;
  for (py::ssize_t i = 0; i < n; ++i) {
    OperatingPoint p = point_of(h, nq_rows >= 0 ? py::object(py::none()) : q,
                                nv_rows >= 0 ? py::object(py::none()) : v, t);
    if (nq_rows >= 0) p.q = Q.row(static_cast<Eigen::Index>(i)).transpose();
    if (nv_rows >= 0) p.v = V.row(static_cast<Eigen::Index>(i)).transpose();
    points.push_back(std::move(p));
  }
  return points;
}

// {name: unit} over an input and lists of outputs and states (units empty: none known).
py::dict units_dict(const std::string& input, const std::string& input_unit,
                    const std::vector<std::string>& outputs,
                    const std::vector<std::string>& output_units,
                    const std::vector<std::string>& states,
                    const std::vector<std::string>& state_units) {
  py::dict d;
  if (!input_unit.empty()) d[py::str(input)] = input_unit;
  for (std::size_t i = 0; i < output_units.size(); ++i) d[py::str(outputs[i])] = output_units[i];
  for (std::size_t i = 0; i < state_units.size(); ++i) d[py::str(states[i])] = state_units[i];
  return d;
}

void bind_state_space(py::module_& m) {
  py::class_<StateSpace>(m, "StateSpace", R"doc(
ẋ = A x + B u, y = C x + D u with named states, inputs and outputs; with dt > 0 the sampled
x[k+1] = A x[k] + B u[k]. Build one from matrices (D may be None for zero; names default to x1..,
u1.., y1..), get one from linearize() or c2d(). Unpacks as A, B, C, D = system, like scipy's and
python-control's; to_scipy() hands it over.)doc")
      .def(py::init([](const py::object& A, const py::object& B, const py::object& C,
                       const py::object& D, std::vector<std::string> states,
                       std::vector<std::string> inputs, std::vector<std::string> outputs,
                       double dt) {
             const MatX a = matrix_arg(A, "A", -1, -1);
             const MatX b = matrix_arg(B, "B", a.rows(), -1);
             const MatX c = matrix_arg(C, "C", -1, a.rows());
             const MatX d = D.is_none() ? MatX() : matrix_arg(D, "D", c.rows(), b.cols());
             return StateSpace(a, b, c, d, std::move(states), std::move(inputs), std::move(outputs),
                               dt);
           }),
           py::arg("A"), py::arg("B"), py::arg("C"), py::arg("D") = py::none(),
           py::arg("state_names") = std::vector<std::string>{},
           py::arg("input_names") = std::vector<std::string>{},
           py::arg("output_names") = std::vector<std::string>{}, py::arg("dt") = 0.0)
      .def_property_readonly("A", [](const StateSpace& s) { return to_numpy(s.A()); })
      .def_property_readonly("B", [](const StateSpace& s) { return to_numpy(s.B()); })
      .def_property_readonly("C", [](const StateSpace& s) { return to_numpy(s.C()); })
      .def_property_readonly("D", [](const StateSpace& s) { return to_numpy(s.D()); })
      .def_property_readonly("state_names", &StateSpace::state_names)
      .def_property_readonly("input_names", &StateSpace::input_names)
      .def_property_readonly("output_names", &StateSpace::output_names)
      .def_property_readonly(
          "units",
          [](const StateSpace& s) {
            const StateSpace::Units& u = s.units();
            py::dict d;
            const auto add = [&](const std::vector<std::string>& names,
                                 const std::vector<std::string>& units) {
              for (std::size_t i = 0; i < units.size(); ++i) d[py::str(names[i])] = units[i];
            };
            add(s.state_names(), u.states);
            add(s.input_names(), u.inputs);
            add(s.output_names(), u.outputs);
            return d;
          },
          "Each state's, input's and output's SI unit by name ({'x.position': 'm', 'force': "
          "'N', ...}) as linearize() knows them; empty for a system built from matrices (c2d "
          "keeps them).")
      .def_property_readonly("dt", &StateSpace::sample_time,
                             "Sample time, s; 0 for a continuous system (python-control's rule).")
      .def_property_readonly("nstates", &StateSpace::state_count)
      .def_property_readonly("ninputs", &StateSpace::input_count)
      .def_property_readonly("noutputs", &StateSpace::output_count)
      .def("__iter__",
           [](const StateSpace& s) {
             return py::iter(py::make_tuple(to_numpy(s.A()), to_numpy(s.B()), to_numpy(s.C()),
                                            to_numpy(s.D())));
           })
      .def(
          "poles",
          [](const StateSpace& s) {
            if (s.state_count() == 0) return complex_array({});
            const Eigen::EigenSolver<MatX> eigen(s.A(), false);
            if (eigen.info() != Eigen::Success) {
              throw NumericalError("poles: the eigenvalue iteration on A did not converge");
            }
            std::vector<Complex> p(eigen.eigenvalues().begin(), eigen.eigenvalues().end());
            std::sort(p.begin(), p.end(), [](Complex a, Complex b) {
              return std::abs(a) != std::abs(b) ? std::abs(a) < std::abs(b) : a.imag() > b.imag();
            });
            return complex_array(p);
          },
          "Eigenvalues of A: in 1/s, or in the z-plane when dt > 0; by magnitude.")
      .def(
          "zeros",
          [](const StateSpace& s) {
            if (!s.is_siso()) {
              throw py::value_error(fmt::format(
                  "zeros: of a single-input single-output system; this one has {} inputs and {} "
                  "outputs: take system.siso(input, output)",
                  s.input_count(), s.output_count()));
            }
            return complex_array(transfer_function(s, 0, 0, 0.0).zeros);
          },
          "Invariant zeros of a one-input one-output system, 1/s (none cancelled).")
      .def(
          "to_scipy",
          [](const StateSpace& s) {
            const py::module_ signal = py::module_::import("scipy.signal");
            if (s.is_discrete()) {
              return signal.attr("StateSpace")(to_numpy(s.A()), to_numpy(s.B()), to_numpy(s.C()),
                                               to_numpy(s.D()), py::arg("dt") = s.sample_time());
            }
            return signal.attr("StateSpace")(to_numpy(s.A()), to_numpy(s.B()), to_numpy(s.C()),
                                             to_numpy(s.D()));
          },
          "scipy.signal.StateSpace with the same matrices (and dt); names stay here.")
      .def(
          "siso",
          [](const StateSpace& s, const py::object& input, const py::object& output) {
            return s.siso(input_arg(s, input), output_arg(s, output));
          },
          py::arg("input"), py::arg("output"), "The one-input, one-output subsystem.")
      .def("__repr__", [](const StateSpace& s) {
        // Names with their units where known: "force [N]".
        const auto named = [](const std::vector<std::string>& names,
                              const std::vector<std::string>& units) {
          std::vector<std::string> out;
          for (std::size_t i = 0; i < names.size(); ++i) {
            const bool unit = i < units.size() && !units[i].empty();
            out.push_back(unit ? fmt::format("{} [{}]", names[i], units[i]) : names[i]);
          }
          return fmt::format("{}", fmt::join(out, ", "));
        };
        std::string text = fmt::format(
            "<momenta.StateSpace: {} states, {} inputs ({}), {} outputs ({}){}>", s.state_count(),
            s.input_count(), named(s.input_names(), s.units().inputs), s.output_count(),
            named(s.output_names(), s.units().outputs),
            s.is_discrete() ? fmt::format(", sampled every {} s", number_text(s.sample_time(), 6))
                            : std::string());
        if (s.state_count() <= 12) {
          text += "\n" + matrix_table("A", s.A(), s.state_names(), s.state_names());
          text += matrix_table("B", s.B(), s.state_names(), s.input_names());
          text += matrix_table("C", s.C(), s.output_names(), s.state_names());
          text += matrix_table("D", s.D(), s.output_names(), s.input_names());
        }
        return text;
      });
}

void bind_linearization(py::module_& m) {
  py::class_<LinearModel>(m, "LinearModel", R"doc(
A model linearized about a point: `system` (A, B, C, D with names), the second-order form over
the free coordinates (mass, damping, stiffness), the point, its acceleration and output values.)doc")
      .def_readonly("system", &LinearModel::system)
      .def_property_readonly("A", [](const LinearModel& l) { return to_numpy(l.system.A()); })
      .def_property_readonly("B", [](const LinearModel& l) { return to_numpy(l.system.B()); })
      .def_property_readonly("C", [](const LinearModel& l) { return to_numpy(l.system.C()); })
      .def_property_readonly("D", [](const LinearModel& l) { return to_numpy(l.system.D()); })
      .def_property_readonly("state_names",
                             [](const LinearModel& l) { return l.system.state_names(); })
      .def_property_readonly("input_names",
                             [](const LinearModel& l) { return l.system.input_names(); })
      .def_property_readonly("output_names",
                             [](const LinearModel& l) { return l.system.output_names(); })
      .def_property_readonly("mass", [](const LinearModel& l) { return to_numpy(l.mass); })
      .def_property_readonly("damping", [](const LinearModel& l) { return to_numpy(l.damping); })
      .def_property_readonly("stiffness",
                             [](const LinearModel& l) { return to_numpy(l.stiffness); })
      .def_property_readonly(
          "q", [](const LinearModel& l) { return to_numpy(l.point.q); },
          "The operating point's configuration.")
      .def_property_readonly("v", [](const LinearModel& l) { return to_numpy(l.point.v); })
      .def_property_readonly("t", [](const LinearModel& l) { return l.point.t; })
      .def_property_readonly("acceleration",
                             [](const LinearModel& l) { return to_numpy(l.acceleration); })
      .def_property_readonly("largest_acceleration", &largest_acceleration,
                             "max |v̇| over the free coordinates at the point (0 at an equilibrium)")
      .def_property_readonly("largest_speed", &largest_speed,
                             "max |v| over the free coordinates at the point")
      .def_property_readonly("output_values",
                             [](const LinearModel& l) { return to_numpy(l.output_values); })
      .def_readonly("states_shifted", &LinearModel::states_shifted)
      .def_readonly("coordinates", &LinearModel::coordinates,
                    "Velocity index of each configuration state.")
      .def_readonly("velocity_coordinates", &LinearModel::velocity_coordinates,
                    "Velocity index of each velocity state.")
      .def_readonly("dependent_coordinates", &LinearModel::dependent_coordinates,
                    "Velocity indices the constraints determine (empty without constraints).")
      .def("__repr__", [](const LinearModel& l) {
        return fmt::format("<momenta.LinearModel: {} states, inputs [{}], outputs [{}]>",
                           l.system.state_count(), fmt::join(l.system.input_names(), ", "),
                           fmt::join(l.system.output_names(), ", "));
      });

  m.def(
      "linearize",
      [](const ModelHandle& h, std::vector<std::string> inputs, std::vector<std::string> outputs,
         const py::object& q, const py::object& v, double t, double angle_step, double length_step,
         std::vector<std::string> independent, const std::string& derivatives, bool open_loop) {
        LinearizationOptions options;
        options.close_loops = !open_loop;
        if (derivatives == "differences") {
          options.derivatives = LinearizationOptions::Derivatives::differences;
        } else if (derivatives != "analytic") {
          throw InvalidArgument(
              fmt::format("linearize: derivatives = '{}' is neither 'analytic' nor 'differences'",
                          derivatives));
        }
        options.inputs = std::move(inputs);
        options.outputs = std::move(outputs);
        options.independent = std::move(independent);
        options.output_specs = h.file->outputs;
        options.angle_step = angle_step;
        options.length_step = length_step;
        const std::vector<OperatingPoint> points = points_of_rows(h, q, v, t);
        if (points.empty()) return py::cast(linearize(h.model(), point_of(h, q, v, t), options));
        // Gain scheduling: one linear model per operating point.
        py::list models;
        for (const OperatingPoint& p : points) models.append(linearize(h.model(), p, options));
        return py::object(std::move(models));
      },
      py::arg("model"), py::kw_only(), py::arg("inputs") = std::vector<std::string>{},
      py::arg("outputs") = std::vector<std::string>{}, py::arg("q") = py::none(),
      py::arg("v") = py::none(), py::arg("t") = 0.0, py::arg("angle_step") = 0.0,
      py::arg("length_step") = 0.0, py::arg("independent") = std::vector<std::string>{},
      py::arg("derivatives") = "analytic", py::arg("open_loop") = false,
      R"doc(Linearizes the model about (t, q, v) — its initial state unless given — as
`momenta linearize` does (a list of them, one per row, when q is an (N, nq) array or v an
(N, nv) one: operating points for gain scheduling; a vector is used for every row): states
[δq; v] over the free joints, inputs the named signals (all by
default), outputs the named model outputs, states or coordinates (the model file's outputs, or
every configuration state, by default). A model with controllers is linearized with its loops
closed (their states appended, the references and undriven signals the inputs); open_loop=True
gives the plant alone, each driven input an input (docs/control.md). With constraints the states are independent coordinates
(docs/constraints.md); `independent` names coordinates to keep as states. `derivatives`:
'analytic' (exact to round-off) or 'differences' (Richardson differences of the equations, the
check; ~1e-12 relative). Raises InvalidArgument on an unknown name (with a did-you-mean).)doc");

  py::class_<Equilibrium>(m, "Equilibrium", "A static equilibrium and its stability.")
      .def_property_readonly("q", [](const Equilibrium& e) { return to_numpy(e.point.q); })
      .def_property_readonly("v", [](const Equilibrium& e) { return to_numpy(e.point.v); })
      .def_property_readonly("residual", [](const Equilibrium& e) { return to_numpy(e.residual); })
      .def_readonly("force_scale", &Equilibrium::force_scale)
      .def_readonly("iterations", &Equilibrium::iterations)
      .def_readonly("linear", &Equilibrium::linear, "The linearization about the equilibrium.")
      .def_property_readonly(
          "unstable_eigenvalues",
          [](const Equilibrium& e) { return complex_array(e.unstable_eigenvalues); })
      .def_readonly("stiffness_rank", &Equilibrium::stiffness_rank)
      .def_property_readonly("stable", &Equilibrium::stable)
      .def("__repr__", [](const Equilibrium& e) {
        std::vector<std::string> q;
        for (Eigen::Index i = 0; i < e.point.q.size(); ++i)
          q.push_back(number_text(e.point.q[i], 6));
        std::vector<std::string> growth;
        for (const Complex& z : e.unstable_eigenvalues) growth.push_back(complex_text(z));
        return fmt::format(
            "<momenta.Equilibrium q = [{}], {} ({} Newton iterations, residual {:.3g} of the "
            "force scale {:.3g})>",
            fmt::join(q, ", "),
            e.stable() ? std::string("stable")
                       : fmt::format("unstable: eigenvalues {}", fmt::join(growth, ", ")),
            e.iterations, e.residual.size() ? e.residual.cwiseAbs().maxCoeff() : 0.0,
            e.force_scale);
      });
  m.def(
      "find_equilibrium",
      [](const ModelHandle& h, const py::object& q_guess, double t, double tolerance,
         int max_iterations) {
        EquilibriumOptions options;
        options.t = t;
        options.tolerance = tolerance;
        options.max_iterations = max_iterations;
        ArgStorage storage;
        const VecX guess =
            q_guess.is_none()
                ? h.model().initial_q()
                : VecX(vector_arg(q_guess, "q_guess", h.model().nq(), "the model's nq", storage));
        return find_equilibrium(h.model(), guess, options);
      },
      py::arg("model"), py::kw_only(), py::arg("q_guess") = py::none(), py::arg("t") = 0.0,
      py::arg("tolerance") = 1e-10, py::arg("max_iterations") = 100,
      "The static equilibrium nearest (by Newton's method) to q_guess (default the initial "
      "configuration), with its linearization and stability. Raises NumericalError when there "
      "is none to be found, naming the largest residual.");
}

void bind_modes(py::module_& m) {
  py::class_<Mode>(m, "Mode", "One eigenvalue of A with its shape.")
      .def_readonly("eigenvalue", &Mode::eigenvalue,
                    "λ, 1/s; of a sampled system the s = ln(z)/T its eigenvalue z samples.")
      .def_readonly("z", &Mode::z, "A's eigenvalue itself: z of a sampled system, else λ.")
      .def_readonly("natural_frequency", &Mode::natural_frequency, "ωn = |λ|, rad/s.")
      .def_readonly("damping_ratio", &Mode::damping_ratio, "ζ = −Re λ/|λ| (NaN when λ = 0).")
      .def_readonly("damped_frequency", &Mode::damped_frequency, "|Im λ|, rad/s.")
      .def_property_readonly(
          "shape", [](const Mode& mode) { return to_numpy(mode.shape); },
          "Right eigenvector, unit norm, largest entry real positive.")
      .def("__repr__", [](const Mode& mode) {
        return fmt::format("<momenta.Mode λ = {:.6g}{:+.6g}j, ωn = {:.6g} rad/s, ζ = {:.4g}>",
                           mode.eigenvalue.real(), mode.eigenvalue.imag(), mode.natural_frequency,
                           mode.damping_ratio);
      });
  py::class_<Modes>(m, "Modes", "Every mode of a system, sorted by natural frequency.")
      .def_readonly("modes", &Modes::modes)
      .def_readonly("state_names", &Modes::state_names)
      .def_property_readonly("eigenvalues",
                             [](const Modes& ms) {
                               std::vector<Complex> z;
                               for (const Mode& mode : ms.modes) z.push_back(mode.eigenvalue);
                               return complex_array(z);
                             })
      .def("__len__", [](const Modes& ms) { return ms.modes.size(); })
      .def(
          "_table_cells",
          [](const Modes& ms) {
            ModesTable t = modes_table_cells(ms);
            return py::make_tuple(t.header, t.rows);
          },
          "The repr's table as (header, rows) of text cells, for _repr_html_.")
      .def("__repr__",
           [](const Modes& ms) {
             return fmt::format("<momenta.Modes: {} modes of {} states>\n{}", ms.modes.size(),
                                ms.state_names.size(), modes_table(ms));
           })
      .def("__getitem__", [](const Modes& ms, std::size_t i) {
        if (i >= ms.modes.size()) throw py::index_error("mode index out of range");
        return ms.modes[i];
      });
  m.def(
      "modes",
      [](const py::object& system) {
        if (py::isinstance<StateSpace>(system)) return modes(system.cast<const StateSpace&>());
        if (py::isinstance<LinearModel>(system)) {
          return modes(system.cast<const LinearModel&>().system);
        }
        return modes(matrix_arg(system, "A", -1, -1));
      },
      py::arg("system"), "Modes of ẋ = A x from a StateSpace, a LinearModel or a square matrix A.");

  py::class_<NormalMode>(m, "NormalMode", "An undamped normal mode, K φ = ω² M φ.")
      .def_readonly("squared_frequency", &NormalMode::squared_frequency, "ω², rad²/s².")
      .def_readonly("natural_frequency", &NormalMode::natural_frequency,
                    "ω, rad/s (NaN for a divergent mode).")
      .def_property_readonly(
          "shape", [](const NormalMode& n) { return to_numpy(n.shape); },
          "Mass-normalized φ (φᵀ M φ = 1).");
  py::class_<NormalModes>(m, "NormalModes", "Undamped normal modes, frequencies ascending.")
      .def_readonly("modes", &NormalModes::modes)
      .def_readonly("coordinate_names", &NormalModes::coordinate_names)
      .def("__len__", [](const NormalModes& n) { return n.modes.size(); })
      .def("__repr__",
           [](const NormalModes& n) {
             return fmt::format("<momenta.NormalModes: {} modes, K φ = ω² M φ>\n{}", n.modes.size(),
                                normal_modes_table(n));
           })
      .def("__getitem__", [](const NormalModes& n, std::size_t i) {
        if (i >= n.modes.size()) throw py::index_error("mode index out of range");
        return n.modes[i];
      });
  m.def("undamped_modes", &undamped_modes, py::arg("linear"),
        "Normal modes of M δq̈ + K δq = 0 from a LinearModel (an equilibrium of a conservative "
        "model).");
  m.def(
      "normal_modes",
      [](const py::object& M, const py::object& K, std::vector<std::string> names) {
        const MatX mass = matrix_arg(M, "M", -1, -1);
        return normal_modes(mass, matrix_arg(K, "K", mass.rows(), mass.rows()), std::move(names));
      },
      py::arg("M"), py::arg("K"), py::arg("coordinate_names") = std::vector<std::string>{},
      "Normal modes of M q̈ + K q = 0 (the generalized symmetric eigenproblem).");
}

void bind_responses(py::module_& m) {
  py::class_<TransferFunction>(m, "TransferFunction",
                               "G(s) = gain · ∏(s − zeros) / ∏(s − poles) of one pair.")
      .def_readonly("input_name", &TransferFunction::input_name)
      .def_readonly("output_name", &TransferFunction::output_name)
      .def_readonly("gain", &TransferFunction::gain)
      .def_property_readonly("zeros",
                             [](const TransferFunction& g) { return complex_array(g.zeros); })
      .def_property_readonly("poles",
                             [](const TransferFunction& g) { return complex_array(g.poles); })
      .def_property_readonly("cancelled",
                             [](const TransferFunction& g) { return complex_array(g.cancelled); })
      .def_readonly("dc_gain", &TransferFunction::dc_gain)
      .def_property_readonly("relative_degree", &TransferFunction::relative_degree)
      .def("__call__", &TransferFunction::operator(), py::arg("s"), "G(s) from the factors.")
      .def("__repr__", [](const TransferFunction& g) {
        return fmt::format("<momenta.TransferFunction {} → {}: {} zeros, {} poles, K = {:.6g}>",
                           g.input_name, g.output_name, g.zeros.size(), g.poles.size(), g.gain);
      });
  m.def(
      "transfer_function",
      [](const py::object& system, const py::object& input, const py::object& output,
         double cancellation_tolerance) {
        const StateSpace s = state_space_arg(system);
        return transfer_function(s, input_arg(s, input), output_arg(s, output),
                                 cancellation_tolerance);
      },
      py::arg("system"), py::arg("input"), py::arg("output"),
      py::arg("cancellation_tolerance") = kDefaultCancellationTolerance,
      "Zero-pole-gain transfer function of one pair (input and output by name or index), "
      "with pole–zero pairs closer than the relative tolerance cancelled.");

  py::class_<FrequencyResponse>(m, "FrequencyResponse", "Bode data of one pair.")
      .def_readonly("input_name", &FrequencyResponse::input_name)
      .def_readonly("output_name", &FrequencyResponse::output_name)
      .def_property_readonly(
          "frequency", [](const FrequencyResponse& f) { return to_numpy(f.frequency); },
          "ω, rad/s.")
      .def_property_readonly(
          "response", [](const FrequencyResponse& f) { return to_numpy(f.response); },
          "G(jω), complex.")
      .def_property_readonly("magnitude",
                             [](const FrequencyResponse& f) { return to_numpy(f.magnitude); })
      .def_property_readonly("magnitude_db",
                             [](const FrequencyResponse& f) { return to_numpy(f.magnitude_db); })
      .def_property_readonly(
          "phase_deg", [](const FrequencyResponse& f) { return to_numpy(f.phase_deg); },
          "Unwrapped phase, degrees.")
      .def("__repr__", [](const FrequencyResponse& f) {
        const Eigen::Index n = f.frequency.size();
        if (n == 0) {
          return fmt::format("<momenta.FrequencyResponse {} → {}: no frequencies>", f.input_name,
                             f.output_name);
        }
        Eigen::Index peak = 0;
        f.magnitude.maxCoeff(&peak);
        return fmt::format(
            "<momenta.FrequencyResponse {} → {}: {} frequencies from {} to {} rad/s; peak {} dB at "
            "{} rad/s, phase {}° to {}°>",
            f.input_name, f.output_name, n, number_text(f.frequency[0], 4),
            number_text(f.frequency[n - 1], 4), number_text(f.magnitude_db[peak], 4),
            number_text(f.frequency[peak], 4), number_text(f.phase_deg[0], 4),
            number_text(f.phase_deg[n - 1], 4));
      });
  m.def(
      "bode",
      [](const py::object& system, const py::object& input, const py::object& output,
         const py::object& frequencies, double omega_min, double omega_max, std::size_t points) {
        const StateSpace s = state_space_arg(system);
        if (!frequencies.is_none()) {
          ArgStorage storage;
          return frequency_response(s, input_arg(s, input), output_arg(s, output),
                                    VecX(vector_arg(frequencies, "frequencies", -1, "", storage)));
        }
        return frequency_response(s, input_arg(s, input), output_arg(s, output), omega_min,
                                  omega_max, points);
      },
      py::arg("system"), py::arg("input"), py::arg("output"), py::kw_only(),
      py::arg("frequencies") = py::none(), py::arg("omega_min") = 0.01,
      py::arg("omega_max") = 100.0, py::arg("points") = 200,
      "Bode data of one pair at the given frequencies (rad/s) or on a log grid from omega_min to "
      "omega_max.");

  py::class_<Crossing>(m, "Crossing", "One crossover: its frequency and the margin it gives.")
      .def_readonly("frequency", &Crossing::frequency, "ω, rad/s.")
      .def_readonly("margin", &Crossing::margin,
                    "GM (a factor) at a phase crossover, PM (degrees) at a gain crossover.");
  py::class_<StabilityMargins>(
      m, "StabilityMargins",
      "Gain and phase margins of a pair as a negative unity-feedback loop L = G "
      "(docs/analysis.md).")
      .def_readonly("gain_margin", &StabilityMargins::gain_margin, "factor; inf without one")
      .def_readonly("gain_margin_db", &StabilityMargins::gain_margin_db, "dB")
      .def_readonly("phase_crossover", &StabilityMargins::phase_crossover, "ω_pc, rad/s (nan)")
      .def_readonly("phase_margin_deg", &StabilityMargins::phase_margin_deg,
                    "degrees; inf without one")
      .def_readonly("gain_crossover", &StabilityMargins::gain_crossover, "ω_gc, rad/s (nan)")
      .def_readonly("phase_crossovers", &StabilityMargins::phase_crossovers)
      .def_readonly("gain_crossovers", &StabilityMargins::gain_crossovers)
      .def("__repr__", [](const StabilityMargins& s) {
        return fmt::format(
            "<momenta.StabilityMargins GM {:.6g} ({:.4g} dB) at {:.6g} rad/s, PM {:.6g}° at "
            "{:.6g} rad/s>",
            s.gain_margin, s.gain_margin_db, s.phase_crossover, s.phase_margin_deg,
            s.gain_crossover);
      });
  m.def(
      "margins",
      [](const py::object& system, const py::object& input, const py::object& output,
         double omega_min, double omega_max, std::size_t points) {
        const StateSpace s = state_space_arg(system);
        return stability_margins(s, input_arg(s, input), output_arg(s, output), omega_min,
                                 omega_max, points);
      },
      py::arg("system"), py::arg("input"), py::arg("output"), py::kw_only(),
      py::arg("omega_min") = 0.01, py::arg("omega_max") = 100.0, py::arg("points") = 2000,
      "Gain and phase margins of one pair taken as the loop L = G of a negative unity-feedback "
      "loop, with their crossover frequencies, over omega_min .. omega_max rad/s.");

  py::class_<NyquistCount>(m, "NyquistCount", R"doc(
Nyquist's criterion Z = N + P for a pair as a negative unity-feedback loop L = G
(docs/analysis.md): `encirclements` N (clockwise, of −1, counted along the contour),
`open_loop_unstable` P and `closed_loop_unstable` Z (poles in the right half-plane, or outside the
unit circle when sampled), `boundary_poles` (gone round), `through_critical_point`.)doc")
      .def_readonly("encirclements", &NyquistCount::encirclements)
      .def_readonly("open_loop_unstable", &NyquistCount::open_loop_unstable)
      .def_readonly("boundary_poles", &NyquistCount::boundary_poles)
      .def_readonly("closed_loop_unstable", &NyquistCount::closed_loop_unstable)
      .def_readonly("through_critical_point", &NyquistCount::through_critical_point)
      .def_readonly("sample_time", &NyquistCount::sample_time)
      .def("__repr__", [](const NyquistCount& c) {
        if (c.through_critical_point)
          return std::string("<momenta.NyquistCount L passes through −1: marginally stable>");
        return fmt::format("<momenta.NyquistCount N = {}, P = {} → Z = {}: {}>", c.encirclements,
                           c.open_loop_unstable, c.closed_loop_unstable,
                           c.closed_loop_unstable == 0 ? "stable" : "unstable");
      });
  m.def(
      "nyquist",
      [](const py::object& system, const py::object& input, const py::object& output) {
        const StateSpace s = state_space_arg(system);
        return nyquist_count(s, input_arg(s, input), output_arg(s, output));
      },
      py::arg("system"), py::arg("input") = 0, py::arg("output") = 0,
      "Nyquist's count Z = N + P of one pair taken as the loop L = G of a negative unity-feedback "
      "loop: N the clockwise encirclements of −1 along the Nyquist contour, P the open-loop and Z "
      "the closed-loop unstable poles. Its curve is bode(...).response.");

  py::class_<TimeResponse>(m, "TimeResponse", "Response of every output and state to one input.")
      .def_readonly("input_name", &TimeResponse::input_name)
      .def_readonly("output_names", &TimeResponse::output_names)
      .def_readonly("state_names", &TimeResponse::state_names)
      .def_property_readonly(
          "units",
          [](const TimeResponse& r) {
            return units_dict(r.input_name, r.input_unit, r.output_names, r.output_units,
                              r.state_names, r.state_units);
          },
          "Each name's SI unit: the input's, every output's and state's ('m', 'rad/s', 'N'); "
          "empty for a system built from matrices.")
      .def_property_readonly("time", [](const TimeResponse& r) { return to_numpy(r.time); })
      .def_property_readonly(
          "outputs", [](const TimeResponse& r) { return to_numpy(r.outputs); },
          "(samples, outputs).")
      .def_property_readonly(
          "states", [](const TimeResponse& r) { return to_numpy(r.states); }, "(samples, states).")
      .def("__repr__", [](const TimeResponse& r) {
        return fmt::format(
            "<momenta.TimeResponse to '{}': {} samples over {} s of outputs [{}] and {} states>",
            r.input_name, r.time.size(),
            number_text(r.time.size() ? r.time[r.time.size() - 1] : 0.0, 6),
            fmt::join(r.output_names, ", "), r.state_names.size());
      });
  m.def(
      "step_response",
      [](const py::object& system, const py::object& input, std::optional<double> final_time,
         std::optional<std::size_t> samples, double amplitude) {
        const StateSpace s = state_space_arg(system);
        return step_response(s, input_arg(s, input), grid_of(final_time, samples), amplitude);
      },
      py::arg("system"), py::arg("input") = 0, py::kw_only(), py::arg("final_time") = py::none(),
      py::arg("samples") = py::none(), py::arg("amplitude") = 1.0,
      "Step response from x(0) = 0, exact at the samples (zero-order hold); automatic horizon "
      "and sampling unless given.");
  m.def(
      "impulse_response",
      [](const py::object& system, const py::object& input, std::optional<double> final_time,
         std::optional<std::size_t> samples) {
        const StateSpace s = state_space_arg(system);
        return impulse_response(s, input_arg(s, input), grid_of(final_time, samples));
      },
      py::arg("system"), py::arg("input") = 0, py::kw_only(), py::arg("final_time") = py::none(),
      py::arg("samples") = py::none(), "Impulse response, x(t) = e^(At) B.");

  py::class_<StepInfo>(m, "StepInfo", "Step-response figures (MATLAB's stepinfo).")
      .def_readonly("final_value", &StepInfo::final_value)
      .def_readonly("rise_time", &StepInfo::rise_time)
      .def_readonly("settling_time", &StepInfo::settling_time)
      .def_readonly("overshoot", &StepInfo::overshoot, "%.")
      .def_readonly("undershoot", &StepInfo::undershoot, "%.")
      .def_readonly("peak", &StepInfo::peak)
      .def_readonly("peak_time", &StepInfo::peak_time)
      .def("__repr__", [](const StepInfo& i) {
        // As `momenta response --step` says them: a figure that does not exist is "undefined".
        const auto in = [](double x, const char* unit) { return quantity_text(x, 6, unit); };
        return fmt::format(
            "<momenta.StepInfo final value {}, rise time {}, settling time (2 %) {}, overshoot {}, "
            "peak {} at {}>",
            in(i.final_value, ""), in(i.rise_time, " s"), in(i.settling_time, " s"),
            in(i.overshoot, " %"), in(i.peak, ""), in(i.peak_time, " s"));
      });
  m.def(
      "step_info",
      [](const py::object& system, const py::object& input, const py::object& output,
         double settling_band) {
        const StateSpace s = state_space_arg(system);
        return step_info(s, input_arg(s, input), output_arg(s, output), TimeGrid{}, settling_band);
      },
      py::arg("system"), py::arg("input") = 0, py::arg("output") = 0,
      py::arg("settling_band") = 0.02,
      "Rise time (10–90 %), settling time, overshoot and peak of the unit step response, exact: "
      "roots of the analytic response y(t) and its rate, not read off samples "
      "(docs/analysis.md).");
}

}  // namespace

void bind_steady_motion(py::module_& m) {
  py::class_<SteadyMotionModes>(m, "SteadyMotionModes",
                                "The linear analysis of a spinning body's steady motion "
                                "(docs/analysis.md, steady motions).")
      .def_readonly("state_names", &SteadyMotionModes::state_names)
      .def_property_readonly("A", [](const SteadyMotionModes& r) { return to_numpy(r.A); })
      .def_readonly("residual", &SteadyMotionModes::residual)
      .def_readonly("eigenvalues", &SteadyMotionModes::eigenvalues,
                    "Seen from the body, each conjugate pair once; conserved quantities' zeros "
                    "left out.")
      .def_readonly("space_frequencies", &SteadyMotionModes::space_frequencies,
                    "rad/s, seen from space (a body symmetric about its spin axis)")
      .def_readonly("whirl", &SteadyMotionModes::whirl, "'forward' or 'backward', per frequency")
      .def_readonly("stable", &SteadyMotionModes::stable)
      .def_readonly("growth_rate", &SteadyMotionModes::growth_rate, "1/s")
      .def_readonly("verdict", &SteadyMotionModes::verdict);
  m.def(
      "steady_motion",
      [](const ModelHandle& h, const py::object& q, const py::object& v, double t) {
        return steady_motion_modes(spinning_body(h.model(), point_of(h, q, v, t)));
      },
      py::arg("model"), py::kw_only(), py::arg("q") = py::none(), py::arg("v") = py::none(),
      py::arg("t") = 0.0,
      "The steady motion of a model's one spinning body (a spherical or free joint) at its "
      "initial state (or q, v), in the variables where it is an equilibrium (ω and the vertical "
      "in the body frame): eigenvalues, frequencies seen from space, the stability verdict. "
      "Raises InvalidArgument when the state is not steady or the model not one such body.");
}

void bind_joint_steady_motion(py::module_& m) {
  py::class_<SteadyMode>(m, "SteadyMode", "One oscillation of a steady motion.")
      .def_readonly("eigenvalue", &SteadyMode::eigenvalue, "1/s, imaginary part > 0")
      .def_readonly("frequency", &SteadyMode::frequency, "rad/s")
      .def_readonly("whirl", &SteadyMode::whirl, "'forward', 'backward' or 'none'");
  py::class_<JointSteadyMotion>(m, "JointSteadyMotion",
                                "A rotor's steady motion in joint coordinates and the linear "
                                "model about it, its turning positions left out (docs/analysis.md, "
                                "steady motions).")
      .def_readonly("turning", &JointSteadyMotion::turning_names, "the turning coordinates")
      .def_readonly("speed", &JointSteadyMotion::speed, "the first one's rate, rad/s")
      .def_property_readonly("spin_axis",
                             [](const JointSteadyMotion& s) { return to_numpy(s.spin_axis_W); })
      .def_readonly("residual", &JointSteadyMotion::residual)
      .def_readonly("cyclic_residual", &JointSteadyMotion::cyclic_residual)
      .def_readonly("full", &JointSteadyMotion::full, "the linearization with every state")
      .def_readonly("reduced", &JointSteadyMotion::reduced, "without the turning positions")
      .def_readonly("modes", &JointSteadyMotion::modes, "ascending frequency, with their whirl")
      .def_readonly("stable", &JointSteadyMotion::stable)
      .def_readonly("growth_rate", &JointSteadyMotion::growth_rate, "1/s");
  m.def(
      "joint_steady_motion",
      [](const ModelHandle& h, std::vector<std::string> inputs, std::vector<std::string> outputs,
         const py::object& q, const py::object& v, double t) {
        LinearizationOptions options;
        options.inputs = std::move(inputs);
        options.outputs = std::move(outputs);
        options.output_specs = h.file->outputs;
        return joint_steady_motion(h.model(), point_of(h, q, v, t), options);
      },
      py::arg("model"), py::kw_only(), py::arg("inputs") = std::vector<std::string>{},
      py::arg("outputs") = std::vector<std::string>{}, py::arg("q") = py::none(),
      py::arg("v") = py::none(), py::arg("t") = 0.0,
      "A rotor turning at constant speed on its joint while everything else rests (its initial "
      "state, or q, v), checked to be a steady motion with a cyclic angle, and linearized "
      "without that angle (Routh): as `momenta linearize/modes/response --about steady`. "
      "Raises InvalidArgument naming why a state is not one.");
}

void bind_steady_precession(py::module_& m) {
  py::class_<SteadyPrecession>(m, "SteadyPrecession",
                               "A symmetric top's steady precession at its tilt and spin "
                               "(docs/analysis.md, steady motions).")
      .def_readonly("tilt", &SteadyPrecession::tilt, "θ from the upward vertical, rad")
      .def_readonly("spin", &SteadyPrecession::spin, "ω₃, rad/s")
      .def_readonly("I1", &SteadyPrecession::I1)
      .def_readonly("I3", &SteadyPrecession::I3)
      .def_readonly("mgl", &SteadyPrecession::mgl)
      .def_readonly("slow", &SteadyPrecession::slow, "the slow precession root, rad/s")
      .def_readonly("fast", &SteadyPrecession::fast, "the fast precession root, rad/s")
      .def_readonly("minimum_spin", &SteadyPrecession::minimum_spin)
      .def_readonly("critical_spin", &SteadyPrecession::critical_spin,
                    "the sleeping top's, 2√(I₁ m g l)/I₃")
      .def_readonly("gyroscopic", &SteadyPrecession::gyroscopic, "m g l / (I₃ ω₃)")
      .def_readonly("gyroscopic_error", &SteadyPrecession::gyroscopic_error)
      .def_readonly("slow_nutation", &SteadyPrecession::slow_nutation)
      .def_readonly("fast_nutation", &SteadyPrecession::fast_nutation)
      .def_readonly("precession", &SteadyPrecession::precession, "the state's own φ̇")
      .def_readonly("residual", &SteadyPrecession::residual);
  m.def(
      "steady_precession",
      [](const ModelHandle& h, const py::object& q, const py::object& v, double t) {
        return steady_precession(spinning_body(h.model(), point_of(h, q, v, t)));
      },
      py::arg("model"), py::kw_only(), py::arg("q") = py::none(), py::arg("v") = py::none(),
      py::arg("t") = 0.0,
      "A symmetric top's steady precession at the tilt and spin of its initial state (or q, v): "
      "both precession roots, the minimum spin, the gyroscopic approximation, the nutation "
      "frequencies, and how far the state is from the nearer root.");
}

void bind_find_steady_precession(py::module_& m) {
  py::class_<FoundPrecession>(m, "FoundPrecession",
                              "Steady precessions of a symmetric top at a chosen tilt and spin.")
      .def_readonly("roots", &FoundPrecession::roots,
                    "SteadyPrecession: both rates, minimum and critical spin, nutation")
      .def_property_readonly(
          "states",
          [](const FoundPrecession& f) {
            py::list states;
            for (const OperatingPoint& p : f.states) {
              states.append(py::make_tuple(to_numpy(p.q), to_numpy(p.v)));
            }
            return states;
          },
          "(q, v) of the model precessing on each root that exists, slow first");
  m.def(
      "find_steady_precession",
      [](const ModelHandle& h, double tilt, double spin) {
        return find_steady_precession(h.model(), tilt, spin);
      },
      py::arg("model"), py::arg("tilt"), py::arg("spin"),
      "The steady precessions of the model's symmetric top at tilt (rad) and spin ω₃ (rad/s), "
      "as `momenta steady` (which takes degrees).");
}

void bind_rolling_steady_motion(py::module_& m) {
  py::class_<RollingSteadyMotion>(m, "RollingSteadyMotion",
                                  "A steady motion of a body of revolution rolling on a level "
                                  "floor (docs/analysis.md, steady motions of rolling bodies).")
      .def_property_readonly("q", [](const RollingSteadyMotion& r) { return to_numpy(r.point.q); })
      .def_property_readonly("v", [](const RollingSteadyMotion& r) { return to_numpy(r.point.v); })
      .def_readonly("lean", &RollingSteadyMotion::lean,
                    "rad: the disk's plane from the vertical, > 0 towards `lateral`")
      .def_readonly("precession", &RollingSteadyMotion::precession, "Ω about the vertical, rad/s")
      .def_readonly("spin", &RollingSteadyMotion::spin, "ω·e, rad/s")
      .def_readonly("relative_spin", &RollingSteadyMotion::relative_spin,
                    "σ = ω·e − Ω n·e, rad/s (relative to the turning frame)")
      .def_readonly("speed", &RollingSteadyMotion::speed, "of the centre of mass, m/s")
      .def_readonly("radius", &RollingSteadyMotion::radius,
                    "of the centre of mass's circle, m (> 0: centre on the lateral side; inf on "
                    "a straight line)")
      .def_readonly("contact_radius", &RollingSteadyMotion::contact_radius, "m")
      .def_property_readonly("heading",
                             [](const RollingSteadyMotion& r) { return to_numpy(r.heading_W); })
      .def_property_readonly("lateral",
                             [](const RollingSteadyMotion& r) { return to_numpy(r.lateral_W); })
      .def_property_readonly(
          "contact_force", [](const RollingSteadyMotion& r) { return to_numpy(r.contact_force); },
          "the floor's force on the body: normal, longitudinal, lateral (N)")
      .def_readonly("residual", &RollingSteadyMotion::residual);
  py::class_<RollingSteadyModes>(m, "RollingSteadyModes",
                                 "The disturbed motion about a rolling body's steady motion, "
                                 "seen from its turning frame.")
      .def_readonly("motion", &RollingSteadyModes::motion)
      .def_readonly("reduced", &RollingSteadyModes::reduced, "ẋ = A x (StateSpace, A only)")
      .def_readonly("eigenvalues", &RollingSteadyModes::eigenvalues,
                    "the wobbles (each conjugate pair once), ascending |λ|")
      .def_readonly("circle_shift", &RollingSteadyModes::circle_shift,
                    "±iΩ: the circle displaced (a neighbouring steady motion)")
      .def_readonly("zero_eigenvalues", &RollingSteadyModes::zero_eigenvalues)
      .def_readonly("stable", &RollingSteadyModes::stable)
      .def_readonly("growth_rate", &RollingSteadyModes::growth_rate, "1/s");
  m.def(
      "find_rolling_steady_motions",
      [](const ModelHandle& h, std::optional<double> lean, std::optional<double> speed,
         std::optional<double> radius, std::optional<double> precession,
         std::optional<double> spin) {
        std::vector<std::pair<RollingCondition, double>> given;
        if (speed) given.emplace_back(RollingCondition::speed, *speed);
        if (radius) given.emplace_back(RollingCondition::radius, *radius);
        if (precession) given.emplace_back(RollingCondition::precession, *precession);
        if (spin) given.emplace_back(RollingCondition::spin, *spin);
        if (given.size() != 1) {
          throw InvalidArgument(fmt::format(
              "find_rolling_steady_motions: give exactly one of speed, radius, precession or "
              "spin ({} given)",
              given.size()));
        }
        return find_rolling_steady_motions(h.model(), lean, given[0].first, given[0].second);
      },
      py::arg("model"), py::kw_only(), py::arg("lean") = py::none(), py::arg("speed") = py::none(),
      py::arg("radius") = py::none(), py::arg("precession") = py::none(),
      py::arg("spin") = py::none(),
      "The steady motions of the model's rolling body at a lean (rad; none on a pivot) and one of "
      "speed (m/s), radius (m; math.inf for a straight line), precession or spin (rad/s): slow "
      "then fast, as `momenta steady` (which takes degrees).");
  m.def(
      "rolling_steady_modes",
      [](const ModelHandle& h, const std::optional<RollingSteadyMotion>& motion,
         const py::object& q, const py::object& v, double t) {
        return rolling_steady_modes(
            h.model(), motion ? *motion : rolling_steady_motion(h.model(), point_of(h, q, v, t)));
      },
      py::arg("model"), py::arg("motion") = py::none(), py::kw_only(), py::arg("q") = py::none(),
      py::arg("v") = py::none(), py::arg("t") = 0.0,
      "The disturbed motion about a steady motion of the model's rolling body (one found, or the "
      "initial state or q, v, checked to be steady): wobble eigenvalues, the displaced circle's, "
      "stability; as `momenta modes --about steady`.");
}

void bind_campbell(py::module_& m) {
  py::class_<CampbellPoint>(m, "CampbellPoint", "One speed of a Campbell diagram.")
      .def_readonly("speed", &CampbellPoint::speed, "rad/s")
      .def_readonly("frequencies", &CampbellPoint::frequencies, "whirl frequencies, rad/s")
      .def_readonly("whirl", &CampbellPoint::whirl, "'backward' / 'forward', per frequency")
      .def_readonly("stable", &CampbellPoint::stable);
  py::class_<CriticalSpeed>(m, "CriticalSpeed", "A forward whirl on the 1× line.")
      .def_readonly("speed", &CriticalSpeed::speed, "rad/s")
      .def_readonly("whirl", &CriticalSpeed::whirl);
  py::class_<CampbellDiagram>(m, "CampbellDiagram", "Whirl frequencies against spin speed.")
      .def_readonly("points", &CampbellDiagram::points)
      .def_readonly("critical_speeds", &CampbellDiagram::critical_speeds);
  m.def(
      "campbell_diagram",
      [](const ModelHandle& h, double speed_from, double speed_to, int points) {
        return model_campbell_diagram(h.model(), speed_from, speed_to, points).diagram;
      },
      py::arg("model"), py::arg("speed_from"), py::arg("speed_to"), py::arg("points") = 41,
      "The Campbell diagram of the model's rotor — one body on a ball or free joint, or a rotor "
      "turning on its joint — from speed_from to speed_to (rad/s), as `momenta campbell` (which "
      "takes rev/min).");
}

void bind_operating_point(py::module_& m) {
  py::class_<LinearAnalysis>(m, "LinearAnalysis", R"doc(
A linear analysis about an operating point chosen as the command line's --about and the report's
linear panel choose it (docs/analysis.md, operating points): `kind` ('joint_coordinates',
'joint_steady', 'rolling_steady', 'spinning_body', 'steady_precession'), `about` (the sentence
saying what it was taken about, and with 'auto' why), `linear` (the LinearModel whose poles and
modes it shows: linearize()'s, a steady motion's reduced one, Euler–Poisson's A, or the nutation
about a precession), `shape_to_tangent` (nv × states: how a mode's shape moves the joints), the
initial state's `largest_acceleration` and `largest_speed`, and what each kind found:
`equilibrium`, `joint_steady`, `rolling_steady`, `spinning_modes`, `precession` (None where not
that kind).)doc")
      .def_property_readonly(
          "kind", [](const LinearAnalysis& r) { return linear_analysis_kind_name(r.kind); })
      .def_readonly("about", &LinearAnalysis::about)
      .def_readonly("linear", &LinearAnalysis::linear)
      .def_property_readonly("shape_to_tangent",
                             [](const LinearAnalysis& r) { return to_numpy(r.shape_to_tangent); })
      .def_readonly("largest_acceleration", &LinearAnalysis::largest_acceleration)
      .def_readonly("largest_speed", &LinearAnalysis::largest_speed)
      .def_readonly("equilibrium", &LinearAnalysis::equilibrium)
      .def_readonly("joint_steady", &LinearAnalysis::joint_steady)
      .def_readonly("rolling_steady", &LinearAnalysis::rolling_steady)
      .def_readonly("spinning_modes", &LinearAnalysis::spinning_modes)
      .def_readonly("precession", &LinearAnalysis::precession)
      .def_property_readonly("has_channels", &LinearAnalysis::has_channels)
      .def("__repr__", [](const LinearAnalysis& r) {
        return fmt::format("<momenta.LinearAnalysis about {}: {} states>", r.about,
                           r.linear.system.A().rows());
      });
  m.def(
      "linear_analysis",
      [](const ModelHandle& h, const std::string& about, const std::vector<std::string>& inputs,
         const std::vector<std::string>& outputs, const std::vector<std::string>& independent,
         const py::object& q, const py::object& v, double t) {
        const bool state_given = !q.is_none() || !v.is_none();
        std::optional<OperatingPointChoice> choice = operating_point_choice(about);
        if (about == "given" || (state_given && about == "auto")) {
          choice = OperatingPointChoice::given;
        }
        if (!choice) {
          throw InvalidArgument(fmt::format(
              "about='{}': expected 'auto', 'initial', 'equilibrium', 'steady' or 'given' (with "
              "q= and v=)",
              about));
        }
        if (state_given && *choice != OperatingPointChoice::given) {
          throw InvalidArgument(
              fmt::format("about='{}' starts from the model's initial state: q= and v= are for "
                          "about='given'",
                          about));
        }
        if (*choice == OperatingPointChoice::given && !state_given) {
          throw InvalidArgument("about='given' needs the state: q= (and v=, t=)");
        }
        LinearizationOptions options;
        options.inputs = inputs;
        options.outputs = outputs;
        options.independent = independent;
        if (h.file) options.output_specs = h.file->outputs;
        std::optional<OperatingPoint> given;
        if (state_given) given = point_of(h, q, v, t);
        return linear_analysis_about(h.model(), *choice, options, given, "the given state");
      },
      py::arg("model"), py::arg("about") = "auto", py::kw_only(),
      py::arg("inputs") = std::vector<std::string>{},
      py::arg("outputs") = std::vector<std::string>{},
      py::arg("independent") = std::vector<std::string>{}, py::arg("q") = py::none(),
      py::arg("v") = py::none(), py::arg("t") = 0.0,
      R"doc(The linear analysis about the operating point `about` names — 'auto' (the initial state
at rest; where it moves, its steady motion if it is one, else the static equilibrium found from
it), 'initial', 'equilibrium', 'steady', or 'given' with q= (and v=, t=) — chosen by the same rule
as `momenta modes --about` and the report's linear panel. Returns a LinearAnalysis. Raises
InvalidArgument when the choice does not apply (naming why), NumericalError when no equilibrium
is found.)doc");
}

void bind_analysis(py::module_& m) {
  bind_state_space(m);
  bind_linearization(m);
  bind_modes(m);
  bind_responses(m);
  bind_steady_motion(m);
  bind_joint_steady_motion(m);
  bind_steady_precession(m);
  bind_find_steady_precession(m);
  bind_rolling_steady_motion(m);
  bind_campbell(m);
  bind_operating_point(m);
}

}  // namespace momenta::python
