/// `stiffness`: mesh-stiffness models of a gear pair over one mesh period.

#include <fmt/format.h>

#include "geardyn/analysis/analyses.h"
#include "geardyn/analysis/geometry_results.h"
#include "geardyn/analysis/stiffness_results.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/geometry/gear_pair.h"

namespace geardyn::analysis {

AnalysisResult stiffnessAnalysis(const config::Config& config, const AnalysisContext& context) {
  const GearPair pair(config::gearPairSpecFromConfig(config));
  const config::MeshStiffnessModels models = config::buildMeshStiffnessModels(config, pair);

  AnalysisResult result("stiffness", config, context);
  io::RunSummary& summary = result.summary;
  summary.warnings = pair.warnings();
  summary.warnings.insert(summary.warnings.end(), models.warnings.begin(), models.warnings.end());
  context.warnings(summary.warnings);
  summary.results = analysis::stiffnessResultsJson(config, pair, models);
  summary.results["geometry"] = {
      {"contact_ratio_transverse", pair.contactRatioTransverse()},
      {"overlap_ratio", pair.overlapRatio()},
      {"base_pitch_transverse", pair.basePitchTransverse()},
      {"mesh_frequency",
       pair.meshFrequency() ? nlohmann::ordered_json(*pair.meshFrequency()) : nullptr}};
  result.addTable("mesh_stiffness.csv", analysis::stiffnessCurveTable(config, pair, models));
  result.addTable("fourier.csv", analysis::fourierTable(summary.results["models"]));

  std::string& text = result.report;
  text = fmt::format("mesh stiffness of {}/{} teeth, contact ratio [-] {:.6f}\n",
                     pair.spec().pinion.teeth, pair.spec().gear.teeth, pair.contactRatioTotal());
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
  const auto& plane = summary.results["plane"];
  text += "  plane: k, F and STE along the transverse line of action (F = T1/r_b1)\n";
  if (pair.baseHelixAngle() > 0.0) {
    const auto& normal = plane["normal"];
    text += fmt::format(
        "  normal plane (beta_b = {:.4f} deg): k_n = k / cos^2 beta_b, mean {:.5e} N/m",
        plane["base_helix_angle_deg"].get<double>(), normal["stiffness_mean"].get<double>());
    if (normal.contains("force")) {
      text += fmt::format("; F_n = F / cos beta_b = {:g} N; STE_n = STE cos beta_b, mean {:.4g} um",
                          normal["force"].get<double>(), normal["ste_mean"].get<double>() * 1e6);
    }
    text += "\n";
  }
  return result;
}

}  // namespace geardyn::analysis
