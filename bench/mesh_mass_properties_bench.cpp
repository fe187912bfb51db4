// Mesh mass properties: integration throughput on a 1e6-triangle closed mesh in memory.
//
// Run: build/bench/mesh_mass_properties_bench --benchmark_repetitions=5
//      --benchmark_report_aggregates_only=true
// and quote the medians: items_per_second is triangles per second.

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

#include <benchmark/benchmark.h>

#include "momenta/inertia/mesh_mass_properties.hpp"
#include "momenta/inertia/triangle_mesh.hpp"

namespace momenta::inertia {
namespace {

// A torus about z (centre radius R, tube radius r) of 2 n k triangles, outward, vertices in
// ring order as a mesh exporter writes them.
TriangleMesh torus(double R, double r, int n, int k) {
  TriangleMesh m;
  m.vertices.reserve(static_cast<std::size_t>(n) * k);
  m.triangles.reserve(2 * static_cast<std::size_t>(n) * k);
  for (int i = 0; i < n; ++i) {
    const double u = 2 * std::numbers::pi * i / n;
    for (int j = 0; j < k; ++j) {
      const double v = 2 * std::numbers::pi * j / k;
      const double rho = R + r * std::cos(v);
      m.vertices.emplace_back(rho * std::cos(u), rho * std::sin(u), r * std::sin(v));
    }
  }
  const auto at = [&](int i, int j) { return (i % n) * k + (j % k); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < k; ++j) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return m;
}

// 1000 × 500 × 2 = 1e6 triangles.
const TriangleMesh& million_triangle_torus() {
  static const TriangleMesh mesh = torus(0.3, 0.1, 1000, 500);
  return mesh;
}

void BM_SolidMeshInMemory(benchmark::State& state) {
  const TriangleMesh& mesh = million_triangle_torus();
  for (auto _ : state) {
    MassProperties p = solid_mesh_mass_properties(mesh, Amount::density(7850));
    benchmark::DoNotOptimize(p);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(mesh.triangles.size()));
}
BENCHMARK(BM_SolidMeshInMemory)->Unit(benchmark::kMillisecond);

void BM_ShellMeshInMemory(benchmark::State& state) {
  const TriangleMesh& mesh = million_triangle_torus();
  for (auto _ : state) {
    MassProperties p = shell_mesh_mass_properties(mesh, Amount::density(7.85));
    benchmark::DoNotOptimize(p);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(mesh.triangles.size()));
}
BENCHMARK(BM_ShellMeshInMemory)->Unit(benchmark::kMillisecond);

void BM_PrepareSolidMesh(benchmark::State& state) {
  const TriangleMesh& mesh = million_triangle_torus();
  for (auto _ : state) {
    TriangleMesh copy = mesh;
    bool flipped = prepare_solid_mesh(copy, "torus");
    benchmark::DoNotOptimize(flipped);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(mesh.triangles.size()));
}
BENCHMARK(BM_PrepareSolidMesh)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace momenta::inertia
