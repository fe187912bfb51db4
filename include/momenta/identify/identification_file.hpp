#pragma once
// Identification files: a model file, the numbers of it to estimate and the experiments whose
// logs they are fitted to — YAML, documented in docs/identification.md ("Grey-box fits").
//
//     name: cruise control test drive
//     model: ../cruise_control.yaml
//     parameters:
//       - {name: m, path: bodies.car.mass, guess: 1500, lower: 100}
//       - {name: b, path: joints.road.damping}
//     experiments:
//       - name: drive
//         data: cruise_control_log.csv
//         inputs: [{column: force, signal: u}]
//         outputs: [{column: speed, channel: speed, noise: 0.05}]
//         set: {joints.road.v0: 0}
//     fit: {max_iterations: 100, rtol: 1e-9, atol: 1e-12, profile: auto}

#include <filesystem>
#include <string>

#include "momenta/identify/grey_box.hpp"

namespace momenta::identify {

/// Reads and checks an identification file; the model and data paths in it are relative to its
/// folder. Throws FileError when it or a file it names cannot be read; ParseError
/// `file:line:column: key: message` for anything wrong in it — an unknown key (with a
/// did-you-mean), a parameter path that leads nowhere in the model file (naming the segment, with
/// a did-you-mean), bounds the wrong way round, a noise ≤ 0, a data file with a missing column,
/// NaN or times that do not increase (its own file:line).
GreyBoxProblem read_identification_file(const std::filesystem::path& path);

/// The same from the file's text: `source` names it in messages, `folder` is where its relative
/// paths start.
GreyBoxProblem parse_identification_file(const std::string& text, const std::string& source,
                                         const std::filesystem::path& folder);

/// True when the YAML file at `path` reads as an identification file (it has `experiments:`),
/// not a model file: how `momenta identify FILE` tells the two routes apart.
bool is_identification_file(const std::filesystem::path& path);

}  // namespace momenta::identify
