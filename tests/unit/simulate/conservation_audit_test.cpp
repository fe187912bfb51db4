// ConservationAudit: drifts against values computed by hand.

#include "momenta/simulate/conservation_audit.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"

namespace momenta::simulate {
namespace {

// Every drift below is one subtraction and one division of exactly representable numbers, or
// nearly so: 1e-15 relative is a few ulps.
constexpr double kTol = 1e-15;

TEST(ConservationAudit, ScalarDriftIsRelativeToTheInitialValue) {
  ConservationAudit audit;
  const int e = audit.add("energy", -4.0);
  audit.record(e, -4.0);
  audit.record(e, -3.0);  // +1 / 4
  audit.record(e, -4.5);  // −0.5 / 4
  const AuditEntry& entry = audit.entry(e);
  EXPECT_EQ(entry.name, "energy");
  EXPECT_EQ(entry.scale, 4.0);
  EXPECT_NEAR(entry.final_drift, -0.125, kTol);
  EXPECT_NEAR(entry.max_drift, 0.25, kTol);
  EXPECT_EQ(entry.records, 3);
}

TEST(ConservationAudit, FloorReplacesASmallInitialValue) {
  ConservationAudit audit;
  // E0 = 1e-20 would turn round-off into enormous drifts; the floor 2 is used instead.
  const int e = audit.add("energy", 1e-20, 2.0);
  audit.record(e, 1e-20 + 0.5);
  EXPECT_EQ(audit.entry(e).scale, 2.0);
  EXPECT_NEAR(audit.entry(e).final_drift, 0.25, kTol);
  // Both zero: the drift is the absolute error.
  const int z = audit.add("zero", 0.0, 0.0);
  audit.record(z, 3e-16);
  EXPECT_EQ(audit.entry(z).scale, 1.0);
  EXPECT_EQ(audit.entry(z).final_drift, 3e-16);
}

TEST(ConservationAudit, VectorDriftIsTheNormOfTheChange) {
  ConservationAudit audit;
  const int h = audit.add("H", Vec3(3.0, 0.0, 4.0));  // |H0| = 5
  audit.record(h, Vec3(3.0, 1.0, 4.0));               // |ΔH| = 1 → 0.2
  audit.record(h, Vec3(0.0, 0.0, 5.0));               // same norm, rotated: |ΔH| = √10
  const AuditEntry& entry = audit.entry(h);
  EXPECT_EQ(entry.initial, 5.0);
  EXPECT_NEAR(entry.final_drift, std::sqrt(10.0) / 5.0, kTol);
  EXPECT_NEAR(entry.max_drift, std::sqrt(10.0) / 5.0, kTol);
}

TEST(ConservationAudit, NonFiniteValueShowsInTheMaximum) {
  ConservationAudit audit;
  const int e = audit.add("energy", 1.0);
  audit.record(e, 1.5);
  audit.record(e, std::numeric_limits<double>::quiet_NaN());
  audit.record(e, 1.0);
  EXPECT_TRUE(std::isnan(audit.entry(e).max_drift));
}

TEST(ConservationAudit, ResetStartsAgain) {
  ConservationAudit audit;
  const int e = audit.add("energy", 2.0);
  audit.record(e, 3.0);
  audit.reset();
  EXPECT_EQ(audit.entry(e).max_drift, 0.0);
  EXPECT_EQ(audit.entry(e).records, 0);
  audit.record(e, 2.5);
  EXPECT_NEAR(audit.entry(e).max_drift, 0.25, kTol);
}

TEST(ConservationAudit, RejectsNonFiniteInitialValueAndBadFloor) {
  ConservationAudit audit;
  EXPECT_THROW(audit.add("energy", std::numeric_limits<double>::infinity()), InvalidArgument);
  EXPECT_THROW(audit.add("energy", 1.0, -1.0), InvalidArgument);
  EXPECT_THROW(audit.add("H", Vec3(1.0, std::nan(""), 0.0)), InvalidArgument);
  EXPECT_TRUE(audit.empty());
}

}  // namespace
}  // namespace momenta::simulate
