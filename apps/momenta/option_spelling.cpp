#include "option_spelling.hpp"

#include <array>
#include <utility>

namespace momenta::cli {

std::string command_line_spelling(std::string_view name, std::string_view value) {
  // The library's names whose flags differ from --<name> with '_' as '-'.
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 3> kFlags{{
      {"step", "--dt"},
      {"relative_tolerance", "--rtol"},
      {"absolute_tolerance", "--atol"},
  }};
  // What to use instead, where that is a command or a pair of flags.
  if (name == "code") return "--cpp or --python";
  if (name == "linearize") return "`momenta linearize`";
  std::string flag;
  for (const auto& [option, spelled] : kFlags) {
    if (option == name) flag = spelled;
  }
  if (flag.empty()) {
    flag = "--" + std::string(name);
    for (char& c : flag)
      if (c == '_') c = '-';
  }
  return value.empty() ? flag : flag + " " + std::string(value);
}

}  // namespace momenta::cli
