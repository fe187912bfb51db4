#pragma once
// Messages that must stay on one line — `file:line:column: message` of the file readers, a failed
// run's message in a sweep's results — when a library message wrapped into them could carry a
// newline.

#include <algorithm>
#include <string>

namespace momenta {

/// `text` with every newline replaced by a space.
inline std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

}  // namespace momenta
