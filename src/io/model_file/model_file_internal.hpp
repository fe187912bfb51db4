#pragma once
// Shared pieces of the model-file reader (model_file*.cpp): where every named thing was declared,
// name look-ups that fail at the referencing line with a did-you-mean, and the section readers.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "momenta/io/model_file.hpp"
#include "momenta/io/part_file.hpp"
#include "momenta/io/yaml_reader.hpp"
#include "momenta/model/controller.hpp"
#include "momenta/model/model_builder.hpp"
#include "one_line.hpp"

namespace momenta::io::detail {

/// Reads, checks and builds the model file whose parsed document is `root` (read_model_file
/// after the parsing); paths inside it are relative to `base_dir`.
ModelFile compose_model_file(const YamlNode& root, const std::filesystem::path& base_dir);

// The number at a dotted path in a document (io/file_template.hpp), or nothing where the path's
// last key is absent. Throws InvalidArgument for a path that leads nowhere or to no number.
std::optional<double> number_in(const YamlNode& document, const std::string& path);

/// The `simulation:` section of `root` (a model file's, or a sweep file's), checked.
model::SimulationSettings read_simulation(const YamlNode& root);

/// The things of one kind declared in a file (bodies, joints, force elements, signals): their
/// names in file order and the node that declared each, for messages at its line.
class Declared {
 public:
  /// `kind` names the kind in messages ("body", "joint", ...).
  explicit Declared(std::string kind) : kind_(std::move(kind)) {}

  /// Records `name` declared by `node` (the list entry); throws at `name_node` if it is empty or
  /// repeats an earlier one (naming that one's line).
  void add(const std::string& name, const YamlNode& node, const YamlNode& name_node);

  /// The declaring node of `name`, or nothing.
  std::optional<YamlNode> find(std::string_view name) const;
  bool contains(std::string_view name) const { return find(name).has_value(); }
  const std::vector<std::string>& names() const { return names_; }

  /// The name `ref` (a scalar) holds, which must be declared (or be "world" when `allow_world`);
  /// throws at `ref`: "unknown body 'wheal' (did you mean 'wheel'?); bodies: ...".
  std::string resolve(const YamlNode& ref, bool allow_world = false) const;

 private:
  std::string kind_;
  std::vector<std::string> names_;
  std::map<std::string, YamlNode, std::less<>> nodes_;
};

/// What the readers share while reading one file.
struct Context {
  std::filesystem::path base_dir;
  Declared bodies{"body"};
  Declared joints{"joint"};
  Declared forces{"force element"};
  Declared signals{"signal"};
  Declared constraints{"constraint"};
  Declared controllers{"controller"};
  /// Joint types by joint name (for checks that need them before the model is built).
  std::map<std::string, model::JointType, std::less<>> joint_types;
  /// What each body is made of, by body name, placed in its frame (ModelFile::body_parts).
  std::map<std::string, std::vector<PartSummary>, std::less<>> body_parts;
  /// ModelFile::warnings, as the reader meets them.
  std::vector<std::string> warnings;
  /// The controllers read, in file order: added to the model once its outputs are read
  /// (add_controllers), since a controller may measure one.
  std::vector<model::Controller> controllers_read;
};

/// The body `ref` names, which must be declared and may not be the world: a load, a wheel or a
/// blade on the ground does nothing. Throws at `ref` with `why_not_world` for the world.
std::string moving_body(const YamlNode& ref, const Context& ctx, std::string_view why_not_world);

/// A list section: its elements, or none when the key is absent or empty (`forces:`). Throws
/// unless it is a list.
std::vector<YamlNode> list_section(const YamlNode& root, std::string_view key);

/// An entry's `name:` node (required, a non-empty scalar).
YamlNode name_node(const YamlNode& entry);

/// One `type:` of a typed list entry (a signal, a force element, a constraint) and the keys it
/// takes besides 'name' and 'type'.
struct EntryType {
  std::string_view name;
  std::vector<std::string_view> keys;
};

/// The type `entry` names by its `type:`, after checking the entry's keys against it. Throws at
/// `type:` for an unknown one: "unknown <what> type '…'" with a did-you-mean and the known types.
const EntryType& entry_type(const YamlNode& entry, const std::vector<EntryType>& types,
                            std::string_view what);

/// `inputs:` — every signal, added to the builder and to ctx.signals.
void read_signals(const YamlNode& root, Context& ctx, model::ModelBuilder& builder);
/// `controllers:` — every controller (into ctx.controllers_read), and the inputs they drive
/// (added to the builder as signals, so that forces can name them); after read_signals, before
/// read_forces.
void read_controllers(const YamlNode& root, Context& ctx, model::ModelBuilder& builder);
/// The controllers read, added to the built `model`, each measured name that is one of `outputs`
/// given its spec; an error is reported at the controller's line.
model::Model add_controllers(model::Model model, const Context& ctx,
                             const std::vector<model::OutputSpec>& outputs);
/// `bodies:` and `joints:` — added to the builder and ctx; the joints are checked to form a tree
/// rooted at the world, with every body carried by exactly one joint.
void read_bodies(const YamlNode& root, Context& ctx, model::ModelBuilder& builder);
void read_joints(const YamlNode& root, Context& ctx, model::ModelBuilder& builder);
/// `forces:` — every force element.
void read_forces(const YamlNode& root, Context& ctx, model::ModelBuilder& builder);
/// `constraints:` — every constraint (after the joints, which couplers name).
void read_constraints(const YamlNode& root, Context& ctx, model::ModelBuilder& builder);
/// `outputs:` — checked against the built model.
std::vector<model::OutputSpec> read_outputs(const YamlNode& root, const Context& ctx,
                                            const model::Model& model);

/// A list of numbers or a single number (one coordinate), with its unit converted: `key` in SI,
/// `key_deg` in degrees where `degrees_allowed`, and with `rpm_allowed` (a rate) `key_rpm` in
/// revolutions per minute. Nothing when none of the keys is present.
std::optional<VecX> find_coordinates(const YamlNode& map, std::string_view key,
                                     bool degrees_allowed, std::string_view why_not_degrees,
                                     bool rpm_allowed = false);

}  // namespace momenta::io::detail
