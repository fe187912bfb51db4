#pragma once
// `momenta lqr --write COPY` and `momenta place --write COPY`: a copy of the model file with the
// state feedback just designed as a controller (docs/control.md), ready for `momenta simulate`
// to run the nonlinear mechanism with its loop closed.

#include <string>

#include "linear_model_options.hpp"
#include "momenta/analysis/state_space.hpp"

namespace momenta::cli {

/// Writes to `copy` the model file `loaded` was read from, with the inputs the plant's inputs
/// name taken out of `inputs:` (the controller drives them now) and a `controllers:` section
/// appended: a state_feedback named `name` with gain K (plant inputs × plant states), measuring
/// the plant's states, their operating point as `state_reference` where it is not zero, and the
/// sample time of a sampled plant; `how` is the comment line above it (the command that
/// designed it). Throws FileError when `copy` exists and not `force`, or names the model file
/// itself; InvalidArgument when the model is not a momenta YAML file, already has controllers,
/// or a state is not a coordinate a controller can measure (a rotation's tangent), or an input
/// is not a signal (a prescribed coordinate).
void write_controller_copy(const LoadedLinearModel& loaded, const analysis::StateSpace& plant,
                           const MatX& K, const std::string& name, const std::string& how,
                           const std::string& copy, bool force);

}  // namespace momenta::cli
