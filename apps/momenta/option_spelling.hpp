#pragma once
// How the command line writes the options the library's messages name (common/error.hpp,
// OptionMessage): `step` is --dt, `integrator=bdf` is --integrator bdf, `force` is --force.

#include <string>
#include <string_view>

namespace momenta::cli {

/// The flag for the library's option `name`, followed by `value` when one is given.
std::string command_line_spelling(std::string_view name, std::string_view value);

}  // namespace momenta::cli
