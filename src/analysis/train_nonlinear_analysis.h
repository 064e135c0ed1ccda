#pragma once
/// \file
/// The `nonlinear` analysis of `geardyn train` (train_nonlinear_analysis.cpp), called by
/// trainAnalysis: the train harmonic balance swept in input speed.

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "geardyn/analysis/analysis_result.h"
#include "geardyn/config/config.h"
#include "geardyn/solvers/continuation.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn::analysis::detail {

/// Runs [nonlinear] on `model`: nonlinear_<sweep>.csv per sweep, newmark_checks.csv,
/// summary.results["nonlinear"], a report in `text`. Returns "ok", or "incomplete_sweep" when a
/// continuation stopped (its message in result.errors). InputError for bad keys.
std::string runTrainNonlinear(const GearTrainModel& model, const config::Config& analysis,
                              AnalysisResult& result, std::string& text,
                              const AnalysisContext& context);

/// nonlinear.stability_method: "monodromy" (the default) or "hill".
StabilityMethod stabilityMethod(const config::Config& analysis);

/// Nonlinear Newmark started on every stable solution at nonlinear.newmark_speeds_rpm (unstable
/// ones are listed, not integrated); newmark_checks.csv and the checks' JSON
/// (train_nonlinear_checks.cpp).
nlohmann::ordered_json newmarkChecks(
    const GearTrainModel& model, const config::Config& analysis, TrainHarmonicBalance& hbm,
    const std::vector<std::pair<std::string, ContinuationResult>>& runs, double scale,
    bool stability, AnalysisResult& result, const AnalysisContext& context);

/// The meshes' common period is long (nonlinear.method auto: the largest mesh multiple of the
/// base × nonlinear.torus_mesh_harmonics above forced.torus_above), or method = "torus".
bool nonlinearOnTorus(const GearTrainModel& model, const config::Config& analysis);
/// The nonlinear analysis on the torus of the mesh phases (train_nonlinear_torus.cpp).
std::string runTrainNonlinearTorus(const GearTrainModel& model, const config::Config& analysis,
                                   AnalysisResult& result, std::string& text,
                                   const AnalysisContext& context);

}  // namespace geardyn::analysis::detail
