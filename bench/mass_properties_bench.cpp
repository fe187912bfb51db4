// Composite and principal-axes costs of MassProperties, the innermost operations of part files.

#include <benchmark/benchmark.h>

#include "momenta/inertia/mass_properties.hpp"

namespace momenta::inertia {
namespace {

void BM_Composite(benchmark::State& state) {
  const MassProperties a(2.0, Vec3(0.1, 0.2, 0.3), Vec3(1, 2, 3).asDiagonal());
  const MassProperties b(1.0, Vec3(-0.4, 0.0, 0.1), Vec3(0.5, 0.5, 0.2).asDiagonal());
  for (auto _ : state) {
    MassProperties sum = a + b;
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_Composite);

void BM_PrincipalAxes(benchmark::State& state) {
  Mat3 I;
  I << 2.0, -0.3, 0.1, -0.3, 3.0, 0.2, 0.1, 0.2, 4.0;
  const MassProperties body(5.0, Vec3::Zero(), I);
  for (auto _ : state) {
    PrincipalAxes p = body.principal_axes();
    benchmark::DoNotOptimize(p);
  }
}
BENCHMARK(BM_PrincipalAxes);

}  // namespace
}  // namespace momenta::inertia
