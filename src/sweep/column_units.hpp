#pragma once
// Internal to the sweep runner: the unit of each results column (docs/sweeps.md).

#include <filesystem>
#include <string>
#include <vector>

#include "momenta/model/model.hpp"
#include "momenta/sweep/sweep_spec.hpp"

namespace momenta::sweep::detail {

/// The unit of the number at `path` of a model file (`model` its nominal model) or, with no
/// model, of a part file whose lengths are in `part_length_unit`: "kg" for a mass, "m" for a
/// position or size, a joint's q0 in its coordinate's unit, a spring's stiffness in N/m or
/// N·m/rad, "deg" for a *_deg key; "" where the path does not say.
std::string parameter_unit(const std::string& path, const model::Model* model,
                           const std::string& part_length_unit);

/// The units of a metric's `columns` columns: its column's (`recorded_unit`) for a figure of a
/// simulated column, "s" for the step's times, "%" for overshoot, "1/s" for poles, "rad/s" for
/// natural frequencies, "1" for damping ratios and audit drifts, SI mass properties.
std::vector<std::string> metric_units(const Metric& metric, std::size_t columns,
                                      const std::string& recorded_unit);

/// A part file's `units:` (its lengths), "m" where it gives none.
std::string part_length_unit(const std::filesystem::path& part_file);

}  // namespace momenta::sweep::detail
