#pragma once
/// \file
/// The `forced` analysis of `geardyn train` (train_forced_analysis.cpp), called by
/// trainAnalysis: the linear steady state over a speed range, balanced over the common period
/// of the meshes or on the torus of their phases (forced.method).

#include <string>
#include <vector>

#include "geardyn/analysis/analysis_result.h"
#include "geardyn/config/config.h"
#include "geardyn/io/result_writer.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn::analysis::detail {

/// Runs [forced] on `model`: forced_response.csv, forced_mesh_orders.csv, forced_tones.csv
/// (torus), forced_ods.csv (either method: the operating deflection shapes at the operating
/// speed and at each mesh's largest dynamic factor), summary.results["forced"] with the method,
/// and report lines in `text`.
void runTrainForced(const GearTrainModel& model, const config::Config& analysis,
                    AnalysisResult& result, io::RunSummary& summary, std::string& text,
                    const AnalysisContext& context);
/// As runTrainForced at the input speeds `speeds` [rad/s] instead of forced.speed_*_rpm and
/// forced.points (GearTrainSession::forced).
void runTrainForcedAt(const GearTrainModel& model, const config::Config& analysis,
                      const std::vector<double>& speeds, AnalysisResult& result,
                      io::RunSummary& summary, std::string& text, const AnalysisContext& context);

}  // namespace geardyn::analysis::detail
