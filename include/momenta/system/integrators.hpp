#pragma once
// Every integrator of the registry (model/integrators.hpp) made by name: the general methods of
// integrate/ and the structure-preserving rigid-body methods (rigid_body_integrator.hpp).

#include <memory>
#include <string_view>

#include "momenta/integrate/integrator.hpp"

namespace momenta::system {

/// The integrator with that name. Throws InvalidArgument for a name the registry does not know
/// (with a did-you-mean over every family) or a tolerance that is not positive and finite.
std::unique_ptr<integrate::Integrator> make_integrator(
    std::string_view name, const integrate::Tolerances& tolerances = {});

}  // namespace momenta::system
