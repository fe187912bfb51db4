#include "momenta/io/urdf_file.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <tinyxml2.h>
#include <Eigen/Geometry>

#include "momenta/common/error.hpp"
#include "momenta/common/one_line.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta/model/model_builder.hpp"
#include "urdf/urdf_reader.hpp"
#include "xml/xml_support.hpp"

namespace momenta::io::detail {
namespace {

constexpr std::array<std::string_view, 6> kJointTypes = {"revolute", "continuous", "prismatic",
                                                         "fixed",    "floating",   "planar"};

}  // namespace

UrdfReader::UrdfReader(const tinyxml2::XMLDocument& document, std::string file,
                       const ModelFileOptions& options, std::filesystem::path base_dir)
    : document_(document),
      file_(std::move(file)),
      options_(options),
      base_dir_(std::move(base_dir)),
      package_path_(package_search_path(options.package_path)) {
  if (options.link_density &&
      !(std::isfinite(*options.link_density) && *options.link_density > 0)) {
    throw InvalidArgument(fmt::format("{}: the link density {} kg/m³ is not positive and finite",
                                      file_, *options.link_density));
  }
}

void UrdfReader::fail(const XMLElement* at, const std::string& message) const {
  throw ParseError(file_, at != nullptr ? at->GetLineNum() : 0, 0, OptionMessage{message});
}

void UrdfReader::note(const XMLElement* at, const std::string& message) {
  notes_.emplace_back(at->GetLineNum(), fmt::format("{}:{}: {}", file_, at->GetLineNum(), message));
}

std::string UrdfReader::name_of(const XMLElement* e, const char* what) const {
  const char* name = e->Attribute("name");
  if (name == nullptr || *name == '\0') fail(e, fmt::format("a <{}> needs a name", what));
  return name;
}

double UrdfReader::number(const XMLElement* e, const char* attribute,
                          std::optional<double> fallback) const {
  const char* text = e->Attribute(attribute);
  if (text == nullptr) {
    if (fallback) return *fallback;
    fail(e, fmt::format("<{}> needs the attribute '{}'", e->Name(), attribute));
  }
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  while (end != nullptr && std::isspace(static_cast<unsigned char>(*end))) ++end;
  if (end == text || *end != '\0' || !std::isfinite(value)) {
    fail(e, fmt::format("<{} {}=\"{}\">: not a finite number", e->Name(), attribute, text));
  }
  return value;
}

Vec3 UrdfReader::vector3(const XMLElement* e, const char* attribute, const Vec3& fallback) const {
  const char* text = e->Attribute(attribute);
  if (text == nullptr) return fallback;
  const std::optional<std::vector<double>> v = parse_number_list(text);
  if (!v || v->size() != 3) {
    fail(e,
         fmt::format("<{} {}=\"{}\">: expected three finite numbers", e->Name(), attribute, text));
  }
  return {(*v)[0], (*v)[1], (*v)[2]};
}

// <origin xyz rpy>: rpy are fixed-axis roll, pitch, yaw about x, y, z: R = Rz(y) Ry(p) Rx(r).
Transform UrdfReader::origin(const XMLElement* parent) const {
  const XMLElement* o = parent->FirstChildElement("origin");
  if (o == nullptr) return Transform::identity();
  const Vec3 xyz = vector3(o, "xyz", Vec3::Zero());
  const Vec3 rpy = vector3(o, "rpy", Vec3::Zero());
  const Mat3 R = rotation_from_axis_angle(Vec3::UnitZ(), rpy.z()) *
                 rotation_from_axis_angle(Vec3::UnitY(), rpy.y()) *
                 rotation_from_axis_angle(Vec3::UnitX(), rpy.x());
  return {R, xyz};
}

void UrdfReader::note_ignored_children(const XMLElement* e, const std::string& owner,
                                       std::initializer_list<std::string_view> used) {
  for (const XMLElement* c = e->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    if (std::find(used.begin(), used.end(), std::string_view(c->Name())) != used.end()) continue;
    note(c, fmt::format("<{}> of {}: not used by momenta", c->Name(), owner));
  }
}

void UrdfReader::read_link(const XMLElement* e) {
  const std::string name = name_of(e, "link");
  if (links_.count(name) != 0) {
    fail(e, fmt::format("a second link named '{}' (the first is at line {})", name,
                        links_.at(name).element->GetLineNum()));
  }
  Link link{e, inertia::MassProperties(), false, {}};
  const std::string owner = fmt::format("link '{}'", name);
  if (const XMLElement* inertial = e->FirstChildElement("inertial")) {
    link.has_inertial = true;
    const XMLElement* mass = inertial->FirstChildElement("mass");
    if (mass == nullptr) fail(inertial, fmt::format("the <inertial> of {} needs a <mass>", owner));
    const double m = number(mass, "value", std::nullopt);
    if (!(m >= 0.0)) fail(mass, fmt::format("the mass of {} is negative ({} kg)", owner, m));
    const XMLElement* in = inertial->FirstChildElement("inertia");
    Mat3 I = Mat3::Zero();
    if (in != nullptr) {
      const double ixx = number(in, "ixx", 0.0), iyy = number(in, "iyy", 0.0),
                   izz = number(in, "izz", 0.0), ixy = number(in, "ixy", 0.0),
                   ixz = number(in, "ixz", 0.0), iyz = number(in, "iyz", 0.0);
      I << ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz;
    }
    // The inertia is about the inertial frame's origin (the centre of mass), in its axes.
    // A zero mass with no inertia is a massless link, as a link without <inertial> is.
    const Transform X_BI = origin(inertial);
    if (m != 0.0 || !I.isZero(0.0)) {
      link.mass_properties = inertia::MassProperties(m, X_BI.p, X_BI.R * I * X_BI.R.transpose());
      try {
        link.mass_properties.check_physical(owner);
      } catch (const Error& error) {
        fail(in != nullptr ? in : inertial, one_line(error.what()));
      }
    }
    note_ignored_children(inertial, owner + "'s <inertial>", {"origin", "mass", "inertia"});
  }
  read_geometry(e, link, owner);
  note_ignored_children(e, owner, {"inertial", "visual", "collision"});
  links_.emplace(name, std::move(link));
  link_order_.push_back(name);
}

std::string UrdfReader::link_reference(const XMLElement* joint, const char* which) const {
  const XMLElement* ref = joint->FirstChildElement(which);
  if (ref == nullptr) fail(joint, fmt::format("a <joint> needs a <{}>", which));
  const char* link = ref->Attribute("link");
  if (link == nullptr) fail(ref, fmt::format("<{}> needs the attribute 'link'", which));
  if (links_.count(link) == 0) {
    std::vector<std::string_view> names(link_order_.begin(), link_order_.end());
    fail(ref, fmt::format("unknown link '{}'{}", link, did_you_mean(link, names)));
  }
  return link;
}

void UrdfReader::read_joint(const XMLElement* e) {
  const std::string name = name_of(e, "joint");
  if (joints_.count(name) != 0) {
    fail(e, fmt::format("a second joint named '{}' (the first is at line {})", name,
                        joints_.at(name).element->GetLineNum()));
  }
  const char* type_text = e->Attribute("type");
  if (type_text == nullptr) fail(e, fmt::format("joint '{}' needs a type", name));
  const std::string_view type = type_text;
  if (std::find(kJointTypes.begin(), kJointTypes.end(), type) == kJointTypes.end()) {
    fail(e, fmt::format("joint '{}': unknown type '{}'{}; URDF's are revolute, continuous, "
                        "prismatic, fixed, floating and planar",
                        name, type, did_you_mean(type, kJointTypes)));
  }
  JointEntry entry{e, model::Joint{}, {}, 1.0, 0.0, nullptr};
  model::Joint& joint = entry.joint;
  joint.name = name;
  joint.parent = link_reference(e, "parent");
  joint.child = link_reference(e, "child");
  if (joint.parent == joint.child)
    fail(e, fmt::format("joint '{}' joins link '{}' to itself", name, joint.child));
  joint.X_PJ = origin(e);
  const std::string owner = fmt::format("joint '{}'", name);
  Vec3 axis = Vec3::UnitX();
  if (const XMLElement* a = e->FirstChildElement("axis")) {
    axis = vector3(a, "xyz", Vec3::UnitX());
    if (!(axis.norm() > 1e-12)) fail(a, fmt::format("the axis of {} is zero", owner));
    if (std::abs(axis.norm() - 1.0) > 1e-6) {
      note(a, fmt::format("the axis of {} is not unit (|axis| = {:.6g}): normalized", owner,
                          axis.norm()));
    }
    axis.normalize();
  }
  if (type == "revolute" || type == "continuous") {
    joint.type = model::JointType::revolute;
    joint.axis = axis;
  } else if (type == "prismatic") {
    joint.type = model::JointType::prismatic;
    joint.axis = axis;
  } else if (type == "fixed") {
    joint.type = model::JointType::fixed;
  } else if (type == "floating") {
    joint.type = model::JointType::free;
  } else {
    // Planar: momenta's moves in J's x-y plane; J's z turned onto the URDF axis (the plane's
    // normal), the child's frame kept at the origin.
    joint.type = model::JointType::planar;
    const Transform turn =
        Transform::rotation(Quat::FromTwoVectors(Vec3::UnitZ(), axis).toRotationMatrix());
    joint.X_PJ = joint.X_PJ * turn;
    joint.X_CJ = turn;
  }
  // What momenta keeps (damping, mimic) and what it lists as not used.
  if (const XMLElement* d = e->FirstChildElement("dynamics")) {
    joint.damping = number(d, "damping", 0.0);
    if (joint.damping < 0.0) fail(d, fmt::format("the damping of {} is negative", owner));
    if (number(d, "friction", 0.0) != 0.0) {
      note(d, fmt::format("the Coulomb friction of {} is not modelled", owner));
    }
  }
  if (const XMLElement* limit = e->FirstChildElement("limit")) read_limit(limit, type, entry);
  if (const XMLElement* m = e->FirstChildElement("mimic")) {
    const char* mimicked = m->Attribute("joint");
    if (mimicked == nullptr) fail(m, "<mimic> needs the attribute 'joint'");
    entry.mimic = mimicked;
    entry.multiplier = number(m, "multiplier", 1.0);
    entry.offset = number(m, "offset", 0.0);
    entry.mimic_element = m;
  }
  note_ignored_children(e, owner,
                        {"parent", "child", "origin", "axis", "dynamics", "limit", "mimic"});
  joints_.emplace(name, std::move(entry));
  joint_order_.push_back(name);
}

// A joint's <limit>: the stops of a revolute or prismatic joint (plastic, e = 0: URDF gives no
// restitution), where the robot's start (every q = 0) lies between them; effort and velocity are
// recorded only.
void UrdfReader::read_limit(const XMLElement* limit, std::string_view type, JointEntry& entry) {
  const std::string owner = fmt::format("joint '{}'", entry.joint.name);
  const double effort = number(limit, "effort", 0.0), velocity = number(limit, "velocity", 0.0);
  const std::string unenforced =
      effort != 0.0 || velocity != 0.0
          ? fmt::format("its effort ({:.6g}) and velocity ({:.6g}) limits are not enforced", effort,
                        velocity)
          : std::string();
  // A note, the effort and velocity said after `separator` where they are given.
  const auto note_with = [&](const std::string& text, std::string_view separator) {
    note(limit, unenforced.empty() ? text : fmt::format("{}{}{}", text, separator, unenforced));
  };
  if (type != "revolute" && type != "prismatic") {
    note_with(fmt::format("the <limit> of {} (a {} joint) has no stops", owner, type), ": ");
    return;
  }
  const double lower = number(limit, "lower", 0.0), upper = number(limit, "upper", 0.0);
  if (lower > upper) {
    fail(limit,
         fmt::format("the limits of {}: lower {:.6g} is above upper {:.6g}", owner, lower, upper));
  }
  if (lower == upper) {
    note_with(fmt::format("the limits of {} are not enforced: lower = upper = {:.6g} (URDF's "
                          "default when they are left out) would lock it",
                          owner, lower),
              "; ");
    return;
  }
  if (lower > 0.0 || upper < 0.0) {
    note_with(fmt::format("the limits of {} are not enforced: [{:.6g}, {:.6g}] does not hold the "
                          "robot's start, where every joint is at 0",
                          owner, lower, upper),
              "; ");
    return;
  }
  const auto [low, high] = bounds_as_read(lower, upper);
  if (std::isfinite(low) || std::isfinite(high)) {
    entry.joint.limits = model::JointLimits{low, high, 0.0};
  }
  if (!unenforced.empty()) note(limit, fmt::format("{}: {}", owner, unenforced));
}

namespace {

// Where an item is declared (field by field: GCC 12 misreports a braced one's strings).
ItemLocation located(ModelItemRef::Kind kind, const std::string& name, const XMLElement* at) {
  ItemLocation location;
  location.item.kind = kind;
  location.item.name = name;
  location.line = at->GetLineNum();
  return location;
}

}  // namespace

ModelFile UrdfReader::read() {
  const XMLElement* robot = document_.RootElement();
  if (robot == nullptr || std::string_view(robot->Name()) != "robot") {
    fail(robot, "a URDF file's root element is <robot>");
  }
  // Links first (joints name them), then joints.
  for (const XMLElement* e = robot->FirstChildElement(); e != nullptr;
       e = e->NextSiblingElement()) {
    const std::string_view kind = e->Name();
    if (kind == "link") {
      read_link(e);
    } else if (kind != "joint") {
      note(e, fmt::format("<{}>: not used by momenta", kind));
    }
  }
  if (links_.empty()) fail(robot, "the robot has no <link>");
  for (const XMLElement* e = robot->FirstChildElement("joint"); e != nullptr;
       e = e->NextSiblingElement("joint")) {
    read_joint(e);
  }

  // The tree: each link the child of one joint at most; one root.
  std::map<std::string, std::string> joint_to_child;  // child link → joint
  for (const std::string& j : joint_order_) {
    const JointEntry& entry = joints_.at(j);
    const auto [it, fresh] = joint_to_child.emplace(entry.joint.child, j);
    if (!fresh) {
      fail(entry.element, fmt::format("link '{}' is the child of joints '{}' and '{}': a URDF "
                                      "describes a tree (close loops in a momenta model file)",
                                      entry.joint.child, it->second, j));
    }
  }
  std::vector<std::string> roots;
  for (const std::string& l : link_order_) {
    if (joint_to_child.count(l) == 0) roots.push_back(l);
  }
  if (roots.size() != 1) {
    fail(robot, fmt::format("the links form {} trees, rooted at '{}': a robot is one tree",
                            roots.size(), fmt::join(roots, "', '")));
  }
  const std::string& root = roots.front();
  const bool root_is_world = root == model::kWorldBodyName;

  // The model, parents before children.
  model::ModelBuilder builder;
  builder.set_gravity(Vec3(0, 0, -9.81));
  std::vector<ItemLocation> items;
  std::map<std::string, std::vector<std::string>> children;  // link → joints out of it
  for (const std::string& j : joint_order_) children[joints_.at(j).joint.parent].push_back(j);
  std::vector<std::string> order;
  std::vector<std::string> stack = {root};
  if (!root_is_world) {
    builder.add_body(root, links_.at(root).mass_properties);
    items.push_back(located(ModelItemRef::Kind::body, root, links_.at(root).element));
    model::Joint weld;
    weld.name = root + "_to_world";
    weld.type = model::JointType::fixed;
    weld.parent = model::kWorldBodyName;
    weld.child = root;
    builder.add_joint(weld);
    note(links_.at(root).element,
         fmt::format("link '{}', the root, is fixed to the world (a floating base is a "
                     "<joint type=\"floating\"> from a link named 'world')",
                     root));
  }
  std::set<std::string> reached = {root};
  while (!stack.empty()) {
    const std::string link = stack.back();
    stack.pop_back();
    reached.insert(link);
    for (const std::string& j : children[link]) {
      JointEntry& entry = joints_.at(j);
      if (entry.joint.parent == model::kWorldBodyName && !root_is_world) {
        fail(entry.element, "a link named 'world' that is not the root");
      }
      const std::string& child = entry.joint.child;
      builder.add_body(child, links_.at(child).mass_properties);
      items.push_back(located(ModelItemRef::Kind::body, child, links_.at(child).element));
      builder.add_joint(entry.joint);
      items.push_back(located(ModelItemRef::Kind::joint, j, entry.element));
      stack.push_back(child);
    }
  }
  // Links every joint names but the root cannot reach: their joints close a cycle.
  if (reached.size() != link_order_.size()) {
    std::vector<std::string> stranded;
    for (const std::string& l : link_order_) {
      if (reached.count(l) == 0) stranded.push_back(l);
    }
    fail(links_.at(stranded.front()).element,
         fmt::format("links '{}' do not hang from the root '{}': their joints form a cycle (a URDF "
                     "describes a tree)",
                     fmt::join(stranded, "', '"), root));
  }
  // Mimic joints: couplers q = multiplier · q_mimicked + offset.
  for (const std::string& j : joint_order_) {
    const JointEntry& entry = joints_.at(j);
    if (entry.mimic.empty()) continue;
    if (joints_.count(entry.mimic) == 0) {
      std::vector<std::string_view> names(joint_order_.begin(), joint_order_.end());
      fail(entry.mimic_element, fmt::format("joint '{}' mimics an unknown joint '{}'{}", j,
                                            entry.mimic, did_you_mean(entry.mimic, names)));
    }
    model::JointCoupler coupler;
    coupler.name = j + "_mimic";
    coupler.joint_a = j;
    coupler.joint_b = entry.mimic;
    coupler.ratio = entry.multiplier;
    coupler.offset = entry.offset;
    builder.add_constraint(coupler);
    items.push_back(located(ModelItemRef::Kind::constraint, coupler.name, entry.mimic_element));
  }
  model::Model model = build(builder, items);
  const char* robot_name = robot->Attribute("name");
  std::vector<std::vector<PartSummary>> body_parts(model.bodies().size());
  for (std::size_t b = 0; b < model.bodies().size(); ++b) {
    const auto link = links_.find(model.bodies()[b].name);
    if (link != links_.end()) body_parts[b] = link->second.drawn;
  }
  // The notes in the file's order.
  std::sort(notes_.begin(), notes_.end());
  std::vector<std::string> notes;
  for (auto& [line, text] : notes_) notes.push_back(std::move(text));
  return ModelFile{
      robot_name != nullptr ? robot_name : std::filesystem::path(file_).stem().string(),
      "",
      std::move(model),
      {},
      model::SimulationSettings{},
      file_,
      std::move(items),
      std::move(body_parts),
      {},
      std::move(notes),
      {},
      {},
      {}};
}

// builder.build(), a joint that would carry only massless links said with the links that have
// no <inertial> and how to weigh them.
model::Model UrdfReader::build(const model::ModelBuilder& builder,
                               const std::vector<ItemLocation>& items) {
  const auto hint = [&](const InvalidArgument& error) -> std::string {
    if (!error.item() || error.item()->kind != ModelItemRef::Kind::joint) return {};
    const auto joint = joints_.find(error.item()->name);
    if (joint == joints_.end()) return {};
    std::vector<std::string> unweighed, stack = {joint->second.joint.child};
    while (!stack.empty()) {
      const std::string link = stack.back();
      stack.pop_back();
      if (!links_.at(link).has_inertial && links_.at(link).mass_properties.mass() == 0.0) {
        unweighed.push_back(link);
      }
      for (const auto& [name, entry] : joints_) {
        if (entry.joint.parent == link) stack.push_back(entry.joint.child);
      }
    }
    if (unweighed.empty()) return {};
    return fmt::format(
        " (link '{}' has no <inertial>: give it one{})", fmt::join(unweighed, "', '"),
        options_.link_density ? std::string()
                              : ", or a link density (‹link_density›) to take its mass from "
                                "its collision or visual geometry");
  };
  return build_at_lines(builder, items, file_, hint);
}

namespace {

ModelFile parse_document(const tinyxml2::XMLDocument& document, const std::string& file_name,
                         const ModelFileOptions& options, const std::filesystem::path& base_dir) {
  check_xml_document(document, file_name, "a URDF file holds a <robot>");
  return UrdfReader(document, file_name, options, base_dir).read();
}

}  // namespace
}  // namespace momenta::io::detail

namespace momenta::io {

bool is_urdf_path(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".urdf";
}

ModelFile read_urdf_file(const std::filesystem::path& path, const ModelFileOptions& options) {
  return parse_urdf(detail::read_xml_text(path.string(), "URDF file"), path.string(), options,
                    path.parent_path());
}

ModelFile parse_urdf(const std::string& text, const std::string& file_name,
                     const ModelFileOptions& options, const std::filesystem::path& base_dir) {
  tinyxml2::XMLDocument document;
  document.Parse(text.c_str(), text.size());
  return detail::parse_document(document, file_name, options, base_dir);
}

}  // namespace momenta::io
