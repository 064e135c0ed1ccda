/// Harmonic balance: cost of one continuation point for a 1-DOF gear pair with backlash at
/// H = 15, N = 256 (issue 17 targets on one core: <= 25 µs without stability, <= 0.1 ms with
/// the default stability; NLvib takes 8–10 ms), the whole sweep of the issue's Kahraman–Singh
/// case 0.25–1.25 with derived steps (stability 0: none, 1: Hill, 2: monodromy, the default),
/// and the Saletti et al. (2025) Table 1 sweep at 100 N m (H = 14, 500–3500 Hz, monodromy
/// stability, the steps of tests/reference/saletti_hbm_long_test.cpp): issue #31 bounds its
/// time to within 10 % of the gear-pair solver's before the solvers were unified.

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "geardyn/solvers/harmonic_balance.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/system/gear_pair_model.h"
#include "support/reference_pairs.h"

namespace {

geardyn::GearPairModel kahramanSingh() {
  // The issue-17 case (nondimensional, backlash, 3-harmonic k and e).
  return geardyn::GearPairModel(geardyn::testing::kahramanSinghIssue17Spec());
}

void BM_HbmContinuationPoint(benchmark::State& state) {
  const geardyn::GearPairModel model = kahramanSingh();
  geardyn::HarmonicBalanceOptions options;
  options.harmonics = 15;
  options.samples_per_period = 256;
  geardyn::HarmonicBalance hbm(model, options);
  geardyn::ContinuationOptions sweep;
  sweep.start = 0.25;
  sweep.stop = 1.25;
  geardyn::deriveContinuationSteps(sweep, 1.0, 0.05, options.harmonics);
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

void BM_SalettiTable1Sweep(benchmark::State& state) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  const geardyn::GearPairModel model(geardyn::testing::salettiModelSpec(100.0));
  geardyn::HarmonicBalanceOptions options;
  options.harmonics = 14;
  options.samples_per_period = 256;
  geardyn::HarmonicBalance hbm(model, options);
  geardyn::ContinuationOptions sweep;
  sweep.start = kTwoPi * 500.0;
  sweep.stop = kTwoPi * 3500.0;
  sweep.initial_step = kTwoPi * 5;
  sweep.min_step = kTwoPi * 0.01;
  sweep.max_step = kTwoPi * 200;
  sweep.stability_method = geardyn::StabilityMethod::kMonodromy;
  long long points = 0;
  for (auto _ : state) {
    const auto result = geardyn::continueInFrequency(hbm, sweep);
    points = static_cast<long long>(result.points.size());
    benchmark::DoNotOptimize(result.points.size());
  }
  state.counters["points"] = static_cast<double>(points);
}
BENCHMARK(BM_SalettiTable1Sweep)->Unit(benchmark::kMillisecond);

}  // namespace
