#pragma once
/// \file
/// Time response of the finite-element geared rotor (Visnadi 2021 §4: Newmark γ = 1/2,
/// β = 1/4, Δt = 1e-5 s) with the mesh stiffness updated at every step, at constant speed or
/// along a speed profile (run-up / run-down: mesh angle integrated from the speed).
///
/// There is no FE-rotor stepper: the rotor is its gear train (system/fe_rotor_model.h),
/// integrated by the train's TrainNewmarkStepper (train_time.h) over the FE rotor's own DOFs
/// (TrainStepperSetup::dofs: the axial DOFs a rotor without `axial` lacks are held at zero),
/// with the FE rotor's own load vector (TrainStepperSetup::static_load: drive and load torques,
/// the disks' weight) and the train's unbalances as its excitation. The train's
/// mesh dashpot acts on (δ − e)˙, so with a transmission error and mesh damping the force
/// includes c_m ė (docs/theory/fe_geared_rotor.md).

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "geardyn/progress.h"
#include "geardyn/solvers/newmark.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/system/fe_rotor_model.h"

namespace geardyn {

struct FeTimeOptions {
  NewmarkParameters newmark = NewmarkParameters::averageAcceleration();
  double time_step = 1e-5;             ///< Δt [s]
  double duration = 0.5;               ///< [s]
  double gyro_speed_tolerance = 1e-3;  ///< relative speed change that triggers refactorisation
  int record_every = 1;                ///< record one step in this many
  std::vector<int> channels;           ///< active DOFs to record; empty: all
  /// q(0) from the static equilibrium at t = 0 (mesh stiffness and loads at t = 0) instead of
  /// rest; the minimum-norm solution leaves the rolling rigid-body mode at zero.
  bool start_from_static = false;
  ProgressCallback progress;  ///< (steps done, steps) every 1000 steps
  void validate() const;
};

enum class FeTimeStatus { kCompleted, kDiverged };
std::string toString(FeTimeStatus status);

struct FeTimeResponse {
  std::vector<int> channels;                             ///< recorded active DOFs
  std::vector<double> t;                                 ///< [s]
  std::vector<double> speed;                             ///< pinion speed [rad/s]
  std::vector<double> mesh_stiffness;                    ///< k_m at t [N/m]
  std::vector<double> mesh_force;                        ///< k_m (vᵀq − e) [N]
  Eigen::MatrixXd displacement, velocity, acceleration;  ///< rows: samples, cols: channels
  long long steps = 0;
  int factorisations = 0;
  FeTimeStatus status = FeTimeStatus::kCompleted;
  std::string message;
  bool converged() const { return status == FeTimeStatus::kCompleted; }
};

/// The train's Newmark stepper over the rotor's DOFs (its state in the rotor's DOF order) with
/// the rotor's loads, at its speed profile; the train's unbalances are its own excitation. One
/// step at a time: the building block of solveFeRotorTimeResponse, for benchmarks and tests.
TrainNewmarkStepper feRotorStepper(const FeRotorModel& model, const FeTimeOptions& options);

/// Integrates from t = 0 to `duration`, recording every `record_every` steps (t = 0 included).
FeTimeResponse solveFeRotorTimeResponse(const FeRotorModel& model, const FeTimeOptions& options);

}  // namespace geardyn
