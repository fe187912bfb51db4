#pragma once
// Internal to the report: the sections of a simulation report's data, one function each.

#include <string>
#include <vector>

#include "momenta/analysis/linearize.hpp"
#include "momenta/dynamics/data.hpp"
#include "momenta/model/parameter_source.hpp"
#include "momenta/report/report.hpp"
#include "page_data.hpp"

namespace momenta::report::detail {

/// How many body poses (frames × bodies) the 3-D view keeps at full (float64) precision: the
/// recorded rows are thinned by a whole stride to stay within it, which keeps a 10 s run of a
/// small model at every row or every other and a 20-body model near 60 frames per second.
inline constexpr int kMaxBodyPoses = 12000;
/// Plot columns hold every row up to twice this; beyond, each of this many buckets keeps its
/// first and last time and each column's minimum and maximum (the envelope a plot shows).
inline constexpr int kPlotBuckets = 1000;

/// A simulation report's whole data, as the page embeds it: {kind: "simulation", summary, scene,
/// frames, plots, linear, equations, campbell, diagrams, loops}. Throws InvalidArgument for a run
/// with no file, no rows, or units that do not match its columns, and for `linear` as
/// simulation_report_html says.
json simulation_data(const SimulationRun& run, const LinearSettings& linear,
                     ReportPanels panels = ReportPanels::all);

/// The live report's controls at most (the first in the file's order).
inline constexpr std::size_t kMaxLiveParameters = 24;

/// What the live report needs beside a run's data (live_section.cpp): {file (its name), text
/// (the model file as written), parameters: [{path, value, line, unit, min, max, scale ("log" or
/// "linear")}]} — the masses and body dimensions, the springs' and dampers' constants, the
/// joints' initial coordinates (a rotation's Euler angles among them) and rates and the run's
/// duration, as the file writes them.
json live_json(const io::ModelFile& file);

/// Free-body diagrams: at this many instants of the run (evenly spread rows, the first and last
/// among them), for the first kMaxDiagramBodies bodies (each picture is some 10 kB).
inline constexpr int kDiagramInstants = 5;
inline constexpr int kMaxDiagramBodies = 12;

/// Each body's free-body and kinetic diagrams (SVG) at kDiagramInstants rows of the run:
/// {times, bodies: [{name, svg: [...], residuals: [[|ΣF − m a_G|, |ΣM_G − Ḣ_G|] or the reason
/// there is no diagram]}], omitted}.
json diagrams_json(const SimulationRun& run);

/// The scene: bodies with their parts (or equivalent ellipsoids), joints, springs, loads.
json scene_json(const io::ModelFile& file);

/// Body poses, angular velocities, applied loads and reactions at the kept rows of the run.
json frames_json(const SimulationRun& run);

/// Every recorded column, grouped and decimated for plotting.
json plots_json(const SimulationRun& run);

/// The linear analysis about the point `settings` names, or {available: false, reason}.
/// `fastest_rate` receives the largest |λ| (1/s) when the model was linearized.
json linear_json(const io::ModelFile& file, const LinearSettings& settings, double& fastest_rate);

/// The `fastest_rate` linear_json gives, without the panel (its Bode figures, steps and mode
/// shapes): 0 where the model is not linearized.
double linear_fastest_rate(const io::ModelFile& file, const LinearSettings& settings);

/// The equations of motion in symbols (LaTeX and text, every nonzero parameter a symbol, the
/// file's names), the constraints' rows and the symbols' values; or {available: false, reason}
/// (too many free speeds, too large to print, or a build without the symbolic layer).
json equations_json(const io::ModelFile& file);

/// A parameter's source as the equations' data write it: {kind, index, row, column, magnitude,
/// sign}, the last four where not 0, 0, false, 1 (equation_numbers.cpp reads it back).
json source_json(const model::ParameterSource& source);

/// The model's feedback loops, one per controller: {name, kind, sample_time, svg}, the svg its
/// block diagram (reference, junction, law, hold, actuator, mechanism, sensor); [] without.
json loops_json(const io::ModelFile& file);

/// The Campbell diagram over the speeds `settings.campbell` names, or {available: false, reason}.
json campbell_json(const io::ModelFile& file, const LinearSettings& settings);
/// Body poses after forward kinematics in `data`: per body (world excluded) its position, then
/// its quaternion (x, y, z, w), appended to `positions` and `quaternions`.
void append_poses(const model::Model& model, const dynamics::Data& data,
                  std::vector<double>& positions, std::vector<double>& quaternions);

}  // namespace momenta::report::detail
