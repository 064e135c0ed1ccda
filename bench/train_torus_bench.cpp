// Issue 32: the per-speed cost of the torus balance (train_torus.h) against the common-period
// balance (train_response.h) on the same trains, L = 10 harmonics of each mesh:
// - the hunting-tooth reducer (z 19/71 + 21/59, 12 DOFs): common period 71 stage-1 mesh
//   periods, H = 710 (one iteration: ~15 s), against the torus of two generators (441 tones);
// - the two-stage reducer of the examples (z 23/51 + 17/47): common period 3 mesh periods,
//   H = 30, against the torus with one generator (the same tones) and with two (forced);
// and `forced` at its default settings on the hunting-tooth reducer (derived truncation 22/25,
// product index set against the box of the same N_j) and the truncation estimate.
// Measured in one run (Release, CPU time per speed, load average 8 on 2 cores, 26 Nov 2026):
// hunting-tooth reducer at L = 10: common period 7559 ms, torus 3.96 ms (9 GMRES iterations,
// 441 tones): ratio 1900; two-stage reducer: common period 1.29 ms, torus with one generator
// 1.09 ms (ratio 0.85), with two 3.87 ms. Default settings: product 16.3 ms (1427 tones, 9
// iterations), box 29.2 ms (2295 tones), the estimate 55 ms per sweep: 200 speeds ≈ 3.4 s of
// CPU on one thread (the common period at the derived H = 1562 is not run: r(2H + 1) = 6250
// dense unknowns, ~10³ times the 710 case).
// After the modal compliances, the workspaces, |z|² pivoting and the kept line preconditioner
// (27 Nov 2026, load average 10): default settings product 12.3 ms, box 17.6 ms per fresh
// speed; the default sweep of 200 speeds on one thread 2282 ms fresh and factorised, 2119 ms
// on one workspace (7.36 GMRES iterations per speed instead of 9.37), 1718 ms with the modal
// compliances too, 1494 ms with the line preconditioner kept over speeds (the default; 8.68
// iterations); the estimate 57 ms.
// Run alone: cmake --build build --target geardyn_torus_bench && build/bench/geardyn_torus_bench

#include <benchmark/benchmark.h>

#include <algorithm>
#include <numbers>
#include <string>

#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/train_analysis.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/torus/train_torus.h"
#include "geardyn/torus/train_torus_truncation.h"

