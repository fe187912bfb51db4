// momenta.sweep: a sweep file's runs from Python, on every core (docs/sweeps.md, docs/python.md).

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "momenta/io/sweep_file.hpp"
#include "momenta/sweep/execution.hpp"

namespace momenta::python {

namespace {

// The outcomes as columns: run, each parameter and metric (NaN where undefined), ok, message.
py::dict sweep_columns(const sweep::SweepRunner& runner,
                       const std::vector<sweep::RunOutcome>& outcomes) {
  const std::size_t n = outcomes.size();
  const auto column = [&](auto value_of) {
    py::array_t<double> a(static_cast<py::ssize_t>(n));
    auto view = a.mutable_unchecked<1>();
    for (std::size_t r = 0; r < n; ++r) view(static_cast<py::ssize_t>(r)) = value_of(outcomes[r]);
    return a;
  };
  py::dict result;
  py::array_t<long> runs(static_cast<py::ssize_t>(n));
  py::array_t<bool> ok(static_cast<py::ssize_t>(n));
  py::list messages;
  for (std::size_t r = 0; r < n; ++r) {
    runs.mutable_at(static_cast<py::ssize_t>(r)) = outcomes[r].run;
    ok.mutable_at(static_cast<py::ssize_t>(r)) = outcomes[r].ok;
    messages.append(outcomes[r].message);
  }
  result["run"] = runs;
  for (std::size_t p = 0; p < runner.parameter_columns().size(); ++p) {
    result[py::str(runner.parameter_columns()[p])] =
        column([p](const sweep::RunOutcome& o) { return o.parameters[p]; });
  }
  for (std::size_t m = 0; m < runner.metric_columns().size(); ++m) {
    result[py::str(runner.metric_columns()[m])] =
        column([m](const sweep::RunOutcome& o) { return o.metrics[m]; });
  }
  result["ok"] = ok;
  result["message"] = messages;
  return result;
}

}  // namespace

void bind_sweep(py::module_& m) {
  m.def(
      "sweep",
      [](const std::filesystem::path& path, std::optional<int> threads) {
        const sweep::SweepRunner runner(io::read_sweep_file(path));
        std::vector<long> runs(static_cast<std::size_t>(runner.run_count()));
        for (std::size_t k = 0; k < runs.size(); ++k) runs[k] = static_cast<long>(k);
        std::vector<sweep::RunOutcome> outcomes;
        outcomes.reserve(runs.size());
        {
          py::gil_scoped_release release;
          sweep::run_in_order(runner, runs, threads.value_or(sweep::default_thread_count()),
                              [&](sweep::RunOutcome&& o) { outcomes.push_back(std::move(o)); });
        }
        return sweep_columns(runner, outcomes);
      },
      py::arg("path"), py::arg("threads") = py::none(),
      "Every run of the sweep file at `path` (docs/sweeps.md) on `threads` threads (default: every "
      "core), as columns: 'run', each parameter and metric (float64 arrays, NaN where a run does "
      "not define it), 'ok' (bool array) and 'message' (list). The numbers are those `momenta "
      "sweep` writes, bit for bit; pandas.DataFrame(result) makes a table of them.");
}

}  // namespace momenta::python
