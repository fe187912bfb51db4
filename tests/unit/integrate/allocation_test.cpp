// Integrator steps must not allocate: counts heap allocations (malloc, operator new) around them.
#include <gtest/gtest.h>

#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/integrate/symplectic_euler.hpp"
#include "momenta/model/integrators.hpp"
#include "momenta_test/allocation_counter.hpp"
#include "test_systems.hpp"

namespace momenta::integrate {
namespace {

TEST(IntegratorAllocation, StepsDoNotAllocate) {
  test::FreeRigidBody system(Vec3(1.0, 2.0, 3.0));
  for (const model::IntegratorInfo& info : model::integrators()) {
    if (info.family != model::IntegratorFamily::general) continue;
    const std::string_view name = info.name;
    auto integrator = make_integrator(name);
    State state{0.0, VecX(4), VecX(Vec3(0.01, 2.0, 0.01))};
    state.q << 1.0, 0.0, 0.0, 0.0;
    integrator->initialize(system, state);
    // The first step is outside the count: CVODE (bdf) allocates its saved Jacobian there, once
    // per run (cvLsInitialize), not per step.
    integrator->step(system, state, 1e-2);
    const long before = momenta::test::allocation_count();
    for (int i = 0; i < 100; ++i) integrator->step(system, state, 1e-2);
    EXPECT_EQ(momenta::test::allocation_count() - before, 0) << name;
  }
}

}  // namespace
}  // namespace momenta::integrate
