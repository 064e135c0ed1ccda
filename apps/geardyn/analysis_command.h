#pragma once
/// \file
/// The commands over the library's analyses (geardyn/analysis/analyses.h).

#include <functional>
#include <string>

#include "command.h"
#include "geardyn/analysis/analysis_result.h"
#include "geardyn/analysis/run_budget.h"

namespace geardyn::cli {

using analysis::RunEstimate;

/// Refuses a run that does not fit (InputError) and prints the note of a long one on stderr
/// (unless quiet).
void checkRunEstimate(const RunEstimate& estimate, const CommandOptions& options,
                      const std::string& label);

/// Runs `run` with a context for command `name` (progress lines, warnings, threads; `estimate`
/// gives the size of a stage the analysis is about to run, refused when too large), writes the
/// result folder with the plots of `plot_kind` when `plots`, prints the report; returns the
/// exit code.
int runLibraryResult(
    const std::string& name, const std::string& plot_kind, bool plots,
    const CommandOptions& options,
    const std::function<analysis::AnalysisResult(analysis::AnalysisContext&)>& run,
    const std::function<RunEstimate(const std::string&, long long)>& estimate = {});

/// The command `name` of the library's runAnalysis on a loaded configuration.
int runLibraryAnalysis(const std::string& name, const config::Config& config,
                       const CommandOptions& options);

}  // namespace geardyn::cli
