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
#include "geardyn/io/csv_table.h"
#include "geardyn/stats/study_design.h"

namespace geardyn::config {

struct SweepOutput {
  std::string name;     ///< column name
  std::string pointer;  ///< JSON pointer into the case's summary "results"
};

struct SweepDefinition {
  std::string title;
  std::string command;
  std::filesystem::path base;  ///< absolute
  StudyDesign design = StudyDesign::kGrid;
  long long samples = 0;
  std::uint64_t seed = 1;
  std::string seed_key;
  std::vector<std::string> set;
  std::vector<SweepOutput> outputs;
  std::vector<StudyParameter> parameters;
  bool keep_case_results = false;
  bool plots = true;
  nlohmann::ordered_json resolved;  ///< the study as resolved (recorded in every result)

  long long caseCount() const;
  StudyCase caseAt(long long index) const;
  /// The overrides of case `c` applied to the base configuration ("key=value" in TOML).
  std::vector<std::string> overridesOf(const StudyCase& c) const;
  /// A hash of everything that determines the cases and their outputs (the resume check): the
  /// study, the base file's text and `base_inputs` (what else the base reads, e.g. the gearbox
  /// file a `train` analysis file names, as its resolved configuration).
  std::string fingerprint(const std::string& base_inputs = "") const;
};

/// A value of a study as a TOML literal ("0.10000000000000001", "\"text\"", "true").
std::string tomlLiteral(const nlohmann::json& value);

/// The reference of a sweep file for `geardyn schema sweep` (the parameters table takes any key
/// of the base command; its forms are described there).
ConfigSchema sweepSchema();

/// Reads and validates the [study] of a sweep file (unknown keys rejected with a suggestion).
/// `extra_set` (the command line's --set) is appended to study.set.
SweepDefinition loadSweepDefinition(const std::filesystem::path& file,
                                    const std::vector<std::string>& extra_set = {});

}  // namespace geardyn::config
