// Integrator steps must not allocate: counts global operator new calls around them.
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/integrate/symplectic_euler.hpp"
#include "test_systems.hpp"

namespace {
thread_local long allocations = 0;
}  // namespace

void* operator new(std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace momenta::integrate {
namespace {

TEST(IntegratorAllocation, StepsDoNotAllocate) {
  test::FreeRigidBody system(Vec3(1.0, 2.0, 3.0));
  for (const auto name : integrator_names()) {
    auto integrator = make_integrator(name);
    State state{0.0, VecX(4), VecX(Vec3(0.01, 2.0, 0.01))};
    state.q << 1.0, 0.0, 0.0, 0.0;
    integrator->initialize(system, state);
    const long before = allocations;
    for (int i = 0; i < 100; ++i) integrator->step(system, state, 1e-2);
    EXPECT_EQ(allocations - before, 0) << name;
  }
}

}  // namespace
}  // namespace momenta::integrate
