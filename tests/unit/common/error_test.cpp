// Errors that name options (common/error.hpp, OptionMessage): what() reads them in the library's
// words, a front end in its own, and the options are data.
#include "momenta/common/error.hpp"

#include <string>
#include <string_view>

#include <gtest/gtest.h>

namespace momenta {
namespace {

std::string flags(std::string_view name, std::string_view value) {
  const std::string flag = name == "step" ? "--dt" : "--" + std::string(name);
  return value.empty() ? flag : flag + " " + std::string(value);
}

TEST(Error, OptionsAreReadPlainlyOrAsAFrontEndSpellsThem) {
  const NumericalError e(OptionMessage{"try a smaller ‹step›, or ‹integrator=bdf›"});
  EXPECT_STREQ(e.what(), "try a smaller step, or integrator bdf");
  EXPECT_EQ(e.spelled(flags), "try a smaller --dt, or --integrator bdf");
  EXPECT_EQ(e.options(), (std::vector<std::string>{"step", "integrator"}));
  // Rewrapped with its marks kept, it still names them.
  const NumericalError wrapped(OptionMessage{e.spelled(keep_option_marks) + " (3 rows written)"});
  EXPECT_EQ(wrapped.spelled(flags), "try a smaller --dt, or --integrator bdf (3 rows written)");
  // A message without marks reads the same everywhere; one at a file's line keeps its place.
  const InvalidArgument plain("no options here");
  EXPECT_EQ(plain.spelled(flags), "no options here");
  EXPECT_TRUE(plain.options().empty());
  const ParseError at("f.csv", 1, 1, OptionMessage{"start over with ‹force›"});
  EXPECT_STREQ(at.what(), "f.csv:1:1: start over with force");
  EXPECT_EQ(at.spelled(flags), "f.csv:1:1: start over with --force");
  EXPECT_EQ(at.line(), 1);
}

TEST(Error, TheSymbolAnErrorIsAboutIsData) {
  InvalidArgument e("two parameters are named 'm'");
  EXPECT_FALSE(e.symbol().has_value());
  e.about_symbol("m");
  e.about_symbol("ignored: the first wins");
  EXPECT_EQ(e.symbol(), "m");
}

}  // namespace
}  // namespace momenta
