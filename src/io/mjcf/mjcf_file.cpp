#include "momenta/io/mjcf_file.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <set>
#include <span>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "mjcf/mjcf_reader.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/one_line.hpp"
#include "momenta/common/suggest.hpp"
#include "xml/xml_support.hpp"

namespace momenta::io {
namespace detail {
namespace {

// The elements MJCF allows where momenta reads, the ones it uses first.
constexpr std::array<std::string_view, 16> kTopLevel = {
    "compiler",  "option", "default", "worldbody", "equality", "actuator", "size",   "visual",
    "statistic", "asset",  "contact", "tendon",    "sensor",   "keyframe", "custom", "extension"};
constexpr std::array<std::string_view, 13> kBodyChildren = {
    "inertial", "joint",     "freejoint", "geom",   "body",  "site",     "camera",
    "light",    "composite", "flexcomp",  "plugin", "frame", "replicate"};

}  // namespace

ItemLocation located_at(ModelItemRef::Kind kind, const std::string& name, int line, int column) {
  ItemLocation location;
  location.item.kind = kind;
  location.item.name = name;
  location.line = line;
  location.column = column;
  return location;
}

MjcfReader::MjcfReader(const tinyxml2::XMLDocument& document_, std::string_view text_,
                       std::string file_, const std::filesystem::path& base_dir)
    : document(document_), text(text_), file(std::move(file_)), mesh_dir(base_dir) {
  classes_["main"] = DefaultClass{};
}

// --- messages
// --------------------------------------------------------------------------------------

void MjcfReader::fail(const XMLElement* at, const std::string& message,
                      const char* attribute) const {
  throw ParseError(file, at != nullptr ? at->GetLineNum() : 0, xml_column(text, at, attribute),
                   message);
}

void MjcfReader::note(const XMLElement* at, const std::string& message) {
  notes_.emplace_back(at->GetLineNum(), fmt::format("{}:{}: {}", file, at->GetLineNum(), message));
}

// --- attributes
// ------------------------------------------------------------------------------------

MjcfAttribute MjcfReader::attribute(const MjcfElement& e, const char* name) const {
  if (const char* own = e.xml->Attribute(name)) return {own, e.xml};
  // The class in force, then its ancestors up to "main".
  for (auto it = classes_.find(e.class_name); it != classes_.end();
       it = classes_.find(it->second.parent)) {
    const auto entry = it->second.entries.find(e.kind);
    if (entry != it->second.entries.end()) {
      if (const char* inherited = entry->second->Attribute(name)) return {inherited, entry->second};
    }
    if (it->second.parent.empty()) break;
  }
  return {};
}

std::vector<double> MjcfReader::numbers(const MjcfElement& e, const char* name, std::size_t fewest,
                                        std::size_t most,
                                        std::optional<std::vector<double>> fallback) const {
  const MjcfAttribute a = attribute(e, name);
  if (!a) {
    if (fallback) return *fallback;
    fail(e.xml, fmt::format("<{}> needs the attribute '{}'", e.xml->Name(), name));
  }
  const std::optional<std::vector<double>> values = parse_number_list(a.text);
  if (!values) {
    fail(a.where,
         fmt::format("<{} {}=\"{}\">: not a list of finite numbers", a.where->Name(), name, a.text),
         name);
  }
  if (values->size() < fewest || values->size() > most) {
    const std::string count =
        fewest == most ? fmt::format("{}", fewest) : fmt::format("{} to {}", fewest, most);
    fail(a.where,
         fmt::format("<{} {}=\"{}\">: expected {} number{}, found {}", a.where->Name(), name,
                     a.text, count, most == 1 ? "" : "s", values->size()),
         name);
  }
  return *values;
}

double MjcfReader::number(const MjcfElement& e, const char* name,
                          std::optional<double> fallback) const {
  std::optional<std::vector<double>> fallback_list;
  if (fallback) fallback_list = std::vector<double>{*fallback};
  return numbers(e, name, 1, 1, fallback_list).front();
}

Vec3 MjcfReader::vector3(const MjcfElement& e, const char* name, const Vec3& fallback) const {
  const std::vector<double> v =
      numbers(e, name, 3, 3, std::vector<double>{fallback.x(), fallback.y(), fallback.z()});
  return {v[0], v[1], v[2]};
}

std::string MjcfReader::keyword(const MjcfElement& e, const char* name,
                                std::initializer_list<std::string_view> choices,
                                std::string_view fallback) const {
  const MjcfAttribute a = attribute(e, name);
  if (!a) return std::string(fallback);
  const std::string_view value = a.text;
  if (std::find(choices.begin(), choices.end(), value) == choices.end()) {
    const std::vector<std::string_view> list(choices);
    fail(a.where,
         fmt::format("<{} {}=\"{}\">: not one of {}{}", a.where->Name(), name, value,
                     fmt::join(list, ", "), did_you_mean(value, list)),
         name);
  }
  return std::string(value);
}

bool MjcfReader::flag(const MjcfElement& e, const char* name, bool fallback) const {
  const std::string value =
      keyword(e, name, {"true", "false", "auto"}, fallback ? "true" : "false");
  return value == "auto" ? fallback : value == "true";
}

void MjcfReader::check_attributes(const XMLElement* xml,
                                  std::initializer_list<std::string_view> known) const {
  for (const tinyxml2::XMLAttribute* a = xml->FirstAttribute(); a != nullptr; a = a->Next()) {
    const std::string_view name = a->Name();
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    const std::vector<std::string_view> list(known);
    fail(xml,
         fmt::format("<{}>: unknown attribute '{}'{}", xml->Name(), name, did_you_mean(name, list)),
         a->Name());
  }
}

// --- compiler, option, defaults
// --------------------------------------------------------------------

void MjcfReader::read_compiler(const XMLElement* xml) {
  check_attributes(xml, {"autolimits",      "boundmass",         "boundinertia",     "settotalmass",
                         "balanceinertia",  "strippath",         "coordinate",       "angle",
                         "fitaabb",         "eulerseq",          "meshdir",          "texturedir",
                         "discardvisual",   "convexhull",        "usethread",        "fusestatic",
                         "inertiafromgeom", "inertiagrouprange", "exactmeshinertia", "assetdir"});
  const MjcfElement e{xml, "compiler", "main"};
  angle_scale = keyword(e, "angle", {"degree", "radian"}, "degree") == "degree"
                    ? 3.14159265358979323846 / 180.0
                    : 1.0;
  if (const char* sequence = xml->Attribute("eulerseq")) {
    const std::string_view s = sequence;
    if (s.size() != 3 || s.find_first_not_of("xyzXYZ") != std::string_view::npos) {
      fail(xml,
           fmt::format("<compiler eulerseq=\"{}\">: three of x, y, z (rotating axes) and X, "
                       "Y, Z (fixed axes)",
                       s),
           "eulerseq");
    }
    euler_sequence = s;
  }
  inertia_from_geom = keyword(e, "inertiafromgeom", {"false", "true", "auto"}, "auto");
  auto_limits = flag(e, "autolimits", true);
  // Mesh files: relative to meshdir, else assetdir, each relative to the model's folder.
  for (const char* folder : {"meshdir", "assetdir"}) {
    if (const char* given = xml->Attribute(folder)) {
      mesh_dir = mesh_dir / given;
      break;
    }
  }
  strip_path = flag(e, "strippath", false);
  exact_mesh_inertia = flag(e, "exactmeshinertia", false);
  if (keyword(e, "coordinate", {"local", "global"}, "local") == "global") {
    fail(xml,
         "<compiler coordinate=\"global\">: momenta reads local coordinates only (MuJoCo "
         "itself dropped global ones in 2.3.3)",
         "coordinate");
  }
  // Settings that would change the masses the file gives: refused rather than ignored.
  for (const char* changes : {"boundmass", "boundinertia", "settotalmass"}) {
    if (number(e, changes, 0.0) > 0.0) {
      fail(xml,
           fmt::format("<compiler {}>: momenta takes the masses as the file gives them; give "
                       "each body its mass",
                       changes),
           changes);
    }
  }
  if (flag(e, "balanceinertia", false)) {
    fail(xml,
         "<compiler balanceinertia=\"true\">: momenta refuses an inertia no body has rather "
         "than changing it",
         "balanceinertia");
  }
}

void MjcfReader::read_option(const XMLElement* xml) {
  check_attributes(
      xml,
      {"timestep",          "apirate",        "impratio",      "tolerance",   "noslip_tolerance",
       "mpr_tolerance",     "gravity",        "wind",          "magnetic",    "density",
       "viscosity",         "o_margin",       "o_solref",      "o_solimp",    "integrator",
       "collision",         "cone",           "jacobian",      "solver",      "iterations",
       "noslip_iterations", "mpr_iterations", "ls_iterations", "ls_tolerance"});
  const MjcfElement e{xml, "option", "main"};
  builder.set_gravity(vector3(e, "gravity", Vec3(0, 0, -9.81)));
  if (number(e, "density", 0.0) != 0.0 || number(e, "viscosity", 0.0) != 0.0) {
    note(xml, "<option> density and viscosity: the medium's forces are not modelled");
  }
  if (xml->Attribute("timestep") != nullptr || xml->Attribute("integrator") != nullptr) {
    note(xml,
         "<option> timestep and integrator: momenta chooses its own (the simulation "
         "settings, docs/integrators.md)");
  }
  for (const XMLElement* c = xml->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    if (std::string_view(c->Name()) != "flag") {
      note(c, fmt::format("<{}> of <option>: not used by momenta", c->Name()));
      continue;
    }
    if (const char* gravity = c->Attribute("gravity");
        gravity != nullptr && std::string_view(gravity) == "disable") {
      builder.set_gravity(Vec3::Zero());
    }
    if (const char* contact = c->Attribute("contact");
        contact != nullptr && std::string_view(contact) == "disable") {
      contacts_on = false;
    }
  }
}

std::string MjcfReader::class_of(const XMLElement* xml, const std::string& inherited,
                                 const char* attribute) const {
  const char* name = xml->Attribute(attribute);
  if (name == nullptr) return inherited;
  if (classes_.count(name) == 0) {
    std::vector<std::string_view> known;
    for (const auto& [n, c] : classes_) known.push_back(n);
    fail(xml, fmt::format("unknown class '{}'{}", name, did_you_mean(name, known)), attribute);
  }
  return name;
}

void MjcfReader::read_defaults(const XMLElement* xml, const std::string& parent) {
  // The top <default> is "main" (named or not); each nested one a class of its own.
  std::string name = "main";
  if (const char* given = xml->Attribute("class")) name = given;
  if (!parent.empty()) {
    if (xml->Attribute("class") == nullptr) fail(xml, "a nested <default> needs a class");
    // "main" is the top class: a nested one of that name would be its own ancestor.
    if (classes_.count(name) != 0) {
      fail(xml, fmt::format("a second default class named '{}'", name), "class");
    }
    classes_[name] = DefaultClass{parent, {}};
  }
  DefaultClass& own = classes_[name];
  for (const XMLElement* c = xml->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    std::string kind = c->Name();
    if (kind == "default") {
      read_defaults(c, name);
      continue;
    }
    // Every actuator shortcut sets the one default actuator of its class, as in MuJoCo.
    static constexpr std::array<std::string_view, 9> kActuators = {
        "general", "motor",    "position", "velocity", "intvelocity",
        "damper",  "cylinder", "muscle",   "adhesion"};
    if (std::find(kActuators.begin(), kActuators.end(), kind) != kActuators.end()) {
      kind = "actuator";
    }
    own.entries[kind] = c;
  }
}

// --- the body tree
// ---------------------------------------------------------------------------------

void MjcfReader::read_world_element(const XMLElement* c) {
  const std::string_view kind = c->Name();
  const char* name = c->Attribute("name");
  const std::string label =
      name != nullptr ? fmt::format("<{} name=\"{}\">", kind, name) : fmt::format("<{}>", kind);
  if (kind == "geom") {
    const MjcfElement e{c, "geom", class_of(c, "main")};
    const std::string type = keyword(
        e, "type",
        {"sphere", "capsule", "cylinder", "ellipsoid", "box", "mesh", "plane", "hfield", "sdf"},
        "sphere");
    if (type == "plane") {
      world_planes.push_back(
          MjcfGeom{e,
                   fmt::format("plane {}", label),
                   name != nullptr ? name : fmt::format("world_geom{}", world_geom_count),
                   std::string(model::kWorldBodyName),
                   type,
                   pose(e),
                   {}});
    } else {
      note(c, fmt::format("{} in the world ({}): contacts are with the world's planes only; "
                          "not drawn",
                          label, shape_with_article(type)));
    }
    ++world_geom_count;
  } else if (kind == "joint" || kind == "freejoint" || kind == "inertial") {
    fail(c, fmt::format("the world cannot have a <{}>", kind));
  } else {
    note(c, fmt::format("{}: not used by momenta", label));
  }
}

void MjcfReader::read_body(const XMLElement* xml, const std::string& parent, const Transform& X_WP,
                           const std::string& inherited_class) {
  check_attributes(xml, {"name", "childclass", "pos", "quat", "mocap", "axisangle", "xyaxes",
                         "zaxis", "euler", "user", "gravcomp"});
  ++body_count;  // MuJoCo's body number (the world is 0)
  const char* given = xml->Attribute("name");
  const std::string name = given != nullptr ? given : fmt::format("body{}", body_count);
  if (name == model::kWorldBodyName) fail(xml, "a body named 'world': the world is <worldbody>");
  if (const auto it = bodies.find(name); it != bodies.end()) {
    fail(xml,
         fmt::format("a second body named '{}' (the first is at line {})", name,
                     it->second.element->GetLineNum()),
         "name");
  }
  const std::string child_class = class_of(xml, inherited_class, "childclass");
  const Transform X_PB = pose(MjcfElement{xml, "body", child_class});
  const Transform X_WB = X_WP * X_PB;
  if (const char* mocap = xml->Attribute("mocap"); mocap && std::string_view(mocap) == "true") {
    note(xml, fmt::format("body '{}' is a mocap body: fixed where the file draws it", name));
  }

  // What the body's elements are: used, noted, or unknown.
  for (const XMLElement* c = xml->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    const std::string_view kind = c->Name();
    if (std::find(kBodyChildren.begin(), kBodyChildren.end(), kind) == kBodyChildren.end()) {
      fail(c, fmt::format("<{}> in body '{}': not an element of a body{}", kind, name,
                          did_you_mean(kind, kBodyChildren)));
    }
    if (kind == "site" || kind == "camera" || kind == "light" || kind == "plugin") {
      const char* n = c->Attribute("name");
      note(c, fmt::format("<{}{}> of body '{}': not used by momenta", kind,
                          n != nullptr ? fmt::format(" name=\"{}\"", n) : "", name));
    } else if (kind != "inertial" && kind != "joint" && kind != "freejoint" && kind != "geom" &&
               kind != "body") {
      fail(c, fmt::format("<{}> in body '{}': momenta reads bodies, joints, geoms and inertials "
                          "(write the {} out as bodies)",
                          kind, name, kind));
    }
  }

  // The body, its mass from its inertial or geoms, carried by its joints.
  std::vector<PartSummary> parts;
  const inertia::MassProperties mass_properties =
      body_mass_properties(xml, name, child_class, parts);
  bodies.emplace(name, MjcfBody{name, xml, X_WB});
  const std::vector<std::string> chain = body_joints(xml, name, parent, X_PB, X_WB, child_class);
  const bool has_joint =
      xml->FirstChildElement("joint") != nullptr || xml->FirstChildElement("freejoint") != nullptr;
  if (has_joint || moving_bodies.count(parent) != 0) moving_bodies.insert(name);
  for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
    builder.add_body(chain[k], inertia::MassProperties());  // massless links of a joint chain
  }
  builder.add_body(name, mass_properties);
  items.push_back(
      located_at(ModelItemRef::Kind::body, name, xml->GetLineNum(), xml_column(text, xml)));
  body_parts[name] = std::move(parts);

