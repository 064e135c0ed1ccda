#pragma once
/// \file
/// What every `geardyn <command>` shares: its parsed command-line options, the way it loads its
/// configuration and where it writes its results.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"

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
  bool progress = true;    ///< progress lines on stderr for runs over ~2 s (--no-progress: off)
  bool resume = false;     ///< sweep: continue from the journal of an interrupted run
  bool overwrite = false;  ///< sweep: discard the journal of a previous run in the folder
  /// Write the gearbox TOML the file translates into to stdout and stop (no analysis); a
  /// command without a translation refuses it (config/translated_gearbox.h).
  bool print_gearbox = false;

  /// The folder results go to.
  std::filesystem::path resultFolder() const;
};

/// One subcommand: its name, one-line help, configuration schema and what it runs.
struct Command {
  Command(std::string name_, std::string help_, std::function<config::ConfigSchema()> schema_,
          std::function<int(const config::Config&, const CommandOptions&)> run_)
      : name(std::move(name_)),
        help(std::move(help_)),
        schema(std::move(schema_)),
        run(std::move(run_)) {}

  std::string name;
  std::string help;
  std::function<config::ConfigSchema()> schema;
  std::function<int(const config::Config&, const CommandOptions&)> run;
  /// When set, the schema depends on the configuration file (e.g. `rotor` with [model] type =
  /// "fe_geared_rotor"); `schema` stays the default one.
  std::function<config::ConfigSchema(const std::filesystem::path&)> schema_for_file;
  /// When set, the command reads its file itself (no schema validation by the caller): `sweep`,
  /// `train` (an analysis file and the gearbox file it names).
  std::function<int(const CommandOptions&)> run_file;
  /// With run_file, for `sweep`: reads `file` with `overrides` as one run_file run into one
  /// folder would (InputError naming a bad key, a did-you-mean for an unknown one) and returns
  /// its configuration; `schema_for_file` then gives every key the file and --set take.
  std::function<config::Config(const std::filesystem::path&, const std::vector<std::string>&)>
      load_file;
  /// Further schemas `geardyn schema COMMAND` prints after the default one.
  std::vector<std::function<config::ConfigSchema()>> variant_schemas;
  /// A run of the command on one of the examples, shown by `geardyn COMMAND --help`.
  std::string example;
  /// Its files translate into a gearbox description (--print-gearbox,
  /// config/translated_gearbox.h).
  bool has_gearbox = false;
  /// Takes --resume and --overwrite (a journal of finished cases in its result folder: sweep).
  bool resumable = false;
};

/// The analysis commands, in the order `geardyn --help` lists them.
std::vector<Command> allCommands();

/// The schema `command` validates `file` with: its own (chosen by the file when it has
/// variants), knowing the other analysis commands' schemas so that their sections and keys in
/// the same file are ignored with a note but still spell-checked (one file, many commands).
config::ConfigSchema commandSchema(const Command& command, const std::filesystem::path& file);

/// Loads `file` with `schema` (commandSchema) and `overrides`: config::loadConfigFile, or for
/// `ltca` on a mesh of a gearbox (gearbox.file) config::loadLtcaOnGearboxMesh.
config::Config loadCommandFile(const Command& command, const std::filesystem::path& file,
                               const config::ConfigSchema& schema,
                               const std::vector<std::string>& overrides);
/// Loads `options.config_file` with commandSchema and prints its notes as warnings.
config::Config loadCommandConfig(const Command& command, const CommandOptions& options);

/// Prints "what" to stdout unless quiet.
void report(const CommandOptions& options, const std::string& text);

/// Prints "warning: TEXT" on stderr, once per distinct text in this process (a sweep's cases
/// do not repeat the warning they share); a note (analysis::isNote: it changes no number) is
/// printed as it is, and not at all when `quiet` (geardyn/notes.h). Thread-safe.
void warn(const std::string& text, bool quiet = false);
/// warn() for a batch, one line per kind of warning (analysis::groupedWarnings).
void warnAll(const std::vector<std::string>& texts, bool quiet = false);

/// The exit codes with their meaning, as `geardyn --help` and docs/cli.md list them.
std::string exitCodesText();

}  // namespace geardyn::cli
