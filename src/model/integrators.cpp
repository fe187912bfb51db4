#include "momenta/model/integrators.hpp"

#include <array>
#include <vector>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"

namespace momenta::model {
namespace {

constexpr std::string_view kAnyModel = "any model";
constexpr std::string_view kOneRigidBody =
    "one body on a free joint (gravity allowed), or on a spherical joint under gravity (a heavy "
    "top); no force elements or joint damping";

constexpr std::array<IntegratorInfo, 9> kIntegrators = {{
    {"rk4", IntegratorFamily::general, 4, false, kAnyModel,
     "classic fourth-order Runge–Kutta, fixed step (Munthe-Kaas form on rotations)"},
    {"symplectic_euler", IntegratorFamily::general, 1, false, kAnyModel,
     "semi-implicit Euler: v ← v + h a(q, v), q ← q ⊕ h v; symplectic for separable systems"},
    {"dopri5", IntegratorFamily::general, 5, true, kAnyModel,
     "Dormand–Prince 5(4), adaptive step under rtol/atol, dense output"},
    {"bdf", IntegratorFamily::general, 5, true, kAnyModel,
     "variable-order BDF (1–5) of SUNDIALS CVODE for stiff models, adaptive under rtol/atol, "
     "Newton's method on a difference-quotient Jacobian"},
    {"sdirk3", IntegratorFamily::general, 3, false, kAnyModel,
     "L-stable singly diagonally implicit Runge–Kutta of order 3 (Alexander 1977), fixed step: "
     "stable at any step on stiff models"},
    {"splitting", IntegratorFamily::rigid_body, 2, false, kOneRigidBody,
     "Strang splitting into exact rotations about the principal axes (Dullweber, Leimkuhler & "
     "McLachlan 1997); symplectic, H to round-off"},
    {"splitting4", IntegratorFamily::rigid_body, 4, false, kOneRigidBody,
     "Suzuki's fourth-order composition of the same splitting (Suzuki 1990)"},
    {"lie_group", IntegratorFamily::rigid_body, 2, false, kOneRigidBody,
     "Lie group variational integrator (Lee, Leok & McClamroch 2005)"},
    {"exact", IntegratorFamily::rigid_body, kExactOrder, false,
     "a torque-free body (free joint, or spherical joint with the centre of mass at the pivot or "
     "no gravity)",
     "the exact torque-free motion in elliptic functions; no truncation error"},
}};

}  // namespace

std::span<const IntegratorInfo> integrators() { return kIntegrators; }

const IntegratorInfo* find_integrator(std::string_view name) {
  for (const IntegratorInfo& info : kIntegrators) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

const IntegratorInfo& integrator_info(std::string_view name) {
  if (const IntegratorInfo* info = find_integrator(name)) return *info;
  std::vector<std::string_view> names;
  for (const IntegratorInfo& info : kIntegrators) names.push_back(info.name);
  throw InvalidArgument(fmt::format("unknown integrator '{}'{}; known: {}", name,
                                    did_you_mean(name, names), integrator_name_list()));
}

std::string integrator_name_list() {
  std::vector<std::string_view> names;
  for (const IntegratorInfo& info : kIntegrators) names.push_back(info.name);
  return fmt::format("{}", fmt::join(names, ", "));
}

}  // namespace momenta::model