  for (const XMLElement* c = xml->FirstChildElement("body"); c != nullptr;
       c = c->NextSiblingElement("body")) {
    read_body(c, name, X_WB, child_class);
  }
}

// The body's joints, in order, as momenta joints: MuJoCo applies them one after the other, each
// about its axis through its anchor in the body frame as moved by those before it — a chain of
// massless bodies whose frames all coincide with the body's at the drawn configuration. Returns
// the bodies each joint carries (the last is the body itself).
std::vector<std::string> MjcfReader::body_joints(const XMLElement* body, const std::string& name,
                                                 const std::string& parent, const Transform& X_PB,
                                                 const Transform& X_WB,
                                                 const std::string& child_class) {
  std::vector<const XMLElement*> elements;
  for (const XMLElement* c = body->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    const std::string_view kind = c->Name();
    if (kind == "joint" || kind == "freejoint") elements.push_back(c);
  }
  std::vector<std::string> carried;
  if (elements.empty()) {
    // No joint: welded to its parent, as in MuJoCo.
    model::Joint weld;
    weld.name = fmt::format("{}_to_{}", name, parent);
    weld.type = model::JointType::fixed;
    weld.parent = parent;
    weld.child = name;
    weld.X_PJ = X_PB;
    builder.add_joint(weld);
    items.push_back(located_at(ModelItemRef::Kind::joint, weld.name, body->GetLineNum(),
                               xml_column(text, body)));
    return {name};
  }
  std::string previous = parent;
  for (std::size_t k = 0; k < elements.size(); ++k) {
    const XMLElement* xml = elements[k];
    const bool free_element = std::string_view(xml->Name()) == "freejoint";
    if (free_element) {
      check_attributes(xml, {"name", "group"});
    } else {
      check_attributes(xml, {"name",
                             "class",
                             "type",
                             "group",
                             "pos",
                             "axis",
                             "springdamper",
                             "limited",
                             "solreflimit",
                             "solimplimit",
                             "solreffriction",
                             "solimpfriction",
                             "stiffness",
                             "range",
                             "margin",
                             "ref",
                             "springref",
                             "armature",
                             "damping",
                             "frictionloss",
                             "user",
                             "actuatorfrclimited",
                             "actuatorfrcrange"});
    }
    const MjcfElement e{xml, "joint", class_of(xml, child_class)};
    ++joint_count;
    const char* given = xml->Attribute("name");
    model::Joint joint;
    joint.name = given != nullptr ? given : fmt::format("joint{}", joint_count - 1);
    if (const auto it = joints.find(joint.name); it != joints.end()) {
      fail(xml,
           fmt::format("a second joint named '{}' (the first is at line {})", joint.name,
                       it->second.element->GetLineNum()),
           "name");
    }
    const std::string type =
        free_element ? "free" : keyword(e, "type", {"hinge", "slide", "ball", "free"}, "hinge");
    const std::string owner = fmt::format("joint '{}'", joint.name);
    double qpos_at_zero = 0.0;  // MuJoCo's qpos where momenta's q is 0: `ref`
    double qpos_spring = 0.0;   // where its springs (and its tendons') relax: `springref`
    joint.parent = previous;
    joint.child = k + 1 == elements.size() ? name : fmt::format("{}_{}", name, joint.name);
    // A rotor's reflected inertia, on any <joint> (a <freejoint> has none).
    joint.armature = free_element ? 0.0 : number(e, "armature", 0.0);
    if (joint.armature < 0.0) fail(xml, fmt::format("the armature of {} is negative", owner));
    if (type == "free") {
      // Free: MuJoCo's qpos is the body's position and orientation in the world, its qvel the
      // world velocity and the body's angular velocity — momenta's free joint from the world,
      // the state starting where the file draws the body.
      if (parent != model::kWorldBodyName || elements.size() != 1) {
        fail(xml, fmt::format("{}: a free joint is the only joint of a body of the world (as "
                              "MuJoCo requires)",
                              owner));
      }
      joint.type = model::JointType::free;
      const Quat q_WB(X_WB.R);
      joint.q0.resize(7);
      joint.q0 << X_WB.p, q_WB.w(), q_WB.x(), q_WB.y(), q_WB.z();
    } else {
      const Vec3 anchor = vector3(e, "pos", Vec3::Zero());
      Vec3 axis = vector3(e, "axis", Vec3::UnitZ());
      if (!(axis.norm() > 1e-12)) fail(xml, fmt::format("the axis of {} is zero", owner), "axis");
      axis.normalize();
      joint.type = type == "hinge"   ? model::JointType::revolute
                   : type == "slide" ? model::JointType::prismatic
                                     : model::JointType::spherical;
      joint.axis = axis;
      joint.X_PJ = (k == 0 ? X_PB : Transform::identity()) * Transform::translation(anchor);
      joint.X_CJ = Transform::translation(anchor);
      joint.damping = number(e, "damping", 0.0);
      if (joint.damping < 0.0) fail(xml, fmt::format("the damping of {} is negative", owner));
      const double unit = type == "slide" ? 1.0 : angle_scale;
      const double ref = number(e, "ref", 0.0) * unit;
      if (type != "ball") {
        qpos_at_zero = ref;
        qpos_spring = number(e, "springref", 0.0) * unit;
      }
      const double stiffness = number(e, "stiffness", 0.0);
      if (stiffness < 0.0) fail(xml, fmt::format("the stiffness of {} is negative", owner));
      if (ref != 0.0 && type != "ball") {
        note(xml, fmt::format("{}: its coordinate counts from the configuration the file draws "
                              "(MuJoCo's qpos − ref, ref = {:.6g})",
                              owner, ref));
      }
      if (stiffness > 0.0 && type == "ball") {
        note(xml, fmt::format("the stiffness of {} (a ball joint) is not modelled", owner));
      } else if (stiffness > 0.0) {
        model::TorsionalSpringDamper spring;
        spring.name = joint.name + "_spring";
        spring.joint = joint.name;
        spring.stiffness = stiffness;
        spring.rest_angle = qpos_spring - ref;
        builder.add_force_element(spring);
        items.push_back(located_at(ModelItemRef::Kind::force_element, spring.name,
                                   xml->GetLineNum(), xml_column(text, xml)));
      }
      joint.limits = joint_limits(xml, e, owner, type, ref);
      if (number(e, "frictionloss", 0.0) != 0.0) {
        note(xml, fmt::format("the dry friction of {} is not modelled", owner));
      }
    }
    builder.add_joint(joint);
    items.push_back(located_at(ModelItemRef::Kind::joint, joint.name, xml->GetLineNum(),
                               xml_column(text, xml)));
    joints.emplace(joint.name, MjcfJoint{xml, joint, qpos_at_zero, qpos_spring});
    joint_order.push_back(joint.name);
    carried.push_back(joint.child);
    previous = joint.child;
  }
  return carried;
}

// A hinge's or slide's `range` where `limited` (or `auto` with <compiler autolimits>, MuJoCo's
// default) makes it one: stops on momenta's coordinate (qpos − ref), plastic (MuJoCo's limits are
// soft, their default solref critically damped: no rebound). Not enforced, with a note, where the
// file's start (qpos = ref) is outside the range, and on a ball joint (a cone on its swing).
std::optional<model::JointLimits> MjcfReader::joint_limits(const XMLElement* xml,
                                                           const MjcfElement& e,
                                                           const std::string& owner,
                                                           const std::string& type, double ref) {
  if (!attribute(e, "range")) return std::nullopt;
  const std::string limited = keyword(e, "limited", {"true", "false", "auto"}, "auto");
  if (limited == "false" || (limited == "auto" && !auto_limits)) return std::nullopt;
  if (type == "ball") {
    note(xml, fmt::format("the range of {} (a ball joint's cone) is not enforced", owner));
    return std::nullopt;
  }
  const std::vector<double> range = numbers(e, "range", 2, 2);
  const double unit = type == "slide" ? 1.0 : angle_scale;
  if (!(range[0] < range[1])) {
    fail(xml,
         fmt::format("the range of {} [{:.6g}, {:.6g}] is empty: a limited joint's range is "
                     "lower < upper",
                     owner, range[0], range[1]),
         "range");
  }
  const auto [low, high] = bounds_as_read(range[0], range[1]);
  if (!std::isfinite(low) && !std::isfinite(high)) return std::nullopt;
  const model::JointLimits limits{low * unit - ref, high * unit - ref, 0.0};
  if (limits.lower > 0.0 || limits.upper < 0.0) {
    note(xml, fmt::format("the limits of {} are not enforced: its start (qpos = ref = {:.6g}) is "
                          "outside its range [{:.6g}, {:.6g}]",
                          owner, ref / unit, range[0], range[1]));
    return std::nullopt;
  }
  return limits;
}

namespace {

// The entry of `table` called `name` (a body or joint the file names), or a failure at `attribute`
// with a did-you-mean among `names`.
template <typename Table>
const typename Table::mapped_type& named(const MjcfReader& reader, const Table& table,
                                         std::span<const std::string_view> names,
                                         std::string_view kind, const XMLElement* at,
                                         const char* attribute, const char* name) {
  if (name == nullptr) {
    reader.fail(at, fmt::format("<{}> needs the attribute '{}'", at->Name(), attribute));
  }
  const auto it = table.find(name);
  if (it == table.end()) {
    reader.fail(at, fmt::format("unknown {} '{}'{}", kind, name, did_you_mean(name, names)),
                attribute);
  }
  return it->second;
}

}  // namespace

const MjcfBody& MjcfReader::body_named(const XMLElement* at, const char* attribute,
                                       const char* name) const {
  std::vector<std::string_view> names;
  for (const auto& [n, b] : bodies) names.push_back(n);
  return named(*this, bodies, names, "body", at, attribute, name);
}

const MjcfJoint& MjcfReader::joint_named(const XMLElement* at, const char* attribute,
                                         const char* name) const {
  const std::vector<std::string_view> names(joint_order.begin(), joint_order.end());
  return named(*this, joints, names, "joint", at, attribute, name);
}

// --- the document
// ----------------------------------------------------------------------------------

ModelFile MjcfReader::read() {
  const XMLElement* root = document.RootElement();
  if (root == nullptr || std::string_view(root->Name()) != "mujoco") {
    fail(root, fmt::format("an MJCF file's root element is <mujoco>{}",
                           root != nullptr && std::string_view(root->Name()) == "robot"
                               ? " (a URDF <robot> is read from a file named *.urdf)"
                               : ""));
  }
  check_attributes(root, {"model"});
  // Settings and classes first (they apply wherever they appear), then the bodies, then what
  // names them.
  for (const XMLElement* c = root->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    const std::string_view kind = c->Name();
    if (kind == "include") {
      fail(c, "<include>: momenta reads one MJCF file; paste the included file in");
    }
    if (std::find(kTopLevel.begin(), kTopLevel.end(), kind) == kTopLevel.end()) {
      fail(c,
           fmt::format("<{}>: not an element of <mujoco>{}", kind, did_you_mean(kind, kTopLevel)));
    }
    if (kind == "compiler") read_compiler(c);
    if (kind == "option") read_option(c);
    if (kind == "default") read_defaults(c, "");
  }
  for (const XMLElement* c = root->FirstChildElement("asset"); c != nullptr;
       c = c->NextSiblingElement("asset")) {
    read_assets(c);
  }
  bool any_body = false;
  for (const XMLElement* world = root->FirstChildElement("worldbody"); world != nullptr;
       world = world->NextSiblingElement("worldbody")) {
    for (const XMLElement* c = world->FirstChildElement(); c != nullptr;
         c = c->NextSiblingElement()) {
      if (std::string_view(c->Name()) == "body") {
        read_body(c, model::kWorldBodyName, Transform::identity(), "main");
        any_body = true;
      } else {
        read_world_element(c);
      }
    }
  }
  if (!any_body) fail(root, "the model has no <body> in its <worldbody>");
  // The tendons first: an equality may name one.
  for (const XMLElement* c = root->FirstChildElement("tendon"); c != nullptr;
       c = c->NextSiblingElement("tendon")) {
    read_tendons(c);
  }
  for (const XMLElement* c = root->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    const std::string_view kind = c->Name();
    if (kind == "equality") {
      read_equality(c);
    } else if (kind == "actuator") {
      read_actuators(c);
    } else if (kind == "contact") {
      read_contact_section(c);
    } else if (kind != "compiler" && kind != "option" && kind != "default" && kind != "worldbody" &&
               kind != "asset" && kind != "keyframe" && kind != "tendon") {
      int count = 0;
      for (const XMLElement* e = c->FirstChildElement(); e != nullptr; e = e->NextSiblingElement())
        ++count;
      note(c, fmt::format(
                  "<{}>{}: not used by momenta", kind,
                  count > 0 ? fmt::format(" ({} element{})", count, count == 1 ? "" : "s") : ""));
    }
  }

  add_contacts();
  model::Model model = build_at_lines(builder, items, file);
  std::vector<Keyframe> keyframes;
  for (const XMLElement* c = root->FirstChildElement("keyframe"); c != nullptr;
       c = c->NextSiblingElement("keyframe")) {
    read_keyframes(c, model, keyframes);
  }
  // A key named `initial` (as momenta's MJCF writer keeps a model's initial velocities) is the
  // initial state; any other is one to ask for (ModelFileOptions::keyframe, --keyframe).
  for (const Keyframe& key : keyframes) {
    if (key.name == "initial") model = model.with_initial_state(key.q, key.v);
  }
  std::vector<std::vector<PartSummary>> parts(model.bodies().size());
  for (auto& [name, list] : body_parts) {
    parts[static_cast<std::size_t>(model.body_index(name))] = std::move(list);
  }
  std::stable_sort(notes_.begin(), notes_.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> notes;
  for (auto& [line, note_text] : notes_) notes.push_back(std::move(note_text));
  const char* model_name = root->Attribute("model");
  return ModelFile{model_name != nullptr ? model_name : std::filesystem::path(file).stem().string(),
                   "",
                   std::move(model),
                   std::move(outputs),
                   model::SimulationSettings{},
                   file,
                   std::move(items),
                   std::move(parts),
                   {},
                   std::move(notes),
                   {},
                   std::move(keyframes),
                   {}};
}

}  // namespace detail

bool is_mjcf_path(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".xml" || extension == ".mjcf";
}

ModelFile read_mjcf_file(const std::filesystem::path& path) {
  return parse_mjcf(detail::read_xml_text(path.string(), "MJCF file"), path.string(),
                    path.parent_path());
}

ModelFile parse_mjcf(const std::string& text, const std::string& file_name,
                     const std::filesystem::path& base_dir) {
  tinyxml2::XMLDocument document;
  document.Parse(text.c_str(), text.size());
  detail::check_xml_document(document, file_name, "an MJCF file holds a <mujoco>");
  return detail::MjcfReader(document, text, file_name, base_dir).read();
}

}  // namespace momenta::io
