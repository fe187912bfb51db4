#include "stable_addresses.hpp"

#include <sys/personality.h>
#include <unistd.h>

#include <cstdlib>

namespace momenta::cli {

void run_with_stable_addresses(char** argv) {
  // The environment marks the second run, so that a refusal cannot loop.
  constexpr const char* kMark = "MOMENTA_STABLE_ADDRESSES";
  if (std::getenv(kMark) != nullptr) return;
  const int current = personality(0xffffffff);
  if (current == -1 || (current & ADDR_NO_RANDOMIZE) != 0) return;
  if (personality(static_cast<unsigned long>(current) | ADDR_NO_RANDOMIZE) == -1) return;
  setenv(kMark, "1", 1);
  execv("/proc/self/exe", argv);
  // execv returned: run here, randomized or not.
  personality(static_cast<unsigned long>(current));
}

}  // namespace momenta::cli
