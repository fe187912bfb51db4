// The build without SUNDIALS (the report's in-page engine, wasm/): `bdf` is refused when it is
// chosen, by name and with the integrators that build has for stiff models. bdf.cpp is the
// integrator itself.

#include "momenta/common/error.hpp"
#include "momenta/integrate/bdf.hpp"

namespace momenta::integrate {

namespace {

[[noreturn]] void refuse() {
  throw InvalidArgument(
      "integrator 'bdf' (SUNDIALS CVODE) is not in the report's in-page engine; for a stiff "
      "model choose 'sdirk3' (implicit, L-stable), or run it with the momenta command");
}

}  // namespace

struct Bdf::Solver {};

Bdf::Bdf(const Tolerances& tolerances) : tolerances_(tolerances) { refuse(); }
Bdf::~Bdf() = default;
void Bdf::initialize(SecondOrderSystem&, const State&) { refuse(); }
double Bdf::step(SecondOrderSystem&, State&, double) { refuse(); }

}  // namespace momenta::integrate
