// Reading a model file and building its model: a 100-body tree (a floating trunk and four limbs
// of 25 capsule links on alternating hinges) as MJCF (mass properties from the geoms, defaults
// from a class) and as URDF (inertials given). Issue 29's aim: ≤ 5 ms each (medians).
//
//   build/bench/model_loading_bench --benchmark_repetitions=10
//   --benchmark_report_aggregates_only=true

#include <string>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "momenta/io/mjcf_file.hpp"
#include "momenta/io/urdf_file.hpp"

namespace {

constexpr int kLimbs = 4, kLinks = 25;  // 4 × 25 links; the trunk is body 101

std::string limb_mjcf(int limb, int link) {
  if (link == kLinks) return "";
  return fmt::format(
      "<body name='l{0}_{1}' pos='0 0 -0.1'><joint name='j{0}_{1}' axis='{2}'/>"
      "<geom fromto='0 0 0 0 0 -0.1' size='0.01'/>{3}</body>",
      limb, link, link % 2 == 0 ? "0 1 0" : "1 0 0", limb_mjcf(limb, link + 1));
}

std::string tree_mjcf() {
  std::string limbs;
  for (int limb = 0; limb < kLimbs; ++limb) limbs += limb_mjcf(limb, 0);
  return "<mujoco model='tree'><default><geom type='capsule' density='1200'/></default>"
         "<worldbody><body name='trunk' pos='0 0 3'><freejoint/><geom type='box' "
         "size='0.2 0.1 0.3'/>" +
         limbs + "</body></worldbody></mujoco>";
}

std::string tree_urdf() {
  std::string xml =
      "<robot name='tree'><link name='world'/><link name='trunk'><inertial><mass value='10'/>"
      "<inertia ixx='0.3' iyy='0.4' izz='0.1'/></inertial></link>"
      "<joint name='root' type='floating'><parent link='world'/><child link='trunk'/></joint>";
  for (int limb = 0; limb < kLimbs; ++limb) {
    for (int link = 0; link < kLinks; ++link) {
      xml += fmt::format(
          "<link name='l{0}_{1}'><inertial><origin xyz='0 0 -0.05'/><mass value='0.04'/>"
          "<inertia ixx='3.4e-5' iyy='3.4e-5' izz='2e-6'/></inertial></link>"
          "<joint name='j{0}_{1}' type='continuous'><parent link='{2}'/><child link='l{0}_{1}'/>"
          "<origin xyz='0 0 -0.1'/><axis xyz='{3}'/></joint>",
          limb, link, link == 0 ? std::string("trunk") : fmt::format("l{}_{}", limb, link - 1),
          link % 2 == 0 ? "0 1 0" : "1 0 0");
    }
  }
  return xml + "</robot>";
}

void BM_ReadMjcf100Bodies(benchmark::State& state) {
  const std::string text = tree_mjcf();
  for (auto _ : state) {
    const momenta::io::ModelFile file = momenta::io::parse_mjcf(text, "tree.xml");
    benchmark::DoNotOptimize(file.model.nv());
  }
  state.counters["bodies"] = static_cast<double>(kLimbs * kLinks + 1);
}
BENCHMARK(BM_ReadMjcf100Bodies)->Unit(benchmark::kMillisecond);

void BM_ReadUrdf100Bodies(benchmark::State& state) {
  const std::string text = tree_urdf();
  for (auto _ : state) {
    const momenta::io::ModelFile file = momenta::io::parse_urdf(text, "tree.urdf");
    benchmark::DoNotOptimize(file.model.nv());
  }
  state.counters["bodies"] = static_cast<double>(kLimbs * kLinks + 1);
}
BENCHMARK(BM_ReadUrdf100Bodies)->Unit(benchmark::kMillisecond);

}  // namespace
