#pragma once
// Text to a double by std::from_chars's rule (C++17 [charconv.from.chars], general format): an
// optional '-', then decimal digits with an optional point and exponent, or "inf", "infinity",
// "nan", "nan(...)"; no leading blanks, no '+', no hex prefix; no locale; correctly rounded.
//
// One place for it because not every standard library has it: libc++ before release 17 (the
// one emscripten 3.1.6 compiles the report's in-page engine with, wasm/) offers from_chars for
// integers only. There the same grammar is checked here and the number converted by strtod,
// which musl rounds correctly as well, so both builds read every number to the same double.

#include <system_error>

namespace momenta {

struct CharsToDoubleResult {
  const char* ptr;  ///< one past the last character of the number; `first` where there is none
  std::errc ec;  ///< {}; invalid_argument (no number); result_out_of_range (beyond double's range)
};

/// std::from_chars(first, last, value) for a double, on every standard library. `value` is
/// left as it was unless ec is {}.
CharsToDoubleResult chars_to_double(const char* first, const char* last, double& value);

namespace detail {
/// The grammar checked by hand and the number converted by strtod: what chars_to_double is
/// where the library lacks from_chars for doubles; tested against from_chars where it has it.
CharsToDoubleResult chars_to_double_by_strtod(const char* first, const char* last, double& value);
}  // namespace detail

}  // namespace momenta
