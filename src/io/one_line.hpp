#pragma once
// Shared by the file readers (part files, model files): file messages must stay on one line,
// `file:line:column: message`, and a library message wrapped into one could carry a newline.

#include <algorithm>
#include <string>

namespace momenta::io::detail {

/// `text` with every newline replaced by a space.
inline std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

}  // namespace momenta::io::detail
