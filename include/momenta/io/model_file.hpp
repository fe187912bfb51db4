#pragma once
// Model files: a multibody system described in YAML — bodies, joints, force elements, input
// signals, outputs and simulation settings (format: docs/model-format.md).

#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "momenta/common/error.hpp"
#include "momenta/io/part_file.hpp"
#include "momenta/model/model.hpp"
#include "momenta/model/output_spec.hpp"
#include "momenta/model/simulation_settings.hpp"

namespace momenta::io {

/// Where a model file declares one item (1-based line and column).
struct ItemLocation {
  ModelItemRef item;
  int line = 0;
  int column = 0;
};

/// A named state of the model — an MJCF `<keyframe><key>` — in momenta's layout: q and v as the
/// model orders them (docs/model-formats.md says how MuJoCo's qpos and qvel map to them).
struct Keyframe {
  std::string name;   ///< the key's name, or `key<i>` (its index) for an unnamed one
  double time = 0.0;  ///< s: the key's `time`
  VecX q, v;
  int line = 0;  ///< where the file declares it
};

/// What a model file describes.
struct ModelFile {
  std::string name;                        ///< The file's `name:`, or the file's stem.
  std::string description;                 ///< The file's `description:`, or empty.
  model::Model model;                      ///< Built and validated.
  std::vector<model::OutputSpec> outputs;  ///< The `outputs:` section, in file order.
  model::SimulationSettings simulation;
  std::string file;                 ///< The file's name as messages give it.
  std::vector<ItemLocation> items;  ///< Where each body, joint, force element, signal is declared.
  /// What each body is made of, placed in its frame B, for drawing it: indexed like
  /// model.bodies() (the world's entry empty); one part for a body given by `shape` or `mesh`,
  /// the file's parts for a `part` file, none for a body given by mass, com and inertia.
  std::vector<std::vector<PartSummary>> body_parts;
  /// Body b's parts (empty where the file gives none, or for a body built after reading).
  std::span<const PartSummary> parts_of(int b) const {
    return static_cast<std::size_t>(b) < body_parts.size()
               ? std::span<const PartSummary>(body_parts[static_cast<std::size_t>(b)])
               : std::span<const PartSummary>();
  }
  /// The `symbols:` section: momenta's name of a parameter or coordinate in the equations
  /// (m_bob, L_bob, pivot; docs/equations.md) → the name the user writes (m, L, theta), with
  /// where the entry is, for `momenta equations` (symbolic::EquationOptions::names).
  struct SymbolName {
    std::string name;
    int line = 0, column = 0;
  };
  std::map<std::string, SymbolName> symbol_names;
  /// What the file says that momenta does not use, one `file:line: what` each (a URDF's joint
  /// limits, visuals, transmissions: docs/model-formats.md); empty for momenta's own files. An
  /// option a note names is marked ‹name› (common/error.hpp): a front end spells it with
  /// spell_options.
  std::vector<std::string> notes;
  /// What the file says that is allowed but likely not meant, one `file:line:column: what` each
  /// (a revolute joint's q0 of 30, beyond a turn: 30 rad, or 30 degrees meant?). The front ends
  /// show them when they read the file.
  std::vector<std::string> warnings;
  /// The file's named states (MJCF keyframes), in file order; empty for other formats.
  std::vector<Keyframe> keyframes;
  /// The `live:` section (docs/report.md, "The live report"): the numbers the report's live page
  /// offers to change, in the file's order, each by its dotted path (io/file_template.hpp), with
  /// the slider's range where the entry gives one. Empty: the page chooses (masses, lengths,
  /// constants, initial values, inputs, gains). Each path is checked to lead to a number the
  /// file writes, and a range to hold it.
  struct LiveNumber {
    std::string path;
    std::optional<double> min, max;
    int line = 0, column = 0;
  };
  std::vector<LiveNumber> live_numbers;
  /// The keyframe of that name. Throws InvalidArgument naming the file and the keys it has (with
  /// a did-you-mean), or saying it has none.
  const Keyframe& keyframe(std::string_view name) const;
  /// The names alone (symbolic::EquationOptions::names).
  std::map<std::string, std::string> given_symbol_names() const {
    std::map<std::string, std::string> names;
    for (const auto& [ours, given] : symbol_names) names[ours] = given.name;
    return names;
  }

  /// The error at the line of the item it is about (Error::item()), as ParseError
  /// `file:line:column: message`; nullopt when it names no item this file declares. For errors
  /// found after reading — a singular mass matrix found by the system layer, say.
  std::optional<ParseError> locate(const Error& error) const;
};

/// What a robot description needs besides its own text (URDF: docs/model-formats.md#meshes).
/// momenta's own files and MJCF do not use these.
struct ModelFileOptions {
  /// Folders searched, in order, for the package a `package://NAME/path` URI names: the first
  /// that is itself named NAME or holds a folder NAME (as ROS_PACKAGE_PATH's entries do). The
  /// folders of the environment's ROS_PACKAGE_PATH are searched after these.
  std::vector<std::filesystem::path> package_path;
  /// The density (kg/m³) of the links a URDF gives no <inertial>: each gets the mass properties
  /// of its collision geometry (else its visual geometry) filled with it. Without it such links
  /// are massless, as URDF says.
  std::optional<double> link_density;
  /// A keyframe of the file (ModelFile::keyframes) whose state becomes the model's initial state
  /// — MuJoCo's mj_resetDataKeyframe; any format may be asked, only MJCF files have them.
  std::optional<std::string> keyframe;
};

/// Reads, checks and builds a model file. Paths inside it (part files, meshes, CSV tables) are
/// relative to its folder.
///
/// Throws FileError when the file, or a file it names, is missing or unreadable. Throws
/// ParseError, one line `file:line:column: key path: message`, for every problem with its
/// content: malformed YAML; an unknown key (with a did-you-mean suggestion); a missing or doubled
/// key; a number that is not finite or out of range (a negative mass, a zero length); a name that
/// is unknown (with a did-you-mean) or repeated; a joint tree with a cycle, a body without a
/// joint or a massless subtree on a joint whose motion is free (singular mass matrix); a non-unit
/// axis or quaternion; a signal table whose times do not increase; an output that does not fit its
/// target. Problems found only when the model is assembled are reported at the line of the
/// body, joint or element they name. A file named `*.urdf` is read as a URDF robot description
/// (io/urdf_file.hpp, docs/model-formats.md), `*.xml` or `*.mjcf` as MJCF (io/mjcf_file.hpp);
/// `options` serve URDF files.
ModelFile read_model_file(const std::filesystem::path& path, const ModelFileOptions& options = {});

/// As read_model_file, from YAML text; `file_name` labels messages and `base_dir` resolves
/// relative paths.
ModelFile parse_model_file(const std::string& text, const std::string& file_name,
                           const std::filesystem::path& base_dir);

/// Outputs written as a model file's `outputs:` list (YAML or JSON text: "[{name: tip, body:
/// arm, quantity: position}]"), checked against a built `model` as a file's are (its bodies,
/// joints, signals, force elements and constraints by name). `label` names the text in
/// messages. For models built in code (Python's ModelBuilder.add_output).
std::vector<model::OutputSpec> parse_outputs(const std::string& text, const std::string& label,
                                             const model::Model& model);

}  // namespace momenta::io
