#pragma once
/// \file
/// Configuration and results of `geardyn identify`: the schema, the whirl spectra read from
/// result folders of `geardyn rotor` or `geardyn spectrum`, the known rotor data, priors, an
/// optional truth, and the result tables.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geardyn/config/config_schema.h"
#include "geardyn/config/identify_config.h"
#include "geardyn/identify/dte_identification.h"
#include "geardyn/io/csv_table.h"

namespace geardyn::analysis {

/// One input spectrum: the folder, the peaks in the probe frame, their noise, and the rotor
/// configuration when the folder was written by `geardyn rotor` (its truth).
struct WhirlSpectrumInput {
  std::filesystem::path folder;
  std::string file;  ///< spectrum_peaks.csv or frequency_components.csv
  MeasuredWhirlPeaks peaks;
  std::optional<LateralRotorSpec> truth;
};

/// Reads a result folder: summary.json (pinion speed, frame, coefficient noise, command) and
/// spectrum_peaks.csv (or frequency_components.csv when there is none). `key` names the
/// configuration key for messages.
WhirlSpectrumInput readWhirlSpectrum(const std::filesystem::path& folder, const std::string& key);

/// The identified parameters as JSON (results.identified): value, ci95, identifiable.
nlohmann::ordered_json identifiedJson(const DteIdentification& r);

/// parameter,harmonic,value,ci_low,ci_high,identifiable,true,error (error: relative for
/// magnitudes, absolute [rad] for phases; empty without a truth).
io::CsvTable identifiedTable(const DteIdentification& r,
                             const std::optional<LateralRotorSpec>& truth);

}  // namespace geardyn::analysis
