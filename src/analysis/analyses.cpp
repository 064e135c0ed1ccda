/// The table of analyses: names, schemas, functions.

#include "geardyn/analysis/analyses.h"

#include <chrono>

#include "geardyn/analysis/geometry_results.h"
#include "geardyn/analysis/hbm_results.h"
#include "geardyn/analysis/identify_results.h"
#include "geardyn/analysis/ltca_results.h"
#include "geardyn/analysis/rotor_results.h"
#include "geardyn/analysis/simulate_results.h"
#include "geardyn/analysis/stats_results.h"
#include "geardyn/analysis/stiffness_results.h"
#include "geardyn/config/did_you_mean.h"
#include "geardyn/config/fe_rotor_config.h"
#include "geardyn/config/gearbox_config.h"
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

namespace geardyn::analysis {
namespace {

/// `train` with its gearbox inline (a file that names one: loadAnalysisConfig).
config::ConfigSchema trainSchema() {
  return config::trainSchema(true);
}

/// `rotor`: the finite-element rotor when the file has [model], else Rao's lateral rotor.
AnalysisResult rotorAnalysis(const config::Config& config, const AnalysisContext& context) {
  return config.resolved().contains("model") ? feRotorAnalysis(config, context)
                                             : lateralRotorAnalysis(config, context);
}

/// `train` on a configuration with its gearbox inline (loadAnalysisConfig's combined form).
AnalysisResult trainOnCombinedConfig(const config::Config& config, const AnalysisContext& context) {
  return trainAnalysis({config, config, config.source(), config.source(), {}}, context);
}

}  // namespace

const std::vector<AnalysisCommand>& analysisCommands() {
  static const std::vector<AnalysisCommand> table = {
      {"geometry",
       "involute gear-pair geometry: radii, contact ratios, checks, mass properties",
       "geometry examples/geometry_rao2023_rig.toml",
       config::geometrySchema,
       {},
       false,
       geometryAnalysis},
      {"stiffness",
       "mesh stiffness over a mesh period: API, step, Fourier, potential energy, ISO 6336; "
       "statistics, Fourier coefficients, loaded transmission error",
       "stiffness examples/stiffness_visnadi2021_spur.toml",
       config::stiffnessSchema,
       {},
       false,
       stiffnessAnalysis},
      {"simulate",
       "time integration of the gear-pair model (Newmark, Dormand-Prince) to its steady state: "
       "transmission error, mesh force, harmonics, contact loss",
       "simulate examples/simulate_gear_pair_backlash.toml   (--print-gearbox: its gearbox)",
       config::simulateSchema,
       {},
       true,
       simulateAnalysis},
      {"stats",
       "statistics of the dynamic mean excitation (Gelman 2005): mean excitation ratio R from "
       "the model or from moments, with a simulated check",
       "stats examples/stats_gelman2005_case1_a025.toml",
       config::statsSchema,
       {},
       true,
       statsAnalysis},
      {"hbm",
       "harmonic-balance forced response (AFT) continued in frequency through folds, with Hill "
       "stability and Newmark checks",
       "hbm examples/hbm_saletti2025_100Nm.toml",
       config::hbmSchema,
       {},
       true,
       hbmAnalysis},
      {"rotor",
       "geared rotors: Rao 2023's lateral rotor with asymmetric TE (Dormand-Prince and exact "
       "frequency domain, full spectra, probe records, study) or, with [model] type = "
       "\"fe_geared_rotor\", the finite-element two-shaft rotor of Visnadi 2021 (Newmark, "
       "run-up, modal, Campbell, mesh-stiffness comparison)",
       "rotor examples/rotor_visnadi2021_modal.toml   (--print-gearbox: its gearbox)",
       config::rotorSchema,
       {config::feRotorSchema},
       true,
       rotorAnalysis},
      {"train",
       "any gear train described once (shafts, gears, meshes, bearings, couplings, planetary "
       "stages, flexible shafts): kinematics and mesh phasing, static load sharing, modes, "
       "Campbell, forced response, Newmark, run-up, probe records, mesh statistics, nonlinear "
       "steady state",
       "train examples/train_two_stage_reducer.toml --out results/reducer",
       trainSchema,
       {config::gearboxSchema},
       false,
       trainOnCombinedConfig},
      {"spectrum",
       "full spectra of probe records (CSV, WAV, HDF5) with a keyphasor: whole cycles, phase "
       "compensation, forward/backward whirl peaks of a gear pair",
       "spectrum examples/spectrum_two_stage_reducer_probes.toml",
       config::spectrumSchema,
       {},
       false,
       spectrumAnalysis},
      {"identify",
       "gear-mesh DTE parameters (k_m, e_m, c_m, TE harmonics, runouts) from full-spectrum whirl "
       "peaks: the thesis's three-step algorithm or a joint estimator with 95 % intervals",
       "identify examples/identify_rao2023_table41.toml   (--print-gearbox: the rig's gearbox)",
       config::identifySchema,
       {},
       true,
       identifyAnalysis},
      {"ltca",
       "loaded tooth contact analysis with flank modifications, of a pair or of a gearbox's mesh: "
       "loaded STE, load sharing, secant/tangent stiffness, Harris map, Gelman statistics against "
       "load",
       "ltca examples/ltca_two_stage_reducer_stage1.toml",
       config::ltcaSchema,
       {},
       false,
       ltcaAnalysis}};
  return table;
}

namespace {

const AnalysisCommand& entry(const std::string& name) {
  for (const auto& e : analysisCommands()) {
    if (name == e.name) return e;
  }
  std::string allowed = "one of";
  for (const auto& e : analysisCommands()) allowed += std::string(" ") + e.name;
  if (const auto match = config::closestMatch(name, analysisNames())) {
    allowed += "; did you mean '" + *match + "'?";
  }
  throw InputError("analysis", name, allowed);
}

}  // namespace

const std::vector<std::string>& analysisNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& e : analysisCommands()) out.emplace_back(e.name);
    return out;
  }();
  return names;
}

config::ConfigSchema analysisSchema(const std::string& name, const std::string& model_type) {
  const AnalysisCommand& own = entry(name);
  config::ConfigSchema schema =
      name == "rotor" && model_type == "fe_geared_rotor" ? config::feRotorSchema() : own.schema();
  if (name == "train") return schema;
  for (const auto& other : analysisCommands()) {
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
  const AnalysisCommand& command = entry(name);  // InputError with the names when unknown
  const auto start = std::chrono::steady_clock::now();
  AnalysisResult result = command.run(config, context);
  result.summary.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace geardyn::analysis
