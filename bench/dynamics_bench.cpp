/// SDOF gear pair, Newmark with backlash: the issue's target is >= 1e7 steps/s on one core.
/// The model is the simulate example: Fourier stiffness (2 harmonics), 1 error harmonic,
/// backlash contact; and a step stiffness (one comparison per evaluation) for the floor.

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "geardyn/solvers/time_response.h"
#include "geardyn/stats/monte_carlo.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/stiffness/step_stiffness.h"
#include "geardyn/system/gear_pair_model.h"
#include "support/reference_pairs.h"

namespace {

geardyn::GearPairModel backlashModel(bool step) {
  geardyn::GearPairModelSpec spec = geardyn::testing::issue4ExampleSpec();
  spec.contact = geardyn::ContactLaw::kBacklash;
  spec.backlash = 1e-4;
  if (step) {
    spec.stiffness = std::make_shared<geardyn::StepMeshStiffness>(
        geardyn::StepMeshStiffness::fromMean(4.55e8, 1.6));
  }
  return geardyn::GearPairModel(spec);
}

void BM_NewmarkBacklashSteps(benchmark::State& state) {
  const geardyn::GearPairModel model = backlashModel(state.range(0) == 1);
  constexpr long long kSteps = 1 << 20;
  const double h = 1e-3 / 512;
  for (auto _ : state) {
    const auto s =
        geardyn::integrateNewmark(model, geardyn::NewmarkParameters::averageAcceleration(), 0.0, h,
                                  kSteps, 3.1e-6 + 1e-4, 0.0, 1e-14);
    benchmark::DoNotOptimize(s.x);
  }
  state.SetItemsProcessed(state.iterations() * kSteps);
}
BENCHMARK(BM_NewmarkBacklashSteps)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("step_stiffness")
    ->Unit(benchmark::kMillisecond);

}  // namespace

namespace {

/// Monte Carlo of the mean excitation ratio: 400 samples of a 25-tooth revolution on 1 and 2
/// threads (the issue's target: >= 1.8x on 2 threads).
void BM_MeanExcitationMonteCarlo(benchmark::State& state) {
  const geardyn::GearPairModel model(geardyn::testing::issue4ExampleSpec());
  geardyn::MonteCarloOptions options;
  options.samples = 400;
  options.teeth = 25;
  options.pitch_error_std = 1e-6;
  options.profile_error_std = 2e-6;
  options.stiffness_std = 0.03;
  options.baseload = 1418.4;
  options.threads = static_cast<int>(state.range(0));
  for (auto _ : state)
    benchmark::DoNotOptimize(geardyn::runMeanExcitationMonteCarlo(model, options).size());
  state.SetItemsProcessed(state.iterations() * options.samples);
}
BENCHMARK(BM_MeanExcitationMonteCarlo)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
