#pragma once
/// \file
/// The result folder of one run: summary.json (version, command, resolved configuration, seed,
/// status, warnings, headline results, list of files) plus CSV tables and other files. The run's
/// files are staged in a hidden folder and moved into the result folder only when the summary is
/// written, so a run that fails (an exception, an early return, a kill) leaves either nothing or
/// the previous run's complete results — never a partial result set that looks finished.

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
  double wall_time_s = 0.0;           ///< wall time of the run [s]
  /// The numerical method failed (status says how): the CLI exits with code 1.
  bool numerical_failure = false;
  nlohmann::ordered_json results = nlohmann::ordered_json::object();  ///< headline numbers
};

/// Writes the files of one run into a folder (created if missing).
///
/// Until the first writeSummary the files go to a staging folder `.partial-<pid>-<n>` inside
/// the result folder. writeSummary commits: it removes the previous run's summary.json and the
/// files that summary lists (nothing else: a folder is never emptied blindly), moves the staged
/// files in (one rename each) and writes summary.json last. Files written after the commit (the
/// plots) go straight to the result folder. When the process has used at least kDurableAfter
/// of processor time, the commit flushes the files to disk (each file, then the folder), so that
/// a power failure cannot leave a summary without its files; quicker runs skip the flush, which
/// would cost more than redoing them (about 5 ms a file on a virtual disk, measured for issue
/// 22). A writer destroyed before its commit removes its staging folder, and the folders it
/// created when they are empty. Staging folders of killed runs (their process gone) are removed
/// by the next writer of the folder.
class ResultWriter {
 public:
  /// Processor time of the process [s] from which a commit flushes the files to disk.
  static constexpr double kDurableAfter = 1.0;

  explicit ResultWriter(std::filesystem::path folder);
  ~ResultWriter();
  ResultWriter(const ResultWriter&) = delete;
  ResultWriter& operator=(const ResultWriter&) = delete;

  /// The result folder.
  const std::filesystem::path& folder() const noexcept { return folder_; }
  /// Where a file named `name` is to be written now (staging before the commit, the result
  /// folder after), for writers of their own (HDF5, probe records); then recordFile(name).
  std::filesystem::path pathFor(const std::string& name) const;

  /// Writes `name` (e.g. "gears.csv") atomically and records it for the summary.
  void writeCsv(const std::string& name, const CsvTable& table);
  void writeText(const std::string& name, const std::string& content);
  /// Records a file that something else wrote at pathFor(name) (e.g. a plot).
  void recordFile(const std::string& name) { files_.push_back(name); }

  /// Writes summary.json (atomically) listing every file written so far; the first call commits
  /// the staged files (see the class comment). Returns its path.
  std::filesystem::path writeSummary(const RunSummary& summary);

  const std::vector<std::string>& files() const noexcept { return files_; }
  bool committed() const noexcept { return committed_; }

 private:
  void commit();
  void discard() noexcept;

  std::filesystem::path folder_, staging_;
  std::filesystem::path created_root_;  ///< outermost folder created here ("" when none)
  bool committed_ = false, durable_ = false;
  std::vector<std::string> files_;
};

/// The JSON document of summary.json (also what Python's `to_dict` functions return).
nlohmann::ordered_json summaryJson(const RunSummary& summary,
                                   const std::vector<std::string>& files = {});

}  // namespace geardyn::io
