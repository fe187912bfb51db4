// libFuzzer harness: the model-file reader on arbitrary text. Any momenta::Error is a correct
// refusal; a crash, a hang, a sanitizer report or another exception type is a finding.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "momenta/common/error.hpp"
#include "momenta/io/model_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    momenta::io::parse_model_file(text, "fuzz.yaml", std::filesystem::temp_directory_path());
  } catch (const momenta::Error&) {
  }
  return 0;
}
