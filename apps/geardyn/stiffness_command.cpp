/// `geardyn stiffness CONFIG`: mesh-stiffness models of a gear pair over one mesh period.

#include <fmt/format.h>

#include <iostream>

#include "command.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/io/result_writer.h"
#include "geardyn/io/stiffness_results.h"
#include "plotting.h"

namespace geardyn::cli {

int runStiffness(const config::Config& config, const CommandOptions& options) {
  const GearPair pair(config::gearPairSpecFromConfig(config));
  const config::MeshStiffnessModels models = config::buildMeshStiffnessModels(config, pair);

  io::RunSummary summary;
  summary.command = "stiffness";
  summary.config_source = options.config_file.string();
  summary.config = config.resolved();
  summary.warnings = pair.warnings();
  summary.warnings.insert(summary.warnings.end(), models.warnings.begin(), models.warnings.end());
  for (const auto& warning : summary.warnings) warn(warning);
  summary.results = io::stiffnessResultsJson(config, pair, models);
  summary.results["geometry"] = {
      {"contact_ratio_transverse", pair.contactRatioTransverse()},
      {"overlap_ratio", pair.overlapRatio()},
      {"base_pitch_transverse", pair.basePitchTransverse()},
      {"mesh_frequency",
       pair.meshFrequency() ? nlohmann::ordered_json(*pair.meshFrequency()) : nullptr}};

  io::ResultWriter writer(options.resultFolder());
  writer.writeCsv("mesh_stiffness.csv", io::stiffnessCurveTable(config, pair, models));
  writer.writeCsv("fourier.csv", io::fourierTable(summary.results["models"]));
  auto summary_path = writer.writeSummary(summary);
  if (config::outputOptionsFromConfig(config).plots) {
    for (const auto& file : drawPlots("stiffness", writer.folder())) writer.recordFile(file);
    summary_path = writer.writeSummary(summary);
  }

  std::string text =
      fmt::format("mesh stiffness of {}/{} teeth, contact ratio {:.6f}\n", pair.spec().pinion.teeth,
                  pair.spec().gear.teeth, pair.contactRatioTotal());
  text += fmt::format("  {:<18} {:>12} {:>12} {:>12} {:>12}\n", "model [N/m]", "mean", "min", "max",
                      "std");
  for (const auto& [name, json] : summary.results["models"].items()) {
    text += fmt::format("  {:<18} {:>12.5e} {:>12.5e} {:>12.5e} {:>12.5e}\n", name,
                        json["mean"].get<double>(), json["min"].get<double>(),
                        json["max"].get<double>(), json["std"].get<double>());
  }
  if (summary.results.contains("static_transmission_error")) {
    const auto& ste = summary.results["static_transmission_error"];
    text += fmt::format("  loaded STE at F = {:g} N: mean {:.4g} um, peak to peak {:.4g} um\n",
                        ste["force"].get<double>(), ste["mean"].get<double>() * 1e6,
                        ste["peak_to_peak"].get<double>() * 1e6);
  }
  text += fmt::format("results: {}\n", summary_path.string());
  report(options, text);
  return kExitOk;
}

}  // namespace geardyn::cli
