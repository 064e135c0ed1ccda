#pragma once
/// \file
/// Configuration and results of gear-pair geometry: the [pinion], [gear] and [pair] sections
/// (shared by every command that needs a gear pair), the GearPairSpec they describe, and the
/// JSON / CSV form of a GearPair.

#include <nlohmann/json.hpp>

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/io/csv_table.h"

namespace geardyn::config {

/// Adds the [pinion], [gear] and [pair] sections to a schema. With `required` false the gear
/// keys that are otherwise required become optional (for commands that need a gear pair only
/// for some choices); hasGearPair then says whether one was given.
void addGearPairSections(ConfigSchema& schema, bool required = true);

/// Adds the keys of one gear ([pinion], [gear], or a collection item such as "gears.*"):
/// teeth, module, pressure_angle_deg, helix_angle_deg, face_width, profile shift, rack,
/// bore and material. Without `required` the keys without a default are optional. A non-empty
/// `bore_default` makes bore_diameter optional (absent: 0 from gearSpecFromConfig) and says in
/// its documentation what the reader derives instead.
void addGearSection(ConfigSchema& schema, const std::string& name, const std::string& role,
                    bool required, const std::string& bore_default = {});
/// The gear at a section of a configuration (InputError naming the key when teeth, module or
/// face_width is missing).
GearSpec gearSpecFromConfig(const Config& config, const std::string& name);

/// Whether a configuration describes a gear pair (pinion.teeth given).
bool hasGearPair(const Config& config);

/// The schema of `geardyn geometry`.
ConfigSchema geometrySchema();

/// The gear pair a configuration with the sections of addGearPairSections describes.
GearPairSpec gearPairSpecFromConfig(const Config& config);

}  // namespace geardyn::config
