// REXS import (issue 20): the largest example model (FVA planetary stage, REXS 1.4 JSON,
// 155 KB) and the FVA two-stage gearbox (REXS 1.6 XML) from ../shared/rexs/ read, mapped onto
// the gearbox description and read back as a validated gearbox configuration (target < 50 ms).
// Skipped when the example folder is absent.

#include <benchmark/benchmark.h>

#include <filesystem>

#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/rexs_gearbox_config.h"
#include "geardyn/io/rexs/rexs_gearbox.h"

namespace geardyn {
namespace {

const std::filesystem::path kRexs =
    std::filesystem::path(GEARDYN_SOURCE_DIR) / ".." / "shared" / "rexs";

void importFile(benchmark::State& state, const char* name) {
  const auto path = kRexs / name;
  if (!std::filesystem::exists(path)) {
    state.SkipWithError(("REXS example not found: " + path.string()).c_str());
    return;
  }
  for (auto _ : state) {
    const auto imported = config::importRexsFile(path);
    const config::Config config = config::parseConfig(imported.toml, name, config::gearboxSchema());
    benchmark::DoNotOptimize(config.resolved().size());
  }
}

void BM_RexsImportPlanetaryJson(benchmark::State& state) {
  importFile(state, "FVA_Planetary_stage_-_Minus_gearing_1.1_vers2.rexsj");
}
void BM_RexsImportTwoStageXml(benchmark::State& state) {
  importFile(state, "FVA-Industriegetriebe_2_stufig_1-6.rexs");
}
BENCHMARK(BM_RexsImportPlanetaryJson)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RexsImportTwoStageXml)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace geardyn
