#pragma once
// The integrator registry: every integrator a model can be run with, by name, with its order and
// what it applies to. The one list every front end asks — the model-file reader, the command
// line, the docs' table (docs/integrators.md) and the factories (system/integrators.hpp) — so a
// name accepted in one place is accepted everywhere.

#include <limits>
#include <span>
#include <string>
#include <string_view>

namespace momenta::model {

/// Which implementation family an integrator belongs to.
enum class IntegratorFamily {
  general,     ///< integrate/: any model (Runge–Kutta, symplectic Euler, Dormand–Prince)
  rigid_body,  ///< system/rigid_body_integrator.hpp: one body on a free or spherical joint
};

/// What order() reports for "exact": it has no truncation error.
inline constexpr int kExactOrder = std::numeric_limits<int>::max();

struct IntegratorInfo {
  std::string_view name;  ///< "rk4", "dopri5", "splitting", ...
  IntegratorFamily family;
  int order;                    ///< order of accuracy; kExactOrder for the exact flow
  bool adaptive;                ///< chooses its own step under rtol/atol
  std::string_view applies_to;  ///< which models, in words
  std::string_view summary;     ///< one line: the method and its reference
};

/// Every integrator, in the order the docs list them.
std::span<const IntegratorInfo> integrators();

/// The integrator with that name, or nullptr.
const IntegratorInfo* find_integrator(std::string_view name);

/// The integrator with that name; throws InvalidArgument "unknown integrator 'x'; did you mean
/// ...? known: rk4, ..." otherwise.
const IntegratorInfo& integrator_info(std::string_view name);

/// "rk4, symplectic_euler, dopri5, bdf, sdirk3, splitting, splitting4, lie_group, exact".
std::string integrator_name_list();

}  // namespace momenta::model
