#pragma once
/// \file
/// `geardyn report RESULT_DIR [--out FILE.html]`: one self-contained HTML report (headline
/// numbers, resolved configuration, interactive plotly.js figures) of a result folder. Thin:
/// the Python package draws it (`python -m geardyn.report`, python/geardyn/report.py), with the
/// interpreter and package folder the PNG plots use (plotting.h).

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>

namespace geardyn::cli {

class ReportCommand {
 public:
  /// Registers the subcommand on `app`.
  explicit ReportCommand(CLI::App& app);
  /// Its exit code if it was the subcommand parsed, else nothing.
  std::optional<int> runIfParsed() const;

 private:
  CLI::App* sub_ = nullptr;
  std::filesystem::path folder_, out_;
  bool quiet_ = false;
};

}  // namespace geardyn::cli
