// libFuzzer harness: the URDF reader on arbitrary text, its links' geometry included. Any
// momenta::Error is a correct refusal; a crash, a hang, a sanitizer report or another exception
// type is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "momenta/common/error.hpp"
#include "momenta/io/urdf_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // Inputs of odd length also weigh their links without <inertial> from their geometry (meshes
  // named relative to the working folder, the repository's root under scripts/fuzz.sh).
  momenta::io::ModelFileOptions options;
  if (size % 2 == 1) options.link_density = 1000.0;
  try {
    momenta::io::parse_urdf(text, "fuzz.urdf", options);
  } catch (const momenta::Error&) {
  }
  return 0;
}
