// MJCF frames (pos and the five ways to give an orientation) and a body's mass properties from
// its <inertial> or, by MuJoCo's rule, from its geoms (mujoco.readthedocs.io, XML Reference:
// body/inertial, body/geom, compiler/inertiafromgeom).

#include <cmath>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "mjcf/mjcf_reader.hpp"
#include "momenta/common/error.hpp"
#include "momenta/common/one_line.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/inertia/mesh_mass_properties.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta/io/mesh_file.hpp"
#include "momenta/math/rotation.hpp"
#include "xml/xml_support.hpp"

namespace momenta::io::detail {
namespace {

// R_AB from MuJoCo's euler angles: each lower-case axis turns with the frame (post-multiplied),
// each upper-case one stays fixed in the parent (pre-multiplied), as MuJoCo composes them.
Mat3 rotation_from_mjcf_euler(std::string_view sequence, const Vec3& angles) {
  Mat3 R = Mat3::Identity();
  for (int i = 0; i < 3; ++i) {
    const char axis = sequence[static_cast<std::size_t>(i)];
    const int k = std::tolower(static_cast<unsigned char>(axis)) - 'x';
    const Mat3 turn = rotation_from_axis_angle(Vec3::Unit(k), angles[i]);
    R = std::islower(static_cast<unsigned char>(axis)) ? Mat3(R * turn) : Mat3(turn * R);
  }
  return R;
}

}  // namespace

Transform MjcfReader::pose(const MjcfElement& e) const {
  const Vec3 p = vector3(e, "pos", Vec3::Zero());
  // At most one orientation, as MuJoCo requires.
  const char* given = nullptr;
  for (const char* name : {"quat", "axisangle", "euler", "xyaxes", "zaxis"}) {
    if (!attribute(e, name)) continue;
    if (given != nullptr && e.xml->Attribute(name) != nullptr) {
      fail(e.xml,
           fmt::format("<{}> gives its orientation twice ('{}' and '{}')", e.xml->Name(), given,
                       name),
           name);
    }
    if (given == nullptr) given = name;
  }
  if (given == nullptr) return Transform::translation(p);
  const std::string_view kind = given;
  const MjcfAttribute where = attribute(e, given);
  Mat3 R;
  if (kind == "quat") {
    const std::vector<double> q = numbers(e, "quat", 4, 4);
    const Quat quat(q[0], q[1], q[2], q[3]);
    if (!(quat.norm() > 1e-12)) fail(where.where, "the quaternion is zero", "quat");
    R = quat.normalized().toRotationMatrix();
  } else if (kind == "axisangle") {
    const std::vector<double> a = numbers(e, "axisangle", 4, 4);
    const Vec3 axis(a[0], a[1], a[2]);
    if (!(axis.norm() > 1e-12)) fail(where.where, "the rotation axis is zero", "axisangle");
    R = rotation_from_axis_angle(axis.normalized(), a[3] * angle_scale);
  } else if (kind == "euler") {
    R = rotation_from_mjcf_euler(euler_sequence, vector3(e, "euler", Vec3::Zero()) * angle_scale);
  } else if (kind == "xyaxes") {
    const std::vector<double> a = numbers(e, "xyaxes", 6, 6);
    Vec3 x(a[0], a[1], a[2]), y(a[3], a[4], a[5]);
    // y made perpendicular to x, as MuJoCo does.
    if (!(x.norm() > 1e-12)) fail(where.where, "the x axis is zero", "xyaxes");
    x.normalize();
    y -= x.dot(y) * x;
    if (!(y.norm() > 1e-12)) fail(where.where, "the y axis is zero or along x", "xyaxes");
    y.normalize();
    R.col(0) = x;
    R.col(1) = y;
    R.col(2) = x.cross(y);
  } else {
    const Vec3 z = vector3(e, "zaxis", Vec3::UnitZ());
    if (!(z.norm() > 1e-12)) fail(where.where, "the z axis is zero", "zaxis");
    R = Quat::FromTwoVectors(Vec3::UnitZ(), z.normalized()).toRotationMatrix();
  }
  return {R, p};
}

void MjcfReader::read_assets(const XMLElement* section) {
  for (const XMLElement* m = section->FirstChildElement(); m != nullptr;
       m = m->NextSiblingElement()) {
    if (std::string_view(m->Name()) != "mesh") {
      note(m, fmt::format("<{}> in <asset>: not used by momenta", m->Name()));
      continue;
    }
    check_attributes(m, {"name", "class", "content_type", "file", "vertex", "normal", "texcoord",
                         "face", "refpos", "refquat", "scale", "smoothnormal"});
    const MjcfElement e{m, "mesh", class_of(m, "main")};
    if (m->Attribute("vertex") != nullptr) {
      fail(m, "<mesh vertex=...>: momenta reads meshes from files (STL, OBJ)", "vertex");
    }
    const char* file_name = m->Attribute("file");
    if (file_name == nullptr || *file_name == '\0') fail(m, "<mesh> needs the attribute 'file'");
    for (const char* reference : {"refpos", "refquat"}) {
      if (m->Attribute(reference) != nullptr) {
        fail(m,
             fmt::format("<mesh {}>: momenta reads a mesh in the coordinates of its file",
                         reference),
             reference);
      }
    }
    std::filesystem::path path = file_name;
    if (strip_path) path = path.filename();
    if (!path.is_absolute()) path = mesh_dir / path;
    const char* given = m->Attribute("name");
    // MuJoCo names a mesh without a name after its file, without folder and extension.
    const std::string name =
        given != nullptr ? std::string(given) : std::filesystem::path(file_name).stem().string();
    if (meshes_.count(name) != 0) {
      fail(m,
           fmt::format("a second mesh named '{}' (the first is at line {})", name,
                       meshes_.at(name).element->GetLineNum()),
           "name");
    }
    meshes_.emplace(name, MeshAsset{m, path, vector3(e, "scale", Vec3::Ones()), nullptr});
  }
}

std::shared_ptr<const inertia::TriangleMesh> MjcfReader::mesh_asset(const XMLElement* at,
                                                                    const std::string& name) {
  const auto found = meshes_.find(name);
  if (found == meshes_.end()) {
    std::vector<std::string_view> names;
    for (const auto& [known, asset] : meshes_) names.push_back(known);
    fail(at, fmt::format("unknown mesh '{}'{}", name, did_you_mean(name, names)), "mesh");
  }
  MeshAsset& asset = found->second;
  if (asset.read) return asset.read;
  if (!(asset.scale.cwiseAbs().minCoeff() > 0.0)) {
    fail(asset.element, fmt::format("the scale of mesh '{}' has a zero factor", name), "scale");
  }
  try {
    asset.read =
        std::make_shared<const inertia::TriangleMesh>(read_mesh_file(asset.path, asset.scale));
  } catch (const Error& error) {
    fail(asset.element, fmt::format("mesh '{}': {}", name, one_line(error.what())), "file");
  }
  return asset.read;
}

std::optional<std::filesystem::path> MjcfReader::missing_mesh_file(const std::string& name) const {
  const auto found = meshes_.find(name);
  if (found == meshes_.end() || found->second.read) return std::nullopt;
  const std::filesystem::path& path = found->second.path;
  if (std::filesystem::exists(path)) return std::nullopt;
  return path;
}

std::pair<inertia::Amount, double> MjcfReader::geom_amount(const MjcfElement& e,
                                                           const std::string& label) const {
  // Its mass, or its density (MuJoCo's default 1000 kg/m³, water).
  const MjcfAttribute mass_given = attribute(e, "mass");
  const double amount = mass_given ? number(e, "mass", std::nullopt) : number(e, "density", 1000.0);
  if (amount < 0.0) {
    fail(e.xml, fmt::format("{} has a negative {}", label, mass_given ? "mass" : "density"),
         mass_given ? "mass" : "density");
  }
  return {mass_given ? inertia::Amount::mass(amount) : inertia::Amount::density(amount), amount};
}

// A mesh geom: the mesh asset it names, in its own coordinates (scaled), placed by the geom's
// pos and orientation — as MuJoCo composes the mesh's own offset into the geom frame, so the
// mesh lies where its file draws it — and, where the geoms give the body's mass, the solid it
// bounds (closed, exact: MuJoCo's exactmeshinertia; its legacy default agrees for convex meshes).
std::optional<PartSummary> MjcfReader::mesh_geom(const MjcfElement& e, const std::string& label,
                                                 const std::string& body, std::size_t index,
                                                 bool weighed) {
  const XMLElement* g = e.xml;
  if (attribute(e, "fromto")) {
    fail(g,
         fmt::format("{} is a mesh: fromto gives the axis of a capsule, cylinder, box or "
                     "ellipsoid (as MuJoCo requires)",
                     label),
         "fromto");
  }
  const MjcfAttribute named = attribute(e, "mesh");
  if (!named) fail(g, fmt::format("{} is a mesh and names none (mesh=\"...\")", label));
  const auto [material, amount] = geom_amount(e, label);
  // A mesh that only draws may be missing (files often travel without their meshes).
  if (!(weighed && amount > 0.0)) {
    if (const std::optional<std::filesystem::path> missing = missing_mesh_file(named.text)) {
      note(g, fmt::format("not drawn: {}: mesh '{}', file {} not found", label, named.text,
                          missing->string()));
      return std::nullopt;
    }
  }
  PartSummary part;
  part.kind = "mesh";
  part.mesh = mesh_asset(named.where, named.text);
  const Transform X_BG = pose(e);
  inertia::MassProperties in_G;
  if (weighed && amount > 0.0) {
    if (!exact_mesh_inertia && !mesh_inertia_noted_) {
      note(g,
           "mesh geoms are weighed as the solids they bound; MuJoCo 2.2 does so with "
           "<compiler exactmeshinertia=\"true\"> (its default can weigh a mesh otherwise)");
      mesh_inertia_noted_ = true;
    }
    inertia::TriangleMesh solid = *part.mesh;
    try {
      inertia::prepare_solid_mesh(solid, named.text);
      in_G = inertia::solid_mesh_mass_properties(solid, material);
    } catch (const Error& error) {
      fail(g,
           fmt::format("{}: mesh '{}' cannot give body '{}' its mass: {}; give the body an "
                       "<inertial>",
                       label, named.text, body, one_line(error.what())),
           "mesh");
    }
  }
  const char* given = g->Attribute("name");
  part.name = given != nullptr ? given : fmt::format("{}.geom{}", body, index);
  part.line = g->GetLineNum();
  part.mass_properties = in_G.transformed(X_BG.R, X_BG.p);
  part.R_BS = X_BG.R;
  part.p_BoSo_B = X_BG.p;
  return part;
}

inertia::MassProperties MjcfReader::body_mass_properties(const XMLElement* body,
                                                         const std::string& name,
                                                         const std::string& class_name,
                                                         std::vector<PartSummary>& parts) {
  const XMLElement* inertial = body->FirstChildElement("inertial");
  if (inertial != nullptr && inertial->NextSiblingElement("inertial") != nullptr) {
    fail(inertial->NextSiblingElement("inertial"),
         fmt::format("body '{}' has a second <inertial>", name));
  }
  const bool from_geoms =
      inertia_from_geom == "true" || (inertia_from_geom == "auto" && inertial == nullptr);
  if (inertial != nullptr && inertia_from_geom == "true") {
    note(inertial, fmt::format("the <inertial> of body '{}' is replaced by its geoms' (<compiler "
                               "inertiafromgeom=\"true\">)",
                               name));
  }

  // Every geom: its mass properties in B (drawn, and summed when the geoms give the mass).
  inertia::MassProperties from_geom_sum;
  int geom_index = 0;
  for (const XMLElement* g = body->FirstChildElement("geom"); g != nullptr;
       g = g->NextSiblingElement("geom"), ++geom_index) {
    check_attributes(
        g,
        {"name",      "class",      "type",      "contype",  "conaffinity", "condim",  "group",
         "priority",  "size",       "material",  "friction", "mass",        "density", "solmix",
         "solref",    "solimp",     "margin",    "gap",      "fromto",      "pos",     "quat",
         "axisangle", "xyaxes",     "zaxis",     "euler",    "hfield",      "mesh",    "fitscale",
         "rgba",      "fluidshape", "fluidcoef", "user",     "shellinertia"});
    const MjcfElement e{g, "geom", class_of(g, class_name)};
    const char* given = g->Attribute("name");
    const std::string label = given != nullptr ? fmt::format("geom '{}'", given)
                                               : fmt::format("a geom of body '{}'", name);
    const std::string type = keyword(
        e, "type",
        {"sphere", "capsule", "cylinder", "ellipsoid", "box", "mesh", "plane", "hfield", "sdf"},
        "sphere");
    // For the contacts: every geom, its frame and sizes where it is a shape momenta poses.
    MjcfGeom& geom = body_geoms.emplace_back(
        MjcfGeom{e,
                 label,
                 given != nullptr ? given : fmt::format("{}_geom{}", name, geom_index),
                 name,
                 type,
                 Transform::identity(),
                 {}});
    if (type == "mesh") {
      if (std::optional<PartSummary> part = mesh_geom(e, label, name, parts.size(), from_geoms)) {
        if (from_geoms) from_geom_sum += part->mass_properties;
        parts.push_back(std::move(*part));
      }
      continue;
    }
    if (type == "hfield" || type == "plane" || type == "sdf") {
      if (from_geoms) {
        fail(g, fmt::format("{} is a {}: momenta cannot find its mass; give body '{}' an "
                            "<inertial>",
                            label, type, name));
      }
      note(g, fmt::format("{} (a {}): not drawn; contacts are not modelled", label, type));
      continue;
    }
    // The shape and its frame: size and pos/orientation, or fromto (the axis from one end to
    // the other, a capsule's or cylinder's length, a box's or ellipsoid's third half-size).
    // The geom as a part to draw: momenta's part kinds carry MJCF's five names.
    PartSummary part;
    part.kind = type;
    Transform X_BG;
    const MjcfAttribute fromto = attribute(e, "fromto");
    if (fromto && type == "sphere") {
      fail(fromto.where,
           fmt::format("{} is a sphere: fromto gives the axis of a capsule, "
                       "cylinder, box or ellipsoid (as MuJoCo requires)",
                       label),
           "fromto");
    }
    const bool along_fromto = static_cast<bool>(fromto);
    std::vector<double> size = numbers(e, "size", 1, 3, std::vector<double>{});
    double length = 0.0;
    if (along_fromto) {
      const std::vector<double> ends = numbers(e, "fromto", 6, 6);
      const Vec3 from(ends[0], ends[1], ends[2]), to(ends[3], ends[4], ends[5]);
      length = (to - from).norm();
      if (!(length > 0.0))
        fail(fromto.where, fmt::format("the ends of {} coincide", label), "fromto");
      X_BG = Transform(Quat::FromTwoVectors(Vec3::UnitZ(), (to - from) / length).toRotationMatrix(),
                       (from + to) / 2.0);
    } else {
      X_BG = pose(e);
    }
    const std::size_t needed = type == "sphere"                          ? 1
                               : type == "capsule" || type == "cylinder" ? (along_fromto ? 1 : 2)
                               : along_fromto                            ? 2
                                                                         : 3;
    if (size.size() < needed) {
      fail(g,
           fmt::format("{} (a {}) needs {} size{}, the file gives {}", label, type, needed,
                       needed == 1 ? "" : "s", size.size()),
           "size");
    }
    if (along_fromto && (type == "box" || type == "ellipsoid")) size.resize(2);
    if (along_fromto) size.push_back(length / 2.0);  // the half-length along the axis
    geom.X_BG = X_BG;
    geom.size = size;
    const auto [material, amount] = geom_amount(e, label);
    inertia::MassProperties in_G;
    try {
      // A massless geom (mass or density 0) keeps its shape to draw and adds nothing.
      const inertia::Amount sized = amount > 0.0 ? material : inertia::Amount::density(1.0);
      if (type == "sphere") {
        in_G = inertia::solid_sphere(sized, size[0]);
        part.sizes = {{"radius", size[0]}};
      } else if (type == "capsule") {
        in_G = inertia::capsule(sized, size[0], 2.0 * size[1]);
        part.sizes = {{"radius", size[0]}, {"length", 2.0 * size[1]}};
      } else if (type == "cylinder") {
        in_G = inertia::solid_cylinder(sized, size[0], 2.0 * size[1]);
        part.sizes = {{"radius", size[0]}, {"length", 2.0 * size[1]}};
      } else if (type == "box") {
        const Vec3 edges = 2.0 * Vec3(size[0], size[1], size[2]);
        in_G = inertia::box(sized, edges);
        part.sizes = {{"size.x", edges.x()}, {"size.y", edges.y()}, {"size.z", edges.z()}};
      } else {
        const Vec3 semi(size[0], size[1], size[2]);
        in_G = inertia::ellipsoid(sized, semi);
        part.sizes = {
            {"semi_axes.x", semi.x()}, {"semi_axes.y", semi.y()}, {"semi_axes.z", semi.z()}};
      }
      if (amount == 0.0) in_G = inertia::MassProperties();
    } catch (const InvalidArgument& error) {
      fail(g, fmt::format("{}: {}", label, one_line(error.what())), "size");
    }
    part.name = given != nullptr ? given : fmt::format("{}.geom{}", name, parts.size());
    part.line = g->GetLineNum();
    part.mass_properties = in_G.transformed(X_BG.R, X_BG.p);
    part.R_BS = X_BG.R;
    part.p_BoSo_B = X_BG.p;
    if (from_geoms) from_geom_sum += part.mass_properties;
    parts.push_back(std::move(part));
  }
  if (from_geoms) return from_geom_sum;
  if (inertial == nullptr) return inertia::MassProperties();

  // <inertial>: the mass at its pos, the principal moments along its axes (or the full tensor).
  check_attributes(inertial, {"pos", "quat", "axisangle", "xyaxes", "zaxis", "euler", "mass",
                              "diaginertia", "fullinertia"});
  const MjcfElement e{inertial, "inertial", class_name};
  const std::string owner = fmt::format("body '{}'", name);
  const double m = number(e, "mass", std::nullopt);
  if (!(m >= 0.0))
    fail(inertial, fmt::format("the mass of {} is negative ({} kg)", owner, m), "mass");
  const Transform X_BI = pose(e);
  Mat3 I_I;
  const bool full = inertial->Attribute("fullinertia") != nullptr;
  if (full == (inertial->Attribute("diaginertia") != nullptr)) {
    fail(inertial,
         fmt::format("the <inertial> of {} gives one of diaginertia and fullinertia", owner));
  }
  if (full) {
    if (X_BI.R != Mat3::Identity()) {
      fail(inertial, "fullinertia is given in the body's axes: an orientation cannot go with it",
           "fullinertia");
    }
    const std::vector<double> f = numbers(e, "fullinertia", 6, 6);
    I_I << f[0], f[3], f[4], f[3], f[1], f[5], f[4], f[5], f[2];
  } else {
    const Vec3 d = vector3(e, "diaginertia", Vec3::Zero());
    I_I = d.asDiagonal();
  }
  // Mass 0 and no inertia: a massless body (a link of a joint chain), as momenta's files allow.
  if (m == 0.0 && I_I.isZero(0.0)) return inertia::MassProperties();
  inertia::MassProperties result(m, X_BI.p, X_BI.R * I_I * X_BI.R.transpose());
  try {
    result.check_physical(owner);
  } catch (const Error& error) {
    fail(inertial, one_line(error.what()), full ? "fullinertia" : "diaginertia");
  }
  return result;
}

}  // namespace momenta::io::detail
