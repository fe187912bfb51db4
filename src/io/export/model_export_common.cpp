// What the two model writers share (model_export_common.hpp).

#include "export/model_export_common.hpp"

#include <variant>

#include <fmt/format.h>

namespace momenta::io::detail {

double joint_viscous_damping(const model::Model& model, int joint) {
  double damping = model.joints()[static_cast<std::size_t>(joint)].damping;
  for (const model::ForceElement& element : model.force_elements()) {
    if (const auto* f = std::get_if<model::JointFriction>(&element); f && f->joint_index == joint) {
      damping += f->viscous;
    }
  }
  return damping;
}

std::vector<std::string> loads_not_written(const model::Model& model, std::string_view format) {
  std::vector<std::string> lost;
  for (const model::ForceElement& element : model.force_elements()) {
    const std::string& name = model::force_element_name(element);
    std::visit(
        [&](const auto& e) {
          using T = std::decay_t<decltype(e)>;
          if constexpr (std::is_same_v<T, model::LinearSpringDamper>) {
            lost.push_back(fmt::format("spring-damper '{}' between two points", name));
          } else if constexpr (std::is_same_v<T, model::TorsionalSpringDamper>) {
            if (e.joint.empty() || format == "URDF") {
              lost.push_back(fmt::format("torsional spring '{}'", name));
            }
          } else if constexpr (std::is_same_v<T, model::FixedTendon>) {
            if (format == "URDF") lost.push_back(fmt::format("tendon '{}'", name));
          } else if constexpr (std::is_same_v<T, model::AppliedForce>) {
            lost.push_back(fmt::format("applied force '{}'", name));
          } else if constexpr (std::is_same_v<T, model::AppliedTorque>) {
            lost.push_back(fmt::format("applied torque '{}'", name));
          }
        },
        element);
  }
  for (const model::Joint& joint : model.joints()) {
    if (joint.is_prescribed()) {
      lost.push_back(
          fmt::format("the prescribed motion of joint '{}' (written free to move)", joint.name));
    }
  }
  return lost;
}

std::vector<std::string> restitution_not_written(const model::Model& model, std::string_view why) {
  std::vector<std::string> lost;
  for (const model::Joint& joint : model.joints()) {
    if (!joint.limits || joint.limits->restitution == 0.0) continue;
    lost.push_back(
        fmt::format("the restitution {} of joint '{}''s stops ({}: read back, they are "
                    "plastic)",
                    joint.limits->restitution, joint.name, why));
  }
  return lost;
}

std::vector<std::string> meshes_not_written(const ModelFile& file) {
  std::vector<std::string> lost;
  for (std::size_t b = 0; b < file.body_parts.size(); ++b) {
    std::vector<std::string> meshes;
    for (const PartSummary& part : file.body_parts[b]) {
      if (part.kind == "mesh" && !part.hole) meshes.push_back(part.name);
    }
    if (meshes.empty()) continue;
    lost.push_back(fmt::format(
        "the mesh{} '{}' of body '{}', not drawn (the body's inertial "
        "keeps its mass)",
        meshes.size() == 1 ? "" : "es", fmt::join(meshes, "', '"), file.model.bodies()[b].name));
  }
  return lost;
}

}  // namespace momenta::io::detail
