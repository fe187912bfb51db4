// libFuzzer harness: the measured-data reader (CSV with a header, docs/identification.md) on
// arbitrary text. Any momenta::Error is a correct refusal; a crash, a hang, a sanitizer report or
// another exception type is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "momenta/common/error.hpp"
#include "momenta/io/measured_data.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    momenta::io::parse_measured_csv(text, "fuzz.csv");
  } catch (const momenta::Error&) {
  }
  return 0;
}
