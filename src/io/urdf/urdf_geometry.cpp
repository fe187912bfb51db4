// A URDF link's geometry: the <visual> and <collision> shapes the report draws (box, cylinder,
// sphere, mesh), the mass properties of a link without <inertial> from its geometry filled with a
// stated density, and where a mesh's file name (package://, file://, relative) leads
// (wiki.ros.org/urdf/XML/link; docs/model-formats.md#meshes).

#include <cmath>
#include <cstdlib>
#include <system_error>

#include <fmt/format.h>

#include "momenta/common/error.hpp"
#include "momenta/common/one_line.hpp"
#include "momenta/inertia/mesh_mass_properties.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta/io/mesh_file.hpp"
#include "urdf/urdf_reader.hpp"

namespace momenta::io::detail {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kPackageScheme = "package://";
constexpr std::string_view kFileScheme = "file://";

// A folder named `package` below `root`, at most `depth` levels down, that holds a package.xml
// (how ROS tells a package from any folder of that name); empty when there is none.
fs::path find_package_below(const fs::path& root, const std::string& package, int depth) {
  std::error_code error;
  for (fs::directory_iterator it(root, error), end; !error && it != end; it.increment(error)) {
    if (!it->is_directory(error)) continue;
    const fs::path& folder = it->path();
    if (folder.filename() == package && fs::exists(folder / "package.xml", error)) return folder;
    if (depth > 1) {
      const fs::path found = find_package_below(folder, package, depth - 1);
      if (!found.empty()) return found;
    }
  }
  return {};
}

// The folder of package `package` on `search`: an entry named so, an entry's sub-folder named
// so, or (as ROS finds packages in a workspace) one up to three levels down beside a package.xml.
fs::path find_package(const std::string& package, const std::vector<fs::path>& search) {
  std::error_code error;
  for (const fs::path& folder : search) {
    if (folder.filename() == package && fs::is_directory(folder, error)) return folder;
    if (fs::is_directory(folder / package, error)) return folder / package;
  }
  for (const fs::path& folder : search) {
    const fs::path found = find_package_below(folder, package, 3);
    if (!found.empty()) return found;
  }
  return {};
}

}  // namespace

std::vector<fs::path> package_search_path(const std::vector<fs::path>& given) {
  std::vector<fs::path> search = given;
  if (const char* ros = std::getenv("ROS_PACKAGE_PATH")) {
    std::string_view rest = ros;
    while (!rest.empty()) {
      const std::size_t colon = rest.find(':');
      const std::string_view entry = rest.substr(0, colon);
      if (!entry.empty()) search.emplace_back(entry);
      rest = colon == std::string_view::npos ? std::string_view() : rest.substr(colon + 1);
    }
  }
  return search;
}

fs::path resolve_mesh_uri(std::string_view uri, const fs::path& base_dir,
                          const std::vector<fs::path>& package_path) {
  if (uri.substr(0, kPackageScheme.size()) == kPackageScheme) {
    const std::string_view rest = uri.substr(kPackageScheme.size());
    const std::size_t slash = rest.find('/');
    const std::string package(rest.substr(0, slash));
    if (package.empty() || slash == std::string_view::npos || slash + 1 == rest.size()) {
      throw InvalidArgument(
          fmt::format("'{}' is not package://PACKAGE/path/to/mesh", std::string(uri)));
    }
    if (package_path.empty()) {
      throw InvalidArgument(OptionMessage{fmt::format(
          "'{}' names package '{}', and no package path is given: give the folder that holds "
          "it with ‹package_path› or ROS_PACKAGE_PATH",
          std::string(uri), package)});
    }
    const fs::path folder = find_package(package, package_path);
    if (folder.empty()) {
      std::vector<std::string> searched;
      for (const fs::path& p : package_path) searched.push_back(p.string());
      throw InvalidArgument(OptionMessage{fmt::format(
          "package '{}' of '{}' is not found in {} (neither a folder of that name nor one "
          "holding it): give the folder that holds it with ‹package_path›",
          package, std::string(uri), fmt::join(searched, ", "))});
    }
    return folder / fs::path(std::string(rest.substr(slash + 1)));
  }
  if (uri.substr(0, kFileScheme.size()) == kFileScheme) {
    return fs::path(std::string(uri.substr(kFileScheme.size())));
  }
  const std::size_t scheme = uri.find("://");
  if (scheme != std::string_view::npos) {
    throw InvalidArgument(fmt::format(
        "'{}': momenta reads meshes from package://, file:// or a path relative to the URDF's "
        "folder, not {}://",
        std::string(uri), std::string(uri.substr(0, scheme))));
  }
  const fs::path path{std::string(uri)};
  return path.is_absolute() ? path : base_dir / path;
}

