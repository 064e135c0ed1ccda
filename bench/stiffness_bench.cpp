/// Mesh stiffness: the targets are one mesh period at 1000 positions for the Visnadi
/// 25/30 pair with the potential-energy model in <= 7 ms on one core (preparation included),
/// and well under a microsecond per evaluation of a prepared curve.

#include <benchmark/benchmark.h>

#include <numbers>

#include "geardyn/geometry/gear_pair.h"
#include "geardyn/stiffness/potential_energy_stiffness.h"
#include "support/reference_pairs.h"

namespace {

geardyn::GearPair visnadiPair(double helix_deg) {
  return geardyn::GearPair(geardyn::testing::visnadiPairSpec(helix_deg));
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
