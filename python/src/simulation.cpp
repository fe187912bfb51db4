// momenta.simulate: a run of a model, as `momenta simulate` makes it (the same merge of keyword
// arguments over the model file's `simulation:` section, the same columns and audit), returned
// as a SimulationResult whose table is one numpy array.

#include <Python.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <atomic>
#include <memory>
#include <optional>

#include "bindings.hpp"
#include "model_handle.hpp"
#include "momenta/common/error.hpp"
#include "momenta/model/event_spec.hpp"
#include "momenta/report/report.hpp"
#include "momenta/simulate/run_request.hpp"
#include "momenta/simulate/simulation.hpp"

namespace momenta::python {
namespace {

// Rows appended to one contiguous buffer (row-major), handed to numpy without a copy.
class BufferSink final : public simulate::RowSink {
 public:
  explicit BufferSink(std::size_t expected_rows) : expected_rows_(expected_rows) {}
  void begin(std::span<const std::string> columns) override {
    columns_.assign(columns.begin(), columns.end());
    values_->reserve(expected_rows_ * columns_.size());
  }
  void row(std::span<const double> values) override {
    values_->insert(values_->end(), values.begin(), values.end());
  }
  const std::vector<std::string>& columns() const { return columns_; }

  // The table as a rows × columns array owning the buffer.
  py::array_t<double> release() {
    auto* owned = values_.release();
    py::capsule free_when_done(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
    const auto cols = static_cast<py::ssize_t>(columns_.size());
    const py::ssize_t rows = cols ? static_cast<py::ssize_t>(owned->size()) / cols : 0;
    return py::array_t<double>({rows, cols}, {cols * sizeof(double), sizeof(double)}, owned->data(),
                               free_when_done);
  }

 private:
  std::size_t expected_rows_;
  std::vector<std::string> columns_;
  std::unique_ptr<std::vector<double>> values_ = std::make_unique<std::vector<double>>();
};

struct SimulationResult {
  std::shared_ptr<const io::ModelFile> file;  // the model run, for the report
  std::vector<std::string> columns;
  std::vector<std::string> units;  // each column's, as Simulation::column_units
  py::array_t<double> data;
  simulate::SimulationSummary summary;
  simulate::SimulationOptions options;
  std::string thinning_note;
  std::string stop_reason;  // the NumericalError's message when the run stopped early

