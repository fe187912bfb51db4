#include "model_argument.hpp"

#include <fmt/format.h>

#include "momenta/frontend/model_loading.hpp"
#include "option_checks.hpp"

namespace momenta::cli {

void add_model_argument(CLI::App* command, ModelArgument& model, const std::string& help) {
  command->add_option("MODEL", model.file, help)->required();
  command->add_option("--package-path", model.package_path,
                      "URDF: a folder holding the packages its package://NAME/... meshes name "
                      "(repeat for more; ROS_PACKAGE_PATH is searched after)");
  command
      ->add_option("--link-density", model.link_density,
                   "URDF: density, kg/m³, filling the collision (else visual) geometry of each "
                   "link without <inertial> to give it mass")
      ->check(positive_finite());
  command->add_option("--keyframe", model.keyframe,
                      "MJCF: start from the state of this <keyframe><key> (its qpos and qvel) "
                      "instead of the configuration the file draws, at rest");
}

io::ModelFile load_model(const ModelArgument& model) {
  io::ModelFileOptions options;
  options.package_path.assign(model.package_path.begin(), model.package_path.end());
  options.link_density = model.link_density;
  options.keyframe = model.keyframe;
  io::ModelFile file = frontend::load_model(model.file, options);
  // What the file says that is allowed but likely not meant: said before any result.
  for (const std::string& warning : file.warnings)
    fmt::print(stderr, "momenta: note: {}\n", warning);
  return file;
}

}  // namespace momenta::cli
