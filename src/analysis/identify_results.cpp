#include "geardyn/analysis/identify_results.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "geardyn/analysis/rotor_results.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/config/identify_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/config/rotor_config.h"
#include "geardyn/error.h"
#include "geardyn/signal/gear_whirl.h"
#include "geardyn/stiffness/iso6336_stiffness.h"

namespace geardyn::analysis {
namespace {

nlohmann::ordered_json number(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json valueJson(const IdentifiedValue& v) {
  return {{"value", number(v.value)},
          {"ci95", nlohmann::ordered_json::array({number(v.low), number(v.high)})},
          {"identifiable", v.identifiable}};
}

nlohmann::ordered_json phasorJson(const IdentifiedPhasor& p) {
  return {{"amplitude", valueJson(p.amplitude)}, {"phase", valueJson(p.phase)}};
}

/// Rows of a whirl-peak table (shaft,component,frequency_hz,re,im,...) as written by
/// whirlPeaksTable: text in the first two columns, finite numbers in the others.
std::vector<std::pair<std::string, WhirlComponent>> readPeakTable(const std::filesystem::path& path,
                                                                  const std::string& key) {
  std::ifstream in(path);
  if (!in) throw InputError(key, path.string(), "cannot be read");
  std::string line;
  std::getline(in, line);
  const auto split = [](const std::string& l) {
    std::vector<std::string> cells;
    std::size_t start = 0;
    while (true) {
      const auto comma = l.find(',', start);
      cells.push_back(l.substr(start, comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    return cells;
  };
  const auto header = split(line);
  // The names of whirlPeaksTable, or the ones it wrote before its columns carried units.
  const auto column = [&](const std::string& name, const std::string& older = "") {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name || (!older.empty() && header[i] == older)) return i;
    throw InputError(key, path.string(), fmt::format("has no column '{}'", name));
  };
  const std::size_t cs = column("shaft"), cc = column("component"), cf = column("frequency_hz"),
                    cr = column("re_m", "re"), ci = column("im_m", "im");
  std::vector<std::pair<std::string, WhirlComponent>> rows;
  for (int row = 2; std::getline(in, line); ++row) {
    if (line.empty()) continue;
    const auto cells = split(line);
    if (cells.size() != header.size()) {
      throw InputError(
          key, path.string(),
          fmt::format("row {} has {} cells, the header {}", row, cells.size(), header.size()));
    }
    const auto number = [&](std::size_t c) {
      try {
        std::size_t used = 0;
        const double v = std::stod(cells[c], &used);
        if (used == cells[c].size() && std::isfinite(v)) return v;
      } catch (const std::exception&) {
      }
      throw InputError(
          key, path.string(),
          fmt::format("row {}, column {}: '{}' is not a finite number", row, header[c], cells[c]));
    };
    rows.push_back({cells[cs], WhirlComponent{cells[cc], number(cf), {number(cr), number(ci)}}});
  }
  return rows;
}

}  // namespace

WhirlSpectrumInput readWhirlSpectrum(const std::filesystem::path& folder, const std::string& key) {
  WhirlSpectrumInput in;
  in.folder = folder;
  const auto summary_path = folder / "summary.json";
  std::ifstream stream(summary_path);
  if (!stream) {
    throw InputError(key, folder.string(),
                     "a result folder of `geardyn rotor` or `geardyn spectrum` (no summary.json)");
  }
  nlohmann::ordered_json summary;
  try {
    summary = nlohmann::ordered_json::parse(stream);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(key, summary_path.string(), fmt::format("is not valid JSON: {}", e.what()));
  }
  const std::string command = summary.value("command", "");
  if (command != "rotor" && command != "spectrum") {
    throw InputError(key, folder.string(),
                     fmt::format("was written by `geardyn {}`, not rotor or spectrum", command));
  }
  bool shaft_frame = false;
  try {
    const auto& results = summary.at("results");
    in.peaks.pinion_speed = results.at("frequencies").at("pinion_hz").get<double>();
    shaft_frame = summary.at("config").at("spectrum").at("frame").get<std::string>() == "shaft";
    if (results.contains("coefficient_noise")) {
      in.peaks.coefficient_sigma = {results["coefficient_noise"].at("pinion").get<double>(),
                                    results["coefficient_noise"].at("gear").get<double>()};
    }
  } catch (const nlohmann::json::exception& e) {
    throw InputError(
        key, summary_path.string(),
        fmt::format("lacks the pinion speed, frame or noise of a spectrum ({})", e.what()));
  }
  in.file = std::filesystem::exists(folder / "spectrum_peaks.csv") ? "spectrum_peaks.csv"
                                                                   : "frequency_components.csv";
  for (const auto& [shaft, c] : readPeakTable(folder / in.file, key)) {
    const int s = shaft == "pinion" ? 0 : shaft == "gear" ? 1 : -1;
    if (s < 0) {
      throw InputError(key, (folder / in.file).string(),
                       fmt::format("shaft '{}' is neither pinion nor gear", shaft));
    }
    // Back to the probe frame (the shaft frame conjugates the pinion shaft: an involution).
    in.peaks.peaks[s].push_back(inShaftFrame(c, s == 0 && shaft_frame));
  }
  if (command == "rotor") {
    try {
      in.truth = config::lateralRotorSpecFromConfig(
          config::Config(summary["config"], summary_path.string()));
    } catch (const std::exception&) {
      // A configuration of another geardyn version: no truth to compare with.
    }
  }
  return in;
}

nlohmann::ordered_json identifiedJson(const DteIdentification& r) {
  nlohmann::ordered_json te = {{"x", nlohmann::ordered_json::array()},
                               {"y", nlohmann::ordered_json::array()}};
  for (std::size_t i = 0; i < r.te_x.size(); ++i) {
    auto x = phasorJson(r.te_x[i]);
    auto y = phasorJson(r.te_y[i]);
    x["harmonic"] = y["harmonic"] = i + 1;
    te["x"].push_back(x);
    te["y"].push_back(y);
  }
  return {
      {"mesh_stiffness", valueJson(r.mesh_stiffness)},
      {"mean_te", valueJson(r.mean_te)},
      {"mesh_damping", valueJson(r.mesh_damping)},
      {"te", te},
      {"runout", {{"pinion", phasorJson(r.pinion_runout)}, {"gear", phasorJson(r.gear_runout)}}}};
}

io::CsvTable identifiedTable(const DteIdentification& r,
                             const std::optional<LateralRotorSpec>& truth) {
  // Each row in its parameter's unit (the unit column); error: relative, or in rad for phases.
  io::CsvTable t({"parameter", "harmonic", "unit", "value", "ci_low", "ci_high", "identifiable",
                  "true", "error"});
  const auto add = [&](const std::string& name, long long harmonic, const IdentifiedValue& v,
                       std::optional<double> exact, bool phase) {
    const std::string unit = phase                      ? "rad"
                             : name == "mesh_stiffness" ? "N/m"
                             : name == "mesh_damping"   ? "N s/m"
                                                        : "m";
    std::vector<io::CsvCell> row{
        name, harmonic, unit, v.value, v.low, v.high, static_cast<long long>(v.identifiable)};
    if (exact) {
      row.push_back(*exact);
      row.push_back(phase ? std::remainder(v.value - *exact, 2.0 * std::numbers::pi)
                          : v.value / *exact - 1.0);
    } else {
      row.push_back(std::string());
      row.push_back(std::string());
    }
    t.addRow(row);
  };
  const auto val = [&](auto f) -> std::optional<double> {
    return truth ? std::optional<double>(f(*truth)) : std::nullopt;
  };
  add("mesh_stiffness", 0, r.mesh_stiffness, val([](auto& s) { return s.mesh_stiffness; }), false);
  add("mean_te", 0, r.mean_te, val([](auto& s) { return s.mean_te; }), false);
  add("mesh_damping", 0, r.mesh_damping, val([](auto& s) { return s.mesh_damping; }), false);
  for (std::size_t i = 0; i < r.te_x.size(); ++i) {
    const long long h = static_cast<long long>(i) + 1;
    const bool has = truth && i < truth->te_x.size();
    add("te_x_amplitude", h, r.te_x[i].amplitude,
        has ? std::optional<double>(truth->te_x[i].amplitude) : std::nullopt, false);
    add("te_x_phase", h, r.te_x[i].phase,
        has ? std::optional<double>(truth->te_x[i].phase) : std::nullopt, true);
    add("te_y_amplitude", h, r.te_y[i].amplitude,
        has ? std::optional<double>(truth->te_y[i].amplitude) : std::nullopt, false);
    add("te_y_phase", h, r.te_y[i].phase,
        has ? std::optional<double>(truth->te_y[i].phase) : std::nullopt, true);
  }
  add("pinion_runout", 0, r.pinion_runout.amplitude, val([](auto& s) { return s.pinion_runout; }),
      false);
  add("pinion_runout_phase", 0, r.pinion_runout.phase,
      val([](auto& s) { return s.pinion_runout_phase; }), true);
  add("gear_runout", 0, r.gear_runout.amplitude, val([](auto& s) { return s.gear_runout; }), false);
  add("gear_runout_phase", 0, r.gear_runout.phase, val([](auto& s) { return s.gear_runout_phase; }),
      true);
  return t;
}

}  // namespace geardyn::analysis
