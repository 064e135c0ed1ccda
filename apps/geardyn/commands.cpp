/// The table of analysis commands. A new command adds one line here and one *_command.cpp.

#include "analysis_command.h"
#include "command.h"
#include "geardyn/analysis/analyses.h"
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
#include "geardyn/config/sweep_config.h"
#include "geardyn/config/train_analysis.h"
#include "geardyn/io/geometry_results.h"
#include "geardyn/io/hbm_results.h"
#include "geardyn/io/identify_results.h"
#include "geardyn/io/ltca_results.h"
#include "geardyn/io/rotor_results.h"
#include "geardyn/io/simulate_results.h"
#include "geardyn/io/stats_results.h"
#include "geardyn/io/stiffness_results.h"
#include "geardyn/io/sweep_results.h"

namespace geardyn::cli {

int runSweep(const CommandOptions& options);
int runTrain(const CommandOptions& options);

namespace {
/// The command that runs the library analysis `name` (analysis_command.cpp).
std::function<int(const config::Config&, const CommandOptions&)> analysisRunner(std::string name) {
  return [name](const config::Config& config, const CommandOptions& options) {
    return runLibraryAnalysis(name, config, options);
  };
}
}  // namespace

std::vector<Command> allCommands() {
  Command rotor{
      "rotor",
      "geared rotors: Rao 2023's lateral rotor with asymmetric TE (Dormand-Prince and exact "
      "frequency domain, full spectra, probe records, study) or, with [model] type = "
      "\"fe_geared_rotor\", the finite-element two-shaft rotor of Visnadi 2021 (Newmark, run-up, "
      "modal, Campbell, mesh-stiffness comparison)",
      config::rotorSchema, analysisRunner("rotor")};
  rotor.schema_for_file = [](const std::filesystem::path& file) {
    return config::peekConfigString(file, "model.type") == "fe_geared_rotor"
               ? config::feRotorSchema()
               : config::rotorSchema();
  };
  rotor.variant_schemas = {config::feRotorSchema};
  Command sweep{"sweep",
                "any analysis over a grid or random sample of its configuration keys, on all "
                "cores or across machines (mpirun -n N geardyn sweep ...), resumable "
                "(--resume), gathered into sweep.h5 and sweep.csv",
                config::sweepSchema, nullptr};
  sweep.run_file = runSweep;
  Command train{"train",
                "any gear train described once (shafts, gears, meshes, bearings, couplings, "
                "planetary stages): kinematics and mesh phasing, static load sharing, modes, "
                "Campbell, frequency-domain forced response and Newmark time response",
                [] { return config::trainSchema(false); }, nullptr};
  train.run_file = runTrain;
  // A sweep's parameters may name any key of the analysis file or of its gearbox.
  train.schema_for_file = [](const std::filesystem::path&) { return config::trainSchema(true); };
  train.load_file = [](const std::filesystem::path& file,
                       const std::vector<std::string>& overrides) {
    return analysis::loadAnalysisConfig("train", file, overrides);
  };
  train.variant_schemas = {config::gearboxSchema};
  return {
      {"geometry", "involute gear-pair geometry: radii, contact ratios, checks, mass properties",
       config::geometrySchema, analysisRunner("geometry")},
      {"stiffness",
       "mesh stiffness over a mesh period: API, step, Fourier, potential energy, ISO 6336; "
       "statistics, Fourier coefficients, loaded transmission error",
       config::stiffnessSchema, analysisRunner("stiffness")},
      {"simulate",
       "time integration of the gear-pair model (Newmark, Dormand-Prince) to its steady state: "
       "transmission error, mesh force, harmonics, contact loss",
       config::simulateSchema, analysisRunner("simulate")},
      {"stats",
       "statistics of the dynamic mean excitation (Gelman 2005): mean excitation ratio R from "
       "the model or from moments, with a simulated check",
       config::statsSchema, analysisRunner("stats")},
      {"hbm",
       "harmonic-balance forced response (AFT) continued in frequency through folds, with Hill "
       "stability and Newmark checks",
       config::hbmSchema, analysisRunner("hbm")},
      rotor,
      train,
      {"spectrum",
       "full spectra of probe records (CSV, WAV, HDF5) with a keyphasor: whole cycles, phase "
       "compensation, forward/backward whirl peaks of a gear pair",
       config::spectrumSchema, analysisRunner("spectrum")},
      {"identify",
       "gear-mesh DTE parameters (k_m, e_m, c_m, TE harmonics, runouts) from full-spectrum whirl "
       "peaks: the thesis's three-step algorithm or a joint estimator with 95 % intervals",
       config::identifySchema, analysisRunner("identify")},
      {"ltca",
       "loaded tooth contact analysis with flank modifications: loaded STE, load sharing, "
       "secant/tangent stiffness, Harris map, Gelman statistics against load",
       config::ltcaSchema, analysisRunner("ltca")},
      sweep,
  };
}

config::ConfigSchema commandSchema(const Command& command, const std::filesystem::path& file) {
  config::ConfigSchema schema =
      command.schema_for_file ? command.schema_for_file(file) : command.schema();
  for (const Command& other : allCommands()) {
    if (other.name == command.name || other.run_file) continue;
    schema.addForeignSchema(other.schema());
    for (const auto& variant : other.variant_schemas) schema.addForeignSchema(variant());
  }
  return schema;
}

config::Config loadCommandFile(const Command& command, const std::filesystem::path& file,
                               const config::ConfigSchema& schema,
                               const std::vector<std::string>& overrides) {
  // `ltca` on a mesh of a gearbox file (gearbox.file, gearbox.mesh): the pair is translated.
  if (command.name == "ltca" && !config::peekConfigString(file, "gearbox.file").empty()) {
    return config::loadLtcaOnGearboxMesh(file, schema, overrides);
  }
  return config::loadConfigFile(file, schema, overrides);
}

config::Config loadCommandConfig(const Command& command, const CommandOptions& options) {
  config::Config config = loadCommandFile(
      command, options.config_file, commandSchema(command, options.config_file), options.overrides);
  for (const auto& note : config.notes()) warn(note);
  return config;
}

}  // namespace geardyn::cli
