#pragma once
/// \file
/// A train's periodic steady state recorded from rest by Dormand–Prince (train_dormand_prince.h)
/// on a uniform grid, the way a measurement or Rao's thesis (2023, §4.2: ode45 over 15 s, 2¹⁵
/// samples) records it: the end of the transient is detected by comparing the response with
/// itself one common period T_c later, and the steady window is a whole number of common
/// periods, so that every component of the full spectrum falls on an FFT bin.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "geardyn/solvers/train_dormand_prince.h"

namespace geardyn {

struct TrainRecordOptions {
  double duration = 15.0;     ///< [s] (thesis §4.2: 15 s)
  long long samples = 32768;  ///< requested samples over the duration (thesis: 2¹⁵)
  /// Snap the sample interval so that one common period holds a whole number of samples
  /// (exact FFT bins for every component); false keeps duration/(samples − 1) as linspace does.
  bool align_to_common_period = true;
  double steady_tolerance = 1e-6;  ///< |q(t + T_c) − q(t)| ≤ tol · max|q| marks steady state
  /// Tolerances, scales and progress (simulated time, duration) [s] of the integration.
  TrainDormandPrinceOptions integrator;

  void validate() const;  ///< InputError naming time.duration, time.samples, ...
};

enum class TrainRecordStatus {
  kSteadyState,  ///< the transient decayed and at least one common period follows it
  kTransient,    ///< the record ends before a whole steady common period
  kNonFinite,    ///< the integration produced NaN or Inf
};
std::string toString(TrainRecordStatus status);

struct TrainRecord {
  std::vector<double> t;             ///< [s], uniform
  Eigen::MatrixXd displacement;      ///< rows: samples, columns: the recorded DOFs [m, rad]
  double sample_rate = 0.0;          ///< [Hz]
  double common_period = 0.0;        ///< [s]
  long long samples_per_period = 0;  ///< per common period (0 when not aligned)
  long long transient_end = 0;       ///< first steady sample
  long long window_begin = 0;        ///< the steady window [window_begin, window_end)
  long long window_end = 0;          ///<   holds `window_periods` common periods
  int window_periods = 0;
  long long steps = 0;  ///< accepted Dormand–Prince steps
  long long rhs_evaluations = 0;
  TrainRecordStatus status = TrainRecordStatus::kSteadyState;
  std::string message;
  bool converged() const { return status == TrainRecordStatus::kSteadyState; }
};

/// Records the DOFs `dofs` of the train at input speed Ω [rad/s] from rest at t = 0, with the
/// steady state's common period T_c [s] (> 0).
TrainRecord recordTrainFromRest(const GearTrainModel& model, double input_speed,
                                const std::vector<int>& dofs, double common_period,
                                const TrainRecordOptions& options);

}  // namespace geardyn
