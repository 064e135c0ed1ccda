/// The gearbox translations of the commands' older file forms (config/translated_gearbox.h).

#include "geardyn/config/translated_gearbox.h"

#include "geardyn/config/fe_rotor_gearbox.h"
#include "geardyn/config/gear_pair_gearbox.h"
#include "geardyn/config/rotor_config.h"
#include "geardyn/config/rotor_gearbox.h"

namespace geardyn::config {

std::optional<std::string> translatedGearbox(const std::string& command, const Config& config) {
  // The gear-pair commands ([model] = the SDOF pair: a train with one mesh).
  if (command == "simulate" || command == "hbm" || command == "stats") {
    return gearPairGearbox(config);
  }
  // The finite-element two-shaft rotor (Visnadi & de Castro 2021), else Rao's lateral rotor.
  if (command == "rotor") {
    if (auto fe = feRotorGearbox(config)) return fe;
    return lateralRotorGearbox(config);
  }
  // The identification's known rig (its TE unknown: stated as t_p at zero amplitude).
  if (command == "identify") {
    return lateralRotorGearboxToml(knownRotorFromConfig(config), config.source());
  }
  return std::nullopt;
}

}  // namespace geardyn::config
