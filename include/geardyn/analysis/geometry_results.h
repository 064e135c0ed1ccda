#pragma once
/// \file
/// Configuration and results of gear-pair geometry: the [pinion], [gear] and [pair] sections
/// (shared by every command that needs a gear pair), the GearPairSpec they describe, and the
/// JSON / CSV form of a GearPair.

#include <nlohmann/json.hpp>

#include "geardyn/config/config_schema.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/io/csv_table.h"

namespace geardyn::analysis {

/// Headline numbers of a gear pair (summary.json "results"): pair quantities, then one object
/// per member. SI units; angles in rad with a `_deg` companion.
nlohmann::ordered_json toJson(const GearPair& pair);

/// One row per member (pinion, gear) with the per-gear quantities; units in the column names.
io::CsvTable memberTable(const GearPair& pair);

/// Half a tooth of each member (see ToothProfile): columns member, x_m, y_m, in the member's
/// frame (centre at the origin, tooth centreline along +y).
io::CsvTable toothProfileTable(const GearPair& pair);

}  // namespace geardyn::analysis
