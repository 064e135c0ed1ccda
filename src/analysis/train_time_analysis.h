#pragma once
/// \file
/// The `time` analysis of `geardyn train` (train_time_analysis.cpp), called by trainAnalysis:
/// Newmark at one speed to the periodic steady state, its duration derived from the transient
/// (solvers/train_transient.h), compared with the frequency-domain steady state.

#include <optional>
#include <string>

#include "geardyn/analysis/analysis_result.h"
#include "geardyn/config/config.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn::analysis::detail {

/// Runs [time] on `model`: time_history.csv, probes, summary.results["time"], report lines in
/// `text`; `record` receives the Newmark record (for `stats` after `time`). Returns 0, or 1 when
/// Newmark diverged. InputError before it allocates when a mode the meshes drive has no
/// damping (naming the keys that would damp it) or when the run would not fit in memory.
int runTrainTime(const GearTrainModel& model, const config::Config& analysis,
                 AnalysisResult& result, std::string& text,
                 std::optional<TrainTimeResponse>& record, const AnalysisContext& context);

}  // namespace geardyn::analysis::detail
