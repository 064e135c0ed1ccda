#pragma once
/// \file
/// Configuration and results of `geardyn stats`: Gelman's mean excitation ratio from the
/// gear-pair model (with an optional simulated check) or from given moments.

#include <nlohmann/json.hpp>

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/stats/mean_excitation.h"
#include "geardyn/stats/monte_carlo.h"

namespace geardyn::config {

/// The schema of `geardyn stats`: the simulate sections plus [stats].
ConfigSchema statsSchema();

/// [monte_carlo] options for a model (teeth default: [pinion] teeth, else 1).
MonteCarloOptions monteCarloOptionsFromConfig(const Config& config, double baseload, int threads);

/// The statistics of a CSV record when source = "csv": K̄ = mean K, k = K/K̄,
/// e_f = E_f K̄ / F₀ with F₀ = stats.baseload (required) and a = stats.a.
MeanExcitation meanExcitationFromConfigCsv(const Config& config);

/// The moments of [stats] when source = "moments".
MeanExcitation meanExcitationFromConfigMoments(const Config& config);

}  // namespace geardyn::config
