#pragma once
/// \file
/// The `runup` analysis of `geardyn train` (train_runup_analysis.cpp), called by trainAnalysis:
/// Newmark along a linear input-speed ramp, order tracking and a waterfall.

#include "geardyn/analysis/analysis_result.h"
#include "geardyn/config/config.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn::analysis::detail {

/// Runs [runup] on `model`: runup.csv, waterfall.csv, summary.results["runup"], a report line
/// in `text`. Returns 0, or 1 when Newmark diverged. InputError for bad keys and for a run that
/// would not fit in memory (run_budget.h).
int runTrainRunUp(const GearTrainModel& model, const config::Config& analysis,
                  AnalysisResult& result, std::string& text, const AnalysisContext& context);

}  // namespace geardyn::analysis::detail
