#include "momenta/io/model_file.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <map>
#include <numbers>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "model_file/model_file_internal.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/io/mjcf_file.hpp"
#include "momenta/io/urdf_file.hpp"
#include "momenta/model/integrators.hpp"

namespace momenta::io {
namespace detail {

// --- names ---------------------------------------------------------------------------------------

void Declared::add(const std::string& name, const YamlNode& node, const YamlNode& name_node) {
  if (name.empty()) name_node.fail(fmt::format("a {}'s name may not be empty", kind_));
  if (const auto earlier = find(name)) {
    name_node.fail(fmt::format("a second {} named '{}' (the first is at line {})", kind_, name,
                               earlier->line()));
  }
  names_.push_back(name);
  nodes_.emplace(name, node);
}

std::optional<YamlNode> Declared::find(std::string_view name) const {
  const auto it = nodes_.find(name);
  if (it == nodes_.end()) return std::nullopt;
  return it->second;
}

std::string Declared::resolve(const YamlNode& ref, bool allow_world) const {
  const std::string name = ref.as_string();
  if (allow_world && name == model::kWorldBodyName) return name;
  if (contains(name)) return name;
  std::vector<std::string_view> candidates(names_.begin(), names_.end());
  if (allow_world) candidates.insert(candidates.begin(), model::kWorldBodyName);
  std::string known = candidates.empty() ? "none are declared" : "";
  constexpr std::size_t kListed = 10;
  for (std::size_t i = 0; i < std::min(candidates.size(), kListed); ++i) {
    known += fmt::format("{}'{}'", i == 0 ? "" : ", ", candidates[i]);
  }
  if (candidates.size() > kListed) known += ", ...";
  ref.fail(fmt::format("unknown {} '{}'{}; known: {}", kind_, name, did_you_mean(name, candidates),
                       known));
}

std::string moving_body(const YamlNode& ref, const Context& ctx, std::string_view why_not_world) {
  if (ref.as_string() == model::kWorldBodyName) ref.fail(std::string(why_not_world));
  return ctx.bodies.resolve(ref);
}

std::vector<YamlNode> list_section(const YamlNode& root, std::string_view key) {
  const auto node = root.find(key);
  if (!node || node->is_null()) return {};
  return node->elements();
}

YamlNode name_node(const YamlNode& entry) {
  const YamlNode name = entry.at("name");
  if (!name.is_scalar()) name.fail("expected a name");
  return name;
}

const EntryType& entry_type(const YamlNode& entry, const std::vector<EntryType>& types,
                            std::string_view what) {
  const YamlNode type_node = entry.at("type");
  const std::string type = type_node.as_string();
  const auto it =
      std::find_if(types.begin(), types.end(), [&](const EntryType& t) { return t.name == type; });
  if (it == types.end()) {
    std::vector<std::string_view> names;
    for (const EntryType& t : types) names.push_back(t.name);
    type_node.fail(fmt::format("unknown {} type '{}'{}; known: {}", what, type,
                               did_you_mean(type, names), fmt::join(names, ", ")));
  }
  std::vector<std::string_view> keys = {"name", "type"};
  keys.insert(keys.end(), it->keys.begin(), it->keys.end());
  entry.check_keys(keys);
  return *it;
}

std::optional<VecX> find_coordinates(const YamlNode& map, std::string_view key,
                                     bool degrees_allowed, std::string_view why_not_degrees,
                                     bool rpm_allowed) {
  const std::string deg = fmt::format("{}_deg", key);
  const std::string rpm = fmt::format("{}_rpm", key);
  const std::array<std::string_view, 3> names = {key, deg, rpm};
  const auto which = map.which_of(rpm_allowed ? std::span<const std::string_view>(names)
                                              : std::span<const std::string_view>(names).first(2));
  if (!which) return std::nullopt;
  const YamlNode node = map.at(*which);
  if ((*which == deg || *which == rpm) && !degrees_allowed) {
    node.fail(fmt::format("{} are not allowed here ({}): give '{}' in SI units",
                          *which == deg ? "degrees" : "revolutions per minute", why_not_degrees,
                          key));
  }
  VecX values = node.is_sequence() ? node.as_vector() : VecX::Constant(1, node.as_double());
  if (*which == deg) values *= std::numbers::pi / 180.0;
  if (*which == rpm) values *= 2.0 * std::numbers::pi / 60.0;
  return values;
}

}  // namespace detail

namespace {

using detail::Context;

constexpr std::array<std::string_view, 13> kModelFileKeys = {
    "name",   "description", "gravity", "bodies",     "joints",  "forces", "constraints",
    "inputs", "controllers", "outputs", "simulation", "symbols", "live"};

// The `symbols:` section: each key (momenta's name) to an identifier (checked by the equations,
// which know the names) — letters, digits and '_', starting with a letter.
std::map<std::string, ModelFile::SymbolName> read_symbol_names(const YamlNode& root) {
  std::map<std::string, ModelFile::SymbolName> names;
  const auto section = root.find("symbols");
  if (!section || section->is_null()) return names;
  section->expect_map("a map from momenta's names to yours (m_bob: m)");
  for (const std::string& key : section->keys()) {
    const YamlNode value = section->at(key);
    if (names.count(key) != 0) value.fail(fmt::format("'{}' is named twice", key));
    const std::string name = value.as_string();
    const bool identifier = !name.empty() && std::isalpha(static_cast<unsigned char>(name[0])) &&
                            std::all_of(name.begin(), name.end(), [](char c) {
                              return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                            });
    if (!identifier) {
      value.fail(
          fmt::format("'{}' is not a name for the equations: use letters, digits and '_', "
                      "starting with a letter (theta, m_1)",
                      name));
    }
    names[key] = {name, value.line(), value.column()};
  }
  return names;
}

// The `live:` section: each entry a path, or {path, min, max}; each path a number the file
// writes (the page changes numbers, it does not add keys). The range is the slider's: a sweep
// or the page's own field may go past it, so the value is not held to it here.
std::vector<ModelFile::LiveNumber> read_live_numbers(const YamlNode& root) {
  std::vector<ModelFile::LiveNumber> numbers;
  const auto section = root.find("live");
  if (!section || section->is_null()) return numbers;
  if (!section->is_sequence()) {
    section->fail(
        "a list of the numbers the live report offers to change: each a path "
        "(forces.suspension.stiffness) or {path, min, max}");
  }
  for (const YamlNode& entry : section->elements()) {
    ModelFile::LiveNumber number{{}, std::nullopt, std::nullopt, entry.line(), entry.column()};
    const YamlNode path = entry.is_map() ? entry.at("path") : entry;
    if (entry.is_map()) {
      entry.check_keys({"path", "min", "max"});
      number.min = entry.find_number("min");
      number.max = entry.find_number("max");
    }
    number.path = path.as_string();
    std::optional<double> value;
    try {
      value = detail::number_in(root, number.path);
    } catch (const InvalidArgument& error) {
      path.fail(detail::one_line(error.what()));
    }
    if (!value) {
      path.fail(
          fmt::format("'{}' names no number this file writes: the live page changes the "
                      "file's numbers (write the key, with its value, to offer it)",
                      number.path));
    }
    for (const ModelFile::LiveNumber& earlier : numbers) {
      if (earlier.path == number.path) {
        path.fail(fmt::format("'{}' is listed twice (line {})", number.path, earlier.line));
      }
    }
    if (number.min && number.max && !(*number.min < *number.max)) {
      entry.fail(fmt::format("min {} must be less than max {}", *number.min, *number.max));
    }
    numbers.push_back(std::move(number));
  }
  return numbers;
}

// The declarations of one kind of item.
const detail::Declared& declared_of(ModelItemRef::Kind kind, const Context& ctx) {
  switch (kind) {
    case ModelItemRef::Kind::body:
      return ctx.bodies;
    case ModelItemRef::Kind::joint:
      return ctx.joints;
    case ModelItemRef::Kind::force_element:
      return ctx.forces;
    case ModelItemRef::Kind::constraint:
      return ctx.constraints;
    case ModelItemRef::Kind::controller:
      return ctx.controllers;
    case ModelItemRef::Kind::signal:
      break;
  }
  return ctx.signals;
}

// The node that declares the item an error is about, if the file declares it.
std::optional<YamlNode> declaring_node(const Error& error, const Context& ctx) {
  if (!error.item()) return std::nullopt;
  return declared_of(error.item()->kind, ctx).find(error.item()->name);
}

// Where the file declares each body, joint, force element and signal.
std::vector<ItemLocation> item_locations(const Context& ctx) {
  std::vector<ItemLocation> locations;
  for (const ModelItemRef::Kind kind :
       {ModelItemRef::Kind::body, ModelItemRef::Kind::joint, ModelItemRef::Kind::force_element,
        ModelItemRef::Kind::signal, ModelItemRef::Kind::constraint,
        ModelItemRef::Kind::controller}) {
    const detail::Declared& declared = declared_of(kind, ctx);
    for (const std::string& name : declared.names()) {
      const YamlNode node = *declared.find(name);
      locations.push_back({{kind, name}, node.line(), node.column()});
    }
  }
  return locations;
}

}  // namespace

namespace {

// `events:` of `simulation:` — each a condition "tension < 0" (recorded), or a map {name, when,
// action}. Which quantities exist is checked once the outputs are known (frontend::accept_model).
void read_events(const YamlNode& node, model::SimulationSettings& s) {
  if (!node.is_sequence()) {
    node.fail("a list of events: each 'QUANTITY < VALUE' or {name, when, action: record|stop}");
  }
  for (const YamlNode& item : node.elements()) {
    const YamlNode when = item.is_map() ? item.at("when") : item;
    if (item.is_map()) item.check_keys({"name", "when", "action"});
    model::EventSpec event;
    try {
      event = model::parse_event_condition(when.as_string());
    } catch (const InvalidArgument& e) {
      when.fail(e.what());
    }
    if (item.is_map()) {
      if (const auto name = item.find_string("name")) event.name = *name;
      if (const auto action = item.find("action")) {
        const std::string name = action->as_string();
        const std::optional<model::EventAction> known = model::find_event_action(name);
        if (!known) {
          action->fail(fmt::format(
              "'{}' is not an action: record (write a row and go on) or stop (end the run there)",
              name));
        }
        event.action = *known;
      }
    }
    for (const model::EventSpec& other : s.events) {
      if (other.name == event.name) item.fail(fmt::format("a second event named '{}'", event.name));
    }
    s.events.push_back(std::move(event));
    s.event_positions.push_back({item.line(), item.column()});
  }
}

}  // namespace

// `simulation:` — defaults for `momenta simulate`.
model::SimulationSettings detail::read_simulation(const YamlNode& root) {
  model::SimulationSettings s;
  const auto node = root.find("simulation");
  if (!node || node->is_null()) return s;
  node->expect_map("a map {duration, step, integrator, rtol, atol, every, events}");
  node->check_keys({"duration", "step", "integrator", "rtol", "atol", "every", "events"});
  s.position = {node->line(), node->column()};
  s.duration = node->find_number("duration", Bound::kPositive);
  if (s.duration)
    s.duration_position = {node->at("duration").line(), node->at("duration").column()};
  s.step = node->find_number("step", Bound::kPositive);
  if (s.step) s.step_position = {node->at("step").line(), node->at("step").column()};
  s.relative_tolerance = node->find_number("rtol", Bound::kPositive);
  s.absolute_tolerance = node->find_number("atol", Bound::kPositive);
  if (const auto integrator = node->find("integrator")) {
    const std::string name = integrator->as_string();
    try {
      model::integrator_info(name);
    } catch (const InvalidArgument& e) {
      integrator->fail(e.what());
    }
    s.integrator = name;
  }
  if (const auto every = node->find("every")) {
    const long long n = every->as_integer();
    if (n < 1) every->fail(fmt::format("must be a whole number >= 1, got {}", n));
    s.every = static_cast<long>(n);
  }
  if (const auto events = node->find("events")) read_events(*events, s);
  if (s.step && s.duration && *s.step > *s.duration) {
    node->at("step").fail(
        fmt::format("step {} s is longer than the duration {} s", *s.step, *s.duration));
  }
  return s;
}

ModelFile detail::compose_model_file(const YamlNode& root, const std::filesystem::path& base_dir) {
  root.expect_map("a model file: a map with 'bodies' and 'joints'");
  root.check_keys(kModelFileKeys);

  std::string name =
      root.find_string("name").value_or(std::filesystem::path(root.file()).stem().string());
  std::string description = root.find_string("description").value_or("");

  Context ctx;
  ctx.base_dir = base_dir;
  model::ModelBuilder builder;
  builder.set_gravity(root.find_vec3("gravity").value_or(Vec3(0, 0, -9.81)));

  // Signals first (joints and forces name them) with the controllers' (they drive inputs), then
  // the tree, then what acts on it.
  detail::read_signals(root, ctx, builder);
  detail::read_controllers(root, ctx, builder);
  detail::read_bodies(root, ctx, builder);
  detail::read_joints(root, ctx, builder);
  detail::read_forces(root, ctx, builder);
  detail::read_constraints(root, ctx, builder);

  // What the reader did not check itself, the builder does: report it at the line of the item
  // it is about.
  model::Model model = [&] {
    try {
      return builder.build();
    } catch (const InvalidArgument& e) {
      const std::string message = detail::one_line(e.what());
      const auto node = declaring_node(e, ctx);
      throw node ? node->error(message) : root.error(message);
    }
  }();

  std::vector<model::OutputSpec> outputs = detail::read_outputs(root, ctx, model);
  // The controllers last: one may measure an output.
  model = detail::add_controllers(std::move(model), ctx, outputs);
  model::SimulationSettings simulation = detail::read_simulation(root);
  std::vector<std::vector<PartSummary>> body_parts(model.bodies().size());
  for (std::size_t b = 1; b < body_parts.size(); ++b) {
    body_parts[b] = std::move(ctx.body_parts[model.bodies()[b].name]);
  }
  ModelFile file{std::move(name),
                 std::move(description),
                 std::move(model),
                 std::move(outputs),
                 simulation,
                 root.file(),
                 item_locations(ctx),
                 std::move(body_parts),
                 read_symbol_names(root),
                 {},
                 std::move(ctx.warnings),
                 {},
                 read_live_numbers(root)};
  return file;
}

std::vector<model::OutputSpec> parse_outputs(const std::string& text, const std::string& label,
                                             const model::Model& model) {
  const YamlNode root = YamlNode::load_string("outputs: " + text, label);
  // The model's own names are what the outputs may name.
  detail::Context ctx;
  const auto declare = [&](detail::Declared& declared, const std::string& name) {
    if (!declared.contains(name)) declared.add(name, root, root);
  };
  for (int b = 1; b < model.num_bodies(); ++b) declare(ctx.bodies, model.body(b).name);
  for (const model::Joint& j : model.joints()) declare(ctx.joints, j.name);
  for (const model::Signal& s : model.signals()) declare(ctx.signals, s.name());
  for (const model::ForceElement& f : model.force_elements())
    declare(ctx.forces, model::force_element_name(f));
  for (const model::Constraint& c : model.constraints())
    declare(ctx.constraints, model::constraint_name(c));
  return detail::read_outputs(root, ctx, model);
}

namespace {

ModelFile read_any_format(const std::filesystem::path& path, const ModelFileOptions& options) {
  if (is_urdf_path(path)) return read_urdf_file(path, options);
  if (is_mjcf_path(path)) return read_mjcf_file(path);
  return detail::compose_model_file(YamlNode::load_file(path), path.parent_path());
}

}  // namespace

ModelFile read_model_file(const std::filesystem::path& path, const ModelFileOptions& options) {
  ModelFile file = read_any_format(path, options);
  if (options.keyframe) {
    const Keyframe& key = file.keyframe(*options.keyframe);
    file.model = file.model.with_initial_state(key.q, key.v);
  }
  return file;
}

const Keyframe& ModelFile::keyframe(std::string_view key_name) const {
  for (const Keyframe& key : keyframes) {
    if (key.name == key_name) return key;
  }
  if (keyframes.empty()) {
    throw InvalidArgument(
        fmt::format("keyframe '{}': {} has no keyframes (an MJCF <keyframe> "
                    "section holds them)",
                    key_name, file));
  }
  std::vector<std::string_view> names;
  for (const Keyframe& key : keyframes) names.push_back(key.name);
  throw InvalidArgument(fmt::format("keyframe '{}': {} has no such key{}; its keys: {}", key_name,
                                    file, did_you_mean(key_name, names), fmt::join(names, ", ")));
}

std::optional<ParseError> ModelFile::locate(const Error& error) const {
  if (!error.item()) return std::nullopt;
  for (const ItemLocation& at : items) {
    if (at.item.kind == error.item()->kind && at.item.name == error.item()->name) {
      return ParseError(file, at.line, at.column, detail::one_line(error.what()));
    }
  }
  return std::nullopt;
}

ModelFile parse_model_file(const std::string& text, const std::string& file_name,
                           const std::filesystem::path& base_dir) {
  return detail::compose_model_file(YamlNode::load_string(text, file_name), base_dir);
}

}  // namespace momenta::io
