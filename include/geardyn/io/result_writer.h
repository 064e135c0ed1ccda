#pragma once
/// \file
/// The result folder of one run: summary.json (version, command, resolved configuration, seed,
/// status, warnings, headline results, list of files) plus CSV tables and other files, each
/// written atomically.

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geardyn/io/csv_table.h"

namespace geardyn::io {

/// What summary.json records about a run.
struct RunSummary {
  std::string command;                ///< "geometry", "stiffness", ...
  std::string config_source;          ///< the configuration file (or "" from Python)
  nlohmann::ordered_json config;      ///< the fully resolved configuration
  std::optional<std::uint64_t> seed;  ///< random seed, absent for deterministic commands
  std::string status = "ok";          ///< "ok" or a solver status ("max_iterations", ...)
  std::vector<std::string> warnings;  ///< design or numerical warnings, full sentences
  nlohmann::ordered_json results = nlohmann::ordered_json::object();  ///< headline numbers
};

/// Writes the files of one run into a folder (created if missing). If the folder holds an
/// earlier run's summary.json, the files that summary lists are removed first (nothing else).
class ResultWriter {
 public:
  explicit ResultWriter(std::filesystem::path folder);

  const std::filesystem::path& folder() const noexcept { return folder_; }

  /// Writes `name` (e.g. "gears.csv") atomically and records it for the summary.
  void writeCsv(const std::string& name, const CsvTable& table);
  void writeText(const std::string& name, const std::string& content);
  /// Records a file that something else wrote into the folder (e.g. a plot).
  void recordFile(const std::string& name) { files_.push_back(name); }

  /// Writes summary.json (atomically) listing every file written so far; call it last, so that
  /// a summary on disk means the run's files are complete. Returns its path.
  std::filesystem::path writeSummary(const RunSummary& summary);

  const std::vector<std::string>& files() const noexcept { return files_; }

 private:
  std::filesystem::path folder_;
  std::vector<std::string> files_;
};

/// The JSON document of summary.json (also what Python's `to_dict` functions return).
nlohmann::ordered_json summaryJson(const RunSummary& summary,
                                   const std::vector<std::string>& files = {});

}  // namespace geardyn::io
