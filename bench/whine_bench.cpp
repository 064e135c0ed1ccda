/// The gearbox's own deflection into its meshes' loaded contact (issue 36), on the flexible
/// two-stage reducer at its load case: the static deflection, the mesh misalignment, the
/// loaded tooth contact of both meshes (40 slices × 64 positions) and the coupling iterations
/// to the fixed point (tolerance 1e-4 of the face width). Target: ≤ 1 s for the whole chain.
/// `cmake --build build --target geardyn_whine_bench && build/bench/geardyn_whine_bench`.

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "geardyn/config/gearbox_config.h"
#include "geardyn/solvers/train_loaded_contact.h"

namespace {

geardyn::GearTrainModel flexibleReducer() {
  const auto config = geardyn::config::loadConfigFile(
      std::string(GEARDYN_SOURCE_DIR "/examples/gearboxes/two_stage_reducer_flexible.toml"),
      geardyn::config::gearboxSchema());
  std::vector<std::string> warnings;
  return geardyn::GearTrainModel(geardyn::config::gearTrainFromConfig(config, warnings));
}

/// The whole chain, the contact models (potential-energy tables of both pairs) included.
void BM_WhineChainTwoStageReducer(benchmark::State& state) {
  const geardyn::GearTrainModel model = flexibleReducer();
  geardyn::TrainLoadedContactOptions options;  // 40 slices, 64 positions, tolerance 1e-4
  int iterations = 0;
  for (auto _ : state) {
    const auto contacts = geardyn::trainMeshContacts(model, options.slices);
    const auto r = geardyn::solveTrainLoadedContact(model, contacts, options);
    iterations = r.iterations;
    benchmark::DoNotOptimize(r.meshes.front().face.k_hbeta);
  }
  state.counters["coupling_iterations"] = iterations;
  state.counters["dofs"] = model.dofCount();
}
BENCHMARK(BM_WhineChainTwoStageReducer)->Unit(benchmark::kMillisecond);

}  // namespace
