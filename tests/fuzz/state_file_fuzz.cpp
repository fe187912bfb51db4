// libFuzzer harness: the state-file reader (JSON) on arbitrary text, for a model of two
// coordinates and two velocities. Any momenta::Error is a correct refusal; a crash, a hang, a
// sanitizer report or another exception type (nlohmann's own) is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "momenta/common/error.hpp"
#include "momenta/io/state_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    momenta::io::parse_state_file(text, "fuzz.json", 2, 2);
  } catch (const momenta::Error&) {
  }
  return 0;
}
