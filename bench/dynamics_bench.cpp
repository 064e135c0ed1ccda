/// SDOF gear pair, Newmark with backlash: the target is >= 1e7 steps/s on one core.
/// The model is the simulate example: Fourier stiffness (2 harmonics), 1 error harmonic,
/// backlash contact; and a step stiffness (one comparison per evaluation) for the floor.

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "geardyn/models/gear_pair_model.h"
#include "geardyn/solvers/time_response.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/stiffness/step_stiffness.h"

namespace {

geardyn::GearPairModel backlashModel(bool step) {
  geardyn::GearPairModelSpec spec;
  spec.mass = 1.589;
  spec.damping = 2 * 0.05 * std::sqrt(4.55e8 * 1.589);
  spec.mean_force = 1418.4;
  spec.contact = geardyn::ContactLaw::kBacklash;
  spec.backlash = 1e-4;
  if (step) {
    spec.stiffness = std::make_shared<geardyn::StepMeshStiffness>(
        geardyn::StepMeshStiffness::fromMean(4.55e8, 1.6));
  } else {
    spec.stiffness = std::make_shared<geardyn::FourierMeshStiffness>(
        4.55e8, std::vector<double>{0.2, 0.1}, std::vector<double>{std::numbers::pi, std::numbers::pi}, 1.6);
  }
  spec.transmission_error.addFourier({1e-6}, {0.0});
  spec.mesh_frequency = 1000.0;
  return geardyn::GearPairModel(spec);
}

void BM_NewmarkBacklashSteps(benchmark::State& state) {
  const geardyn::GearPairModel model = backlashModel(state.range(0) == 1);
  constexpr long long kSteps = 1 << 20;
  const double h = 1e-3 / 512;
  for (auto _ : state) {
    const auto s = geardyn::integrateNewmark(model, geardyn::NewmarkParameters::averageAcceleration(),
                                             0.0, h, kSteps, 3.1e-6 + 1e-4, 0.0, 1e-14);
    benchmark::DoNotOptimize(s.x);
  }
  state.SetItemsProcessed(state.iterations() * kSteps);
}
BENCHMARK(BM_NewmarkBacklashSteps)->Arg(0)->Arg(1)->ArgName("step_stiffness")->Unit(benchmark::kMillisecond);

}  // namespace
