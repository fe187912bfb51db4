#include "momenta/frontend/model_loading.hpp"

#include "momenta/common/error.hpp"
#include "momenta/system/multibody_system.hpp"

namespace momenta::frontend {

io::ModelFile load_model(const std::filesystem::path& path) {
  io::ModelFile file = io::read_model_file(path);
  try {
    const system::MultibodySystem accepted(file.model);
  } catch (const Error& e) {
    if (auto located = file.locate(e)) throw *located;
    throw;
  }
  return file;
}

}  // namespace momenta::frontend
