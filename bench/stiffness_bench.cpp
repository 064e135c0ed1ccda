/// Mesh stiffness: the targets are one mesh period at 1000 positions for the Visnadi
/// 25/30 pair with the potential-energy model in <= 7 ms on one core (preparation included),
/// and well under a microsecond per evaluation of a prepared curve.

#include <benchmark/benchmark.h>

#include <numbers>

#include "geardyn/geometry/gear_pair.h"
#include "geardyn/stiffness/potential_energy_stiffness.h"

namespace {

geardyn::GearPair visnadiPair(double helix_deg) {
  geardyn::GearPairSpec spec;
  for (geardyn::GearSpec* g : {&spec.pinion, &spec.gear}) {
    g->normal_module = 3e-3;
    g->normal_pressure_angle = 20.0 * std::numbers::pi / 180.0;
    g->face_width = 20e-3;
    g->youngs_modulus = 200e9;
    g->poisson_ratio = 0.3;
    g->bore_diameter = 30e-3;
  }
  spec.pinion.teeth = 25;
  spec.gear.teeth = 30;
  spec.pinion.helix_angle = helix_deg * std::numbers::pi / 180.0;
  spec.gear.helix_angle = -spec.pinion.helix_angle;
  return geardyn::GearPair(spec);
}

/// Prepare the model and evaluate one mesh period at 1000 positions (the target).
void BM_PotentialEnergyPeriod1000(benchmark::State& state) {
  const geardyn::GearPair pair = visnadiPair(static_cast<double>(state.range(0)));
  geardyn::PotentialEnergyOptions options;
  options.root = state.range(1) ? geardyn::ToothRoot::kTrochoid : geardyn::ToothRoot::kStraight;
  for (auto _ : state) {
    const geardyn::PotentialEnergyMeshStiffness k(pair, options);
    double sum = 0.0;
    for (int i = 0; i < 1000; ++i) sum += k.stiffness(i / 1000.0);
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_PotentialEnergyPeriod1000)
    ->ArgsProduct({{0, 5}, {0, 1}})
    ->ArgNames({"helix_deg", "trochoid"})
    ->Unit(benchmark::kMillisecond);

/// One evaluation of a prepared curve (what a variable-speed simulation pays per time step).
void BM_PotentialEnergyEvaluate(benchmark::State& state) {
  const geardyn::GearPair pair = visnadiPair(static_cast<double>(state.range(0)));
  geardyn::PotentialEnergyOptions options;
  options.slices = static_cast<int>(state.range(1));
  const geardyn::PotentialEnergyMeshStiffness k(pair, options);
  double phase = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(k.stiffness(phase));
    phase += 0.000123;
  }
}
BENCHMARK(BM_PotentialEnergyEvaluate)
    ->Args({0, 0})
    ->Args({5, 0})
    ->Args({5, 20})
    ->ArgNames({"helix_deg", "slices"})
    ->Unit(benchmark::kNanosecond);

}  // namespace
