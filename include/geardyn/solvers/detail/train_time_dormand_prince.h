#pragma once
/// \file
/// The `time` response of a linear train by Dormand–Prince (time.method = "dormand_prince",
/// train_dormand_prince.h): the Newmark run's plan (recorded window, its sample interval Δt,
/// duration; train_time.h) sampled from an error-controlled integration instead of a fixed step.

#include "geardyn/progress.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn::detail {

/// solveTrainTimeResponse's run with options.method = kDormandPrince: the same record (times,
/// q, mesh forces, q̇ and q̈ when asked), from the mean static deflection
/// (options.start_from_static) or rest; status "diverged" once the state stops being finite.
/// InputError naming time.method for a train with nonlinear elements.
TrainTimeResponse solveTrainTimeDormandPrince(const GearTrainModel& model, double input_speed,
                                              const TrainTimeOptions& options,
                                              const TrainTimePlan& plan,
                                              const ProgressCallback& progress);

}  // namespace geardyn::detail
