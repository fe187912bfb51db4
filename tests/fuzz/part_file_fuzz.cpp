// libFuzzer harness: the part-file reader on arbitrary text (see model_file_fuzz.cpp).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "momenta/common/error.hpp"
#include "momenta/io/part_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    momenta::io::parse_part_file(text, "fuzz.yaml", std::filesystem::temp_directory_path());
  } catch (const momenta::Error&) {
  }
  return 0;
}
