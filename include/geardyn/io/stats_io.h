#pragma once
/// \file
/// Configuration and results of `geardyn stats`: Gelman's mean excitation ratio from the
/// gear-pair model (with an optional simulated check) or from given moments.

#include <nlohmann/json.hpp>

#include "geardyn/io/config.h"
#include "geardyn/io/config_schema.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/stats/mean_excitation.h"
#include "geardyn/stats/monte_carlo.h"

namespace geardyn::io {

/// The schema of `geardyn stats`: the simulate sections plus [stats].
ConfigSchema statsSchema();

/// Every statistic of a MeanExcitation, by the paper's names.
nlohmann::ordered_json toJson(const MeanExcitation& s);

/// [monte_carlo] options for a model (teeth default: [pinion] teeth, else 1).
MonteCarloOptions monteCarloOptionsFromConfig(const Config& config, double baseload, int threads);

/// results.monte_carlo: the distributions of R and L_d (also in newtons: L_d F₀).
nlohmann::ordered_json monteCarloJson(const MonteCarloOptions& options,
                                      const std::vector<MonteCarloSample>& samples);
/// monte_carlo.csv (one row per sample) and histogram.csv (of R).
CsvTable monteCarloTable(const std::vector<MonteCarloSample>& samples);
CsvTable histogramTable(const std::vector<MonteCarloSample>& samples, int bins);

/// The statistics of a CSV record when source = "csv": K̄ = mean K, k = K/K̄,
/// e_f = E_f K̄ / F₀ with F₀ = stats.baseload (required) and a = stats.a.
MeanExcitation meanExcitationFromConfigCsv(const Config& config);

/// The moments of [stats] when source = "moments".
MeanExcitation meanExcitationFromConfigMoments(const Config& config);

}  // namespace geardyn::io
