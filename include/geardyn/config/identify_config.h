#pragma once
/// \file
/// Configuration and results of `geardyn identify`: the schema, the whirl spectra read from
/// result folders of `geardyn rotor` or `geardyn spectrum`, the known rotor data, priors, an
/// optional truth, and the result tables.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/identify/dte_identification.h"
#include "geardyn/io/csv_table.h"

namespace geardyn::config {

ConfigSchema identifySchema();

IdentificationOptions identificationOptionsFromConfig(const Config& config);

}  // namespace geardyn::config
