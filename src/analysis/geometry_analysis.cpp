/// `geometry`: involute gear-pair geometry from [pinion], [gear], [pair].

#include <fmt/format.h>

#include "geardyn/analysis/analyses.h"
#include "geardyn/analysis/geometry_results.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/geometry/gear_pair.h"

namespace geardyn::analysis {

AnalysisResult geometryAnalysis(const config::Config& config, const AnalysisContext& context) {
  const GearPair pair(config::gearPairSpecFromConfig(config));
  context.warnings(pair.warnings());

  AnalysisResult result("geometry", config, context);
  io::RunSummary& summary = result.summary;
  summary.warnings = pair.warnings();
  summary.results = analysis::toJson(pair);
  result.addTable("gears.csv", analysis::memberTable(pair));
  result.addTable("tooth_profiles.csv", analysis::toothProfileTable(pair));

  const auto mm = [](double metres) { return metres * 1e3; };
  result.report = fmt::format(
      "gear pair {}/{} teeth, m_n = {:g} mm, a_w = {:.6g} mm, alpha_wt = {:.6g} deg\n"
      "  base diameters    {:.7g} / {:.7g} mm\n"
      "  tip diameters     {:.7g} / {:.7g} mm\n"
      "  contact ratio [-] transverse {:.7f}, overlap {:.7f}, total {:.7f}\n",
      pair.spec().pinion.teeth, pair.spec().gear.teeth, mm(pair.spec().pinion.normal_module),
      mm(pair.centreDistance()), summary.results["operating_pressure_angle_deg"].get<double>(),
      mm(2 * pair.pinion().base_radius), mm(2 * pair.gear().base_radius),
      mm(2 * pair.pinion().tip_radius), mm(2 * pair.gear().tip_radius),
      pair.contactRatioTransverse(), pair.overlapRatio(), pair.contactRatioTotal());
  if (auto f = pair.meshFrequency())
    result.report += fmt::format("  mesh frequency    {:.6g} Hz\n", *f);
  return result;
}

}  // namespace geardyn::analysis
