// MJCF's contacts as momenta's unilateral contacts (docs/model-formats.md, docs/contacts.md): each
// geom of a moving body against each plane of the world that MuJoCo would collide it with — a
// sphere as itself, a capsule as the spheres at its two ends, a cylinder as the rims of its two
// faces, a box as its eight corners —, with MuJoCo's sliding friction and no rebound. MuJoCo's
// contacts are soft (a spring and damper set by solref and solimp); momenta's are rigid: no
// penetration, friction that sticks, impacts where a geom lands.

#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "mjcf/mjcf_reader.hpp"
#include "momenta/common/error.hpp"
#include "xml/xml_support.hpp"

namespace momenta::io::detail {
namespace {

// What MuJoCo mixes into a contact's parameters from each of its two geoms.
struct Surface {
  int contype = 1;
  int conaffinity = 1;
  int condim = 3;
  int priority = 0;
  double sliding_friction = 1.0;
};

Surface surface_of(const MjcfReader& reader, const MjcfGeom& geom) {
  const MjcfElement& e = geom.element;
  Surface s;
  s.contype = static_cast<int>(reader.number(e, "contype", 1.0));
  s.conaffinity = static_cast<int>(reader.number(e, "conaffinity", 1.0));
  s.condim = static_cast<int>(reader.number(e, "condim", 3.0));
  s.priority = static_cast<int>(reader.number(e, "priority", 0.0));
  const std::vector<double> friction =
      reader.numbers(e, "friction", 1, 3, std::vector<double>{1.0, 0.005, 0.0001});
  s.sliding_friction = friction[0];
  const MjcfAttribute where = reader.attribute(e, "friction");
  if (!(s.sliding_friction >= 0.0)) {
    reader.fail(where.where, fmt::format("the friction of {} is negative", geom.label), "friction");
  }
  if (s.condim != 1 && s.condim != 3 && s.condim != 4 && s.condim != 6) {
    reader.fail(
        reader.attribute(e, "condim").where,
        fmt::format("the condim of {} is {}: MuJoCo's are 1, 3, 4 and 6", geom.label, s.condim),
        "condim");
  }
  return s;
}

// MuJoCo's filter: a pair is tested where either's contype shares a bit with the other's
// conaffinity.
bool collide(const Surface& a, const Surface& b) {
  return (a.contype & b.conaffinity) != 0 || (b.contype & a.conaffinity) != 0;
}

// MuJoCo's mixing: the geom of higher priority gives the contact's parameters; at equal priority
// the larger condim and the larger friction.
Surface mixed(const Surface& a, const Surface& b) {
  if (a.priority != b.priority) return a.priority > b.priority ? a : b;
  Surface s = a;
  s.condim = std::max(a.condim, b.condim);
  s.sliding_friction = std::max(a.sliding_friction, b.sliding_friction);
  return s;
}

// One shape momenta poses on the body: a sphere (a point where the radius is 0) or a disk's rim
// about its frame's z axis, and the suffix its contact's name takes.
struct Feature {
  std::string suffix;
  Transform X_BF;
  model::ContactShape shape;
  double radius;
};

// The shapes standing in for a geom; none for the geoms momenta cannot pose.
std::vector<Feature> features_of(const MjcfGeom& geom) {
  const auto along_axis = [&](double z) { return geom.X_BG * Transform::translation({0, 0, z}); };
  if (geom.type == "sphere") {
    return {{"", geom.X_BG, model::ContactShape::sphere, geom.size[0]}};
  }
  if (geom.type == "capsule") {
    const double r = geom.size[0], h = geom.size[1];
    return {{"_end1", along_axis(-h), model::ContactShape::sphere, r},
            {"_end2", along_axis(h), model::ContactShape::sphere, r}};
  }
  if (geom.type == "cylinder") {
    const double r = geom.size[0], h = geom.size[1];
    return {{"_rim1", along_axis(-h), model::ContactShape::disk, r},
            {"_rim2", along_axis(h), model::ContactShape::disk, r}};
  }
  if (geom.type == "box") {  // its eight corners, points (size: the half lengths)
    std::vector<Feature> corners;
    for (int k = 0; k < 8; ++k) {
      const Vec3 p_GC((k & 1) ? geom.size[0] : -geom.size[0],
                      (k & 2) ? geom.size[1] : -geom.size[1],
                      (k & 4) ? geom.size[2] : -geom.size[2]);
      corners.push_back({fmt::format("_corner{}", k + 1), geom.X_BG * Transform::translation(p_GC),
                         model::ContactShape::sphere, 0.0});
    }
    return corners;
  }
  return {};
}

}  // namespace

std::string shape_with_article(std::string_view type) {
  const bool vowel = !type.empty() && std::string_view("aeiou").find(type[0]) != std::string::npos;
  return fmt::format("{} {}", vowel ? "an" : "a", type);
}

void MjcfReader::read_contact_section(const XMLElement* section) {
  for (const XMLElement* xml = section->FirstChildElement(); xml != nullptr;
       xml = xml->NextSiblingElement()) {
    const std::string_view kind = xml->Name();
    if (kind != "exclude") {
      note(xml, fmt::format("<{}> of <contact>: not used (momenta's contacts are the bodies' "
                            "geoms against the world's planes)",
                            kind));
      continue;
    }
    check_attributes(xml, {"name", "body1", "body2"});
    const char* ends[2] = {xml->Attribute("body1"), xml->Attribute("body2")};
    const char* attributes[2] = {"body1", "body2"};
    for (int k = 0; k < 2; ++k) {
      if (ends[k] == nullptr) {
        fail(xml, fmt::format("<exclude> needs the attribute '{}'", attributes[k]));
      }
      if (std::string_view(ends[k]) != model::kWorldBodyName) {
        body_named(xml, attributes[k], ends[k]);
      }
    }
    for (int k = 0; k < 2; ++k) {
      if (std::string_view(ends[k]) == model::kWorldBodyName) {
        excluded_from_world.insert(ends[1 - k]);
      }
    }
  }
}

void MjcfReader::add_contacts() {
  if (world_planes.empty()) return;
  if (!contacts_on) {
    note(world_planes.front().element.xml,
         "contacts are disabled (<option><flag contact=\"disable\">): the world's planes hold "
         "nothing");
    return;
  }
  bool between_bodies_noted = false;
  std::vector<Surface> geom_surfaces;  // each body geom's, read once for every plane
  for (const MjcfGeom& geom : body_geoms) geom_surfaces.push_back(surface_of(*this, geom));
  for (const MjcfGeom& plane : world_planes) {
    const Surface plane_surface = surface_of(*this, plane);
    const Vec3 n_W = plane.X_BG.R.col(2);
    for (std::size_t g = 0; g < body_geoms.size(); ++g) {
      const MjcfGeom& geom = body_geoms[g];
      if (moving_bodies.count(geom.body) == 0 || excluded_from_world.count(geom.body) != 0) {
        continue;
      }
      const Surface& geom_surface = geom_surfaces[g];
      if (!collide(plane_surface, geom_surface)) continue;
      const std::vector<Feature> features = features_of(geom);
      if (features.empty()) {
        note(geom.element.xml,
             fmt::format("{} ({}) passes through {}: momenta poses spheres, capsules, "
                         "cylinders and boxes on planes",
                         geom.label, shape_with_article(geom.type), plane.label));
        continue;
      }
      const Surface s = mixed(plane_surface, geom_surface);
      if (s.condim > 3) {
        note(geom.element.xml,
             fmt::format("{} on {}: condim {} — its torsional{} friction is not modelled (the "
                         "sliding friction is)",
                         geom.label, plane.label, s.condim, s.condim == 6 ? " and rolling" : ""));
      }
      const double mu = s.condim == 1 ? 0.0 : s.sliding_friction;
      for (const Feature& f : features) {
        model::Contact contact;
        contact.name = fmt::format("{}{}_{}", geom.name, f.suffix, plane.name);
        contact.frame = {geom.body, f.X_BF};
        contact.shape = f.shape;
        contact.radius = f.radius;
        contact.plane_normal = n_W;
        contact.plane_point = plane.X_BG.p;
        contact.restitution = 0.0;
        contact.static_friction = mu;
        contact.kinetic_friction = mu;
        builder.add_constraint(contact);
        items.push_back(located_at(ModelItemRef::Kind::constraint, contact.name,
                                   geom.element.xml->GetLineNum(),
                                   xml_column(text, geom.element.xml)));
      }
      if (!between_bodies_noted && moving_bodies.size() > 1) {
        note(geom.element.xml,
             "the bodies' geoms touch the world's planes; against each other they pass through "
             "(momenta does not import contacts between bodies)");
        between_bodies_noted = true;
      }
    }
  }
}

}  // namespace momenta::io::detail
