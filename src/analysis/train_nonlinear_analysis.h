#pragma once
/// \file
/// The `nonlinear` analysis of `geardyn train` (train_nonlinear_analysis.cpp), called by
/// trainAnalysis: the train harmonic balance swept in input speed.

#include <string>

#include "geardyn/analysis/analysis_result.h"
#include "geardyn/config/config.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn::analysis::detail {

/// Runs [nonlinear] on `model`: nonlinear_<sweep>.csv per sweep, newmark_checks.csv,
/// summary.results["nonlinear"], a report in `text`. Returns "ok", or "incomplete_sweep" when a
/// continuation stopped (its message in result.errors). InputError for bad keys.
std::string runTrainNonlinear(const GearTrainModel& model, const config::Config& analysis,
                              AnalysisResult& result, std::string& text,
                              const AnalysisContext& context);

/// The meshes' common period is long (nonlinear.method auto: the largest mesh multiple of the
/// base × nonlinear.torus_mesh_harmonics above forced.torus_above), or method = "torus".
bool nonlinearOnTorus(const GearTrainModel& model, const config::Config& analysis);
/// The nonlinear analysis on the torus of the mesh phases (train_nonlinear_torus.cpp).
std::string runTrainNonlinearTorus(const GearTrainModel& model, const config::Config& analysis,
                                   AnalysisResult& result, std::string& text,
                                   const AnalysisContext& context);

}  // namespace geardyn::analysis::detail
