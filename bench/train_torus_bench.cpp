// Issue 32: the per-speed cost of the torus balance (train_torus.h) against the common-period
// balance (train_response.h) on the same trains, L = 10 harmonics of each mesh:
// - the hunting-tooth reducer (z 19/71 + 21/59, 12 DOFs): common period 71 stage-1 mesh
//   periods, H = 710 (one iteration: ~15 s), against the torus of two generators (441 tones);
// - the two-stage reducer of the examples (z 23/51 + 17/47): common period 3 mesh periods,
//   H = 30, against the torus with one generator (the same tones) and with two (forced).
// Measured (Release, 2 cores shared with 4 other builds, CPU time per speed): hunting-tooth
// reducer 9.6 s common period against 5.7 ms torus (9 GMRES iterations, 441 tones); two-stage
// reducer 2.4 ms common period, 1.7 ms torus with one generator, 5.8 ms with two.
// Run alone: cmake --build build --target geardyn_torus_bench && build/bench/geardyn_torus_bench

#include <benchmark/benchmark.h>

#include <algorithm>
#include <numbers>
#include <string>

#include "geardyn/config/gearbox_config.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/solvers/train_torus.h"

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

}  // namespace
}  // namespace geardyn
