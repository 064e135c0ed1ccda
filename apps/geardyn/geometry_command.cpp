/// `geardyn geometry CONFIG`: involute gear-pair geometry from [pinion], [gear], [pair].

#include <fmt/format.h>

#include <iostream>

#include "command.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/io/geometry_results.h"
#include "geardyn/io/result_writer.h"
#include "plotting.h"

namespace geardyn::cli {

int runGeometry(const config::Config& config, const CommandOptions& options) {
  const GearPair pair(config::gearPairSpecFromConfig(config));
  for (const auto& warning : pair.warnings()) warn(warning);

  io::RunSummary summary;
  summary.command = "geometry";
  summary.config_source = options.config_file.string();
  summary.config = config.resolved();
  summary.warnings = pair.warnings();
  summary.results = io::toJson(pair);

  io::ResultWriter writer(options.resultFolder());
  writer.writeCsv("gears.csv", io::memberTable(pair));
  writer.writeCsv("tooth_profiles.csv", io::toothProfileTable(pair));
  auto summary_path = writer.writeSummary(summary);
  if (config::outputOptionsFromConfig(config).plots) {
    // The plotter reads summary.json; the summary is written again to list the plots.
    for (const auto& file : drawPlots("geometry", writer.folder())) writer.recordFile(file);
    summary_path = writer.writeSummary(summary);
  }

  const auto mm = [](double metres) { return metres * 1e3; };
  std::string text = fmt::format(
      "gear pair {}/{} teeth, m_n = {:g} mm, a_w = {:.6g} mm, alpha_wt = {:.6g} deg\n"
      "  base diameters    {:.7g} / {:.7g} mm\n"
      "  tip diameters     {:.7g} / {:.7g} mm\n"
      "  contact ratio     transverse {:.7f}, overlap {:.7f}, total {:.7f}\n",
      pair.spec().pinion.teeth, pair.spec().gear.teeth, mm(pair.spec().pinion.normal_module),
      mm(pair.centreDistance()), summary.results["operating_pressure_angle_deg"].get<double>(),
      mm(2 * pair.pinion().base_radius), mm(2 * pair.gear().base_radius),
      mm(2 * pair.pinion().tip_radius), mm(2 * pair.gear().tip_radius),
      pair.contactRatioTransverse(), pair.overlapRatio(), pair.contactRatioTotal());
  if (auto f = pair.meshFrequency()) text += fmt::format("  mesh frequency    {:.6g} Hz\n", *f);
  text += fmt::format("results: {}\n", summary_path.string());
  report(options, text);
  return kExitOk;
}

}  // namespace geardyn::cli
