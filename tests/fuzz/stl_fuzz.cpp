// libFuzzer harness: STL files, binary and ASCII (mesh_file_fuzz.hpp).
#include "mesh_file_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fuzz_mesh_file(data, size, ".stl");
}
