#pragma once
/// \file
/// Configuration and results of `geardyn hbm`: the [hbm] and [sweep] sections, the forced
/// response sweep table and the one-period details at requested frequencies.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/config/simulate_config.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/solvers/harmonic_balance.h"

namespace geardyn::config {

/// The schema of `geardyn hbm`: the dynamics sections plus [hbm] and [sweep].
ConfigSchema hbmSchema();

HarmonicBalanceOptions harmonicBalanceOptionsFromConfig(const Config& config);

}  // namespace geardyn::config
