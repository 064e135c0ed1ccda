#pragma once
/// \file
/// Configuration and results of `geardyn ltca`: the gear pair, the flank modifications, the
/// loaded tooth contact analysis at a load, the Harris map and Gelman's statistics against
/// load.

#include <filesystem>
#include <string>
#include <vector>

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/contact/loaded_contact.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/stats/load_statistics.h"

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

/// `geardyn ltca` on a mesh of a gearbox: `file` names the gearbox (gearbox.file, relative to
/// it) and the mesh (gearbox.mesh, an external mesh of [meshes]; --set may change either). The
/// mesh's gears become [pinion] and [gear] (gear a is the pinion), its centre_distance
/// pair.centre_distance, its modifications [modifications] (unless the file has its own), and
/// its static force along the transverse line of action at the gearbox's operating point
/// ltca.force (unless given); the result is validated by `schema` as a standalone pair's file.
/// InputError for an unknown mesh (the mesh names, with a did-you-mean), an internal mesh, a
/// [pinion] or [gear] section or pair.centre_distance beside gearbox.file, or a mesh without
/// load. The file's [pair] driver (default: gear a, the pinion) and speed_rpm are kept.
Config loadLtcaOnGearboxMesh(const std::filesystem::path& file, const ConfigSchema& schema,
                             const std::vector<std::string>& overrides);

}  // namespace geardyn::config
