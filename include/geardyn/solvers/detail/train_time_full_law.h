#pragma once
/// \file
/// The `time` response of a train with a rolling bearing's full law (bearings.<name>.model =
/// "nonlinear", bearing_clearance.h): the linear run's plan (step, duration, recorded window;
/// train_time.h) integrated by the nonlinear Newmark of train_nonlinear_time.h, whose Newton
/// takes the bearing's whole load–deflection law (docs/theory/rolling_bearings.md).

#include "geardyn/progress.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn::detail {

/// Sizes the record of a run: `recorded` samples of q (and of q̇, q̈ with `rates`) over `dofs`,
/// the forces of `meshes` meshes.
void sizeTrainTimeRecord(TrainTimeResponse& r, long long recorded, int dofs, int meshes,
                         bool rates);

/// Sample i of the record from a stepper at its last step (TrainNewmarkStepper,
/// TrainNonlinearNewmark): its time, q (q̇, q̈ with `rates`) and every mesh force.
template <class Stepper>
void recordTrainTimeSample(TrainTimeResponse& r, long long i, const Stepper& s, bool rates) {
  r.t(i) = s.time();
  r.displacement.row(i) = s.displacement().transpose();
  if (rates) {
    r.velocity.row(i) = s.velocity().transpose();
    r.acceleration.row(i) = s.acceleration().transpose();
  }
  for (Eigen::Index m = 0; m < r.mesh_force.cols(); ++m) {
    r.mesh_force(i, m) = s.meshForce(static_cast<int>(m));
  }
}

/// Some clearance bearing of `model` carries a rolling bearing's full law.
bool hasFullBearingLaw(const GearTrainModel& model);

/// solveTrainTimeResponse's run for such a model: the same record (times, q, mesh forces, rates
/// when asked), from the mean static deflection (options.start_from_static) or rest; status
/// "diverged" with a message when Newton fails or the state stops being finite.
TrainTimeResponse solveTrainTimeFullLaw(const GearTrainModel& model, double input_speed,
                                        const TrainTimeOptions& options, const TrainTimePlan& plan,
                                        const ProgressCallback& progress);

}  // namespace geardyn::detail
