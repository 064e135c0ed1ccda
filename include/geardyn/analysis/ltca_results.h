#pragma once
/// \file
/// Configuration and results of `geardyn ltca`: the gear pair, the flank modifications, the
/// loaded tooth contact analysis at a load, the Harris map and Gelman's statistics against
/// load.

#include "geardyn/config/config_schema.h"
#include "geardyn/config/ltca_config.h"
#include "geardyn/contact/loaded_contact.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/stats/load_statistics.h"

namespace geardyn::analysis {

/// phase, ste_m, no_load_te_m, secant_stiffness, tangent_stiffness, load_pair_j..., share_pair_j
io::CsvTable ltcaTable(const std::vector<LoadedContactPoint>& points, double force);
/// force_n, peak_to_peak_m, mean_m, harmonic_1_m, ...
io::CsvTable harrisTable(const std::vector<HarrisPoint>& map);
/// a, m1_k, m1_ef, d_k, d_e, r_ke, delta_m1_ef, variable_term_v, ratio_eq7, ratio_eq11
io::CsvTable loadStatisticsTable(const std::vector<LoadStatistics>& stats);

}  // namespace geardyn::analysis
