#include "momenta/common/chars_to_double.hpp"

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>

namespace momenta {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The length of the longest prefix of [first, last) that from_chars' general format takes as a
// number (after an optional '-'), or 0.
std::size_t number_length(const char* first, const char* last) {
  const std::string_view text(first, static_cast<std::size_t>(last - first));
  std::size_t i = text.starts_with('-') ? 1 : 0;
  const auto starts_with_word = [&](std::string_view word) {
    if (text.size() - i < word.size()) return false;
    for (std::size_t k = 0; k < word.size(); ++k) {
      if (std::tolower(static_cast<unsigned char>(text[i + k])) != word[k]) return false;
    }
    return true;
  };
  if (starts_with_word("infinity")) return i + 8;
  if (starts_with_word("inf")) return i + 3;
  if (starts_with_word("nan")) {
    std::size_t end = i + 3;
    if (end < text.size() && text[end] == '(') {  // nan(n-char-sequence)
      std::size_t close = end + 1;
      while (close < text.size() &&
             (std::isalnum(static_cast<unsigned char>(text[close])) || text[close] == '_')) {
        ++close;
      }
      if (close < text.size() && text[close] == ')') end = close + 1;
    }
    return end;
  }
  std::size_t digits = 0;
  while (i < text.size() && is_digit(text[i])) ++i, ++digits;
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && is_digit(text[i])) ++i, ++digits;
  }
  if (digits == 0) return 0;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    std::size_t e = i + 1;
    if (e < text.size() && (text[e] == '+' || text[e] == '-')) ++e;
    if (e < text.size() && is_digit(text[e])) {
      while (e < text.size() && is_digit(text[e])) ++e;
      i = e;
    }
  }
  return i;
}

}  // namespace

namespace detail {

CharsToDoubleResult chars_to_double_by_strtod(const char* first, const char* last, double& value) {
  const std::size_t length = number_length(first, last);
  if (length == 0) return {first, std::errc::invalid_argument};
  const std::string number(first, length);  // strtod needs the terminating zero
  errno = 0;
  char* end = nullptr;
  const double parsed = std::strtod(number.c_str(), &end);
  // strtod says ERANGE of a subnormal result too, which from_chars returns as it is; a number
  // that over- or underflows (±inf, ±0 from nonzero digits) is out of range for both.
  if (errno == ERANGE && (parsed == 0.0 || std::isinf(parsed))) {
    return {first + length, std::errc::result_out_of_range};
  }
  value = parsed;
  return {first + length, std::errc()};
}

}  // namespace detail

CharsToDoubleResult chars_to_double(const char* first, const char* last, double& value) {
#if defined(__cpp_lib_to_chars)
  const auto [ptr, ec] = std::from_chars(first, last, value);
  return {ptr, ec};
#else
  return detail::chars_to_double_by_strtod(first, last, value);
#endif
}

}  // namespace momenta
