#include "momenta/common/suggest.hpp"

#include <array>
#include <vector>

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

TEST(EditDistance, CountsASwapOfNeighboursAsOneEdit) {
  EXPECT_EQ(edit_distance("wrold", "world"), 1u);
  EXPECT_EQ(edit_distance("ab", "ba"), 1u);
  EXPECT_EQ(edit_distance("abc", "ca"), 3u);  // optimal string alignment: no edit of a swapped pair
  EXPECT_EQ(did_you_mean("wrold", std::vector<std::string_view>{"world", "link"}),
            " (did you mean 'world'?)");
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
