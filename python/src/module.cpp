// momenta._core: the compiled part of the `momenta` Python package (python/momenta/ re-exports
// it with the Python-side conveniences).

#include "bindings.hpp"

PYBIND11_MODULE(_core, m) {
  using namespace momenta::python;
  m.doc() = "momenta: model, simulate and analyse mechanical systems (compiled core)";
  m.attr("__version__") = MOMENTA_VERSION;
  // Whether equations() and symbolic_transfer_function() are here (MOMENTA_WITH_SYMBOLIC: they
  // link GiNaC, GPL-2.0-or-later; THIRD-PARTY-NOTICES.md).
  m.attr("with_symbolic") = static_cast<bool>(MOMENTA_WITH_SYMBOLIC);
  bind_errors(m);
  py::module_ inertia = m.def_submodule("inertia", "Mass properties (momenta.inertia).");
  bind_inertia(inertia);
  bind_balancing(inertia);
  bind_model(m);
  bind_state_derivative(m);
  bind_dynamics(m);
  bind_simulation(m);
  bind_analysis(m);
  bind_control(m);
  bind_sweep(m);
  bind_mechanics(m);
  bind_identify(m);
}
