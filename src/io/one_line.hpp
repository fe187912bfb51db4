#pragma once
// The file readers' name for momenta::one_line (common/one_line.hpp).

#include "momenta/common/one_line.hpp"

namespace momenta::io::detail {

using ::momenta::one_line;

}  // namespace momenta::io::detail
