#pragma once
/// \file
/// Configuration and results of `geardyn stats`: Gelman's mean excitation ratio from the
/// gear-pair model (with an optional simulated check) or from given moments.

#include <nlohmann/json.hpp>

#include "geardyn/config/config_schema.h"
#include "geardyn/config/stats_config.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/stats/mean_excitation.h"
#include "geardyn/stats/monte_carlo.h"

namespace geardyn::analysis {

/// Every statistic of a MeanExcitation, by the paper's names.
nlohmann::ordered_json toJson(const MeanExcitation& s);

/// results.monte_carlo: the distributions of R and L_d (also in newtons: L_d F₀).
nlohmann::ordered_json monteCarloJson(const MonteCarloOptions& options,
                                      const std::vector<MonteCarloSample>& samples);
/// monte_carlo.csv (one row per sample) and histogram.csv (of R).
io::CsvTable monteCarloTable(const std::vector<MonteCarloSample>& samples);
io::CsvTable histogramTable(const std::vector<MonteCarloSample>& samples, int bins);

}  // namespace geardyn::analysis
