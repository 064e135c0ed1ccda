/// geardyn: gear-pair and geared-rotor dynamics from the command line.
///   geardyn <command> CONFIG.toml [--out DIR] [--set section.key=value]... [--threads N] [--quiet]
/// A thin layer: it reads a configuration, calls the library and writes results (DESIGN.md).

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include "command.h"
#include "geardyn/config/did_you_mean.h"
#include "geardyn/config/translated_gearbox.h"
#include "geardyn/error.h"
#include "geardyn/version.h"
#include "report_command.h"
#include "rexs_command.h"

namespace {

using geardyn::cli::CommandOptions;

/// The configuration file must be a readable, non-empty file before a command starts: a missing
/// or unreadable file is an I/O failure (exit 3), stdin is refused, an empty one is bad input.
int checkConfigFile(const geardyn::cli::Command& command, const CommandOptions& options) {
  const std::string prefix = "geardyn " + command.name + ": ";
  const std::filesystem::path& file = options.config_file;
  if (file == "-") {
    std::cerr << prefix
              << "error: config = \"-\": reading the configuration from stdin is not supported; "
                 "write it to a file and pass its path\n";
    return geardyn::cli::kExitBadInput;
  }
  std::error_code ec;
  std::ifstream in(file);
  if (!std::filesystem::is_regular_file(file, ec) || !in) {
    std::cerr << prefix << "I/O error: cannot read the configuration file " << file << ": "
              << (std::filesystem::exists(file, ec) ? "not a readable regular file"
                                                    : "no such file")
              << "\n";
    return geardyn::cli::kExitIoFailure;
  }
  for (std::string line; std::getline(in, line);) {
    const auto first = line.find_first_not_of(" \t\r\xEF\xBB\xBF");
    if (first != std::string::npos && line[first] != '#') return geardyn::cli::kExitOk;
  }
  if (!options.overrides.empty()) return geardyn::cli::kExitOk;
  std::cerr << prefix << "error: " << file
            << ": the configuration is empty; start from `geardyn schema " << command.name
            << "` (the reference of every key)\n";
  return geardyn::cli::kExitBadInput;
}

/// "simulat" → "did you mean simulate?", before CLI11's generic message.
int rejectUnknownCommand(int argc, char** argv, const std::vector<std::string>& names) {
  if (argc < 2 || argv[1][0] == '-') return geardyn::cli::kExitOk;
  const std::string given = argv[1];
  for (const auto& name : names)
    if (name == given) return geardyn::cli::kExitOk;
  std::string list;
  for (const auto& name : names) list += (list.empty() ? "" : ", ") + name;
  const auto match = geardyn::config::closestMatch(given, names);
  std::cerr << "geardyn: unknown command \"" << given << "\""
            << (match ? "; did you mean " + *match + "?" : std::string())
            << " The commands are: " << list << " (geardyn --help)\n";
  return geardyn::cli::kExitBadInput;
}

/// --print-gearbox: the gearbox the file translates into, on stdout (issue #31).
int printGearbox(const geardyn::cli::Command& command, const CommandOptions& options) {
  const auto refuse = [&] {
    std::cerr << "geardyn " << command.name << ": error: --print-gearbox: `" << command.name
              << "` has no translation into a gearbox description for this file (the gear-pair "
                 "commands simulate, hbm and stats, rotor and identify files have one)\n";
    return geardyn::cli::kExitBadInput;
  };
  if (command.run_file) return refuse();
  const auto text = geardyn::config::translatedGearbox(
      command.name, geardyn::cli::loadCommandConfig(command, options));
  if (!text) return refuse();
  std::cout << *text << std::flush;
  return geardyn::cli::kExitOk;
}

int runCommand(const geardyn::cli::Command& command, const CommandOptions& options) {
  if (const int code = checkConfigFile(command, options); code != geardyn::cli::kExitOk)
    return code;
  try {
    if (options.print_gearbox) return printGearbox(command, options);
    if (command.run_file) return command.run_file(options);
    return command.run(geardyn::cli::loadCommandConfig(command, options), options);
  } catch (const geardyn::InputError& error) {
    std::cerr << "geardyn " << command.name << ": error: " << error.what() << "\n";
    return geardyn::cli::kExitBadInput;
  } catch (const geardyn::IoError& error) {
    std::cerr << "geardyn " << command.name << ": I/O error: " << error.what() << "\n";
    return geardyn::cli::kExitIoFailure;
  } catch (const std::exception& error) {
    std::cerr << "geardyn " << command.name << ": internal error (please report): " << error.what()
              << "\n";
    return geardyn::cli::kExitInternalError;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "geardyn: gear-pair and geared-rotor dynamics, from gear geometry to mesh stiffness, "
      "dynamic response, spectra and identification."};
  app.set_version_flag("--version", std::string("geardyn ") + geardyn::kVersion);
  app.require_subcommand(1);
  app.footer(geardyn::cli::exitCodesText() +
             "\nConfiguration reference of a command: geardyn schema COMMAND");

  const auto commands = geardyn::cli::allCommands();
  std::vector<std::string> command_names{"schema", "import", "export", "report"};
  for (const auto& command : commands) command_names.push_back(command.name);
  if (const int code = rejectUnknownCommand(argc, argv, command_names); code != 0) return code;
  std::map<std::string, CommandOptions> options;
  for (const auto& command : commands) {
    CommandOptions& o = options[command.name];
    CLI::App* sub = app.add_subcommand(command.name, command.help);
    sub->add_option("config", o.config_file, "configuration file (TOML)")->required();
    sub->add_option("--out,-o", o.out_dir, "result folder (default: results/<config stem>/)")
        ->check([](const std::string& value) {
          return value.empty() ? std::string("--out needs a folder name (an empty path was given)")
                               : std::string();
        });
    sub->add_option("--set,-s", o.overrides,
                    "override a configuration value: section.key=value (repeatable)")
        ->allow_extra_args(false);
    sub->add_option("--threads,-j", o.threads, "worker threads (default: all cores)")
        ->check([](const std::string& value) {
          std::size_t used = 0;
          long long n = 0;
          try {
            n = std::stoll(value, &used);
          } catch (const std::exception&) {
            used = 0;
          }
          return used == value.size() && n >= 1 && n <= 4096
                     ? std::string()
                     : "--threads = " + value + ": must be an integer in [1, 4096]";
        });
    sub->add_flag("--quiet,-q", o.quiet, "print nothing but warnings and errors");
    sub->add_flag("--progress,!--no-progress", o.progress,
                  "progress lines with an ETA on stderr for runs over ~2 s (the default; "
                  "--no-progress: none)");
    if (command.has_gearbox) {
      sub->add_flag("--print-gearbox", o.print_gearbox,
                    "write the gearbox description (TOML) the file translates into to stdout and "
                    "exit without analysing (simulate, hbm, stats, rotor files)");
    }
    if (!command.example.empty()) sub->footer("Example:\n  geardyn " + command.example);
    if (command.resumable) {
      sub->add_flag("--resume", o.resume,
                    "continue an interrupted sweep from its journal in the result folder");
      sub->add_flag("--overwrite", o.overwrite,
                    "discard the journal of a previous sweep in the result folder and start again");
    }
  }

  const geardyn::cli::RexsCommands rexs_commands(app);
  const geardyn::cli::ReportCommand report_command(app);
  std::string schema_command;
  CLI::App* schema_sub =
      app.add_subcommand("schema", "print the configuration reference of a command (Markdown)");
  std::vector<std::string> names;
  for (const auto& command : commands) names.push_back(command.name);
  schema_sub->add_option("command", schema_command, "the command")
      ->required()
      ->check([names](const std::string& value) {
        if (std::find(names.begin(), names.end(), value) != names.end()) return std::string();
        std::string known;
        for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
        const auto match = geardyn::config::closestMatch(value, names);
        return "'" + value + "' is not one of " + known +
               (match ? "; did you mean '" + *match + "'?" : std::string());
      });

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? 0 : geardyn::cli::kExitBadInput;
  }

  if (const auto code = rexs_commands.runIfParsed()) return *code;
  if (const auto code = report_command.runIfParsed()) return *code;
  if (schema_sub->parsed()) {
    for (const auto& command : commands) {
      if (command.name != schema_command) continue;
      std::cout << command.schema().referenceMarkdown();
      for (const auto& variant : command.variant_schemas)
        std::cout << "\n" << variant().referenceMarkdown();
    }
    return geardyn::cli::kExitOk;
  }
  for (const auto& command : commands) {
    if (app.got_subcommand(command.name)) return runCommand(command, options[command.name]);
  }
  return geardyn::cli::kExitBadInput;
}
