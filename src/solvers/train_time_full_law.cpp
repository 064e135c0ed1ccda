/// The `time` response with a rolling bearing's full law: the linear run's plan through the
/// nonlinear Newmark (detail/train_time_full_law.h).

#include "geardyn/solvers/detail/train_time_full_law.h"

#include <fmt/format.h>

#include <algorithm>

#include "geardyn/solvers/train_nonlinear_time.h"
#include "geardyn/solvers/train_response.h"

namespace geardyn::detail {

void sizeTrainTimeRecord(TrainTimeResponse& r, long long recorded, int dofs, int meshes,
                         bool rates) {
  r.t.resize(recorded);
  r.displacement.resize(recorded, dofs);
  r.mesh_force.resize(recorded, meshes);
  if (rates) {
    r.velocity.resize(recorded, dofs);
    r.acceleration.resize(recorded, dofs);
  }
}

bool hasFullBearingLaw(const GearTrainModel& model) {
  const auto& bearings = model.clearanceBearings();
  return std::any_of(bearings.begin(), bearings.end(),
                     [](const TrainClearanceBearing& b) { return b.rolling != nullptr; });
}

TrainTimeResponse solveTrainTimeFullLaw(const GearTrainModel& model, double input_speed,
                                        const TrainTimeOptions& options, const TrainTimePlan& plan,
                                        const ProgressCallback& progress) {
  // The nonlinear stepper's defaults (TrainNonlinearTimeOptions): Newton to 1e-13 of the largest
  // coordinate in at most 50 iterations; no event refinement, as the linear run's fixed steps.
  const TrainNonlinearTimeOptions defaults;
  TrainNonlinearNewmark stepper(model, input_speed, plan.time_step, options.newmark);
  const int n = model.dofCount();
  Eigen::VectorXd q0 = Eigen::VectorXd::Zero(n);
  if (options.start_from_static) q0 = solveTrainStatic(model, input_speed).displacement;
  stepper.reset(0.0, q0, Eigen::VectorXd::Zero(n));

  TrainTimeResponse r;
  r.time_step = plan.time_step;
  r.transient = plan.transient;
  const long long per_period = plan.steps_per_period, steps = plan.steps;
  const long long recorded = options.record_periods * per_period;
  const long long first = steps - recorded;
  sizeTrainTimeRecord(r, recorded, n, static_cast<int>(model.meshes().size()),
                      options.record_rates);
  for (long long k = 1; k <= steps; ++k) {
    const bool converged = stepper.step(defaults.newton_tolerance, defaults.max_newton_iterations);
    if (!converged || (k % per_period == 0 && !stepper.displacement().allFinite())) {
      r.status = "diverged";
      r.message = fmt::format("Newmark with the full bearing law {} at t = {:.6g} s",
                              converged ? "diverged" : "failed (Newton)", stepper.time());
      r.steps = k;
      return r;
    }
    if (k % per_period == 0 && progress) {
      progress(static_cast<double>(k), static_cast<double>(steps));
    }
    if (k > first) recordTrainTimeSample(r, k - first - 1, stepper, options.record_rates);
  }
  r.steps = steps;
  return r;
}

}  // namespace geardyn::detail
