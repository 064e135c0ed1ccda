#pragma once
/// \file
/// Periodic steady state of the gear-pair model by time integration: Newmark (fixed step) or
/// Dormand–Prince 5(4) (adaptive, Boost.Odeint), integrated mesh period after mesh period until
/// two consecutive periods agree, then the last periods are returned.

#include <string>
#include <vector>

#include "geardyn/progress.h"
#include "geardyn/solvers/newmark.h"
#include "geardyn/system/gear_pair_model.h"

namespace geardyn {

enum class TimeIntegrator { kNewmark, kDormandPrince };

/// Options in, summary out (STYLE.md). Time in the model's units (s, or t₁ = ω_n t).
struct TimeResponseOptions {
  TimeIntegrator method = TimeIntegrator::kNewmark;
  NewmarkParameters newmark = NewmarkParameters::averageAcceleration();
  int steps_per_period = 256;  ///< Newmark steps per mesh period (multiple of output points)
  int output_points_per_period = 128;
  double relative_tolerance = 1e-9;   ///< Dormand–Prince
  double absolute_tolerance = 1e-15;  ///< Dormand–Prince, in units of x
  double newton_tolerance = 1e-14;    ///< Newmark Newton step, relative to the deflection scale
  int max_newton_iterations = 60;
  double steady_tolerance = 1e-7;  ///< max |x_n − x_{n−1}| over a period / (max |x| over it)
  int min_periods = 3;
  int max_periods = 2000;
  int output_periods = 4;  ///< periods returned once steady (or at the end)
  double initial_displacement = 0.0;
  double initial_velocity = 0.0;
  bool start_from_static = true;  ///< x(0) = static deflection F / k(0) + e(0), v(0) = 0
  /// Period of the response when the mesh frequency is 0 (LTI): the extra forces' period.
  double period = 0.0;
  ProgressCallback progress;  ///< called after every period with (periods, max_periods)

  void validate() const;
};

enum class TimeResponseStatus {
  kSteadyState,    ///< consecutive periods agree to steady_tolerance
  kMaxPeriods,     ///< still changing after max_periods (e.g. quasi-periodic or chaotic)
  kDiverged,       ///< unbounded growth (parametric instability) or non-finite values
  kNewtonFailure,  ///< a Newmark step's Newton iterations did not converge
};
std::string toString(TimeResponseStatus status);

struct TimeResponse {
  std::vector<double> t, x, v;  ///< samples of the returned periods [s], [m], [m/s]
  double period = 0.0;          ///< mesh period [s]
  TimeResponseStatus status = TimeResponseStatus::kSteadyState;
  int periods = 0;           ///< periods integrated
  double last_change = 0.0;  ///< relative change between the last two periods
  long long steps = 0;       ///< integrator steps (accepted)
  int max_newton_iterations = 0;
  long long newton_failures = 0;
  std::string message;  ///< one line for people
  bool converged() const { return status == TimeResponseStatus::kSteadyState; }
};

TimeResponse solveTimeResponse(const GearPairModel& model, const TimeResponseOptions& options);

/// Fixed-step Newmark over [t0, t0 + n h] from (x, v): the building block of solveTimeResponse,
/// exposed for order-of-accuracy tests. Returns the final state.
NewmarkState integrateNewmark(const GearPairModel& model, NewmarkParameters parameters, double t0,
                              double h, long long n, double x, double v, double newton_tolerance);

/// Dormand–Prince 5(4) over [t0, t1] from (x, v) with the given tolerances; returns {x, v}.
std::pair<double, double> integrateDormandPrince(const GearPairModel& model, double t0, double t1,
                                                 double x, double v, double rtol, double atol);

}  // namespace geardyn
