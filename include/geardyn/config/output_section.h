#pragma once
/// \file
/// The [output] section every command shares: what to write besides summary.json and the CSV
/// tables.

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"

namespace geardyn::config {

struct OutputOptions {
  bool plots = true;  ///< draw PNG plots (needs Debian's python3-matplotlib)
};

/// Adds [output] with its keys to a schema.
void addOutputSection(ConfigSchema& schema);

OutputOptions outputOptionsFromConfig(const Config& config);

}  // namespace geardyn::config