  std::size_t column_index(const std::string& name) const {
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (columns[i] == name) return i;
    }
    throw py::key_error(
        fmt::format("no column '{}'; the columns are {}", name, fmt::join(columns, ", ")));
  }
  // Column i as a view of the table (no copy).
  py::array column(std::size_t i) const {
    return data[py::make_tuple(py::slice(py::none(), py::none(), py::none()), i)];
  }
};

py::list audit_of(const simulate::SimulationSummary& s) {
  py::list out;
  for (const simulate::AuditEntry& e : s.audit) {
    py::dict d;
    d["name"] = e.name;
    d["initial"] = e.initial;
    d["scale"] = e.scale;
    d["final_drift"] = e.final_drift;
    d["max_drift"] = e.max_drift;
    d["records"] = e.records;
    out.append(d);
  }
  return out;
}

py::dict summary_of(const simulate::SimulationSummary& s) {
  py::dict d;
  d["integrator"] = s.integrator;
  d["order"] = s.order;
  d["adaptive"] = s.adaptive;
  d["step"] = s.step;
  d["t_end"] = s.t_end;
  d["steps"] = s.statistics.steps;
  d["rejected_steps"] = s.statistics.rejected_steps;
  d["evaluations"] = s.statistics.evaluations;
  d["wall_seconds"] = s.wall_seconds;
  d["rows"] = s.rows;
  // What the run tells about stiffness (an explicit method held, or unstable, by it), or None.
  const std::string stiffness = spell_options(simulate::stiffness_note(s), python_spelling);
  d["stiffness"] = stiffness.empty() ? py::object(py::none()) : py::object(py::str(stiffness));
  // What the summary says of a singular initial configuration of the constraints, or None.
  const std::string singular = simulate::singular_start_note(s.initial_state);
  d["singular_start"] = singular.empty() ? py::object(py::none()) : py::object(py::str(singular));
  // The events that happened, in time order: name, condition, time, the quantity's value there
  // and the action (the last is "stop" when one ended the run).
  py::list events;
  for (const simulate::EventOccurrence& e : s.events) {
    py::dict event;
    event["name"] = e.name;
    event["condition"] = e.condition;
    event["time"] = e.time;
    event["value"] = e.value;
    event["action"] = std::string(model::event_action_name(e.action));
    events.append(event);
  }
  d["events"] = events;
  // The joints' stops and the contacts: every impact, rest and release, in time order
  // (simulate/unilaterals.hpp); a contact's has its name under "contact" and an empty "joint".
  py::list stops;
  for (const simulate::StopEvent& e : s.stop_events) {
    py::dict stop;
    stop["kind"] = std::string(simulate::stop_event_kind_name(e.kind));
    stop["joint"] = e.joint;
    stop["contact"] = e.contact;
    stop["stop"] = e.contact.empty() ? (e.upper ? "upper" : "lower") : "";
    stop["time"] = e.time;
    stop["rate_before"] = e.rate_before;
    stop["rate_after"] = e.rate_after;
    stop["impulse"] = e.impulse;
    stop["energy_lost"] = e.energy_lost;
    stop["rest_time"] = e.rest_time;
    // A contact with friction: "sticking" or "sliding" after a rest, stick or slip ("" else), and
    // at a stick or slip the friction sticking needs and the cone's μs N (N) — for a slip in
    // another's impact ("in_impact") the friction impulse and μs P_n (N·s).
    stop["friction"] = std::string(simulate::friction_state_name(e.friction));
    stop["friction_needed"] = e.friction_needed;
    stop["friction_limit"] = e.friction_limit;
    stop["in_impact"] = e.in_impact;
    stops.append(stop);
  }
  d["stops"] = stops;
  return d;
}

// The inputs a Python controller drives: those named, else every input no controller of the
// model drives and no joint follows (Model.input_names less the driven ones).
std::vector<std::string> controller_drives(const model::Model& model,
                                           const std::optional<std::vector<std::string>>& named) {
  if (named) return *named;
  std::vector<std::string> drives;
  for (int s = 0; s < static_cast<int>(model.signals().size()); ++s) {
    if (!model.joint_prescribed_by(s) && !model.is_driven(s))
      drives.push_back(model.signals()[static_cast<std::size_t>(s)].name());
  }
  if (drives.empty()) {
    throw InvalidArgument(
        "simulate(controller=...): the model has no input for it to drive (declare one under "
        "`inputs:`, a force's `signal:` naming it)");
  }
  return drives;
}

// The model with `fn` as the external controller `controller` (model/controller.hpp): u =
// fn(t, q, v), one number per drive (a float for one), held `sample_time` s when positive.
model::Model with_python_controller(const model::Model& model, const py::object& fn,
                                    const std::optional<std::vector<std::string>>& drives,
                                    double sample_time, std::optional<double> u_min,
                                    std::optional<double> u_max) {
  if (!PyCallable_Check(fn.ptr())) {
    throw py::type_error(
        fmt::format("simulate: controller must be a function fn(t, q, v) -> u, "
                    "got {}",
                    std::string(py::str(py::type::of(fn)))));
  }
  model::Controller c;
  c.name = "controller";
  c.kind = model::ControllerKind::external;
  c.drives = controller_drives(model, drives);
  c.sample_time = sample_time;
  if (u_min) c.actuator.min = *u_min;
  if (u_max) c.actuator.max = *u_max;
  const std::size_t m = c.drives.size();
  c.law = std::make_shared<const model::ControlLaw>(
      [fn, m, names = c.drives](double t, const VecX& q, const VecX& v, std::span<double> u) {
        const py::object out = fn(t, to_numpy(q), to_numpy(v));
        const auto values = as_float_array(out, "the controller's u");
        if (values.size() != static_cast<py::ssize_t>(m)) {
          throw InvalidArgument(fmt::format(
              "the controller returned {} number{} at t = {} s; it drives {} ({}): return {}",
              values.size(), values.size() == 1 ? "" : "s", t, m, fmt::join(names, ", "),
              m == 1 ? "one number" : fmt::format("{} numbers in that order", m)));
        }
        std::copy(values.data(), values.data() + m, u.begin());
      });
  return model.with_controller(c);
}

SimulationResult run_simulation(
    const ModelHandle& h, std::optional<double> duration, std::optional<double> dt,
    std::optional<std::string> integrator, std::optional<double> rtol, std::optional<double> atol,
    std::optional<long> every, bool reactions, const std::vector<std::string>& events,
    const std::vector<std::string>& stop_when, const py::object& controller,
    const std::optional<std::vector<std::string>>& drives, double sample_time,
    std::optional<double> u_min, std::optional<double> u_max) {
  if (controller.is_none() && (drives || sample_time != 0.0 || u_min || u_max)) {
    throw InvalidArgument(
        "simulate: drives, sample_time, u_min and u_max describe a controller; pass "
        "controller=fn too");
  }
  // A Python controller: the run is of a copy of the model with it (the model is left as it was).
  std::shared_ptr<const io::ModelFile> file = h.file;
  if (!controller.is_none()) {
    auto with = std::make_shared<io::ModelFile>(*h.file);
    with->model = with_python_controller(h.model(), controller, drives, sample_time, u_min, u_max);
    file = std::move(with);
  }
  simulate::RunRequest request;
  request.settings.duration = duration;
  request.settings.step = dt;
  request.settings.relative_tolerance = rtol;
  request.settings.absolute_tolerance = atol;
  request.settings.integrator = std::move(integrator);
  request.settings.every = every;
  request.reactions = reactions;
  for (const std::string& condition : events) {
    request.settings.events.push_back(model::parse_event_condition(condition));
  }
  for (const std::string& condition : stop_when) {
    request.settings.events.push_back(
        model::parse_event_condition(condition, model::EventAction::stop));
  }
  simulate::ResolvedRun resolved = simulate::resolve_run(request, h.file->simulation);

  // Ctrl-C: Python's signal handler only sets a flag; check it now and then and end the run.
  std::atomic<bool> stop{false};
  resolved.options.stop = &stop;
  resolved.options.progress = [&stop](double) {
    if (PyErr_CheckSignals() != 0) stop = true;
  };
  simulate::Simulation simulation(file->model, file->outputs, resolved.options);

  const double steps = std::ceil(resolved.options.duration / resolved.options.step);
  BufferSink sink(static_cast<std::size_t>(std::min(steps / resolved.options.every + 2, 1e6)));
  SimulationResult result;
  result.file = file;
  result.options = resolved.options;
  result.thinning_note = resolved.thinning_note;
  result.units = simulation.column_units();
  try {
    result.summary = simulation.run(sink);
  } catch (const Interrupted&) {
    throw py::error_already_set();  // the KeyboardInterrupt PyErr_CheckSignals raised
  } catch (const NumericalError& e) {
    // The rows up to the failure travel with the error, as the CLI keeps them in its CSV.
    result.columns = sink.columns();
    result.data = sink.release();
    const auto rows = static_cast<long>(result.data.shape(0));
    result.summary = simulate::summary_of_stopped_run(resolved.options, rows,
                                                      rows ? *result.data.data(rows - 1, 0) : 0.0);
    result.stop_reason = e.what();
    raise_numerical_error(e, py::cast(std::move(result)));
  }
  result.columns = sink.columns();
  result.data = sink.release();
  return result;
}

// The report page of a result, as `momenta simulate --report` writes it; returns the path.
std::filesystem::path write_result_report(const SimulationResult& r,
                                          const std::filesystem::path& path, bool force,
                                          const std::string& about, std::vector<std::string> inputs,
                                          std::vector<std::string> outputs,
                                          const std::optional<std::array<double, 2>>& campbell) {
  report::SimulationRun run;
  run.file = r.file.get();
  run.columns = r.columns;
  run.units = r.units;
  run.options = r.options;
  run.summary = r.summary;
  run.stop_reason = r.stop_reason;
  const auto rows = static_cast<std::size_t>(r.data.shape(0));
  const std::size_t cols = r.columns.size();
  run.rows.reserve(rows);
  for (std::size_t i = 0; i < rows; ++i) {
    const double* row = r.data.data(static_cast<py::ssize_t>(i), 0);
    run.rows.emplace_back(row, row + cols);
  }
  report::LinearSettings linear;
  linear.about = about;
  linear.inputs = std::move(inputs);
  linear.outputs = std::move(outputs);
  linear.campbell = campbell;
  // Refused in Python's words (the library's message names the CLI's --force).
  if (std::filesystem::exists(path) && !force) {
    throw FileError(
        fmt::format("{}: the file exists; pass force=True to overwrite it", path.string()));
  }
  {
    py::gil_scoped_release unlocked;
    report::write_report(path, report::simulation_report_html(run, linear), force);
  }
  return path;
}

}  // namespace

void bind_simulation(py::module_& m) {
  py::class_<SimulationResult>(m, "SimulationResult", R"doc(
The table of a run: one row per recorded step, the columns of `momenta simulate` (time, every
coordinate and speed by its name in model.q_names and model.v_names, energies, H, the model's outputs, reactions, audit.*), as one
(rows, columns) float64 array `data`. result['time'] or result.time gives a column (a view);
result.audit the conservation audit; result.summary what the run did; to_pandas() a DataFrame.)doc")
      .def_readonly("columns", &SimulationResult::columns, "Column names, in order.")
      .def_property_readonly(
          "units",
          [](const SimulationResult& r) {
            py::dict d;
            for (std::size_t i = 0; i < r.columns.size(); ++i)
              d[py::str(r.columns[i])] = r.units[i];
            return d;
          },
          "Each column's SI unit by name: {'time': 's', 'pivot.angle': 'rad', ...}; '1' for a "
          "relative drift.")
      .def_readonly("data", &SimulationResult::data, "The table, (rows, columns).")
      .def_property_readonly(
          "time", [](const SimulationResult& r) { return r.column(0); }, "Times of the rows, s.")
      .def("__getitem__", [](const SimulationResult& r,
                             const std::string& name) { return r.column(r.column_index(name)); })
      .def("__contains__",
           [](const SimulationResult& r, const std::string& name) {
             return std::find(r.columns.begin(), r.columns.end(), name) != r.columns.end();
           })
      .def("__len__", [](const SimulationResult& r) { return r.data.shape(0); })
      .def_property_readonly(
          "audit", [](const SimulationResult& r) { return audit_of(r.summary); },
          "Conservation audit: a list of dicts (name, initial, scale, final_drift, max_drift, "
          "records) for energy, |H|, H and the quaternion norm where each is conserved.")
      .def_property_readonly(
          "summary", [](const SimulationResult& r) { return summary_of(r.summary); },
          "integrator, order, adaptive, step, t_end, steps, rejected_steps, evaluations, "
          "wall_seconds, rows, stiffness (the summary's sentence when an explicit method was held "
          "or made unstable by stiffness, else None).")
      .def_property_readonly(
          "summary_text",
          [](const SimulationResult& r) {
            return simulate::format_summary(r.summary, python_spelling);
          },
          "The summary as `momenta simulate` prints it.")
      .def_readonly("thinning_note", &SimulationResult::thinning_note,
                    "Set when the default row stride thinned a long fixed-step run.")
      .def_readonly("stop_reason", &SimulationResult::stop_reason,
                    "Why the run stopped early (a NumericalError's message); empty when it ran "
                    "to the end.")
      .def("report", &write_result_report, py::arg("path"), py::kw_only(), py::arg("force") = false,
           py::arg("about") = "auto", py::arg("inputs") = std::vector<std::string>{},
           py::arg("outputs") = std::vector<std::string>{}, py::arg("campbell") = py::none(),
           R"doc(Writes the run's HTML report to `path`, the page `momenta simulate --report`
writes (docs/report.md): the 3-D motion, every column plotted, the linear analysis about
`about` ("auto": the initial state where it is at rest, else the equilibrium found from it;
"initial", "equilibrium" or "steady", for the `inputs` and `outputs` named, all when
empty), the Campbell diagram when `campbell` = (from, to) speeds in rad/s is given, and
the summary with its audit verdict; a run stopped by a non-finite state shows the reason at the
top. Joint reactions are drawn when the run recorded them (simulate(..., reactions=True)).
An existing file is kept (FileError) unless force=True. Returns the path.)doc")
      .def("__repr__", [](const SimulationResult& r) {
        return fmt::format("<momenta.SimulationResult: {} rows × {} columns, t = 0 … {} s, {}>",
                           r.data.shape(0), r.columns.size(), r.summary.t_end,
                           r.summary.integrator);
      });

  m.def(
      "with_initial_state",
      [](const ModelHandle& h, const py::object& q, const py::object& v) {
        ArgStorage storage;
        const VecX q0 = vector_arg(q, "q", h.model().nq(), "the model's nq", storage);
        const VecX v0 = vector_arg(v, "v", h.model().nv(), "the model's nv", storage);
        auto file = std::make_shared<io::ModelFile>(*h.file);
        file->model = h.model().with_initial_state(q0, v0);
        return ModelHandle{std::move(file)};
      },
      py::arg("model"), py::arg("q"), py::arg("v"),
      R"doc(The same model starting from q (nq values: coordinates, quaternions for ball and free
joints) and v (nv values) instead of its q0 and v0 — the state `momenta steady --state` writes,
as `momenta simulate --state` takes it. Raises InvalidArgument naming the size expected or the
first non-finite entry.)doc");
  m.def("simulate", &run_simulation, py::arg("model"), py::kw_only(),
        py::arg("duration") = py::none(), py::arg("dt") = py::none(),
        py::arg("integrator") = py::none(), py::arg("rtol") = py::none(),
        py::arg("atol") = py::none(), py::arg("every") = py::none(), py::arg("reactions") = false,
        py::arg("events") = std::vector<std::string>(),
        py::arg("stop_when") = std::vector<std::string>(), py::arg("controller") = py::none(),
        py::arg("drives") = py::none(), py::arg("sample_time") = 0.0, py::arg("u_min") = py::none(),
        py::arg("u_max") = py::none(),
        R"doc(Integrates the model from its initial state, as `momenta simulate` does: keyword
arguments override the model file's `simulation:` section, which overrides the defaults
(duration 10 s, rk4 at dt 1 ms; rtol/atol alone choose dopri5; a fixed-step run longer than
10 000 steps records every n-th so 10 001 rows remain unless `every` is given). integrator: rk4,
symplectic_euler, dopri5, bdf or sdirk3 (stiff models), or a rigid-body method (splitting,
splitting4, lie_group, exact).
reactions=True adds every joint's reaction wrench. events: conditions to watch, each
'QUANTITY < VALUE', '> VALUE' or '= VALUE' on a column ('tension < 0', 'pivot.angle = 0'): each
time one turns true the table gets a row at that time and summary['events'] an entry;
stop_when: the same, and the run ends at the first.
controller: a Python function fn(t, q, v) -> u closing a loop around the mechanism (q of size
nq, v of size nv, as model.q_names and v_names; u one number per input in `drives`, default every
input of the model no controller of its own drives): called at every evaluation of the dynamics
(continuous), or at t = k·sample_time exactly with u held between (zero-order hold, as a model
file's sampled controller), clamped to [u_min, u_max]. The table gains controller.<input>
columns. Exceptions raised in fn end the run and reach the caller as they are.
Raises InvalidArgument for a bad option,
NumericalError when the state stops being finite (naming the time and coordinate),
KeyboardInterrupt on Ctrl-C.)doc");
}

}  // namespace momenta::python
