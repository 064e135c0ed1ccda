/// geardyn: gear-pair and geared-rotor dynamics from the command line.
///   geardyn <command> CONFIG.toml [--out DIR] [--set section.key=value]... [--threads N] [--quiet]
/// A thin layer: it reads a configuration, calls the library and writes results (DESIGN.md).

#include <CLI/CLI.hpp>
#include <iostream>
#include <map>

#include "command.h"
#include "geardyn/error.h"
#include "geardyn/version.h"

namespace {

using geardyn::cli::CommandOptions;

int runCommand(const geardyn::cli::Command& command, const CommandOptions& options) {
  try {
    if (command.run_file) return command.run_file(options);
    const auto schema =
        command.schema_for_file ? command.schema_for_file(options.config_file) : command.schema();
    const auto config = geardyn::io::loadConfigFile(options.config_file, schema, options.overrides);
    return command.run(config, options);
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
  app.footer(
      "Exit codes: 0 ok, 1 numerical failure (results written, status says so), 2 bad input, "
      "3 I/O failure.\nConfiguration reference of a command: geardyn schema COMMAND");

  const auto commands = geardyn::cli::allCommands();
  std::map<std::string, CommandOptions> options;
  for (const auto& command : commands) {
    CommandOptions& o = options[command.name];
    CLI::App* sub = app.add_subcommand(command.name, command.help);
    sub->add_option("config", o.config_file, "configuration file (TOML)")->required();
    sub->add_option("--out,-o", o.out_dir, "result folder (default: results/<config stem>/)");
    sub->add_option("--set,-s", o.overrides,
                    "override a configuration value: section.key=value (repeatable)")
        ->allow_extra_args(false);
    sub->add_option("--threads,-j", o.threads, "worker threads (default: all cores)")
        ->check(CLI::PositiveNumber);
    sub->add_flag("--quiet,-q", o.quiet, "print nothing but warnings and errors");
    if (command.run_file) {
      sub->add_flag("--resume", o.resume,
                    "continue an interrupted sweep from its journal in the result folder");
    }
  }

  std::string schema_command;
  CLI::App* schema_sub =
      app.add_subcommand("schema", "print the configuration reference of a command (Markdown)");
  std::vector<std::string> names;
  for (const auto& command : commands) names.push_back(command.name);
  schema_sub->add_option("command", schema_command, "the command")
      ->required()
      ->check(CLI::IsMember(names));

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? 0 : geardyn::cli::kExitBadInput;
  }

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
