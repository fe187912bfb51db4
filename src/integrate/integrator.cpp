#include "momenta/integrate/integrator.hpp"

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/integrate/symplectic_euler.hpp"

namespace momenta::integrate {

const std::vector<std::string_view>& integrator_names() {
  static const std::vector<std::string_view> names = {"rk4", "symplectic_euler", "dopri5"};
  return names;
}

std::unique_ptr<Integrator> make_integrator(std::string_view name, const Tolerances& tolerances) {
  if (name == "rk4") return std::make_unique<RungeKutta4>();
  if (name == "symplectic_euler") return std::make_unique<SymplecticEuler>();
  if (name == "dopri5") return std::make_unique<DormandPrince5>(tolerances);
  const auto& names = integrator_names();
  throw InvalidArgument(fmt::format("unknown integrator '{}'{}; known: {}", name,
                                    did_you_mean(name, names), fmt::join(names, ", ")));
}

}  // namespace momenta::integrate
