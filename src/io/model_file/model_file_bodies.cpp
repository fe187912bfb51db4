// Model files, `bodies:`: each body's name and mass properties in its own frame B.

#include <fmt/format.h>

#include "model_file/model_file_internal.hpp"
#include "momenta/common/error.hpp"
#include "momenta/io/part_file.hpp"
#include "momenta/io/part_node.hpp"

namespace momenta::io::detail {
namespace {

using inertia::MassProperties;

// `part: file.yaml`: a part file's composite, its frame placed in B by the body's pose; its parts
// placed in B go to `parts`.
MassProperties read_part_body(const YamlNode& body, const Context& ctx,
                              std::vector<PartSummary>& parts) {
  body.check_keys({"name", "part", "position", "rotation", "quaternion", "euler"});
  const YamlNode ref = body.at("part");
  std::filesystem::path path = ref.as_string();
  if (path.is_relative()) path = ctx.base_dir / path;
  CompositePart part;
  try {
    part = read_part_file(path);
  } catch (const FileError& e) {
    // Say which line names the missing file; problems inside it carry its own name and line.
    throw FileError(ref.error(one_line(e.what())).what());
  }
  const Mat3 R_BS = read_rotation(body);
  const Vec3 p_BoSo_B = body.find_vec3("position").value_or(Vec3::Zero());
  for (PartSummary& p : part.parts) {
    p.mass_properties = p.mass_properties.transformed(R_BS, p_BoSo_B);
    p.p_BoSo_B = R_BS * p.p_BoSo_B + p_BoSo_B;
    p.R_BS = R_BS * p.R_BS;
    parts.push_back(std::move(p));
  }
  return part.total.transformed(R_BS, p_BoSo_B);
}

// `mass`, `com`, `inertia` (about the centre of mass, or about the point `inertia_about`): given
// outright. Mass 0 without inertia is a massless body.
MassProperties read_explicit_body(const YamlNode& body, const std::string& name) {
  body.check_keys({"name", "mass", "com", "inertia", "inertia_about"});
  if (!body.has("mass")) {
    body.fail(
        "a body needs its mass properties: a 'shape' (with its sizes and 'mass' or 'density'), a "
        "'mesh', a 'part' file, or 'mass' (kg) with optional 'com' (m) and 'inertia' (kg·m²)");
  }
  const YamlNode mass_node = body.at("mass");
  const double mass = mass_node.as_double(Bound::kNonNegative);
  const Vec3 p_BoBcm_B = body.find_vec3("com").value_or(Vec3::Zero());
  Mat3 I_given = Mat3::Zero();
  const auto inertia_node = body.find("inertia");
  if (inertia_node) {
    // Three numbers are the diagonal (principal moments along B's axes); else the full tensor.
    const bool diagonal = inertia_node->is_sequence() && inertia_node->size() == 3 &&
                          !inertia_node->elements()[0].is_sequence();
    I_given = diagonal ? Mat3(inertia_node->as_vec3().asDiagonal()) : inertia_node->as_mat3();
  }
  const auto about_node = body.find("inertia_about");
  if (about_node && !inertia_node)
    about_node->fail("'inertia_about' needs an 'inertia' to go with");
  if (mass == 0.0) {
    if (!I_given.isZero(0.0)) {
      inertia_node->fail("a body of mass 0 must have no inertia (a massless body)");
    }
    return MassProperties();
  }
  // Inertia given about a point P (a top's pivot): about the centre of mass by the parallel-axis
  // theorem, I_Bcm = I_P − m (|d|² 1 − d dᵀ) with d = p_PBcm.
  Mat3 I_BBcm_B = I_given;
  if (about_node) {
    const Vec3 d = p_BoBcm_B - about_node->as_vec3();
    I_BBcm_B = I_given - mass * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
  }
  const MassProperties result(mass, p_BoBcm_B, I_BBcm_B);
  try {
    result.check_physical(fmt::format("body '{}'", name));
  } catch (const InvalidInertia& e) {
    std::string message = one_line(e.what());
    if (about_node) {
      message += fmt::format(
          " (derived from the inertia given about [{}, {}, {}] by the parallel-axis theorem: "
          "that tensor and the centre of mass imply no physical body; check both)",
          about_node->as_vec3().x(), about_node->as_vec3().y(), about_node->as_vec3().z());
    }
    (inertia_node ? *inertia_node : mass_node).fail(message);
  }
  return result;
}

}  // namespace

void read_bodies(const YamlNode& root, Context& ctx, model::ModelBuilder& builder) {
  const YamlNode section = root.at("bodies");
  const std::vector<YamlNode> bodies = section.elements();
  if (bodies.empty()) section.fail("the list of bodies is empty");
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const YamlNode& body = bodies[i];
    body.expect_map("a body: a map with 'name' and its mass properties");
    const YamlNode name_node = detail::name_node(body);
    const std::string name = name_node.as_string();
    if (name == model::kWorldBodyName) {
      name_node.fail("'world' is the ground, which every model has: give this body another name");
    }
    ctx.bodies.add(name, body, name_node);

    // Mass properties in B: a shape or a mesh (as in part files), a part file, or explicit.
    MassProperties mass_properties;
    bool uniform_solid = false;
    std::optional<inertia::PrimitiveShape> shape;
    std::vector<PartSummary>& parts = ctx.body_parts[name];
    if (body.has("hole")) {
      body.at("hole").fail("a body cannot be a hole: cut holes in a part file and use 'part'");
    }
    const auto kind = body.which_of({"shape", "mesh", "part"});
    if (kind && *kind != "part") {
      parts.push_back(read_part(body, i, 1.0, std::nullopt, ctx.base_dir));
      parts.back().name = name;
      mass_properties = parts.back().mass_properties;
      uniform_solid = true;
      if (*kind == "shape") {
        shape = inertia::PrimitiveShape{parts.back().kind, parts.back().sizes, parts.back().R_BS};
      }
    } else if (kind) {
      mass_properties = read_part_body(body, ctx, parts);
    } else {
      mass_properties = read_explicit_body(body, name);
    }
    model::Body b;
    b.name = name;
    b.mass_properties = mass_properties;
    b.inertia_scales_with_mass = uniform_solid;
    b.shape = std::move(shape);
    builder.add_body(std::move(b));
  }
}

}  // namespace momenta::io::detail
