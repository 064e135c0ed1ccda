/// `geardyn train ANALYSIS.toml`: any gear train described once (a gearbox file or inline) and
/// analysed (geardyn/analysis/analyses.h, trainAnalysis); with gearbox.all_load_cases, once per
/// load case of a REXS gearbox, each into its own folder.

#include <fmt/format.h>

#include <algorithm>

#include "analysis_command.h"
#include "geardyn/analysis/analyses.h"
#include "geardyn/config/output_section.h"
#include "geardyn/config/rexs_gearbox_config.h"
#include "geardyn/error.h"
#include "geardyn/io/rexs/rexs_gearbox.h"
#include "geardyn/io/rexs/rexs_reader.h"

namespace geardyn::cli {

namespace {

int runTrainOnce(const CommandOptions& options) {
  const analysis::TrainInputs inputs =
      analysis::loadTrainInputs(options.config_file, options.overrides);
  return runLibraryResult(
      "train", "train", config::outputOptionsFromConfig(inputs.analysis).plots, options,
      [&](analysis::AnalysisContext& context) { return analysis::trainAnalysis(inputs, context); });
}

}  // namespace

int runTrain(const CommandOptions& options) {
  const analysis::TrainInputs loaded =
      analysis::loadTrainInputs(options.config_file, options.overrides);
  if (!loaded.analysis.boolean("gearbox.all_load_cases")) return runTrainOnce(options);
  // Every load case of a REXS gearbox: one run each, into its own folder.
  if (!io::rexs::isRexsPath(loaded.gearbox_source) || loaded.analysis.has("gearbox.load_case"))
    throw InputError("gearbox.all_load_cases", "true",
                     "only with a REXS gearbox file and without gearbox.load_case");
  const auto cases = config::importRexsFile(loaded.gearbox_source).load_cases;
  if (cases.empty())
    throw InputError("gearbox.all_load_cases", "true",
                     loaded.gearbox_source + " has no load spectrum");
  int code = kExitOk;
  for (const auto& c : cases) {
    CommandOptions one = options;
    one.out_dir = options.resultFolder() / fmt::format("load_case_{}", c.id);
    one.overrides.push_back("gearbox.all_load_cases=false");
    one.overrides.push_back(fmt::format("gearbox.load_case={}", c.id));
    code = std::max(code, runTrainOnce(one));
  }
  return code;
}

}  // namespace geardyn::cli
