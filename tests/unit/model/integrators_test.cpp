// The integrator registry is the one list every front end asks: each entry must be what the
// factories make (same name, order and adaptivity), and every integrator the families know must
// be in it.
#include "momenta/model/integrators.hpp"

#include <set>
#include <string>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/integrate/integrator.hpp"
#include "momenta/system/integrators.hpp"
#include "momenta/system/rigid_body_integrator.hpp"

namespace momenta::model {
namespace {

TEST(IntegratorRegistry, EveryEntryIsWhatTheFactoryMakes) {
  for (const IntegratorInfo& info : integrators()) {
    const auto integrator = system::make_integrator(info.name);
    ASSERT_NE(integrator, nullptr) << info.name;
    EXPECT_EQ(integrator->name(), info.name);
    EXPECT_EQ(integrator->order(), info.order) << info.name;
    EXPECT_EQ(integrator->adaptive(), info.adaptive) << info.name;
    EXPECT_FALSE(info.applies_to.empty()) << info.name;
    EXPECT_FALSE(info.summary.empty()) << info.name;
  }
}

TEST(IntegratorRegistry, HoldsEveryIntegratorOfEveryFamilyOnce) {
  std::set<std::string> registered;
  for (const IntegratorInfo& info : integrators()) {
    EXPECT_TRUE(registered.insert(std::string(info.name)).second) << "twice: " << info.name;
  }
  std::set<std::string> known;
  for (const auto name : {"rk4", "symplectic_euler", "dopri5", "bdf", "sdirk3"}) {
    known.insert(name);  // what integrate::make_integrator builds, and nothing else
    EXPECT_EQ(integrate::make_integrator(name)->name(), name);
    EXPECT_EQ(integrator_info(name).family, IntegratorFamily::general) << name;
  }
  EXPECT_THROW(integrate::make_integrator("splitting"), InvalidArgument);
  for (const auto name : system::rigid_body_integrator_names()) {
    known.insert(std::string(name));
    EXPECT_EQ(integrator_info(name).family, IntegratorFamily::rigid_body) << name;
  }
  EXPECT_EQ(registered, known);
  EXPECT_EQ(integrator_name_list(),
            "rk4, symplectic_euler, dopri5, bdf, sdirk3, splitting, splitting4, "
            "lie_group, exact");
}

TEST(IntegratorRegistry, UnknownNameSuggestsTheNearestOverEveryFamily) {
  EXPECT_EQ(find_integrator("exactt"), nullptr);
  try {
    integrator_info("exactt");
    FAIL() << "no exception";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'exact'?"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("known: rk4,"), std::string::npos) << e.what();
  }
  EXPECT_THROW(system::make_integrator("splitting5"), InvalidArgument);
}

}  // namespace
}  // namespace momenta::model
