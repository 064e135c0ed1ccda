// Issue 32: the nonlinear torus balance (train_torus_balance.h) on the flexible hunting-tooth
// reducer (examples/gearboxes/hunting_tooth_reducer_flexible.toml: 270 DOFs, backlash at stage 1)
// at the defaults of `geardyn train` [nonlinear] (6 harmonics per mesh, 85 tones):
// - the set-up of one speed (B_p and dB_p of the 85 tones: one sparse LU of D(ω_p) each), which
//   the pseudo-arclength corrector pays at every iteration (its ω moves);
// - the default sweep upward, 0.5-1.5 × the operating speed, with the analysis's step rules
//   (steps 1/100 of the range at most), the whole sweep's CPU per iteration.
// Measured (Release, CPU, one run, load average 8-9 on 2 cores, 27 Nov 2026) after the sparse
// dD/dω: see docs/theory/torus_harmonic_balance.md ("Cost of the nonlinear sweep").
// Run alone: cmake --build build --target geardyn_torus_bench &&
//   build/bench/geardyn_torus_bench --benchmark_filter=Nonlinear

#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>

#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/train_analysis.h"
#include "geardyn/solvers/continuation.h"
#include "geardyn/torus/train_torus_balance.h"
#include "geardyn/torus/train_torus_lyapunov.h"
#include "geardyn/units.h"

namespace geardyn {
namespace {

GearTrainModel flexibleReducer() {
  const config::Config config = config::loadConfigFile(
      std::string(GEARDYN_SOURCE_DIR "/examples/gearboxes/hunting_tooth_reducer_flexible.toml"),
      config::gearboxSchema());
  std::vector<std::string> warnings;
  return GearTrainModel(config::gearTrainFromConfig(config, warnings));
}

TrainTorusBalanceOptions defaultOptions() {
  TrainTorusBalanceOptions options;
  options.mesh_harmonics = 6;  // nonlinear.torus_mesh_harmonics
  return options;
}

// One speed's set-up and residual (range(0) = 1: with ∂R/∂u and ∂R/∂ω, as every corrector
// iteration of the pseudo-arclength continuation asks).
void BM_TorusNonlinearPerSpeed(benchmark::State& state) {
  const GearTrainModel model = flexibleReducer();
  TrainTorusBalance hb(model, defaultOptions());
  const double omega = hb.baseFrequency(model.inputSpeed());
  const Eigen::VectorXd u = hb.startingGuess(omega);
  Eigen::VectorXd r, dr_domega;
  Eigen::MatrixXd J;
  int i = 0;
  for (auto _ : state) {
    const double w = omega * (1.0 + 1e-6 * (++i));  // a new ω: the set-up is not cached
    if (state.range(0) == 1) {
      hb.residual(u, w, r, &J, &dr_domega);
    } else {
      hb.residual(u, w, r, nullptr, nullptr);
    }
    benchmark::DoNotOptimize(r.data());
  }
  state.counters["tones"] = static_cast<double>(hb.tones().cols());
  state.counters["dofs"] = static_cast<double>(model.dofCount());
}
BENCHMARK(BM_TorusNonlinearPerSpeed)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The default sweep upward (as runTrainNonlinearTorus: max step range/100, first step a fifth).
void BM_TorusNonlinearSweepUp(benchmark::State& state) {
  const GearTrainModel model = flexibleReducer();
  std::size_t points = 0;
  for (auto _ : state) {
    TrainTorusBalance hb(model, defaultOptions());
    ContinuationOptions sweep;
    sweep.start = hb.baseFrequency(0.5 * model.inputSpeed());
    sweep.stop = hb.baseFrequency(1.5 * model.inputSpeed());
    const double range = sweep.stop - sweep.start;
    sweep.max_step = range / 100.0;
    sweep.initial_step = sweep.max_step / 5.0;
    sweep.min_step = 1e-6 * range;
    sweep.fold_tolerance = 1e-3 * range;
    sweep.stability = false;
    const ContinuationResult run = continueInFrequency(hb, sweep);
    points = run.points.size();
    benchmark::DoNotOptimize(points);
  }
  state.counters["points"] = static_cast<double>(points);
}
BENCHMARK(BM_TorusNonlinearSweepUp)->Iterations(1)->Unit(benchmark::kMillisecond);

// Stability of one solution at range(0) % of the operating speed (60, 100, 127: below, at and
// near the stage-1 response peak of 1900 rpm) over 100 periods of the slower generator (the
// analysis's window): range(1) = 0, the Newmark check (the whole nonlinear train, 256 steps per
// stage-1 mesh period); 1, the Lyapunov estimate (4 columns, 64 steps per period). Counters: the
// verdicts, λ₁ and the Newmark deviation.
void BM_TorusNonlinearStability(benchmark::State& state) {
  const GearTrainModel model = flexibleReducer();
  TrainTorusBalance hb(model, defaultOptions());
  HarmonicBalancePoint point;
  point.omega = hb.baseFrequency(0.01 * state.range(0) * model.inputSpeed());
  point.q = hb.startingGuess(point.omega);
  hb.solve(point);
  const double slowest = hb.generators().ratio[1] * 0.01 * state.range(0) * model.inputSpeed();
  const double window = 100.0 / slowest;
  for (auto _ : state) {
    if (state.range(1) == 0) {
      const TorusNewmarkCheck check = torusNewmarkCheck(model, hb, point, window, 256, 0.05);
      state.counters["stable"] = check.stable ? 1 : 0;
      state.counters["deviation"] =
          *std::max_element(check.deviation.begin(), check.deviation.end());
    } else {
      const TorusLyapunovEstimate e = torusLyapunovEstimate(model, hb, point, window);
      state.counters["stable"] = e.stable ? 1 : 0;
      state.counters["lambda_per_s"] = e.max_exponent;
    }
  }
  state.counters["converged"] = point.converged ? 1 : 0;
}
BENCHMARK(BM_TorusNonlinearStability)
    ->ArgsProduct({{60, 100, 127}, {0, 1}})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace geardyn
