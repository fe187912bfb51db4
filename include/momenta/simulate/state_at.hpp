#pragma once
// The state a model reaches at a chosen time: what `momenta kinematics --time` and `momenta
// diagram --time` look at.

#include "momenta/integrate/integrator.hpp"
#include "momenta/model/model.hpp"
#include "momenta/simulate/simulation.hpp"

namespace momenta::simulate {

/// The model's state at time t ≥ 0: its initial state (quaternions normalized, prescribed
/// coordinates from their signals, made consistent with its constraints) integrated to t with
/// `options` (duration and every are replaced; the integrator and step are used as given), the
/// prescribed coordinates exactly on their signals. Throws InvalidArgument for t negative or not
/// finite, and what Simulation::run throws.
integrate::State state_at(const model::Model& model, double t, SimulationOptions options);

}  // namespace momenta::simulate
