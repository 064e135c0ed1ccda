// Nonlinear gear trains (issue 17): cost of one continuation point of the train harmonic
// balance on the 3-planet stage with backlash at its 6 meshes (H = 15, N = 256; target <= 1 ms),
// without and with the monodromy stability, and of one nonlinear Newmark step of that stage.

#include <benchmark/benchmark.h>

#include <numbers>

#include "geardyn/solvers/continuation.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/solvers/train_nonlinear_time.h"
#include "geardyn/solvers/train_response.h"
#include "system/nonlinear_sample_trains.h"

namespace geardyn {
namespace {

void BM_TrainHbmContinuationPoint(benchmark::State& state) {
  const GearTrainModel model(testing::nonlinear::planetary(4e-6));
  TrainHarmonicBalanceOptions options;
  options.harmonics = 15;
  options.samples = 256;
  TrainHarmonicBalance hbm(model, options);
  ContinuationOptions c;  // mesh frequency 4–13 kHz: two loops with contact loss, 4 folds
  c.start = 2 * std::numbers::pi * 4000;
  c.stop = 2 * std::numbers::pi * 13000;
  c.max_step = (c.stop - c.start) / 100;
  c.stability = state.range(0) > 0;
  deriveContinuationSteps(c, 0.0, 0.05, options.harmonics);
  long long points = 0;
  for (auto _ : state) {
    const ContinuationResult r = continueInFrequency(hbm, c);
    points += static_cast<long long>(r.points.size());
    benchmark::DoNotOptimize(r.points.data());
  }
  state.counters["points"] = benchmark::Counter(static_cast<double>(points) / state.iterations());
  state.counters["per_point"] = benchmark::Counter(
      static_cast<double>(points), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_TrainHbmContinuationPoint)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("stability")
    ->Unit(benchmark::kMillisecond);

void BM_TrainNonlinearNewmarkStep(benchmark::State& state) {
  const GearTrainModel model(testing::nonlinear::planetary(4e-6));
  const double speed = model.inputSpeed();
  TrainNonlinearNewmark stepper(model, speed, 1e-6, NewmarkParameters::averageAcceleration());
  stepper.reset(0.0, solveTrainStatic(model, speed).displacement,
                Eigen::VectorXd::Zero(model.dofCount()));
  for (auto _ : state) {
    stepper.step(1e-13, 50);
    benchmark::DoNotOptimize(stepper.displacement().data());
  }
}
BENCHMARK(BM_TrainNonlinearNewmarkStep);

}  // namespace
}  // namespace geardyn
