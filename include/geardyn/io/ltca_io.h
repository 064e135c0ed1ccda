#pragma once
/// \file
/// Configuration and results of `geardyn ltca`: the gear pair, the flank modifications, the
/// loaded tooth contact analysis at a load, the Harris map and Gelman's statistics against
/// load.

#include "geardyn/contact/load_statistics.h"
#include "geardyn/contact/loaded_contact.h"
#include "geardyn/io/config.h"
#include "geardyn/io/config_schema.h"
#include "geardyn/io/csv_table.h"

namespace geardyn::io {

ConfigSchema ltcaSchema();

/// Adds [modifications] (designed relief presets, reliefs, crowning, slope and pitch errors).
void addModificationsSection(ConfigSchema& schema);

/// The loaded tooth contact of a gear pair with the [modifications] of a configuration
/// (potential-energy compliance with the [mesh_stiffness.potential_energy] options when the
/// schema has them), `slices` face slices per pair.
std::shared_ptr<const LoadedToothContact> loadedContactFromConfig(const Config& config,
                                                                  const GearPair& pair, int slices);

/// The modifications of [modifications] for the pair's potential-energy model (presets need
/// it for their amount and length).
PairModifications pairModificationsFromConfig(const Config& config,
                                              const PotentialEnergyMeshStiffness& stiffness);

/// phase, ste_m, no_load_te_m, secant_stiffness, tangent_stiffness, load_pair_j..., share_pair_j
CsvTable ltcaTable(const std::vector<LoadedContactPoint>& points, double force);
/// force_n, peak_to_peak_m, mean_m, harmonic_1_m, ...
CsvTable harrisTable(const std::vector<HarrisPoint>& map);
/// a, m1_k, m1_ef, d_k, d_e, r_ke, delta_m1_ef, variable_term_v, ratio_eq7, ratio_eq11
CsvTable loadStatisticsTable(const std::vector<LoadStatistics>& stats);

}  // namespace geardyn::io
