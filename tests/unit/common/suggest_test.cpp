#include "momenta/common/suggest.hpp"

#include <array>

#include <gtest/gtest.h>

namespace momenta {
namespace {

constexpr std::array<std::string_view, 4> kKeys{"mass", "density", "position", "orientation"};

TEST(EditDistance, CountsInsertionsDeletionsSubstitutions) {
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("mass", "mass"), 0u);
  EXPECT_EQ(edit_distance("Mass", "mass"), 0u);
}

TEST(ClosestMatch, SuggestsNearbyKeyOnly) {
  EXPECT_EQ(closest_match("desnity", kKeys).value(), "density");
  EXPECT_EQ(closest_match("positon", kKeys).value(), "position");
  EXPECT_FALSE(closest_match("colour", kKeys).has_value());
  EXPECT_EQ(did_you_mean("mas", kKeys), " (did you mean 'mass'?)");
  EXPECT_EQ(did_you_mean("zzzzzz", kKeys), "");
}

}  // namespace
}  // namespace momenta
