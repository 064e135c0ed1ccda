/// libFuzzer target: arbitrary bytes through the whole `geardyn stiffness` input path (TOML,
/// schema, gear pair, every mesh-stiffness model, results JSON and CSV tables). Bad input may
/// only end in geardyn::InputError.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geardyn/analysis/stiffness_results.h"
#include "geardyn/config/config.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const geardyn::config::ConfigSchema schema = geardyn::config::stiffnessSchema();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    // Keep each input cheap: at most 64 output positions and 4097 table nodes.
    const auto config = geardyn::config::parseConfig(text, "fuzz.toml", schema);
    if (config.integer("mesh_stiffness.positions") > 64 ||
        config.integer("mesh_stiffness.potential_energy.table_points") > 4097 ||
        config.integer("mesh_stiffness.potential_energy.slices") > 200) {
      return 0;
    }
    const geardyn::GearPair pair(geardyn::config::gearPairSpecFromConfig(config));
    const auto models = geardyn::config::buildMeshStiffnessModels(config, pair);
    const auto results = geardyn::analysis::stiffnessResultsJson(config, pair, models);
    volatile std::size_t length =
        results.dump().size() +
        geardyn::analysis::stiffnessCurveTable(config, pair, models).toString().size() +
        geardyn::analysis::fourierTable(results["models"]).toString().size();
    (void)length;
  } catch (const geardyn::InputError&) {
    // the expected outcome for bad input
  }
  return 0;
}
