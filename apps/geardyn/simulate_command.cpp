/// `geardyn simulate CONFIG`: time integration of the gear-pair model to its steady state.

#include <fmt/format.h>

#include <iostream>

#include "command.h"
#include "geardyn/config/output_section.h"
#include "geardyn/config/simulate_config.h"
#include "geardyn/io/result_writer.h"
#include "geardyn/io/simulate_results.h"
#include "plotting.h"
#include "progress.h"
#include "run_estimates.h"

namespace geardyn::cli {

int runSimulate(const config::Config& config, const CommandOptions& options) {
  const config::GearPairModelBuild build = config::buildGearPairModel(config);
  for (const auto& warning : build.warnings) warn(warning);
  const GearPairModel model(build.spec);
  TimeResponseOptions solver = config::timeResponseOptionsFromConfig(config);
  checkRunEstimate(estimateTimeResponse(config), options, "simulate");  // before it allocates
  ProgressReporter progress("simulate", "periods of max_periods",
                            ProgressReporter::enabledFor(options));
  solver.progress = progress.callback();
  const TimeResponse response = solveTimeResponse(model, solver);
  const io::TimeResponseChannels channels = io::channelsOf(model, response);

  io::RunSummary summary;
  summary.command = "simulate";
  summary.config_source = options.config_file.string();
  summary.config = config.resolved();
  summary.warnings = build.warnings;
  summary.status = toString(response.status);
  summary.results = io::timeResponseResultsJson(
      build, model, response, channels, static_cast<int>(config.integer("solver.harmonics")));

  io::ResultWriter writer(options.resultFolder());
  writer.writeCsv("time_response.csv", io::timeResponseTable(channels));
  auto summary_path = writer.writeSummary(summary);
  if (config::outputOptionsFromConfig(config).plots) {
    for (const auto& file : drawPlots("simulate", writer.folder())) writer.recordFile(file);
    summary_path = writer.writeSummary(summary);
  }

  std::string text = fmt::format(
      "gear pair, {} stiffness, f_m / f_n = {:.4g}, zeta = {:.3g}\n", model.meshStiffness().model(),
      summary.results["model"]["frequency_ratio"].get<double>(), build.damping_ratio);
  text += fmt::format("  {}\n", response.message);
  if (summary.results.contains("mesh_force")) {
    const auto& f = summary.results["mesh_force"];
    const std::string force_unit = build.nondimensional ? "" : " N";
    text += fmt::format(
        "  mesh force: mean {:.6g}{}, peak to peak {:.6g}{}, dynamic factor {:.4g}, contact "
        "loss {:.1f} %\n",
        f["mean"].get<double>(), force_unit, f["peak_to_peak"].get<double>(), force_unit,
        summary.results["dynamic_factor"].is_null()
            ? 0.0
            : summary.results["dynamic_factor"].get<double>(),
        100.0 * summary.results["contact_loss_fraction"].get<double>());
  }
  text += fmt::format("results: {}\n", summary_path.string());
  report(options, text);
  if (!response.converged()) {
    std::cerr << "geardyn simulate: " << toString(response.status) << ": " << response.message
              << "\n";
    return kExitNumericalFailure;
  }
  return kExitOk;
}

}  // namespace geardyn::cli
