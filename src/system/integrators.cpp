#include "momenta/system/integrators.hpp"

#include "momenta/model/integrators.hpp"
#include "momenta/system/rigid_body_integrator.hpp"

namespace momenta::system {

std::unique_ptr<integrate::Integrator> make_integrator(std::string_view name,
                                                       const integrate::Tolerances& tolerances) {
  const model::IntegratorInfo& info = model::integrator_info(name);
  if (info.family == model::IntegratorFamily::rigid_body) return make_rigid_body_integrator(name);
  return integrate::make_integrator(name, tolerances);
}

}  // namespace momenta::system
