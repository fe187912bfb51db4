#include "momenta/common/chars_to_double.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace momenta {
namespace {

// The hand-checked grammar with strtod (what the WebAssembly build uses) against this library's
// std::from_chars on the same text: the same end, the same error, the same bits.
void expect_as_from_chars(const std::string& text) {
  SCOPED_TRACE("'" + text + "'");
  const char* first = text.data();
  const char* last = first + text.size();
  double expected = -7.0, got = -7.0;
  const auto reference = std::from_chars(first, last, expected);
  const auto result = detail::chars_to_double_by_strtod(first, last, got);
  EXPECT_EQ(result.ptr - first, reference.ptr - first);
  EXPECT_EQ(result.ec, reference.ec);
  if (std::isnan(expected)) {
    EXPECT_TRUE(std::isnan(got));
  } else {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(expected));
  }
}

TEST(CharsToDouble, TakesFromCharsGrammarAndNothingElse) {
  for (const std::string text : {"0",
                                 "-0",
                                 "1",
                                 "12.5",
                                 ".5",
                                 "5.",
                                 "-.5e3",
                                 "1e10",
                                 "1E-10",
                                 "1e+5",
                                 "1e",
                                 "1e+",
                                 "1e+x",
                                 "2.5e3m",
                                 "",
                                 " 1",
                                 "+1",
                                 "-",
                                 ".",
                                 "-.",
                                 "e5",
                                 "0x1p3",
                                 "-0x10",
                                 "inf",
                                 "-inf",
                                 "INFINITY",
                                 "infinit",
                                 "nan",
                                 "-NaN",
                                 "nan(123)",
                                 "nan(",
                                 "nan(1",
                                 "1,5",
                                 "1..2",
                                 "00012",
                                 "1e400",
                                 "-1e400",
                                 "2.2250738585072014e-308",
                                 "4.9e-324",
                                 "1e-320",
                                 "1e-400",
                                 "0.1000000000000000055511151231257827",
                                 "9007199254740993",
                                 "1.7976931348623157e308",
                                 "1.7976931348623159e308"}) {
    expect_as_from_chars(text);
  }
}

TEST(CharsToDouble, ReadsEveryPrintedDoubleToTheSameBits) {
  std::mt19937_64 random(20261206);
  for (int i = 0; i < 20000; ++i) {
    const double x = std::bit_cast<double>(random());
    if (!std::isfinite(x)) continue;
    expect_as_from_chars(fmt::format("{}", x));       // shortest round trip
    expect_as_from_chars(fmt::format("{:.17g}", x));  // 17 significant digits
    expect_as_from_chars(fmt::format("{:.25e}", x));  // more digits than a double holds
    expect_as_from_chars(fmt::format("{:.3f}", x / 1e300 * 1e3));  // short fixed notation
  }
}

TEST(CharsToDouble, IsFromCharsWhereTheLibraryHasIt) {
  double value = 0.0;
  const std::string text = "3.25 m";
  const auto [ptr, ec] = chars_to_double(text.data(), text.data() + text.size(), value);
  EXPECT_EQ(ec, std::errc());
  EXPECT_EQ(ptr, text.data() + 4);
  EXPECT_EQ(value, 3.25);
}

}  // namespace
}  // namespace momenta
