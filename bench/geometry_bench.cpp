/// Cost of the foundation's hot spots: gear-pair geometry (called once per case in sweeps and
/// design studies) and configuration loading (once per run).

#include <benchmark/benchmark.h>

#include <numbers>

#include "geardyn/config/config.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/geometry/involute.h"

namespace {

geardyn::GearPairSpec rigPair() {
  geardyn::GearPairSpec spec;
  for (geardyn::GearSpec* g : {&spec.pinion, &spec.gear}) {
    g->normal_module = 2e-3;
    g->normal_pressure_angle = 20.0 * std::numbers::pi / 180.0;
    g->face_width = 10e-3;
  }
  spec.pinion.teeth = 16;
  spec.gear.teeth = 35;
  spec.gear.profile_shift = 0.06307;
  spec.centre_distance = 51.125e-3;
  return spec;
}

void BM_GearPairConstruction(benchmark::State& state) {
  const auto spec = rigPair();
  for (auto _ : state) benchmark::DoNotOptimize(geardyn::GearPair(spec).contactRatioTransverse());
}
BENCHMARK(BM_GearPairConstruction);

void BM_InverseInvolute(benchmark::State& state) {
  double value = 0.0149;
  for (auto _ : state) {
    benchmark::DoNotOptimize(geardyn::inverseInvolute(value));
    value += 1e-12;
  }
}
BENCHMARK(BM_InverseInvolute);

void BM_ParseGeometryConfig(benchmark::State& state) {
  const std::string text = R"(
[pinion]
teeth = 16
module = 0.002
face_width = 0.010
[gear]
teeth = 35
module = 0.002
face_width = 0.010
profile_shift = 0.06307
[pair]
centre_distance = 0.051125
speed_rpm = 970.0
)";
  const auto schema = geardyn::config::geometrySchema();
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        geardyn::config::parseConfig(text, "bench.toml", schema).resolved().size());
  }
}
BENCHMARK(BM_ParseGeometryConfig);

}  // namespace
