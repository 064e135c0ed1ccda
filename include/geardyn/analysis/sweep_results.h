#pragma once
/// \file
/// `geardyn sweep CONFIG` (issue #9): the study definition ([study] of a TOML file), the
/// append-only journal that makes a sweep resumable after SIGKILL, and the gathered results
/// (sweep.h5 and sweep.csv, both written atomically).
///
///   [study]
///   command = "simulate"            # any analysis command
///   base = "simulate_case.toml"     # its configuration (relative to this file)
///   design = "grid"                 # grid (full factorial) | zip | random
///   samples = 100                   # random: number of cases
///   seed = 1                        # random: study seed (cases draw from their own streams)
///   seed_key = "monte_carlo.seed"   # optional: a key of the base config set to each case's seed
///   set = ["output.plots=false"]    # fixed overrides of every case
///   outputs = ["p2p=/mesh_force/peak_to_peak", "/dynamic_factor"]   # JSON pointers in results
///   keep_case_results = false       # keep each case's own result folder under cases/
///   [study.parameters]
///   "excitation.speed_rpm" = [1000.0, 2000.0, 3000.0]          # values
///   "model.damping_ratio" = { min = 0.02, max = 0.08, num = 4 } # linspace (grid, zip)
///   "model.mass" = { distribution = "normal", mean = 1.6, std = 0.05 }   # random
///   # also { distribution = "uniform", min, max }, { distribution = "truncated_normal",
///   # mean, std, min, max } and lists of values (drawn uniformly) in a random design.

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "geardyn/config/config_schema.h"
#include "geardyn/config/sweep_config.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/stats/study_design.h"

namespace geardyn::analysis {

/// What became of one case.
struct SweepCaseRecord {
  long long index = 0;
  std::string status;  ///< "ok", the command's status ("diverged", …), "bad_input", "error",
                       ///< "missing_output"
  std::vector<nlohmann::json> values;
  std::vector<double> outputs;  ///< NaN where absent
  std::uint64_t seed = 0;
  std::string message;
  nlohmann::json toJson() const;
  static SweepCaseRecord fromJson(const nlohmann::json& j);
};

/// The journal: one JSON line per finished case, appended and flushed to disk (fdatasync)
/// before the next; its first line is the study fingerprint. A line cut by a kill is dropped.
class SweepJournal {
 public:
  /// Opens `path`. With `resume`, reads the records already there (InputError if the file
  /// belongs to another study); without, starts a new journal (replacing any old one).
  SweepJournal(const std::filesystem::path& path, const std::string& fingerprint, bool resume);
  ~SweepJournal();
  SweepJournal(const SweepJournal&) = delete;
  SweepJournal& operator=(const SweepJournal&) = delete;

  const std::vector<SweepCaseRecord>& previous() const noexcept { return previous_; }
  void append(const SweepCaseRecord& record);

 private:
  int fd_ = -1;
  std::vector<SweepCaseRecord> previous_;
};

/// sweep.h5: /case, /seed, /status, /message, /parameters (n × P, NaN for text values),
/// /parameter_text (n × P), /outputs (n × O), with names and the resolved study and base
/// configuration as attributes; records in case order. Atomic (temporary file + rename).
void writeSweepHdf5(const std::filesystem::path& path, const config::SweepDefinition& study,
                    const std::vector<SweepCaseRecord>& records, const std::string& base_config);

/// sweep.csv: case, status, seed, one column per parameter and output, message.
io::CsvTable sweepTable(const config::SweepDefinition& study,
                        const std::vector<SweepCaseRecord>& records);

/// The value of `pointer` in `results` as a number (booleans 0/1); NaN and `ok` false when it
/// is absent or not a number.
double outputValue(const nlohmann::json& results, const std::string& pointer, bool* ok);

}  // namespace geardyn::analysis
