#pragma once
/// \file
/// Configuration and results of `geardyn stats`: Gelman's mean excitation ratio from the
/// gear-pair model (with an optional simulated check) or from given moments.

#include <nlohmann/json.hpp>

#include "geardyn/io/config.h"
#include "geardyn/io/config_schema.h"
#include "geardyn/stats/mean_excitation.h"

namespace geardyn::io {

/// The schema of `geardyn stats`: the simulate sections plus [stats].
ConfigSchema statsSchema();

/// Every statistic of a MeanExcitation, by the paper's names.
nlohmann::ordered_json toJson(const MeanExcitation& s);

/// The moments of [stats] when source = "moments".
MeanExcitation meanExcitationFromConfigMoments(const Config& config);

}  // namespace geardyn::io
