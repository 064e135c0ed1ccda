/// Loaded tooth contact analysis: a Harris map of 20 loads x 200 positions of the Visnadi spur
/// pair with long relief (the target: <= 50 ms on one core), and one LTCA point.

#include <benchmark/benchmark.h>

#include "geardyn/contact/loaded_contact.h"
#include "support/reference_pairs.h"

namespace {

geardyn::LoadedToothContact relievedPair() {
  auto k = std::make_shared<const geardyn::PotentialEnergyMeshStiffness>(
      geardyn::GearPair(geardyn::testing::visnadiPairSpec()));
  return geardyn::LoadedToothContact(
      k, geardyn::designedTipRelief(*k, 3000.0, true, geardyn::ReliefShape::kLinear), 1);
}

void BM_HarrisMap20x200(benchmark::State& state) {
  const auto contact = relievedPair();
  std::vector<double> loads;
  for (int i = 1; i <= 20; ++i) loads.push_back(300.0 * i);
  for (auto _ : state) benchmark::DoNotOptimize(geardyn::harrisMap(contact, loads, 200));
}
BENCHMARK(BM_HarrisMap20x200)->Unit(benchmark::kMillisecond);

void BM_LtcaPoint(benchmark::State& state) {
  const auto contact = relievedPair();
  double phase = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(contact.solve(phase, 3000.0));
    phase += 0.0137;
    if (phase >= 1.0) phase -= 1.0;
  }
}
BENCHMARK(BM_LtcaPoint);

}  // namespace
