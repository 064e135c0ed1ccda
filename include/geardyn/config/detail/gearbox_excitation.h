#pragma once
/// \file
/// The keys of a gearbox's excitations beside its meshes' transmission errors
/// (system/train_excitation.h): [unbalances.<name>], [runouts.<name>] and
/// [bearing_excitations.<name>], and their reader.

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/system/gear_train.h"

namespace geardyn::config::detail {

void addGearboxExcitationSections(ConfigSchema& schema);

/// Fills spec.unbalances, spec.runouts and spec.bearing_excitations (angles to radians).
void readGearboxExcitations(const Config& config, GearTrainSpec& spec);

}  // namespace geardyn::config::detail
