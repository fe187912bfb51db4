#pragma once
// One libFuzzer harness body for the mesh readers: the input written to a file with the given
// extension, read by io::read_mesh_file (format detection, the text grammars, binary STL through
// assimp, welding), then checked and integrated as a solid the way `momenta inertia` does. Any
// momenta::Error is a correct refusal.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "momenta/common/error.hpp"
#include "momenta/inertia/mesh_mass_properties.hpp"
#include "momenta/io/mesh_file.hpp"

inline int fuzz_mesh_file(const std::uint8_t* data, std::size_t size, const char* extension) {
  static const std::filesystem::path path =
      std::filesystem::temp_directory_path() /
      ("momenta_fuzz_" + std::to_string(::getpid()) + extension);
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    momenta::inertia::TriangleMesh mesh = momenta::io::read_mesh_file(path);
    momenta::inertia::prepare_solid_mesh(mesh, "fuzz");
    momenta::inertia::solid_mesh_mass_properties(mesh, momenta::inertia::Amount::density(1.0));
  } catch (const momenta::Error&) {
  }
  return 0;
}
