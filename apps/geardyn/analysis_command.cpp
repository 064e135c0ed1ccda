/// The analysis commands over the library's analyses (geardyn/analysis/analyses.h): run the
/// analysis with a progress line and the resource check, write its result folder and plots,
/// print its report.

#include "analysis_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <memory>

#include "geardyn/analysis/analyses.h"
#include "geardyn/analysis/run_estimates.h"
#include "geardyn/config/output_section.h"
#include "geardyn/io/result_writer.h"
#include "plotting.h"
#include "progress.h"

namespace geardyn::cli {

void checkRunEstimate(const RunEstimate& estimate, const CommandOptions& options,
                      const std::string& label) {
  const std::string note = analysis::checkRunEstimate(estimate, label);
  if (!note.empty() && !options.quiet) std::cerr << note << "\n";
}

int runLibraryResult(const std::string& name, const std::string& plot_kind, bool plots,
                     const CommandOptions& options,
                     const std::function<analysis::AnalysisResult(analysis::AnalysisContext&)>& run,
                     const std::function<RunEstimate(const std::string&, long long)>& estimate) {
  const bool show_progress = ProgressReporter::enabledFor(options);
  std::unique_ptr<ProgressReporter> stage;  // the stage running now
  analysis::AnalysisContext context;
  context.config_source = options.config_file.string();
  context.threads = options.threads;
  context.warn = [&options](const std::string& text) { warn(text, options.quiet); };
  context.print = [&options](const std::string& text) { report(options, text); };
  context.inform = [&options](const std::string& text) {
    if (!options.quiet) std::cerr << text << std::flush;
  };
  context.progress = [&](const std::string& label, const std::string& unit) {
    stage.reset();  // the previous stage has finished
    stage = std::make_unique<ProgressReporter>(label, unit, show_progress);
    return stage->callback();
  };
  if (estimate) {
    context.check_budget = [&](const std::string& what, long long size) {
      checkRunEstimate(estimate(what, size), options, name);
    };
  }
  const analysis::AnalysisResult result = run(context);
  stage.reset();

  io::ResultWriter writer(options.resultFolder());
  analysis::writeAnalysisResult(result, writer);
  auto path = writer.writeSummary(result.summary);
  if (!result.tables.empty() && plots) {
    // The plotter reads summary.json; the summary is written again to list the plots.
    for (const auto& file : drawPlots(plot_kind, writer.folder())) writer.recordFile(file);
    path = writer.writeSummary(result.summary);
  }
  for (const auto& error : result.errors) std::cerr << "geardyn " << name << ": " << error << "\n";
  report(options, result.report.substr(std::min(result.printed, result.report.size())) +
                      fmt::format("results: {}\n", path.string()));
  return result.summary.numerical_failure ? kExitNumericalFailure : kExitOk;
}

int runLibraryAnalysis(const std::string& name, const config::Config& config,
                       const CommandOptions& options) {
  const auto estimate = [&config](const std::string& stage, long long size) {
    return analysis::estimateStage(stage, size, config);
  };
  const std::string plot_kind =
      name == "rotor" && config.resolved().contains("model") ? "rotor_fe" : name;
  return runLibraryResult(
      name, plot_kind, config::outputOptionsFromConfig(config).plots, options,
      [&](analysis::AnalysisContext& context) {
        return analysis::runAnalysis(name, config, context);
      },
      estimate);
}

}  // namespace geardyn::cli
