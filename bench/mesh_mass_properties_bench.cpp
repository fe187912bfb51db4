// Mesh mass properties on a 1e6-triangle closed mesh (a torus): integration throughput in memory,
// and the whole path from a binary STL file (read through assimp, weld, topology check,
// integration) with the process's peak resident memory.
//
// Run: build/bench/mesh_mass_properties_bench --benchmark_repetitions=5
//      --benchmark_report_aggregates_only=true
// and quote the medians: items_per_second is triangles per second. The STL benchmark runs first
// so its peak-memory counters (getrusage ru_maxrss, MB) are not masked by the in-memory mesh.

#include <sys/resource.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <benchmark/benchmark.h>

#include "momenta/inertia/mesh_mass_properties.hpp"
#include "momenta/inertia/triangle_mesh.hpp"
#include "momenta/io/mesh_file.hpp"

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

// The peak resident set size of the process so far, MB.
double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux.
}

// The temporary STL file (removed at exit) and the peak memory before anything was loaded.
std::filesystem::path stl_path;
double baseline_rss_mb = 0.0;

struct RemoveTemporaryFile {
  ~RemoveTemporaryFile() {
    std::error_code ignored;
    if (!stl_path.empty()) std::filesystem::remove(stl_path, ignored);
  }
} remove_temporary_file;

// Writes the 1e6-triangle torus (in mm) as a binary STL, streaming, without building it in memory.
std::filesystem::path million_triangle_stl() {
  static const std::filesystem::path path = [] {
    baseline_rss_mb = peak_rss_mb();
    const auto file = std::filesystem::temp_directory_path() /
                      ("momenta_bench_torus_" + std::to_string(::getpid()) + ".stl");
    const int n = 1000, k = 500;
    const double R = 300, r = 100;  // mm
    const auto point = [&](int i, int j) {
      const double u = 2 * std::numbers::pi * (i % n) / n;
      const double v = 2 * std::numbers::pi * (j % k) / k;
      const double rho = R + r * std::cos(v);
      return std::array<float, 3>{static_cast<float>(rho * std::cos(u)),
                                  static_cast<float>(rho * std::sin(u)),
                                  static_cast<float>(r * std::sin(v))};
    };
    std::ofstream out(file, std::ios::binary);
    char header[80] = "momenta benchmark torus";
    out.write(header, 80);
    const std::uint32_t count = 2u * n * k;
    out.write(reinterpret_cast<const char*>(&count), 4);
    const auto facet = [&](const std::array<float, 3>& a, const std::array<float, 3>& b,
                           const std::array<float, 3>& c) {
      const float normal[3] = {0, 0, 0};  // Readers recompute it; momenta ignores it.
      out.write(reinterpret_cast<const char*>(normal), 12);
      for (const auto* p : {&a, &b, &c}) out.write(reinterpret_cast<const char*>(p->data()), 12);
      const std::uint16_t attribute = 0;
      out.write(reinterpret_cast<const char*>(&attribute), 2);
    };
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < k; ++j) {
        facet(point(i, j), point(i + 1, j), point(i + 1, j + 1));
        facet(point(i, j), point(i + 1, j + 1), point(i, j + 1));
      }
    }
    stl_path = file;
    return file;
  }();
  return path;
}

// Read + weld (read_mesh_file), topology check (prepare_solid_mesh), integration.
void BM_LoadAndIntegrateBinaryStl(benchmark::State& state) {
  const std::filesystem::path path = million_triangle_stl();
  std::size_t triangles = 0;
  for (auto _ : state) {
    TriangleMesh mesh = io::read_mesh_file(path, 0.001);
    prepare_solid_mesh(mesh, path.string());
    MassProperties p = solid_mesh_mass_properties(mesh, Amount::density(7850));
    benchmark::DoNotOptimize(p);
    triangles = mesh.triangles.size();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(triangles));
  // Peak resident memory of the process before the first load and after the loads (MB).
  state.counters["peak_rss_before_MB"] = baseline_rss_mb;
  state.counters["peak_rss_after_MB"] = peak_rss_mb();
  state.counters["file_MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1048576.0;
}
BENCHMARK(BM_LoadAndIntegrateBinaryStl)->Unit(benchmark::kMillisecond);

// 1000 × 500 × 2 = 1e6 triangles.
const TriangleMesh& million_triangle_torus() {
  static const TriangleMesh mesh = torus(0.3, 0.1, 1000, 500);
  return mesh;
}

void BM_SolidMeshInMemory(benchmark::State& state) {
  const TriangleMesh& mesh = million_triangle_torus();
  const double rss_before = peak_rss_mb();
  for (auto _ : state) {
    MassProperties p = solid_mesh_mass_properties(mesh, Amount::density(7850));
    benchmark::DoNotOptimize(p);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(mesh.triangles.size()));
  // Integration allocates nothing: the peak does not move.
  state.counters["peak_rss_growth_MB"] = peak_rss_mb() - rss_before;
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
