#include "momenta/integrate/integrator.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/integrate/bdf.hpp"
#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/integrate/sdirk3.hpp"
#include "momenta/integrate/symplectic_euler.hpp"

namespace momenta::integrate {

void check_tolerances(std::string_view integrator, const Tolerances& tolerances) {
  if (!(tolerances.relative > 0.0 && std::isfinite(tolerances.relative)) ||
      !(tolerances.absolute > 0.0 && std::isfinite(tolerances.absolute))) {
    throw InvalidArgument(OptionMessage{
        fmt::format("{}: tolerances must be positive and finite, got ‹relative_tolerance={}›, "
                    "‹absolute_tolerance={}›",
                    integrator, tolerances.relative, tolerances.absolute)});
  }
  if (tolerances.relative < kSmallestRelativeTolerance ||
      tolerances.absolute < kSmallestAbsoluteTolerance) {
    throw InvalidArgument(OptionMessage{fmt::format(
        "{}: ‹relative_tolerance={:.3g}›, ‹absolute_tolerance={:.3g}› ask for more than double "
        "precision holds: the relative tolerance must be at least {:.1e} (100 ε) and the "
        "absolute at least {:.0e}",
        integrator, tolerances.relative, tolerances.absolute, kSmallestRelativeTolerance,
        kSmallestAbsoluteTolerance)});
  }
}

void Integrator::interpolate(const SecondOrderSystem&, double, State&) const {
  throw std::logic_error(fmt::format("{} has no dense output: use StepInterpolant", name()));
}

std::unique_ptr<Integrator> make_integrator(std::string_view name, const Tolerances& tolerances) {
  if (name == "rk4") return std::make_unique<RungeKutta4>();
  if (name == "symplectic_euler") return std::make_unique<SymplecticEuler>();
  if (name == "dopri5") return std::make_unique<DormandPrince5>(tolerances);
  if (name == "bdf") return std::make_unique<Bdf>(tolerances);
  if (name == "sdirk3") return std::make_unique<Sdirk3>();  // its own Newton test
  throw InvalidArgument(
      fmt::format("integrate::make_integrator: '{}' is none of rk4, symplectic_euler, dopri5, "
                  "bdf, sdirk3 (system::make_integrator builds every integrator of the registry, "
                  "model/integrators.hpp)",
                  name));
}

}  // namespace momenta::integrate
