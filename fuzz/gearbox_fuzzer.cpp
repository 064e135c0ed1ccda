/// libFuzzer target (issue 34): arbitrary bytes as a gearbox file (TOML) through the schema
/// (unknown keys, ranges), the description (gearTrainFromConfig) and the machine's assembly
/// (GearTrainModel: graph and kinematics checks, a memory limit of 64 MiB so that a huge train
/// is refused, not allocated). Bad input may only end in geardyn::InputError.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geardyn/config/config.h"
#include "geardyn/config/gearbox_config.h"
#include "geardyn/error.h"
#include "geardyn/system/gear_train_model.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const geardyn::config::ConfigSchema schema = geardyn::config::gearboxSchema();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto config = geardyn::config::parseConfig(text, "fuzz.toml", schema);
    std::vector<std::string> warnings;
    const geardyn::GearTrainModel model(geardyn::config::gearTrainFromConfig(config, warnings),
                                        64.0 * (1 << 20));
    volatile int dofs = model.dofCount();
    (void)dofs;
  } catch (const geardyn::InputError&) {
    // the expected outcome for bad input
  }
  return 0;
}
