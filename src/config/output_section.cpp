#include "geardyn/config/output_section.h"

namespace geardyn::config {

void addOutputSection(ConfigSchema& schema) {
  schema.section("output", "What to write besides summary.json and the CSV tables.");
  schema.boolean("output.plots")
      .defaultValue(true)
      .doc("draw PNG plots with matplotlib (skipped with a warning if it is missing)");
}

OutputOptions outputOptionsFromConfig(const Config& config) {
  OutputOptions options;
  options.plots = config.boolean("output.plots");
  return options;
}

}  // namespace geardyn::config
