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
    throw InvalidArgument(
        fmt::format("{}: tolerances must be positive and finite, got rtol = {}, atol = {}",
                    integrator, tolerances.relative, tolerances.absolute));
  }
  if (tolerances.relative < kSmallestRelativeTolerance ||
      tolerances.absolute < kSmallestAbsoluteTolerance) {
    throw InvalidArgument(fmt::format(
        "{}: rtol = {:.3g}, atol = {:.3g} ask for more than double precision holds: rtol must "
        "be at least {:.1e} (100 ε) and atol at least {:.0e}",
        integrator, tolerances.relative, tolerances.absolute, kSmallestRelativeTolerance,
        kSmallestAbsoluteTolerance));
  }
}

void Integrator::interpolate(const SecondOrderSystem&, double, State&) const {
  throw std::logic_error(fmt::format("{} has no dense output: use StepInterpolant", name()));
}

const std::vector<std::string_view>& integrator_names() {
  static const std::vector<std::string_view> names = {"rk4", "symplectic_euler", "dopri5", "bdf",
                                                      "sdirk3"};
  return names;
}

std::unique_ptr<Integrator> make_integrator(std::string_view name, const Tolerances& tolerances) {
  if (name == "rk4") return std::make_unique<RungeKutta4>();
  if (name == "symplectic_euler") return std::make_unique<SymplecticEuler>();
  if (name == "dopri5") return std::make_unique<DormandPrince5>(tolerances);
  if (name == "bdf") return std::make_unique<Bdf>(tolerances);
  if (name == "sdirk3") return std::make_unique<Sdirk3>();  // its own Newton test
  const auto& names = integrator_names();
  throw InvalidArgument(fmt::format("unknown integrator '{}'{}; known: {}", name,
                                    did_you_mean(name, names), fmt::join(names, ", ")));
}

}  // namespace momenta::integrate
