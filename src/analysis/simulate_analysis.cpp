/// `simulate`: time integration of the gear-pair model to its steady state.

#include <fmt/format.h>

#include "geardyn/analysis/analyses.h"
#include "geardyn/analysis/simulate_results.h"
#include "geardyn/config/simulate_config.h"

namespace geardyn::analysis {

AnalysisResult simulateAnalysis(const config::Config& config, const AnalysisContext& context) {
  const config::GearPairModelBuild build = config::buildGearPairModel(config);
  context.warnings(build.warnings);
  const GearPairModel model(build.spec);
  TimeResponseOptions solver = config::timeResponseOptionsFromConfig(config);
  context.checkBudget("simulate");  // before it allocates
  solver.progress = context.progressFor("simulate", "periods of max_periods");
  const TimeResponse response = solveTimeResponse(model, solver);
  const analysis::TimeResponseChannels channels = analysis::channelsOf(model, response);

  AnalysisResult result("simulate", config, context);
  io::RunSummary& summary = result.summary;
  summary.warnings = build.warnings;
  summary.status = toString(response.status);
  summary.results = analysis::timeResponseResultsJson(
      build, model, response, channels, static_cast<int>(config.integer("solver.harmonics")));
  result.addTable("time_response.csv", analysis::timeResponseTable(channels, build.nondimensional));

  std::string& text = result.report;
  text =
      fmt::format("gear pair, {} stiffness, f_m / f_n [-] = {:.4g}, zeta = {:.3g}\n",
                  model.meshStiffness().model(),
                  summary.results["model"]["frequency_ratio"].get<double>(), build.damping_ratio);
  text += fmt::format("  {}\n", response.message);
  if (summary.results.contains("mesh_force")) {
    const auto& f = summary.results["mesh_force"];
    // Along the transverse line of action; nondimensional models: in F₀.
    const std::string force_unit = build.nondimensional ? " [-]" : " N";
    text += fmt::format(
        "  transverse mesh force: mean {:.6g}{}, peak to peak {:.6g}{}, dynamic factor {:.4g} "
        "[-], contact loss {:.1f} %\n",
        f["mean"].get<double>(), force_unit, f["peak_to_peak"].get<double>(), force_unit,
        summary.results["dynamic_factor"].is_null()
            ? 0.0
            : summary.results["dynamic_factor"].get<double>(),
        100.0 * summary.results["contact_loss_fraction"].get<double>());
  }
  if (!response.converged()) {
    result.summary.numerical_failure = true;
    result.errors.push_back(fmt::format("{}: {}", toString(response.status), response.message));
  }
  return result;
}

}  // namespace geardyn::analysis
