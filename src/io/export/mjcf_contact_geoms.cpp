// The MuJoCo geoms of a model's contacts (mjcf_contact_geoms.hpp).

#include "export/mjcf_contact_geoms.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <optional>
#include <string_view>
#include <variant>

#include <fmt/format.h>

namespace momenta::io::detail {
namespace {

// Two rims are one cylinder's, and eight points one box's corners, where they are so to this
// fraction of the shape's size: the last bits of a file's numbers, or of a reader's product
// X_BG · (±size), and nothing a model would mean.
constexpr double kSameShape = 1e-12;

// A contact with a ground plane, and what a geom standing for it with others must share.
struct GroundContact {
  std::size_t index;  // the constraint's
  const model::Contact* contact;
  std::pair<Vec3, Vec3> plane;  // (unit normal, point)

  bool shares_geom_with(const GroundContact& other) const {
    return contact->frame.body_index == other.contact->frame.body_index &&
           contact->shape == other.contact->shape && plane == other.plane &&
           contact->static_friction == other.contact->static_friction;
  }
  Vec3 p_BF() const { return contact->frame.X_BF.p; }
  Vec3 axis() const { return contact->frame.X_BF.R.col(2); }
};

std::vector<GroundContact> ground_contacts_of(const model::Model& model) {
  std::vector<GroundContact> out;
  for (std::size_t i = 0; i < model.constraints().size(); ++i) {
    const auto* c = std::get_if<model::Contact>(&model.constraints()[i]);
    if (c == nullptr || !c->on_ground()) continue;
    out.push_back({i, c, {c->plane_normal.normalized(), c->plane_point}});
  }
  return out;
}

// A cylinder whose face rims are the disks `a` and `b` (a's at −h along its z, b's at +h), or
// none where they are not coaxial, apart and of one radius.
std::optional<MjcfContactGeom> cylinder_of(const GroundContact& a, const GroundContact& b) {
  const double r = a.contact->radius;
  const Vec3 d = b.p_BF() - a.p_BF();
  const double length = d.norm();
  const Vec3 z = a.axis();
  if (!(length > 0.0) || std::abs(b.contact->radius - r) > kSameShape * r ||
      z.cross(b.axis()).norm() > kSameShape || z.cross(d).norm() > kSameShape * length) {
    return std::nullopt;
  }
  MjcfContactGeom g;
  g.type = "cylinder";
  g.size = Vec3(r, length / 2.0, 0.0);
  Mat3 R = a.contact->frame.X_BF.R;
  if (z.dot(d) < 0.0) R = R * Vec3(1.0, -1.0, -1.0).asDiagonal();  // turned about x: z along d
  g.X_BG = Transform(R, a.p_BF() + d / 2.0);
  return g;
}

// The box whose corners are `corners`, or none. Its edges are the shortest vectors from the first
// corner to the others that are square to each other; every corner must be that corner plus a
// choice of edges, each choice once.
std::optional<MjcfContactGeom> box_of(const std::array<Vec3, 8>& corners) {
  std::array<Vec3, 7> to_others;
  double diagonal = 0.0;
  for (std::size_t k = 1; k < 8; ++k) {
    to_others[k - 1] = corners[k] - corners[0];
    diagonal = std::max(diagonal, to_others[k - 1].norm());
  }
  const double tolerance = kSameShape * diagonal;
  if (!(tolerance > 0.0)) return std::nullopt;
  std::vector<Vec3> edge_vectors;  // the edges found so far
  for (int n = 0; n < 3; ++n) {
    const Vec3* shortest = nullptr;
    for (const Vec3& v : to_others) {
      const bool square = std::all_of(edge_vectors.begin(), edge_vectors.end(), [&](const Vec3& e) {
        return std::abs(v.dot(e.normalized())) <= tolerance;
      });
      if (v.norm() > tolerance && square && (shortest == nullptr || v.norm() < shortest->norm())) {
        shortest = &v;
      }
    }
    if (shortest == nullptr) return std::nullopt;
    edge_vectors.push_back(*shortest);
  }
  std::array<bool, 8> matched{};
  for (int choice = 0; choice < 8; ++choice) {
    Vec3 corner = corners[0];
    for (int n = 0; n < 3; ++n) {
      if (choice & (1 << n)) corner += edge_vectors[static_cast<std::size_t>(n)];
    }
    const auto same = [&](std::size_t k) {
      return !matched[k] && (corners[k] - corner).norm() <= tolerance;
    };
    std::size_t k = 0;
    while (k < 8 && !same(k)) ++k;
    if (k == 8) return std::nullopt;
    matched[k] = true;
  }
  // Its axes: the edge nearest the body's x first, then y (each pointing along the body's axis
  // rather than against it; the box is symmetric), and z completing a right-handed frame — the
  // body's own axes for a box square to them.
  MjcfContactGeom g;
  g.type = "box";
  Mat3 R;
  std::array<bool, 3> placed{};
  std::array<Vec3, 3> edges;  // their directions
  for (std::size_t n = 0; n < 3; ++n) edges[n] = edge_vectors[n].normalized();
  for (int axis = 0; axis < 2; ++axis) {
    std::size_t best = 0;
    for (std::size_t n = 0; n < 3; ++n) {
      if (!placed[n] && (placed[best] || std::abs(edges[n][axis]) > std::abs(edges[best][axis]))) {
        best = n;
      }
    }
    placed[best] = true;
    R.col(axis) = edges[best][axis] < 0.0 ? Vec3(-edges[best]) : edges[best];
    g.size[axis] = edge_vectors[best].norm() / 2.0;
  }
  const std::size_t last =
      static_cast<std::size_t>(std::find(placed.begin(), placed.end(), false) - placed.begin());
  R.col(2) = R.col(0).cross(R.col(1));
  g.size[2] = edge_vectors[last].norm() / 2.0;
  g.X_BG = Transform(R, corners[0] + (edge_vectors[0] + edge_vectors[1] + edge_vectors[2]) / 2.0);
  return g;
}

// What the names of a geom's contacts share: their common start less a trailing number, '_' and
// the reader's suffix for a cylinder's rim or a box's corner ("crate_corner1_floor", …,
// "crate_corner8_floor": "crate").
std::string stem_of(const std::vector<std::string>& names) {
  std::string stem = names.front();
  for (const std::string& name : names) {
    const auto end = std::mismatch(stem.begin(), stem.end(), name.begin(), name.end()).first;
    stem.erase(end, stem.end());
  }
  const auto trim = [&] {
    while (!stem.empty() &&
           (stem.back() == '_' || std::isdigit(static_cast<unsigned char>(stem.back()))))
      stem.pop_back();
  };
  trim();
  for (const std::string_view suffix : {"_corner", "_rim"}) {
    if (stem.size() > suffix.size() && stem.ends_with(suffix))
      stem.resize(stem.size() - suffix.size());
  }
  trim();
  return stem.empty() ? "contact" : stem;
}

// `name`, or `name_contact`, `name_contact2`, … where taken; then it is taken.
std::string unique(const std::string& name, std::vector<std::string>& taken) {
  std::string out = name;
  for (int n = 1; std::find(taken.begin(), taken.end(), out) != taken.end(); ++n) {
    out = n == 1 ? name + "_contact" : fmt::format("{}_contact{}", name, n);
  }
  taken.push_back(out);
  return out;
}

}  // namespace

MjcfContactGeoms mjcf_contact_geoms(const model::Model& model, std::vector<std::string> taken) {
  const std::vector<GroundContact> contacts = ground_contacts_of(model);
  std::vector<bool> used(contacts.size(), false);
  MjcfContactGeoms out;
  const auto add = [&](MjcfContactGeom geom, const std::vector<std::size_t>& members) {
    const GroundContact& first = contacts[members.front()];
    std::vector<std::string> names;
    for (std::size_t m : members) {
      used[m] = true;
      geom.contacts.push_back(contacts[m].index);
      names.push_back(contacts[m].contact->name);
    }
    geom.name = unique(members.size() == 1 ? names.front() : stem_of(names), taken);
    geom.body = first.contact->frame.body_index;
    geom.friction = first.contact->static_friction;
    auto plane = std::find(out.planes.begin(), out.planes.end(), first.plane);
    geom.plane = static_cast<std::size_t>(plane - out.planes.begin());
    if (plane == out.planes.end()) out.planes.push_back(first.plane);
    out.geoms.push_back(std::move(geom));
  };
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    if (used[i]) continue;
    const GroundContact& c = contacts[i];
    if (c.contact->shape == model::ContactShape::sphere && c.contact->radius > 0.0) {
      MjcfContactGeom sphere;
      sphere.type = "sphere";
      sphere.size = Vec3(c.contact->radius, 0.0, 0.0);
      sphere.X_BG = Transform::translation(c.p_BF());
      add(sphere, {i});
    } else if (c.contact->shape == model::ContactShape::disk) {
      for (std::size_t j = i + 1; j < contacts.size(); ++j) {
        if (used[j] || !c.shares_geom_with(contacts[j])) continue;
        if (std::optional<MjcfContactGeom> cylinder = cylinder_of(c, contacts[j])) {
          add(*cylinder, {i, j});
          break;
        }
      }
    } else {  // a point: with the next seven of its kind, a box's corners?
      std::vector<std::size_t> members{i};
      for (std::size_t j = i + 1; j < contacts.size() && members.size() < 8; ++j) {
        if (!used[j] && contacts[j].contact->radius == 0.0 && c.shares_geom_with(contacts[j])) {
          members.push_back(j);
        }
      }
      if (members.size() < 8) continue;
      std::array<Vec3, 8> corners;
      for (std::size_t k = 0; k < 8; ++k) corners[k] = contacts[members[k]].p_BF();
      if (std::optional<MjcfContactGeom> box = box_of(corners)) add(*box, members);
    }
  }
  return out;
}

}  // namespace momenta::io::detail
