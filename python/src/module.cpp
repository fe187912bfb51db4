// momenta._core: the compiled part of the `momenta` Python package (python/momenta/ re-exports
// it with the Python-side conveniences).

#include "bindings.hpp"

PYBIND11_MODULE(_core, m) {
  using namespace momenta::python;
  m.doc() = "momenta: model, simulate and analyse mechanical systems (compiled core)";
  m.attr("__version__") = MOMENTA_VERSION;
  bind_errors(m);
  py::module_ inertia = m.def_submodule("inertia", "Mass properties (momenta.inertia).");
  bind_inertia(inertia);
  bind_balancing(inertia);
  bind_model(m);
  bind_dynamics(m);
  bind_simulation(m);
  bind_analysis(m);
  bind_sweep(m);
  bind_mechanics(m);
}
