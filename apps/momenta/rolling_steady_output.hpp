#pragma once
// How `momenta steady` and `momenta modes/linearize --about steady` show the steady motions of a
// rolling body (analysis/rolling_steady_motion.hpp): as text and as JSON.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "momenta/analysis/rolling_steady_motion.hpp"
#include "momenta/io/model_file.hpp"

namespace momenta::cli {

/// One found motion and its modes, as JSON: lean (rad and °), precession, spin, relative_spin,
/// speed, radius and contact_radius (null on a straight line), heading_W, lateral_W,
/// contact_force {normal, longitudinal, lateral}, residual, stable, growth_rate, eigenvalues and
/// circle_shift as [re, im], zero_eigenvalues, and the state {q, v, t}.
nlohmann::ordered_json rolling_motion_json(const analysis::RollingSteadyModes& modes);

/// The text lines of one found motion (numbered `index`, named slow or fast when there are two):
/// its rates, circle, the floor's force, whether a disturbance grows, and the state as `joint`'s
/// q0 and v0 for a model file.
void print_rolling_motion(const analysis::RollingSteadyModes& modes, const std::string& joint,
                          int index, int count);

/// `modes` and `linearize` about a rolling body's steady motion (analysis::
/// linear_analysis_about): the motion and its modes seen from the turning frame (with the
/// matrix A when `with_matrix`).
void print_rolling_steady_modes(const io::ModelFile& file,
                                const analysis::RollingSteadyModes& modes, bool json,
                                bool with_matrix);

}  // namespace momenta::cli
