#pragma once
/// \file
/// The `stats` analysis of `geardyn train` (train_stats_analysis.cpp), called by trainAnalysis:
/// Gelman's mean excitation ratio R and the statistics of the dynamic mesh force and
/// transmission error at every mesh, from a Newmark run with the [time] section's options
/// (train_mesh_statistics.h).

#include "geardyn/analysis/analysis_result.h"
#include "geardyn/config/config.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn::analysis::detail {

/// Runs [stats] on `model`: mesh_statistics.csv, summary.results["stats"], report lines in
/// `text`. `record`: the `time` analysis's Newmark record at the same speed and options, reused
/// (null: run Newmark here). Returns 0, or 1 when Newmark diverged.
int runTrainStats(const GearTrainModel& model, const config::Config& analysis,
                  AnalysisResult& result, std::string& text,
                  const TrainTimeResponse* record = nullptr);

}  // namespace geardyn::analysis::detail