std::shared_ptr<const inertia::TriangleMesh> UrdfReader::mesh(const XMLElement* at,
                                                              const std::string& uri,
                                                              const Vec3& scale, bool weighed) {
  const std::string key = fmt::format("{}|{}|{}|{}", uri, scale.x(), scale.y(), scale.z());
  if (const auto cached = meshes_.find(key); cached != meshes_.end()) return cached->second;
  std::string why;  // why it cannot be had, with the options that would help marked
  std::shared_ptr<const inertia::TriangleMesh> shared;
  try {
    const fs::path path = resolve_mesh_uri(uri, base_dir_, package_path_);
    try {
      shared = std::make_shared<const inertia::TriangleMesh>(read_mesh_file(path, scale));
    } catch (const Error& error) {
      why = fmt::format("mesh '{}': {}", uri, one_line(error.spelled(keep_option_marks)));
    }
  } catch (const InvalidArgument& error) {
    why = one_line(error.spelled(keep_option_marks));
  }
  if (!why.empty()) {  // not kept: each element that names it fails or is noted at its own line
    if (weighed) fail(at, why);
    note(at, fmt::format("not drawn: {}", why));
    return nullptr;
  }
  meshes_.emplace(key, shared);
  return shared;
}

std::optional<PartSummary> UrdfReader::geometry_part(const XMLElement* e, const std::string& owner,
                                                     std::size_t index,
                                                     std::optional<double> density) {
  const std::string role = e->Name();  // "visual" or "collision"
  PartSummary part;
  const char* name = e->Attribute("name");
  part.name = name != nullptr && *name != '\0' ? name : fmt::format("{}[{}]", role, index);
  part.line = e->GetLineNum();
  const Transform X_BS = origin(e);
  part.R_BS = X_BS.R;
  part.p_BoSo_B = X_BS.p;
  const XMLElement* geometry = e->FirstChildElement("geometry");
  if (geometry == nullptr) fail(e, fmt::format("the <{}> of {} needs a <geometry>", role, owner));
  const XMLElement* shape = geometry->FirstChildElement();
  if (shape == nullptr || shape->NextSiblingElement() != nullptr) {
    fail(geometry, fmt::format("the <geometry> of the <{}> of {} holds one of <box>, "
                               "<cylinder>, <sphere> or <mesh>",
                               role, owner));
  }
  const std::string kind = shape->Name();
  const std::string what = fmt::format("the {} {} of {}", role, kind, owner);
  const auto positive = [&](const char* attribute) {
    const double value = number(shape, attribute, std::nullopt);
    if (!(value > 0.0)) {
      fail(shape, fmt::format("the {} of {} is {} m: it must be positive", attribute, what, value));
    }
    return value;
  };
  // The amount a solid is filled with, where its mass is wanted.
  const inertia::Amount fill = inertia::Amount::density(density.value_or(1.0));
  inertia::MassProperties in_S;
  part.kind = kind;
  if (kind == "box") {
    const Vec3 size = vector3(shape, "size", Vec3::Zero());
    if (!(size.minCoeff() > 0.0)) {
      fail(shape, fmt::format("the size of {} must be three positive lengths (m)", what));
    }
    part.sizes = {{"size.x", size.x()}, {"size.y", size.y()}, {"size.z", size.z()}};
    if (density) in_S = inertia::box(fill, size);
  } else if (kind == "cylinder") {
    const double radius = positive("radius"), length = positive("length");
    part.sizes = {{"radius", radius}, {"length", length}};
    if (density) in_S = inertia::solid_cylinder(fill, radius, length);
  } else if (kind == "sphere") {
    const double radius = positive("radius");
    part.sizes = {{"radius", radius}};
    if (density) in_S = inertia::solid_sphere(fill, radius);
  } else if (kind == "mesh") {
    const char* file = shape->Attribute("filename");
    if (file == nullptr || *file == '\0') {
      fail(shape, fmt::format("the mesh of the <{}> of {} needs a filename", role, owner));
    }
    const Vec3 scale = vector3(shape, "scale", Vec3::Ones());
    if (!(scale.cwiseAbs().minCoeff() > 0.0)) {
      fail(shape, fmt::format("the scale of {} has a zero factor", what));
    }
    part.mesh = mesh(shape, file, scale, density.has_value());
    if (part.mesh == nullptr) return std::nullopt;  // only drawn, and noted as not drawn
    if (density) {
      inertia::TriangleMesh solid = *part.mesh;
      try {
        inertia::prepare_solid_mesh(solid, file);
        in_S = inertia::solid_mesh_mass_properties(solid, fill);
      } catch (const Error& error) {
        fail(shape, fmt::format("{} has no <inertial>, and its {} mesh cannot give its mass: {}",
                                owner, role, one_line(error.what())));
      }
    }
  } else {
    fail(shape, fmt::format("<{}> in the <geometry> of the <{}> of {}: URDF's shapes are <box>, "
                            "<cylinder>, <sphere> and <mesh>",
                            kind, role, owner));
  }
  part.mass_properties = in_S.transformed(X_BS.R, X_BS.p);
  for (const XMLElement* c = e->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    const std::string_view child = c->Name();
    if (child == "origin" || child == "geometry") continue;
    note(c, fmt::format("<{}> in the <{}> of {}: not used by momenta{}", child, role, owner,
                        child == "material" ? " (the report colours each body)" : ""));
  }
  return part;
}

