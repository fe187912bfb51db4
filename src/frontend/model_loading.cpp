#include "momenta/frontend/model_loading.hpp"

#include "momenta/common/error.hpp"
#include "momenta/system/multibody_system.hpp"

namespace momenta::frontend {

void accept_model(const io::ModelFile& file) {
  try {
    const system::MultibodySystem accepted(file.model);
  } catch (const Error& e) {
    if (auto located = file.locate(e)) throw *located;
    throw;
  }
}

io::ModelFile load_model(const std::filesystem::path& path) {
  io::ModelFile file = io::read_model_file(path);
  accept_model(file);
  return file;
}

}  // namespace momenta::frontend
