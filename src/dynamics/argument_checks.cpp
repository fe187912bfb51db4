#include "argument_checks.hpp"

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta::dynamics::detail {

void throw_size_error(const char* algorithm, const char* argument, long given, long expected,
                      const char* expected_name) {
  throw InvalidArgument(fmt::format("{}: {} has size {}; the model needs {} ({})", algorithm,
                                    argument, given, expected, expected_name));
}

}  // namespace momenta::dynamics::detail
