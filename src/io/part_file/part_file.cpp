#include "momenta/io/part_file.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string_view>
#include <utility>

#include <fmt/format.h>
#include <Eigen/SVD>

#include "momenta/common/error.hpp"
#include "momenta/common/suggest.hpp"
#include "momenta/inertia/mesh_mass_properties.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta/inertia/triangle_mesh.hpp"
#include "momenta/io/mesh_file.hpp"
#include "momenta/io/part_node.hpp"
#include "momenta/io/yaml_reader.hpp"
#include "momenta/math/rotation.hpp"
#include "one_line.hpp"
#include "part_file/part_file_internal.hpp"

namespace momenta::io {
namespace {

using inertia::Amount;
using inertia::MassProperties;

// What a part's density is per: the dimension of the body.
enum class Measure { kPoint, kLength, kArea, kVolume };

std::string_view density_unit(Measure measure) {
  switch (measure) {
    case Measure::kLength:
      return "kg/m";
    case Measure::kArea:
      return "kg/m²";
    default:
      return "kg/m³";
  }
}

// A primitive of primitives.hpp: its name in part files, its size keys, and how to build it from
// an Amount and the part's node (`unit` converts the file's lengths to metres).
struct Shape {
  std::string_view name;
  std::vector<std::string_view> size_keys;
  Measure measure;
  std::function<MassProperties(Amount, const YamlNode&, double)> build;
};

double length(const YamlNode& part, std::string_view key, double unit) {
  return part.number(key, Bound::kPositive) * unit;
}

// An inner radius: 0 <= inner < outer, reported at the inner radius.
double inner_radius(const YamlNode& part, double outer, double unit) {
  const YamlNode node = part.at("inner_radius");
  const double inner = node.as_double(Bound::kNonNegative) * unit;
  if (!(inner < outer)) {
    node.fail(
        fmt::format("inner_radius {} must be below outer_radius {}", inner / unit, outer / unit));
  }
  return inner;
}

const std::vector<Shape>& shapes() {
  namespace in = inertia;
  static const std::vector<Shape> table = {
      {"point_mass",
       {},
       Measure::kPoint,
       [](Amount a, const YamlNode&, double) { return in::point_mass(a.value()); }},
      {"slender_rod",
       {"length"},
       Measure::kLength,
       [](Amount a, const YamlNode& p, double u) {
         return in::slender_rod(a, length(p, "length", u));
       }},
      {"thin_ring",
       {"radius"},
       Measure::kLength,
       [](Amount a, const YamlNode& p, double u) {
         return in::thin_ring(a, length(p, "radius", u));
       }},
      {"thin_disk",
       {"radius"},
       Measure::kArea,
       [](Amount a, const YamlNode& p, double u) {
         return in::thin_disk(a, length(p, "radius", u));
       }},
      {"annulus",
       {"inner_radius", "outer_radius"},
       Measure::kArea,
       [](Amount a, const YamlNode& p, double u) {
         const double outer = length(p, "outer_radius", u);
         return in::annulus(a, inner_radius(p, outer, u), outer);
       }},
      {"cylinder",
       {"radius", "length"},
       Measure::kVolume,
       [](Amount a, const YamlNode& p, double u) {
         return in::solid_cylinder(a, length(p, "radius", u), length(p, "length", u));
       }},
      {"hollow_cylinder",
       {"inner_radius", "outer_radius", "length"},
       Measure::kVolume,
       [](Amount a, const YamlNode& p, double u) {
         const double outer = length(p, "outer_radius", u);
         return in::hollow_cylinder(a, inner_radius(p, outer, u), outer, length(p, "length", u));
       }},
      {"cylindrical_shell",
       {"radius", "length"},
       Measure::kArea,
       [](Amount a, const YamlNode& p, double u) {
         return in::cylindrical_shell(a, length(p, "radius", u), length(p, "length", u));
       }},
      {"sphere",
       {"radius"},
       Measure::kVolume,
       [](Amount a, const YamlNode& p, double u) {
         return in::solid_sphere(a, length(p, "radius", u));
       }},
      {"hollow_sphere",
       {"inner_radius", "outer_radius"},
       Measure::kVolume,
       [](Amount a, const YamlNode& p, double u) {
         const double outer = length(p, "outer_radius", u);
         return in::hollow_sphere(a, inner_radius(p, outer, u), outer);
       }},
      {"spherical_shell",
       {"radius"},
       Measure::kArea,
       [](Amount a, const YamlNode& p, double u) {
         return in::spherical_shell(a, length(p, "radius", u));
       }},
      {"box",
       {"size"},
       Measure::kVolume,
       [](Amount a, const YamlNode& p, double u) {
         return in::box(a, p.at("size").as_vec3(Bound::kPositive) * u);
       }},
      {"thin_plate",
       {"width", "height"},
       Measure::kArea,
       [](Amount a, const YamlNode& p, double u) {
         return in::thin_rectangular_plate(a, length(p, "width", u), length(p, "height", u));
       }},
      {"cone",
       {"radius", "height"},
       Measure::kVolume,
       [](Amount a, const YamlNode& p, double u) {
         return in::solid_cone(a, length(p, "radius", u), length(p, "height", u));
       }},
      {"ellipsoid",
       {"semi_axes"},
       Measure::kVolume,
       [](Amount a, const YamlNode& p, double u) {
         return in::ellipsoid(a, p.at("semi_axes").as_vec3(Bound::kPositive) * u);
       }},
  };
  return table;
}

// Length units a file may declare with `units:`, in metres.
constexpr std::array<std::pair<std::string_view, double>, 4> kUnits = {
    {{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}, {"in", 0.0254}}};

constexpr std::array<std::string_view, 5> kPartFileKeys = {"name", "description", "units",
                                                           "density", "parts"};
// Keys every part may have, whatever it is.
constexpr std::array<std::string_view, 6> kPoseKeys = {"name",     "hole",       "position",
                                                       "rotation", "quaternion", "euler"};

using detail::one_line;

}  // namespace

// The rotation R_BS of the part frame S in the file's frame B: identity, or exactly one of
// `rotation` (3×3 rows), `quaternion` [w, x, y, z], `euler` {sequence, angles | angles_deg}.
Mat3 read_rotation(const YamlNode& part) {
  const auto which = part.which_of({"rotation", "quaternion", "euler"});
  if (!which) return Mat3::Identity();
  const YamlNode node = part.at(*which);
  if (*which == "rotation") {
    // Hand-written matrices carry few digits: accept 1e-6 (as unit quaternions are), then take the
    // nearest rotation (polar decomposition) so nothing downstream sees the error.
    const Mat3 R = node.as_mat3();
    try {
      check_rotation_matrix(R, "this matrix", 1e-6);
    } catch (const InvalidArgument& e) {
      node.fail(one_line(e.what()));
    }
    Eigen::JacobiSVD<Mat3> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
    return svd.matrixU() * svd.matrixV().transpose();
  }
  if (*which == "quaternion") {
    const VecX wxyz = node.as_vector(4);
    try {
      return quaternion_from_wxyz(Eigen::Vector4d(wxyz), "this").toRotationMatrix();
    } catch (const InvalidArgument& e) {
      node.fail(one_line(e.what()));
    }
  }
  // Euler angles, SciPy's convention (upper case intrinsic, lower case extrinsic).
  node.expect_map("a map {sequence: ZYX, angles_deg: [a, b, c]}");
  node.check_keys({"sequence", "angles", "angles_deg"});
  const YamlNode sequence = node.at("sequence");
  const auto angles = node.find_angles("angles");
  if (!angles) node.fail("missing required key 'angles' (radians) or 'angles_deg' (degrees)");
  try {
    return rotation_from_euler(sequence.as_string(), *angles);
  } catch (const InvalidArgument& e) {
    sequence.fail(one_line(e.what()));
  }
}

namespace {

// How much material a part has: its own `mass:` or `density:`, else the file's default density
// (solids only: a default in kg/m³ means nothing for a plate or a rod).
Amount read_amount(const YamlNode& part, Measure measure, std::string_view kind,
                   std::optional<double> default_density) {
  const auto which = part.which_of({"mass", "density"});
  if (which && *which == "mass") return Amount::mass(part.number("mass", Bound::kPositive));
  if (which) {
    if (measure == Measure::kPoint) {
      part.at("density").fail("a point mass has no size: give its 'mass' instead");
    }
    return Amount::density(part.number("density", Bound::kPositive));
  }
  if (measure == Measure::kVolume && default_density) return Amount::density(*default_density);
  if (measure == Measure::kPoint) part.fail(fmt::format("{} needs a 'mass' (kg)", kind));
  if (measure == Measure::kVolume) {
    part.fail(fmt::format(
        "{} needs a 'mass' (kg) or a 'density' (kg/m³); or give the file a default 'density'",
        kind));
  }
  part.fail(
      fmt::format("{} is thin: it needs a 'mass' (kg) or its own 'density' ({}); the file's "
                  "default density (kg/m³) applies to solids only",
                  kind, density_unit(measure)));
}

MassProperties read_explicit_inertia(const YamlNode& node, double unit) {
  node.expect_map("a map {mass, com, tensor}");
  node.check_keys({"mass", "com", "tensor", "moments"});
  const double mass = node.number("mass", Bound::kPositive);
  const Vec3 com = node.find_vec3("com").value_or(Vec3::Zero()) * unit;
  const auto which = node.which_of({"tensor", "moments"});
  if (!which) node.fail("missing required key 'tensor' (3×3, kg·m²) or 'moments' [Ixx, Iyy, Izz]");
  const YamlNode tensor = node.at(*which);
  const Mat3 I = *which == "tensor" ? tensor.as_mat3() : Mat3(tensor.as_vec3().asDiagonal());
  const MassProperties result(mass, com, I);
  try {
    result.check_physical("explicit inertia");
  } catch (const InvalidInertia& e) {
    tensor.fail(one_line(e.what()));
  }
  return result;
}

// The allowed keys of one part: those of every part, those of its kind, and its sizes.
std::vector<std::string_view> allowed_keys(std::string_view kind_key, const Shape* shape) {
  std::vector<std::string_view> keys(kPoseKeys.begin(), kPoseKeys.end());
  keys.push_back(kind_key);
  if (kind_key == "mesh") {
    keys.insert(keys.end(), {"mass", "density", "scale", "shell"});
  } else if (kind_key == "shape") {
    // A point mass's 'density' is refused by read_amount, with a better message than "unknown".
    keys.insert(keys.end(), {"mass", "density"});
    if (shape != nullptr) keys.insert(keys.end(), shape->size_keys.begin(), shape->size_keys.end());
  }
  return keys;
}

// A shape's sizes in metres, by key, for drawing it; a 3-vector key gives three entries.
std::vector<std::pair<std::string, double>> read_sizes(const YamlNode& part, const Shape& shape,
                                                       double unit) {
  std::vector<std::pair<std::string, double>> sizes;
  for (const std::string_view key : shape.size_keys) {
    const std::string name(key);
    if (!part.has(name)) continue;
    const YamlNode node = part.at(name);
    if (node.is_sequence()) {
      const Vec3 v = node.as_vec3() * unit;
      sizes.insert(sizes.end(), {{name + ".x", v.x()}, {name + ".y", v.y()}, {name + ".z", v.z()}});
    } else {
      sizes.emplace_back(name, node.as_double() * unit);
    }
  }
  return sizes;
}

// A mesh's mass properties; a solid's mesh is first checked closed and turned outward.
inertia::MassProperties mesh_mass_properties(inertia::TriangleMesh& mesh,
                                             const std::filesystem::path& path,
                                             inertia::Amount amount, bool shell) {
  if (shell) return inertia::shell_mesh_mass_properties(mesh, amount);
  inertia::prepare_solid_mesh(mesh, path.string());
  return inertia::solid_mesh_mass_properties(mesh, amount);
}

}  // namespace

// Reads one part in its own frame S and places it in B.
PartSummary read_part(const YamlNode& part, std::size_t index, double unit,
                      std::optional<double> default_density,
                      const std::filesystem::path& base_dir) {
  part.expect_map("a part: a map with 'shape', 'mesh' or 'inertia'");
  PartSummary summary;
  summary.line = part.line();
  summary.name = part.has("name") ? part.at("name").as_string() : fmt::format("parts[{}]", index);

  const auto kind = part.which_of({"shape", "mesh", "inertia"});
  if (!kind) {
    // A misspelt 'shape' is likelier than a forgotten one: report the unknown key first.
    std::vector<std::string_view> any = allowed_keys("shape", nullptr);
    any.insert(any.end(), {"mesh", "inertia", "density", "scale", "shell"});
    for (const Shape& s : shapes()) any.insert(any.end(), s.size_keys.begin(), s.size_keys.end());
    std::sort(any.begin(), any.end());
    any.erase(std::unique(any.begin(), any.end()), any.end());
    part.check_keys(any);
    part.fail("a part needs one of 'shape' (a primitive), 'mesh' (a mesh file) or 'inertia'");
  }

  MassProperties in_S;
  if (*kind == "shape") {
    const YamlNode shape_node = part.at("shape");
    const std::string name = shape_node.as_string();
    const auto& table = shapes();
    const auto it =
        std::find_if(table.begin(), table.end(), [&](const Shape& s) { return s.name == name; });
    if (it == table.end()) {
      std::vector<std::string_view> names;
      for (const Shape& s : table) names.push_back(s.name);
      std::string list;
      for (const auto n : names) list += fmt::format("{}{}", list.empty() ? "" : ", ", n);
      shape_node.fail(fmt::format("unknown shape '{}'{}; expected one of {}", name,
                                  did_you_mean(name, names), list));
    }
    part.check_keys(allowed_keys("shape", &*it));
    summary.kind = name;
    const Amount amount = read_amount(part, it->measure, name, default_density);
    try {
      in_S = it->build(amount, part, unit);
    } catch (const InvalidArgument& e) {
      part.fail(one_line(e.what()));
    }
    summary.sizes = read_sizes(part, *it, unit);
  } else if (*kind == "mesh") {
    part.check_keys(allowed_keys("mesh", nullptr));
    summary.kind = "mesh";
    const YamlNode mesh_node = part.at("mesh");
    std::filesystem::path path = mesh_node.as_string();
    if (path.is_relative()) path = base_dir / path;
    const double scale = part.find_number("scale", Bound::kPositive).value_or(unit);
    const bool shell = part.find_bool("shell").value_or(false);
    const Amount amount = read_amount(part, shell ? Measure::kArea : Measure::kVolume,
                                      shell ? "a shell mesh" : "a mesh", default_density);
    try {
      auto mesh = std::make_shared<inertia::TriangleMesh>(read_mesh_file(path, scale));
      in_S = mesh_mass_properties(*mesh, path, amount, shell);
      summary.mesh = std::move(mesh);
    } catch (const Error& e) {
      mesh_node.fail(one_line(e.what()));
    }
  } else {
    part.check_keys(allowed_keys("inertia", nullptr));
    summary.kind = "inertia";
    in_S = read_explicit_inertia(part.at("inertia"), unit);
  }

  // Place the part: p_BoSo_B and R_BS.
  const Mat3 R_BS = read_rotation(part);
  const Vec3 p_BoSo_B = part.find_vec3("position").value_or(Vec3::Zero()) * unit;
  summary.hole = part.find_bool("hole").value_or(false);
  summary.mass_properties = in_S.transformed(R_BS, p_BoSo_B);
  summary.R_BS = R_BS;
  summary.p_BoSo_B = p_BoSo_B;
  return summary;
}

inertia::MassProperties read_mesh_mass_properties(const std::filesystem::path& path,
                                                  inertia::Amount amount, double scale,
                                                  bool shell) {
  inertia::TriangleMesh mesh = read_mesh_file(path, scale);
  return mesh_mass_properties(mesh, path, amount, shell);
}

// Reads and composes the parts of a parsed part file.
CompositePart detail::compose_part_file(const YamlNode& root, const std::filesystem::path& base_dir,
                                        const PartFileOptions& options) {
  root.expect_map("a part file: a map with a 'parts' list");
  root.check_keys(kPartFileKeys);

  CompositePart result;
  result.name =
      root.find_string("name").value_or(std::filesystem::path(root.file()).stem().string());

  // The file's length unit.
  double unit = 1.0;
  if (const auto units = root.find("units")) {
    const std::string name = units->as_string();
    const auto it =
        std::find_if(kUnits.begin(), kUnits.end(), [&](const auto& u) { return u.first == name; });
    if (it == kUnits.end()) {
      const std::array<std::string_view, 4> names = {"m", "cm", "mm", "in"};
      units->fail(fmt::format("unknown length unit '{}'{}; expected m, cm, mm or in", name,
                              did_you_mean(name, names)));
    }
    unit = it->second;
  }

  // The default density of solids: --density wins over the file's.
  std::optional<double> default_density = root.find_number("density", Bound::kPositive);
  if (options.default_density) {
    const double rho = *options.default_density;
    if (!std::isfinite(rho) || !(rho > 0.0)) {
      throw InvalidArgument(
          fmt::format("default density {} kg/m³ is not positive and finite", rho));
    }
    default_density = rho;
  }

  // Every part, placed in B.
  const YamlNode parts_node = root.at("parts");
  const std::vector<YamlNode> parts = parts_node.elements();
  if (parts.empty()) parts_node.fail("the list of parts is empty");
  for (std::size_t i = 0; i < parts.size(); ++i) {
    result.parts.push_back(read_part(parts[i], i, unit, default_density, base_dir));
  }

  // Sum the solids, then cut the holes one by one, checking the body stays physical after each.
  bool any_solid = false;
  for (const PartSummary& p : result.parts) {
    if (p.hole) continue;
    result.total += p.mass_properties;
    any_solid = true;
  }
  if (!any_solid) parts_node.fail("every part is a hole: holes need a solid part to be cut from");
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const PartSummary& p = result.parts[i];
    if (!p.hole) continue;
    try {
      result.total -= p.mass_properties;
      result.total.check_physical("the part left");
    } catch (const InvalidInertia& e) {
      parts[i].fail(
          fmt::format("hole '{}' leaves no physical body (is it larger than the material "
                      "it is cut from?): {}",
                      p.name, one_line(e.what())));
    }
  }
  return result;
}

CompositePart parse_part_file(const std::string& text, const std::string& file_name,
                              const std::filesystem::path& base_dir,
                              const PartFileOptions& options) {
  return detail::compose_part_file(YamlNode::load_string(text, file_name), base_dir, options);
}

CompositePart read_part_file(const std::filesystem::path& path, const PartFileOptions& options) {
  return detail::compose_part_file(YamlNode::load_file(path), path.parent_path(), options);
}

}  // namespace momenta::io
