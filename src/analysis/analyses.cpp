/// The table of analyses: names, schemas, functions.

#include "geardyn/analysis/analyses.h"

#include <chrono>

#include "geardyn/config/did_you_mean.h"
#include "geardyn/config/fe_rotor_config.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/config/hbm_config.h"
#include "geardyn/config/identify_config.h"
#include "geardyn/config/ltca_config.h"
#include "geardyn/config/rotor_config.h"
#include "geardyn/config/simulate_config.h"
#include "geardyn/config/stats_config.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/config/train_analysis.h"
#include "geardyn/error.h"
#include "geardyn/io/geometry_results.h"
#include "geardyn/io/hbm_results.h"
#include "geardyn/io/identify_results.h"
#include "geardyn/io/ltca_results.h"
#include "geardyn/io/rotor_results.h"
#include "geardyn/io/simulate_results.h"
#include "geardyn/io/stats_results.h"
#include "geardyn/io/stiffness_results.h"

namespace geardyn::analysis {
namespace {

struct Entry {
  const char* name;
  config::ConfigSchema (*schema)();
};

/// `train` with its gearbox inline (a file that names one: loadAnalysisConfig).
config::ConfigSchema trainSchema() {
  return config::trainSchema(true);
}

/// Each analysis's own schema; `rotor` has the finite-element variant too.
const std::vector<Entry>& entries() {
  static const std::vector<Entry> table = {
      {"geometry", config::geometrySchema}, {"stiffness", config::stiffnessSchema},
      {"simulate", config::simulateSchema}, {"stats", config::statsSchema},
      {"hbm", config::hbmSchema},           {"rotor", config::rotorSchema},
      {"spectrum", config::spectrumSchema}, {"identify", config::identifySchema},
      {"ltca", config::ltcaSchema},         {"train", trainSchema}};
  return table;
}

const Entry& entry(const std::string& name) {
  for (const auto& e : entries()) {
    if (name == e.name) return e;
  }
  std::string allowed = "one of";
  for (const auto& e : entries()) allowed += std::string(" ") + e.name;
  if (const auto match = config::closestMatch(name, analysisNames())) {
    allowed += "; did you mean '" + *match + "'?";
  }
  throw InputError("analysis", name, allowed);
}

}  // namespace

const std::vector<std::string>& analysisNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& e : entries()) out.emplace_back(e.name);
    return out;
  }();
  return names;
}

config::ConfigSchema analysisSchema(const std::string& name, const std::string& model_type) {
  const Entry& own = entry(name);
  config::ConfigSchema schema =
      name == "rotor" && model_type == "fe_geared_rotor" ? config::feRotorSchema() : own.schema();
  if (name == "train") return schema;
  for (const auto& other : entries()) {
    if (other.name == name || std::string(other.name) == "train") continue;
    schema.addForeignSchema(other.schema());
    if (std::string(other.name) == "rotor") schema.addForeignSchema(config::feRotorSchema());
  }
  return schema;
}

config::Config loadAnalysisConfig(const std::string& name, const std::filesystem::path& file,
                                  const std::vector<std::string>& overrides) {
  if (name == "ltca" && !config::peekConfigString(file, "gearbox.file").empty()) {
    return config::loadLtcaOnGearboxMesh(file, analysisSchema(name, ""), overrides);
  }
  if (name != "train") {
    return config::loadConfigFile(
        file, analysisSchema(name, config::peekConfigString(file, "model.type")), overrides);
  }
  const TrainInputs inputs = loadTrainInputs(file, overrides);
  if (inputs.analysis.boolean("gearbox.all_load_cases"))
    throw InputError("gearbox.all_load_cases", "true",
                     "false for one run (one load case): make gearbox.load_case a sweep "
                     "parameter, or run `geardyn train` for every load case");
  return inputs.combined();
}

AnalysisResult runAnalysis(const std::string& name, const config::Config& config,
                           const AnalysisContext& context) {
  using Function = AnalysisResult (*)(const config::Config&, const AnalysisContext&);
  Function function = nullptr;
  if (name == "geometry") function = geometryAnalysis;
  if (name == "stiffness") function = stiffnessAnalysis;
  if (name == "simulate") function = simulateAnalysis;
  if (name == "stats") function = statsAnalysis;
  if (name == "hbm") function = hbmAnalysis;
  if (name == "rotor")
    function = config.resolved().contains("model") ? feRotorAnalysis : lateralRotorAnalysis;
  if (name == "spectrum") function = spectrumAnalysis;
  if (name == "identify") function = identifyAnalysis;
  if (name == "ltca") function = ltcaAnalysis;
  if (name != "train" && !function) entry(name);  // throws the InputError with the names
  const auto start = std::chrono::steady_clock::now();
  AnalysisResult result =
      name == "train"
          ? trainAnalysis({config, config, config.source(), config.source(), {}}, context)
          : function(config, context);
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace geardyn::analysis
