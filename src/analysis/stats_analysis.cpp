/// `stats CONFIG`: Gelman's mean excitation ratio.

#include <fmt/format.h>

#include <thread>

#include "geardyn/analysis/analyses.h"
#include "geardyn/analysis/simulate_results.h"
#include "geardyn/analysis/stats_results.h"
#include "geardyn/config/simulate_config.h"
#include "geardyn/config/stats_config.h"

namespace geardyn::analysis {

AnalysisResult statsAnalysis(const config::Config& config, const AnalysisContext& context) {
  AnalysisResult result("stats", config, context);
  io::RunSummary& summary = result.summary;
  int exit_code = 0;
  std::vector<std::pair<std::string, io::CsvTable>> monte_carlo_tables;

  MeanExcitation stats;
  if (config.string("stats.source") == "moments") {
    stats = config::meanExcitationFromConfigMoments(config);
  } else if (config.string("stats.source") == "csv") {
    stats = config::meanExcitationFromConfigCsv(config);
  } else {
    const int threads =
        context.threads > 0 ? context.threads : std::max(1u, std::thread::hardware_concurrency());
    if (config.integer("monte_carlo.samples") > 0)
      context.checkBudget("stats_monte_carlo", threads);
    if (config.boolean("stats.simulate")) context.checkBudget("stats_time");
    const config::GearPairModelBuild build = config::buildGearPairModel(config);
    summary.warnings = build.warnings;
    const GearPairModel model(build.spec);
    const double baseload = build.nondimensional           ? 1.0
                            : config.has("stats.baseload") ? config.real("stats.baseload")
                                                           : model.meanForce();
    stats = meanExcitationFromModel(model, baseload);
    if (config.integer("monte_carlo.samples") > 0) {
      MonteCarloOptions mc = config::monteCarloOptionsFromConfig(config, baseload, threads);
      mc.progress = context.progressFor("stats: Monte Carlo", "samples");
      const auto samples = runMeanExcitationMonteCarlo(model, mc);
      summary.seed = mc.seed;
      summary.results["monte_carlo"] = analysis::monteCarloJson(mc, samples);
      monte_carlo_tables.emplace_back("monte_carlo.csv", analysis::monteCarloTable(samples));
      monte_carlo_tables.emplace_back(
          "histogram.csv",
          analysis::histogramTable(samples,
                                   static_cast<int>(config.integer("monte_carlo.histogram_bins"))));
    }
    if (config.boolean("stats.simulate")) {
      if (model.contact() != ContactLaw::kLinear) {
        summary.warnings.push_back(
            "the mean excitation statistics assume a linear contact (Gelman eq. 1); "
            "with contact loss the simulated mean of k·y differs from L_d");
      }
      TimeResponseOptions solver = config::timeResponseOptionsFromConfig(config);
      solver.progress = context.progressFor("stats: simulation", "periods of max_periods");
      const TimeResponse r = solveTimeResponse(model, solver);
      double mean_kx = 0.0;
      for (std::size_t j = 0; j < r.t.size(); ++j) mean_kx += model.stiffness(r.t[j]) * r.x[j];
      mean_kx /= std::max<std::size_t>(1, r.t.size());
      const double simulated = mean_kx / baseload;  // m₁(k y) with k = K/K̄, y = x/x₀
      summary.results["simulation"] = {
          {"status", toString(r.status)},
          {"message", r.message},
          {"dynamic_mean_excitation", simulated},
          {"relative_difference", simulated / stats.dynamic_mean_excitation - 1.0}};
      if (!r.converged()) {
        summary.status = toString(r.status);
        result.errors.push_back("simulation " + toString(r.status) + ": " + r.message);
        exit_code = 1;
      }
    }
  }
  context.warnings(summary.warnings);
  summary.results["mean_excitation"] = analysis::toJson(stats);

  for (const auto& [name, table] : monte_carlo_tables) result.addTable(name, table);
  std::string text =
      fmt::format("mean excitation ratio R [-] = {:.6g} (eq. 15: {:.6g}, eq. 11: {:.6g})\n",
                  stats.ratio, stats.ratio_eq15, stats.ratio_eq11);
  text += fmt::format(
      "  normalised [-]: a = {:.4g}, d_k = {:.4g}, d_e = {:.4g}, r_ke = {:.4g}, delta m1(e_f) = "
      "{:.4g}\n",
      stats.a, stats.d_k, stats.d_e, stats.r_ke, stats.delta_m1_ef);
  text += fmt::format("  the dynamic mean excitation is {} the transmitted mean load\n",
                      stats.classification());
  if (summary.results.contains("simulation")) {
    text += fmt::format("  simulated mean of k y [-]: {:.8g} (relative difference {:.2g})\n",
                        summary.results["simulation"]["dynamic_mean_excitation"].get<double>(),
                        summary.results["simulation"]["relative_difference"].get<double>());
  }
  if (summary.results.contains("monte_carlo")) {
    const auto& r = summary.results["monte_carlo"]["ratio"];
    text += fmt::format(
        "  Monte Carlo, {} samples: R [-] mean {:.6g}, std {:.3g}, 5/50/95 % {:.5g} / {:.5g} / "
        "{:.5g}\n",
        summary.results["monte_carlo"]["samples"].get<int>(), r["mean"].get<double>(),
        r["std"].get<double>(), r["q05"].get<double>(), r["q50"].get<double>(),
        r["q95"].get<double>());
  }
  result.report = text;
  result.summary.numerical_failure = exit_code != 0;
  return result;
}

}  // namespace geardyn::analysis
