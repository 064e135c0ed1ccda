/// `time` by Dormand–Prince (detail/train_time_dormand_prince.h).

#include "geardyn/solvers/detail/train_time_dormand_prince.h"

#include <fmt/format.h>

#include <numeric>

#include "geardyn/error.h"
#include "geardyn/solvers/detail/train_time_full_law.h"
#include "geardyn/solvers/train_dormand_prince.h"
#include "geardyn/solvers/train_response.h"

namespace geardyn::detail {

TrainTimeResponse solveTrainTimeDormandPrince(const GearTrainModel& model, double input_speed,
                                              const TrainTimeOptions& options,
                                              const TrainTimePlan& plan,
                                              const ProgressCallback& progress) {
  if (model.hasNonlinearElements() || !model.rollingBearings().empty()) {
    throw InputError("time.method", "\"dormand_prince\"",
                     "\"newmark\" for a train with backlash, contact loss, bearing clearances or "
                     "rolling bearings (Dormand–Prince integrates linear trains)");
  }
  const int n = model.dofCount();
  const double dt = plan.time_step;
  const long long recorded = options.record_periods * plan.steps_per_period;
  const long long first = plan.steps - recorded;
  TrainTimeResponse r;
  r.time_step = dt;
  r.transient = plan.transient;
  sizeTrainTimeRecord(r, recorded, n, static_cast<int>(model.meshes().size()),
                      options.record_rates);
  // The Newmark record's times: steps first + 1 … steps of Δt.
  std::vector<double> times(static_cast<std::size_t>(recorded));
  for (long long j = 0; j < recorded; ++j) times[j] = static_cast<double>(first + 1 + j) * dt;
  std::vector<int> dofs(static_cast<std::size_t>(n));
  std::iota(dofs.begin(), dofs.end(), 0);
  TrainDormandPrinceOptions o;
  o.relative_tolerance = options.relative_tolerance;
  o.absolute_tolerance = options.relative_tolerance;
  o.rates = options.record_rates;
  if (options.start_from_static)
    o.initial_displacement = solveTrainStatic(model, input_speed).displacement;
  if (progress) o.progress = progress;
  const TrainDormandPrinceRun run = integrateTrainDormandPrince(
      model, input_speed, times, dofs, o,
      [&](std::size_t i, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
          const Eigen::VectorXd& qddot) {
        const auto k = static_cast<Eigen::Index>(i);
        r.t(k) = times[i];
        r.displacement.row(k) = q.transpose();
        if (options.record_rates) {
          r.velocity.row(k) = qdot.transpose();
          r.acceleration.row(k) = qddot.transpose();
        }
        for (Eigen::Index m = 0; m < r.mesh_force.cols(); ++m)
          r.mesh_force(k, m) = model.meshes()[m].force(times[i], input_speed, q);
      });
  r.steps = plan.steps;
  r.integrator_steps = run.steps;
  if (!run.finite) {
    r.status = "diverged";
    r.message = "Dormand–Prince: the state stopped being finite";
  }
  return r;
}

}  // namespace geardyn::detail
