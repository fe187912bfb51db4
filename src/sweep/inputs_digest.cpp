#include "momenta/sweep/inputs_digest.hpp"

#include <openssl/evp.h>

#include <cstdint>
#include <fstream>
#include <memory>
#include <sstream>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::sweep {

std::string inputs_digest(std::span<const std::filesystem::path> files) {
  const std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> context(EVP_MD_CTX_new(),
                                                                        &EVP_MD_CTX_free);
  bool ok = context != nullptr && EVP_DigestInit_ex(context.get(), EVP_sha256(), nullptr) == 1;
  for (const std::filesystem::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (!in || in.bad()) {
      throw FileError(
          fmt::format("{}: cannot read it again to record what the results are made "
                      "from",
                      file.string()));
    }
    const std::string text = bytes.str();
    // The length first, so that moving bytes from one file to the next changes the digest.
    const std::uint64_t length = text.size();
    ok = ok && EVP_DigestUpdate(context.get(), &length, sizeof length) == 1 &&
         EVP_DigestUpdate(context.get(), text.data(), text.size()) == 1;
  }
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int size = 0;
  ok = ok && EVP_DigestFinal_ex(context.get(), digest, &size) == 1 && size >= 8;
  if (!ok) throw Error("SHA-256 of the sweep's input files failed (OpenSSL)");
  std::string text = "sha256:";
  for (int i = 0; i < 8; ++i) fmt::format_to(std::back_inserter(text), "{:02x}", digest[i]);
  return text;
}

}  // namespace momenta::sweep