namespace geardyn {
namespace {

GearTrainSpec gearbox(const std::string& name) {
  const config::Config config = config::loadConfigFile(
      std::string(GEARDYN_SOURCE_DIR "/examples/gearboxes/") + name, config::gearboxSchema());
  std::vector<std::string> warnings;
  return config::gearTrainFromConfig(config, warnings);
}

const char* const kTrains[] = {"hunting_tooth_reducer.toml", "two_stage_reducer.toml"};

// Common-period balance, one speed (the operating speed), L = 10.
void BM_CommonPeriodPerSpeed(benchmark::State& state) {
  const GearTrainModel model(gearbox(kTrains[state.range(0)]));
  TrainSteadyOptions options;
  const TrainSteadySolver solver(model, options);
  for (auto _ : state) {
    auto s = solver.solve(model.inputSpeed());
    benchmark::DoNotOptimize(s.harmonic.data());
  }
  int largest = 0;
  for (int p : trainBaseFrequency(model, 1, 1 << 30).mesh_multiple) largest = std::max(largest, p);
  state.counters["base_harmonics"] = 2.0 * largest * options.mesh_harmonics + 1.0;
}
BENCHMARK(BM_CommonPeriodPerSpeed)->Arg(0)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CommonPeriodPerSpeed)->Arg(1)->Unit(benchmark::kMillisecond);

// Torus balance, one speed; range(1): forced.torus_above (100: auto grouping; 10: one
// generator per mesh).
void BM_TorusPerSpeed(benchmark::State& state) {
  const GearTrainModel model(gearbox(kTrains[state.range(0)]));
  TrainTorusOptions options;
  options.group_harmonics = static_cast<int>(state.range(1));
  const TrainTorusSolver solver(model, options);
  int iterations = 0;
  for (auto _ : state) {
    auto s = solver.solve(model.inputSpeed());
    iterations = s.iterations;
    benchmark::DoNotOptimize(s.harmonic.data());
  }
  state.counters["generators"] = static_cast<double>(solver.generators().ratio.size());
  state.counters["tones"] = solver.toneCount();
  state.counters["gmres_iterations"] = iterations;
}
BENCHMARK(BM_TorusPerSpeed)
    ->Args({0, 100})
    ->Args({1, 100})
    ->Args({1, 10})
    ->Unit(benchmark::kMillisecond);

// What `geardyn train examples/train_hunting_tooth_reducer.toml` runs in [forced]: its analysis
// file's speeds (config::forcedSpeedsFromConfig: 200 speeds, 0.1–1.5 × the operating speed),
// the truncation estimate over them and the torus options it gives (train_torus_truncation.h).
struct DefaultForced {
  GearTrainModel model;
  std::vector<double> speeds;
  MeshHarmonicsEstimate estimate;
  TrainTorusOptions options;
};
DefaultForced defaultForced(TorusTruncation truncation) {
  const config::Config analysis = config::loadConfigFile(
      GEARDYN_SOURCE_DIR "/examples/train_hunting_tooth_reducer.toml", config::trainSchema(false));
  DefaultForced d{GearTrainModel(gearbox(kTrains[0])), {}, {}, {}};
  d.speeds = config::forcedSpeedsFromConfig(analysis, d.model.inputSpeed());
  d.estimate = estimateMeshHarmonics(d.model, d.speeds);
  d.options = torusOptionsFromEstimate(d.estimate, config::trainTorusOptionsFromConfig(analysis),
                                       truncation);
  return d;
}

// `forced` at its default settings on the hunting-tooth reducer, one speed (the operating
// speed); range(0) = 1: the product index set weighted by the estimate (the default), 0: the
// box of the same N_j.
void BM_TorusDerivedPerSpeed(benchmark::State& state) {
  const DefaultForced d =
      defaultForced(state.range(0) == 1 ? TorusTruncation::kProduct : TorusTruncation::kBox);
  const TrainTorusSolver solver(d.model, d.options);
  int iterations = 0;
  for (auto _ : state) {
    auto s = solver.solve(d.model.inputSpeed());
    iterations = s.iterations;
    benchmark::DoNotOptimize(s.harmonic.data());
  }
  state.counters["tones"] = solver.toneCount();
  state.counters["gmres_iterations"] = iterations;
}
BENCHMARK(BM_TorusDerivedPerSpeed)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

// The default sweep of `forced` on the hunting-tooth reducer on one thread: every one of its
// speeds in ascending order (the solver and the estimate set up outside the timing); the
// time per iteration is the whole sweep's CPU. range(0): 0, fresh solves with D factorised per
// tone pair and the line preconditioner factorised per speed; 1, the same on one workspace
// (buffers reused, GMRES from the previous speeds); 2, with the modal compliances too; 3, and the
// line preconditioner kept over speeds (the default, what `forced` runs per thread).
void BM_TorusDerivedSweep(benchmark::State& state) {
  DefaultForced d = defaultForced(TorusTruncation::kProduct);
  d.options.modal_compliance = state.range(0) >= 2;
  d.options.preconditioner_reuse_iterations = state.range(0) == 3 ? 2 : -1;
  const TrainTorusSolver solver(d.model, d.options);
  int iterations = 0;
  for (auto _ : state) {
    iterations = 0;
    TrainTorusWorkspace workspace;
    for (double speed : d.speeds) {
      auto s = state.range(0) == 0 ? solver.solve(speed) : solver.solve(speed, workspace);
      iterations += s.iterations;
      benchmark::DoNotOptimize(s.harmonic.data());
    }
  }
  state.counters["speeds"] = static_cast<double>(d.speeds.size());
  state.counters["gmres_iterations_per_speed"] =
      static_cast<double>(iterations) / static_cast<double>(d.speeds.size());
}
BENCHMARK(BM_TorusDerivedSweep)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// The truncation estimate itself over the default speeds (once per sweep).
void BM_TruncationEstimate(benchmark::State& state) {
  const DefaultForced d = defaultForced(TorusTruncation::kProduct);
  for (auto _ : state) {
    auto e = estimateMeshHarmonics(d.model, d.speeds);
    benchmark::DoNotOptimize(e.per_mesh.data());
  }
}
BENCHMARK(BM_TruncationEstimate)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace geardyn
