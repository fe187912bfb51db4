#pragma once
// Which columns of a measured data file the inertia route reads (docs/identification.md), and the
// samples taken from them. Per coordinate, named as `momenta simulate` names its columns:
//   each configuration coordinate      <joint>.<q>         shoulder.angle, hip.qw …
//   each velocity coordinate           <joint>.<v>         shoulder.angle_rate, hip.wx …
//   its rate (the acceleration)        <joint>.<v>_dot     shoulder.angle_rate_dot
//   the effort the actuator applied    <joint>.effort      (one-coordinate joints)
//                                      <joint>.effort_<v>  (others: hip.effort_wx)
// in the units of docs/conventions.md (rad, rad/s, rad/s², N·m; m, m/s, m/s², N). Other columns
// (time, anything else logged) are left alone.

#include <string>
#include <string_view>
#include <vector>

#include "momenta/identify/inertia_estimate.hpp"
#include "momenta/identify/position_derivatives.hpp"

namespace momenta::identify {

/// Every column the inertia route needs from a model's data, in the order above.
std::vector<std::string> inertia_data_columns(const Model& model);

/// The samples in a table of measured data (`columns` its header, `values` one row per sample);
/// a column missing is an error naming `source`, the column, what it holds, and a near miss.
/// The rates and the accelerations may each be left out all together: they are then taken from
/// the positions (the accelerations from the rates where those are given) over a `time` column by
/// differentiate_positions with `derivative_window` samples — only where each rate is its
/// position's derivative (`shoulder.angle_rate` of `shoulder.angle`; not a ball joint's);
/// InertiaSamples::derived says so.
InertiaSamples inertia_samples(const Model& model, const std::vector<std::string>& columns,
                               const MatX& values, std::string_view source,
                               int derivative_window = kDefaultDerivativeWindow);

}  // namespace momenta::identify
