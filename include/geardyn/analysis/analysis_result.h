#pragma once
/// \file
/// What one analysis (geometry, stiffness, simulate, hbm, rotor, ...) returns, in memory, and
/// what it is given besides its configuration. The CLI writes an AnalysisResult into a result
/// folder (writeAnalysisResult); Python wraps it without writing anything (Ceres's "Options in,
/// Summary out": the result carries its status and a human report).

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "geardyn/analysis/result_table.h"
#include "geardyn/config/config.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/io/result_writer.h"
#include "geardyn/progress.h"

namespace geardyn::analysis {

/// What an analysis needs from its caller besides the configuration.
struct AnalysisContext {
  /// The configuration file ("" when the configuration came from Python).
  std::string config_source;
  /// Worker threads (0: all hardware threads).
  int threads = 0;
  /// A progress callback for one stage of the run ("hbm: sweep up", counting `unit`); called
  /// once per stage, the stage before it being finished. Unset: no progress.
  std::function<ProgressCallback(const std::string& label, const std::string& unit)> progress;
  /// Called with each design or numerical warning as it arises (they are also in
  /// summary.warnings). Unset: not called.
  std::function<void(const std::string&)> warn;
  /// Called with each finished part of the report (whole lines) as the analysis goes, so a long
  /// run shows what it has done; AnalysisResult::printed counts what was passed. Unset: the
  /// report is only in AnalysisResult::report.
  std::function<void(const std::string&)> print;
  /// Called with notes for the person running it (what a long run is estimated to need, from
  /// analysis::checkRunEstimate); the CLI prints them on stderr unless --quiet. Unset: dropped.
  std::function<void(const std::string&)> inform;

  /// Called before a stage that allocates or runs in proportion to its configuration
  /// ("simulate", "hbm", "rotor_time", "rotor_fe_time" with `size` = DOFs, "stats_monte_carlo",
  /// "stats_time"), so that the caller can refuse a run that would not fit. Unset: not called.
  std::function<void(const std::string& stage, long long size)> check_budget;

  void checkBudget(const std::string& stage, long long size = 0) const {
    if (check_budget) check_budget(stage, size);
  }
  ProgressCallback progressFor(const std::string& label, const std::string& unit) const {
    return progress ? progress(label, unit) : ProgressCallback{};
  }
  void warning(const std::string& text) const {
    if (warn) warn(text);
  }
  /// A batch of warnings, one line per kind (groupedWarnings: five meshes sharing a
  /// condition are one line naming them; summary.warnings keeps each).
  void warnings(const std::vector<std::string>& texts) const;
  void note(const std::string& text) const {
    if (inform && !text.empty()) inform(text);
  }
};

/// A file of the result other than a table (a probe record in WAV or HDF5): its name and how to
/// write it at a path.
struct ResultFile {
  std::string name;
  std::function<void(const std::filesystem::path&)> write;
};

/// The outcome of one analysis.
struct AnalysisResult {
  AnalysisResult() = default;
  /// A result of analysis `command` on `config`: the summary's command, resolved configuration
  /// and configuration source filled in.
  AnalysisResult(std::string command, const config::Config& config, const AnalysisContext& context);

  /// Command, resolved configuration, seed, status, warnings, wall time, results.
  io::RunSummary summary;
  std::vector<std::string> table_names;  ///< "time_response.csv", ... in the order written
  std::vector<ResultTable> tables;       ///< one per name
  std::vector<ResultFile> files;         ///< written after the tables
  /// Headline lines for a person (the CLI prints them; Python's repr shows them).
  std::string report;
  /// The leading characters of `report` already passed to AnalysisContext::print.
  std::size_t printed = 0;
  /// Non-convergence and similar messages (the CLI prints them on stderr).
  std::vector<std::string> errors;

  void addTable(std::string name, const io::CsvTable& table);
  /// The table called `name` (with or without ".csv"); throws std::out_of_range when absent.
  const ResultTable& table(const std::string& name) const;
};

/// Writes the tables and files of `result` with `writer` (not the summary: the caller writes
/// it, after adding its own files such as plots).
void writeAnalysisResult(const AnalysisResult& result, io::ResultWriter& writer);

}  // namespace geardyn::analysis