void UrdfReader::read_geometry(const XMLElement* e, Link& link, const std::string& owner) {
  std::vector<const XMLElement*> visuals, collisions;
  for (const XMLElement* c = e->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    const std::string_view kind = c->Name();
    if (kind == "visual") visuals.push_back(c);
    if (kind == "collision") collisions.push_back(c);
  }
  // The solid that gives a link without <inertial> its mass: its collision geometry, else its
  // visual geometry. What is drawn: its visual geometry, else its collision geometry.
  const bool weighed = !link.has_inertial && options_.link_density.has_value();
  const bool solid_is_collision = !collisions.empty();
  const bool drawn_is_visual = !visuals.empty();
  const std::vector<const XMLElement*>& solids = solid_is_collision ? collisions : visuals;
  const std::vector<const XMLElement*>& drawn = drawn_is_visual ? visuals : collisions;
  std::vector<PartSummary> weighed_parts;
  if (weighed) {
    for (std::size_t i = 0; i < solids.size(); ++i) {
      weighed_parts.push_back(*geometry_part(solids[i], owner, i, options_.link_density));
      link.mass_properties += weighed_parts.back().mass_properties;
    }
  } else if (!link.has_inertial && !solids.empty()) {
    note(e, fmt::format("{} has no <inertial>: massless (a link density, ‹link_density›, would "
                        "give it the mass of its geometry)",
                        owner));
  }
  // The weighed parts are drawn as they are when they are what is drawn (one kind of geometry).
  if (weighed && solid_is_collision != drawn_is_visual) {
    link.drawn = std::move(weighed_parts);
  } else {
    for (std::size_t i = 0; i < drawn.size(); ++i) {
      if (auto part = geometry_part(drawn[i], owner, i, std::nullopt))
        link.drawn.push_back(std::move(*part));
    }
  }
  // Collision geometry neither drawn nor weighed.
  if (drawn_is_visual && !(weighed && solid_is_collision)) {
    for (const XMLElement* c : collisions) {
      note(c, fmt::format("<collision> of {}: not used by momenta (contacts are not modelled)",
                          owner));
    }
  }
}

}  // namespace momenta::io::detail
