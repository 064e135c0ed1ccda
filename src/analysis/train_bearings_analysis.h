#pragma once
/// \file
/// Rolling bearings from their geometry in `geardyn train` (train_bearings_analysis.cpp):
/// the nonlinear static deflection they are linearised about, and their results.

#include <optional>
#include <string>

#include "geardyn/analysis/analysis_result.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn::analysis::detail {

/// The linear model the linear analyses of `model` use when it has rolling bearings (none
/// without: `model` itself serves): `model` linearised at its static deflection at the
/// operating point, with
/// summary.results["bearings"] saying so (per bearing: its deflection, load, 5×5 tangent
/// stiffness, largest element load and contact pressure, L10r), bearings.csv, and report lines.
std::optional<GearTrainModel> linearModelOf(const GearTrainModel& model, AnalysisResult& result,
                                            std::string& text);

/// bearings.csv and summary.results["static"]["rolling_bearings"] from a static result.
void writeRollingBearings(const GearTrainModel& model, const TrainStaticResult& r,
                          AnalysisResult& result, nlohmann::ordered_json& out);

}  // namespace geardyn::analysis::detail
