/// The CLI's commands: the library's analysis commands (analysis::analysisCommands(), the one
/// list) with what the command line adds to them, and `sweep`.

#include "analysis_command.h"
#include "command.h"
#include "geardyn/analysis/analyses.h"
#include "geardyn/config/fe_rotor_config.h"
#include "geardyn/config/ltca_config.h"
#include "geardyn/config/rotor_config.h"
#include "geardyn/config/sweep_config.h"
#include "geardyn/config/train_analysis.h"

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
  std::vector<Command> commands;
  for (const analysis::AnalysisCommand& a : analysis::analysisCommands()) {
    Command command{a.name, a.help, a.schema, analysisRunner(a.name)};
    command.example = a.example;
    command.has_gearbox = a.has_gearbox;
    for (const auto variant : a.variants) command.variant_schemas.emplace_back(variant);
    commands.push_back(std::move(command));
  }
  for (Command& command : commands) {
    if (command.name == "rotor") {
      // The file's [model] type chooses the schema.
      command.schema_for_file = [](const std::filesystem::path& file) {
        return config::peekConfigString(file, "model.type") == "fe_geared_rotor"
                   ? config::feRotorSchema()
                   : config::rotorSchema();
      };
    } else if (command.name == "train") {
      // Reads its analysis file and the gearbox file it names itself.
      command.schema = [] { return config::trainSchema(false); };
      command.run = nullptr;
      command.run_file = runTrain;
      // A sweep's parameters may name any key of the analysis file or of its gearbox.
      command.schema_for_file = [](const std::filesystem::path&) {
        return config::trainSchema(true);
      };
      command.load_file = [](const std::filesystem::path& file,
                             const std::vector<std::string>& overrides) {
        return analysis::loadAnalysisConfig("train", file, overrides);
      };
    }
  }
  Command sweep{"sweep",
                "any analysis over a grid or random sample of its configuration keys, on all "
                "cores or across machines (mpirun -n N geardyn sweep ...), resumable "
                "(--resume), gathered into sweep.h5 and sweep.csv",
                config::sweepSchema, nullptr};
  sweep.run_file = runSweep;
  sweep.resumable = true;
  sweep.example = "sweep examples/sweep_train_torque_damping.toml --threads 2";
  commands.push_back(std::move(sweep));
  return commands;
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
