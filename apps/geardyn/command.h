#pragma once
/// \file
/// What every `geardyn <command>` shares: its parsed command-line options, the way it loads its
/// configuration and where it writes its results.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "geardyn/io/config.h"
#include "geardyn/io/config_schema.h"

namespace geardyn::cli {

/// Exit codes of the geardyn executable (documented in docs/cli.md).
enum ExitCode : int {
  kExitOk = 0,
  kExitNumericalFailure = 1,  ///< e.g. non-convergence; results written, status says so
  kExitBadInput = 2,          ///< usage, configuration or data error
  kExitIoFailure = 3,         ///< a file could not be read or written
  kExitInternalError = 4,     ///< a bug in geardyn: please report it
};

/// The options common to every analysis command.
struct CommandOptions {
  std::filesystem::path config_file;
  std::filesystem::path out_dir;  ///< empty: results/<config stem>/
  std::vector<std::string> overrides;
  int threads = 0;  ///< 0: all hardware threads
  bool quiet = false;
  bool resume = false;  ///< sweep: continue from the journal of an interrupted run

  /// The folder results go to.
  std::filesystem::path resultFolder() const;
};

/// One subcommand: its name, one-line help, configuration schema and what it runs.
struct Command {
  Command(std::string name_, std::string help_, std::function<io::ConfigSchema()> schema_,
          std::function<int(const io::Config&, const CommandOptions&)> run_)
      : name(std::move(name_)),
        help(std::move(help_)),
        schema(std::move(schema_)),
        run(std::move(run_)) {}

  std::string name;
  std::string help;
  std::function<io::ConfigSchema()> schema;
  std::function<int(const io::Config&, const CommandOptions&)> run;
  /// When set, the schema depends on the configuration file (e.g. `rotor` with [model] type =
  /// "fe_geared_rotor"); `schema` stays the default one.
  std::function<io::ConfigSchema(const std::filesystem::path&)> schema_for_file;
  /// When set, the command reads its file itself (no schema validation by the caller): `sweep`.
  std::function<int(const CommandOptions&)> run_file;
  /// Further schemas `geardyn schema COMMAND` prints after the default one.
  std::vector<std::function<io::ConfigSchema()>> variant_schemas;
};

/// The analysis commands, in the order `geardyn --help` lists them.
std::vector<Command> allCommands();

/// Prints "what" to stdout unless quiet.
void report(const CommandOptions& options, const std::string& text);

}  // namespace geardyn::cli
