#pragma once
// The fields of a CSV line as momenta's readers take them (private to src/io): trimmed of
// blanks, numbers finite and whole (chars_to_double: no trailing text, no locale).

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "momenta/common/chars_to_double.hpp"

namespace momenta::io::csv {

inline std::string trim(std::string_view s) {
  const auto not_space = [](char c) { return c != ' ' && c != '\t' && c != '\r'; };
  const auto b = std::find_if(s.begin(), s.end(), not_space);
  const auto e = std::find_if(s.rbegin(), s.rend(), not_space).base();
  return b < e ? std::string(b, e) : std::string();
}

/// True, with `value`, where `text` is one finite number and nothing else.
inline bool parse_number(const std::string& text, double& value) {
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = chars_to_double(text.data(), end, value);
  return ec == std::errc() && ptr == end && std::isfinite(value);
}

/// The comma-separated fields of a line, each trimmed.
inline std::vector<std::string> split_fields(std::string_view line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(
        trim(line.substr(start, comma == std::string_view::npos ? comma : comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

}  // namespace momenta::io::csv
