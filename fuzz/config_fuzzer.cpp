/// libFuzzer target: arbitrary bytes through the whole `geardyn geometry` input path (TOML
/// parse, schema validation, GearPair construction, JSON results). Bad input may only ever end
/// in geardyn::InputError; anything else (another exception, a crash, a sanitizer report) is a
/// bug.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geardyn/analysis/geometry_results.h"
#include "geardyn/config/config.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/error.h"
#include "geardyn/geometry/gear_pair.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const geardyn::config::ConfigSchema schema = geardyn::config::geometrySchema();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto config = geardyn::config::parseConfig(text, "fuzz.toml", schema);
    const geardyn::GearPair pair(geardyn::config::gearPairSpecFromConfig(config));
    volatile std::size_t length = geardyn::analysis::toJson(pair).dump().size();
    (void)length;
  } catch (const geardyn::InputError&) {
    // the expected outcome for bad input
  }
  return 0;
}
