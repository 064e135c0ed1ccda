#pragma once
/// \file
/// `geardyn import FILE.rexs [-o gearbox.toml] [--load-case ID] [--bearing-stiffness N/m]` and
/// `geardyn export gearbox.toml -o out.rexsj`: REXS in and out (config/rexs_gearbox.h).

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>

namespace geardyn::cli {

class RexsCommands {
 public:
  /// Registers both subcommands on `app`.
  explicit RexsCommands(CLI::App& app);
  /// The subcommand that was parsed, or nothing (nullopt).
  std::optional<int> runIfParsed() const;

 private:
  int runImport() const;
  int runExport() const;
  CLI::App* import_ = nullptr;
  CLI::App* export_ = nullptr;
  std::filesystem::path import_file_, import_out_, export_file_, export_out_;
  std::optional<int> load_case_;
  std::optional<double> bearing_stiffness_;
  bool quiet_ = false;
};

}  // namespace geardyn::cli
