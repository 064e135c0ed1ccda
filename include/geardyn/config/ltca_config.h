#pragma once
/// \file
/// Configuration and results of `geardyn ltca`: the gear pair, the flank modifications, the
/// loaded tooth contact analysis at a load, the Harris map and Gelman's statistics against
/// load.

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/contact/load_statistics.h"
#include "geardyn/contact/loaded_contact.h"
#include "geardyn/io/csv_table.h"

namespace geardyn::config {

ConfigSchema ltcaSchema();

/// Adds [modifications] (designed relief presets, reliefs, crowning, slope and pitch errors),
/// or the same keys under `prefix` (e.g. "meshes.*.modifications" for a gearbox mesh).
void addModificationsSection(ConfigSchema& schema, const std::string& prefix = "modifications");

/// The loaded tooth contact of a gear pair with the modifications under `prefix` of a
/// configuration (potential-energy compliance with the [mesh_stiffness.potential_energy]
/// options when the schema has them), `slices` face slices per pair.
std::shared_ptr<const LoadedToothContact> loadedContactFromConfig(
    const Config& config, const GearPair& pair, int slices,
    const std::string& prefix = "modifications");

/// The modifications under `prefix` ([modifications]) for the pair's potential-energy model
/// (presets need it for their amount and length).
PairModifications pairModificationsFromConfig(const Config& config,
                                              const PotentialEnergyMeshStiffness& stiffness,
                                              const std::string& prefix = "modifications");

}  // namespace geardyn::config
