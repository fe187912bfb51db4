// libFuzzer harness: the MJCF reader on arbitrary text. Any momenta::Error is a correct refusal; a
// crash, a hang, a sanitizer report or another exception type is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "momenta/common/error.hpp"
#include "momenta/io/mjcf_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    momenta::io::parse_mjcf(text, "fuzz.xml");
  } catch (const momenta::Error&) {
  }
  return 0;
}
