#pragma once
/// \file
/// Configuration and result tables of `geardyn rotor` (the lateral geared rotor of Rao 2023)
/// and `geardyn spectrum` (full spectra of probe records): schemas, the model and options built
/// from a configuration, and the whirl-component tables both commands write.

#include <array>
#include <nlohmann/json.hpp>
#include <vector>

#include "geardyn/config/config_schema.h"
#include "geardyn/config/rotor_config.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/signal/gear_whirl.h"
#include "geardyn/solvers/rotor_response.h"
#include "geardyn/system/lateral_rotor.h"

namespace geardyn::analysis {

/// The shaft names used in every table: "pinion" (x₁, y₁) and "gear" (x₂, y₂).
inline const std::array<const char*, 2> kShaftNames = {"pinion", "gear"};

/// shaft,component,frequency_hz,re,im,amplitude,phase (spectrum_peaks.csv, and the
/// frequency-domain frequency_components.csv).
io::CsvTable whirlPeaksTable(const std::array<std::vector<WhirlComponent>, 2>& peaks);
/// shaft,frequency_hz,re,im,amplitude,phase, |f| ≤ max_frequency (full_spectrum.csv).
io::CsvTable fullSpectrumTable(const std::array<FullSpectrum, 2>& spectra, double max_frequency);
/// The peaks as JSON: {shaft: {component: {frequency_hz, amplitude, phase}}}.
nlohmann::ordered_json whirlPeaksJson(const std::array<std::vector<WhirlComponent>, 2>& peaks);

/// The frequency-domain components of the model as whirl components of each shaft, referred
/// to t = 0 and reported in `frame`.
std::array<std::vector<WhirlComponent>, 2> frequencyDomainPeaks(
    const std::vector<RotorWhirlResponse>& parts, WhirlFrame frame);

/// The conventions of the reported spectra (summary.json "conventions").
nlohmann::ordered_json whirlConventionsJson(WhirlFrame frame, const std::string& phase_reference);

}  // namespace geardyn::analysis
