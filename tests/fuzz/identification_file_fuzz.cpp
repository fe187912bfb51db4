// libFuzzer harness: the identification-file reader on arbitrary text (its paths relative to the
// examples' identification folder, so a seed's `model: ../cruise_control.yaml` and its logs and
// Bode tests name real files). Any momenta::Error is a correct refusal; a crash, a hang, a
// sanitizer report or another exception type is a finding. The fit itself is not run here: the
// sanitizer build's tests run it.
#include <cstddef>
#include <cstdint>
#include <string>

#include "momenta/common/error.hpp"
#include "momenta/identify/identification_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    momenta::identify::parse_identification_file(text, "fuzz.yaml",
                                                 MOMENTA_FUZZ_IDENTIFICATION_DIR);
  } catch (const momenta::Error&) {
  }
  return 0;
}
