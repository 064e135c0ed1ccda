#pragma once
/// \file
/// The gearbox description file (TOML): named shafts, gears, meshes, bearings, couplings and
/// planetary stages, the operating point and the shared mesh-stiffness model options — its
/// schema (unknown keys and names get a did-you-mean, every value range-checked) and the
/// GearTrainSpec it describes. One gearbox file, many analyses: an analysis file names it with
/// `[gearbox] file = "path"` (relative to the analysis file) or holds the same sections inline.

#include <string>
#include <vector>

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/system/gear_train.h"

namespace geardyn::config {

/// The top-level sections of a gearbox description.
const std::vector<std::string>& gearboxSectionNames();

/// Adds the gearbox sections ([gearbox], [shafts.<name>], [gears.<name>], [meshes.<name>],
/// [bearings.<name>], [couplings.<name>], [planetary.<name>], [operating_point],
/// [mesh_stiffness.*]) to a schema.
void addGearboxSections(config::ConfigSchema& schema);

/// The schema of a gearbox file on its own (`geardyn schema gearbox`).
config::ConfigSchema gearboxSchema();

/// The description in a configuration that holds the gearbox sections. Mesh-stiffness models
/// are built here for each mesh's pair (InputError naming the key when a model does not apply,
/// e.g. a potential-energy model on a ring mesh); their warnings are appended.
GearTrainSpec gearTrainFromConfig(const config::Config& config, std::vector<std::string>& warnings);

}  // namespace geardyn::config
