/// Harmonic balance: cost of one continuation point for a 1-DOF gear pair with backlash at
/// H = 15, N = 256 (issue target <= 0.1 ms on one core; NLvib takes 8–10 ms), and of one
/// Newton solve with and without the Hill stability analysis.

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "geardyn/models/gear_pair_model.h"
#include "geardyn/solvers/harmonic_balance.h"
#include "geardyn/stiffness/fourier_stiffness.h"

namespace {

geardyn::GearPairModel kahramanSingh() {
  // Nondimensional: m = 1, ζ = 0.05, k = 1 + 0.2 cos, backlash b = 1, load 0.1, error 0.1.
  geardyn::GearPairModelSpec spec;
  spec.mass = 1.0;
  spec.damping = 0.1;
  spec.mean_force = 0.1;
  spec.contact = geardyn::ContactLaw::kBacklash;
  spec.backlash = 1.0;
  spec.stiffness = std::make_shared<geardyn::FourierMeshStiffness>(1.0, std::vector<double>{0.2},
                                                                   std::vector<double>{0.0}, 1.6);
  spec.transmission_error.addFourier({0.1}, {0.0});
  return geardyn::GearPairModel(spec);
}

void BM_HbmContinuationPoint(benchmark::State& state) {
  const geardyn::GearPairModel model = kahramanSingh();
  geardyn::HarmonicBalanceOptions options;
  options.harmonics = 15;
  options.samples_per_period = 256;
  geardyn::HarmonicBalance hbm(model, options);
  geardyn::ContinuationOptions sweep;
  sweep.start = 0.5;
  sweep.stop = 1.5;
  sweep.initial_step = 0.002;
  sweep.min_step = 1e-6;
  sweep.max_step = 0.01;
  sweep.stability = state.range(0) > 0;
  sweep.stability_method =
      state.range(0) == 2 ? geardyn::StabilityMethod::kMonodromy : geardyn::StabilityMethod::kHill;
  long long points = 0;
  for (auto _ : state) {
    const auto result = geardyn::continueInFrequency(hbm, sweep);
    points += static_cast<long long>(result.points.size());
    benchmark::DoNotOptimize(result.points.size());
  }
  state.counters["points"] = benchmark::Counter(static_cast<double>(points) / state.iterations());
  state.counters["per_point"] = benchmark::Counter(
      static_cast<double>(points), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_HbmContinuationPoint)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("stability")
    ->Unit(benchmark::kMillisecond);

void BM_HbmResidualAndJacobian(benchmark::State& state) {
  const geardyn::GearPairModel model = kahramanSingh();
  geardyn::HarmonicBalanceOptions options;
  options.harmonics = 15;
  options.samples_per_period = 256;
  geardyn::HarmonicBalance hbm(model, options);
  Eigen::VectorXd q = hbm.linearGuess(0.9), r, dw;
  Eigen::MatrixXd J;
  for (auto _ : state) {
    hbm.residual(q, 0.9, r, &J, &dw);
    benchmark::DoNotOptimize(J.data());
  }
}
BENCHMARK(BM_HbmResidualAndJacobian)->Unit(benchmark::kMicrosecond);

}  // namespace
