// momenta models as URDF (io/model_export.hpp; docs/model-formats.md, "Writing models").

#include <map>
#include <variant>

#include <fmt/format.h>

#include "export/model_export_common.hpp"
#include "momenta/common/error.hpp"
#include "momenta/io/model_export.hpp"
#include "momenta/math/rotation.hpp"
#include "xml/xml_support.hpp"

namespace momenta::io {
namespace {

using detail::number_text;
using detail::vector_text;

// URDF's rpy (fixed-axis roll, pitch, yaw: R = Rz(y) Ry(p) Rx(r)) of a rotation: SciPy's
// extrinsic "xyz".
std::string origin_text(const Transform& X) {
  return fmt::format("<origin xyz=\"{}\" rpy=\"{}\"/>", vector_text(X.p),
                     vector_text(euler_from_rotation("xyz", X.R)));
}

void check_representable(const model::Model& model) {
  for (const model::Joint& joint : model.joints()) {
    const bool kept = !model::joint_traits(joint.type).urdf.empty() &&
                      (joint.type != model::JointType::free || joint.parent_index == 0);
    if (!kept) {
      throw InvalidArgument(OptionMessage{
          fmt::format("joint '{}' ({}{}): URDF has no such joint; write MJCF (‹mjcf›), which "
                      "keeps it",
                      joint.name, model::joint_type_name(joint.type),
                      joint.type == model::JointType::free ? " below the world" : "")});
    }
  }
  for (const model::Constraint& c : model.constraints()) {
    if (!std::holds_alternative<model::JointCoupler>(c)) {
      throw InvalidArgument(OptionMessage{
          fmt::format("constraint '{}' ({}): URDF describes trees (and mimic joints); write MJCF "
                      "(‹mjcf›), which keeps loops",
                      model::constraint_name(c), model::constraint_type_name(c))});
    }
  }
}

}  // namespace

ExportedModel write_urdf(const ModelFile& file) {
  const model::Model& model = file.model;
  check_representable(model);
  std::vector<std::string> lost = detail::loads_not_written(model, "URDF");
  for (std::string& mesh : detail::meshes_not_written(file)) lost.push_back(std::move(mesh));
  for (const model::Joint& joint : model.joints()) {  // URDF has no rotor inertia
    if (joint.armature != 0.0)
      lost.push_back(fmt::format("joint '{}': armature {}", joint.name, joint.armature));
  }
  for (std::string& bounce : detail::restitution_not_written(model, "URDF has none"))
    lost.push_back(std::move(bounce));
  if (model.gravity() != Vec3(0, 0, -9.81)) {
    lost.push_back(fmt::format("gravity {} m/s² (URDF has none: readers take (0, 0, −9.81))",
                               vector_text(model.gravity())));
  }
  std::string out = fmt::format(
      "<!-- Written by momenta export from {} (docs/model-formats.md). "
      "Each link's frame is its joint's child frame. -->\n",
      file.file);
  for (const std::string& l : lost) out += fmt::format("<!-- Not written: {}. -->\n", l);
  out += fmt::format("<robot name=\"{}\">\n  <link name=\"world\"/>\n", file.name);
  // The link of body b: its frame J' of b's joint, X_LB = X_CJ⁻¹; the world's the world.
  const auto X_LB = [&](int body) {
    return body == 0 ? Transform::identity()
                     : model.joints()[static_cast<std::size_t>(body - 1)].X_CJ.inverse();
  };
  for (std::size_t b = 1; b < model.bodies().size(); ++b) {
    const model::Body& body = model.bodies()[b];
    const Transform X = X_LB(static_cast<int>(b));
    const inertia::MassProperties mp = body.mass_properties.transformed(X.R, X.p);
    const Mat3& I = mp.inertia_about_com();
    out += fmt::format("  <link name=\"{}\">\n", body.name);
    // A massless body is a link without <inertial>, URDF's way to say so.
    if (mp.mass() != 0.0 || !I.isZero(0.0)) {
      out += fmt::format(
          "    <inertial>\n      <origin xyz=\"{}\" rpy=\"0 0 0\"/>\n"
          "      <mass value=\"{}\"/>\n      <inertia ixx=\"{}\" ixy=\"{}\" ixz=\"{}\" iyy=\"{}\" "
          "iyz=\"{}\" izz=\"{}\"/>\n    </inertial>\n",
          vector_text(mp.center_of_mass()), number_text(mp.mass()), number_text(I(0, 0)),
          number_text(I(0, 1)), number_text(I(0, 2)), number_text(I(1, 1)), number_text(I(1, 2)),
          number_text(I(2, 2)));
    }
    // What URDF can draw: boxes, cylinders and spheres.
    for (const PartSummary& part : file.parts_of(static_cast<int>(b))) {
      std::map<std::string, double> s(part.sizes.begin(), part.sizes.end());
      std::string geometry;
      if (part.hole) continue;
      if (part.kind == "sphere") {
        geometry = fmt::format("<sphere radius=\"{}\"/>", number_text(s["radius"]));
      } else if (part.kind == "box") {
        geometry = fmt::format("<box size=\"{}\"/>",
                               vector_text(Vec3(s["size.x"], s["size.y"], s["size.z"])));
      } else if (part.kind == "cylinder") {
        geometry = fmt::format("<cylinder radius=\"{}\" length=\"{}\"/>", number_text(s["radius"]),
                               number_text(s["length"]));
      } else {
        continue;
      }
      out += fmt::format("    <visual>\n      {}\n      <geometry>{}</geometry>\n    </visual>\n",
                         origin_text(X * Transform(part.R_BS, part.p_BoSo_B)), geometry);
    }
    out += "  </link>\n";
  }
  // Joints: the origin places J in the parent's link; the child's link is J'.
  for (const model::Joint& joint : model.joints()) {
    // check_representable refused the types URDF has none of.
    // A revolute joint with stops is URDF's revolute (its <limit> required), one without them
    // continuous.
    const std::string_view type = joint.type == model::JointType::revolute && joint.limits
                                      ? std::string_view("revolute")
                                      : model::joint_traits(joint.type).urdf;
    const std::string& parent = model.bodies()[static_cast<std::size_t>(joint.parent_index)].name;
    out += fmt::format(
        "  <joint name=\"{}\" type=\"{}\">\n    <parent link=\"{}\"/>\n    <child "
        "link=\"{}\"/>\n    {}\n",
        joint.name, type, parent, joint.child, origin_text(X_LB(joint.parent_index) * joint.X_PJ));
    if (joint.type == model::JointType::revolute || joint.type == model::JointType::prismatic) {
      out += fmt::format("    <axis xyz=\"{}\"/>\n", vector_text(joint.axis));
    } else if (joint.type == model::JointType::planar) {
      out += "    <axis xyz=\"0 0 1\"/>\n";  // momenta's planar joint moves in J's x-y plane
    }
    if (joint.limits || joint.type == model::JointType::prismatic) {
      // URDF requires a prismatic joint's limits: a bound momenta does not have is written far
      // away (xml/xml_support.hpp), read back as none.
      const model::JointLimits limits = joint.limits.value_or(model::JointLimits{});
      out += fmt::format("    <limit lower=\"{}\" upper=\"{}\" effort=\"0\" velocity=\"0\"/>\n",
                         number_text(detail::bound_as_written(limits.lower)),
                         number_text(detail::bound_as_written(limits.upper)));
    }
    const double damping = detail::joint_viscous_damping(model, joint.index);
    if (damping != 0.0)
      out += fmt::format("    <dynamics damping=\"{}\"/>\n", number_text(damping));
    for (const model::Constraint& c : model.constraints()) {
      const auto& coupler = std::get<model::JointCoupler>(c);
      if (coupler.joint_a_index != joint.index) continue;
      out += fmt::format("    <mimic joint=\"{}\" multiplier=\"{}\" offset=\"{}\"/>\n",
                         coupler.joint_b, number_text(coupler.ratio), number_text(coupler.offset));
    }
    out += "  </joint>\n";
  }
  return {out + "</robot>\n", lost};
}

}  // namespace momenta::io
