// libFuzzer harness: the sweep-file reader on arbitrary text (its paths relative to the examples'
// sweeps folder, so a seed's `model: ../quarter_car.yaml` names a real file). Any momenta::Error is
// a correct refusal; a crash, a hang, a sanitizer report or another exception type is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "momenta/common/error.hpp"
#include "momenta/io/sweep_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    momenta::io::parse_sweep_file(text, "fuzz.yaml", MOMENTA_FUZZ_SWEEP_DIR);
  } catch (const momenta::Error&) {
  }
  return 0;
}
