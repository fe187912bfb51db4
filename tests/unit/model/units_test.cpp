// Units: the quotient of two units, as the live report's controller gains are written (kp in the
// driven input's unit per the measured one's), every factor cancelled.
#include "momenta/model/units.hpp"

#include <gtest/gtest.h>

namespace momenta::model {
namespace {

TEST(UnitRatio, WritesTheQuotientAsTheRestOfMomentaWritesUnits) {
  EXPECT_EQ(unit_ratio("N·m", "rad"), "N·m/rad");
  EXPECT_EQ(unit_ratio("N", "m"), "N/m");
  EXPECT_EQ(unit_ratio("N·s", "m"), "N·s/m");
  EXPECT_EQ(unit_ratio("N·m·s", "rad"), "N·m·s/rad");
  EXPECT_EQ(unit_ratio("N", "m·s"), "N/(m·s)");
  EXPECT_EQ(unit_ratio("N·m", "rad·s"), "N·m/(rad·s)");
}

TEST(UnitRatio, CancelsCommonFactorsAndPowers) {
  // A servo's commanded acceleration per angle: 1/s², per angle·s: 1/s³, its kd 1/s.
  EXPECT_EQ(unit_ratio("rad/s²", "rad"), "1/s²");
  EXPECT_EQ(unit_ratio("rad/s²", "rad·s"), "1/s³");
  EXPECT_EQ(unit_ratio("rad/s²", "rad/s"), "1/s");
  EXPECT_EQ(unit_ratio("N·m", "rad/s"), "N·m·s/rad");
  EXPECT_EQ(unit_ratio("m", "m"), "1");
  EXPECT_EQ(unit_ratio("kg·m²", "m"), "kg·m");
  EXPECT_EQ(unit_ratio("m/s", "m/s²"), "s");
  EXPECT_EQ(unit_ratio("N/(m·s)", "N"), "1/(m·s)");
  EXPECT_EQ(unit_ratio("", "m"), "1/m");
  EXPECT_EQ(unit_ratio("1", "s"), "1/s");
}

}  // namespace
}  // namespace momenta::model
