#pragma once
/// \file
/// Newmark time integration of a gear train with nonlinear meshes (contact loss, backlash;
/// TrainMeshContact) and bearings with radial clearance (bearing_clearance.h: their correction
/// f(u) − k u on u = J q joins the meshes' f̃, V gains their columns, Newton runs on δ and every
/// bearing's (u_y, u_z) with the coupled 2 × 2 Jacobian) to its periodic steady state — the
/// reference for the train harmonic balance (train_harmonic_balance.h):
///
///   M q̈ + (C + Ω G₁) q̇ + K̄ q + Σ_m v_m f̃_m(t, δ_m) = F₀ + Σ_m c_m ė_m v_m,
///   f̃_m = k_m(φ_m) g_m(δ_m − e_m) − k̄_m δ_m,   δ_m = v_mᵀ q,
///
/// with K̄ = K + Ω² K_Ω + Σ k̄ v vᵀ (the mean meshes), g_m the contact law and the mesh dashpots
/// in C acting on (δ − e)˙ as in the linear model (and in the 1-DOF gear-pair model).
///
/// A step solves A q + V f̃(t, Vᵀq) = b with the constant A = K̄ + a₀ M + a₁ (C + ΩG₁)
/// factorised once: q = y − Z f̃(δ), y = A⁻¹ b, Z = A⁻¹ V, so Newton runs on the r mesh
/// deflections only, δ − Vᵀ y + W f̃(t, δ) = 0 with W = Vᵀ Z (r × r, exact condensation). The
/// contact law is piecewise linear: once the contact state of every mesh is right Newton ends
/// in one step. Contact events are not located within a step: the error is first order in the
/// step at an event, so the step is fine (512 a mesh period by default).

#include <Eigen/Dense>
#include <string>

#include "geardyn/solvers/newmark.h"
#include "geardyn/system/gear_train_model.h"
#include "geardyn/system/train_tooth_pairs.h"

namespace geardyn {

struct TrainNonlinearTimeOptions {
  NewmarkParameters newmark = NewmarkParameters::averageAcceleration();
  int steps_per_mesh_period = 512;  ///< of the fastest mesh (whole steps per common period)
  int min_periods = 3;              ///< common periods before the steady-state test
  int max_periods = 20000;
  /// Steady when no mesh deflection changes by more than this times its largest |δ| between
  /// consecutive common periods [-].
  double steady_tolerance = 1e-9;
  double newton_tolerance = 1e-13;  ///< |Δδ| / max |δ| ending Newton [-]
  int max_newton_iterations = 50;
  void validate() const;
};

struct TrainNonlinearTimeResponse {
  Eigen::VectorXd t;                ///< the last common period's step times [s]
  Eigen::MatrixXd displacement;     ///< q at those times (rows: samples, cols: DOFs)
  Eigen::MatrixXd mesh_deflection;  ///< δ_m (rows: samples, cols: meshes) [m]
  Eigen::MatrixXd mesh_force;  ///< k g(δ − e); tooth pairs: Σ_j k_j max(0, δ − e − g_j) [N]
  /// (u_y, u_z) of every clearance bearing (cols: y then z of bearing 0, 1, …) [m].
  Eigen::MatrixXd bearing_displacement;
  double period = 0.0;       ///< common period [s]
  int periods = 0;           ///< common periods integrated
  double last_change = 0.0;  ///< relative change over the last period
  long long steps = 0;
  /// "steady_state", "max_periods" (still changing: quasi-periodic, chaotic or slow),
  /// "newton_failure" or "diverged".
  std::string status = "steady_state";
  std::string message;
  /// Peak to peak of mesh m's deflection over the last period [m].
  double meshPeakToPeak(int mesh) const;
  /// Peak to peak of clearance bearing b's radial displacement |u| over the last period [m].
  double bearingRadialPeakToPeak(int bearing) const;
};

/// One step at a time (the building block, and for benchmarks).
class TrainNonlinearNewmark {
 public:
  TrainNonlinearNewmark(const GearTrainModel& model, double input_speed, double time_step,
                        NewmarkParameters newmark);
  void reset(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot);
  /// One step; false when Newton on the mesh deflections failed.
  bool step(double newton_tolerance, int max_iterations);
  double time() const noexcept { return t_; }
  const Eigen::VectorXd& displacement() const noexcept { return q_; }
  /// The nonlinear coordinates: the mesh deflections δ, then (u_y, u_z) of every clearance
  /// bearing [m].
  const Eigen::VectorXd& coordinates() const noexcept { return delta_; }
  /// f̃ = k g(δ − e) − k̄ δ of every mesh at the time of the last meshState, then f(u) − k u of
  /// every clearance bearing; ∂f̃/∂(δ, u) (block diagonal; only its blocks written) in *slope.
  void nonlinearForces(const Eigen::VectorXd& delta, Eigen::VectorXd& f,
                       Eigen::MatrixXd* slope) const;

 private:
  void meshState(double t);  // k, e and c ė of every mesh at t

  const GearTrainModel& model_;
  double speed_, dt_, gamma_, t_ = 0.0;
  NewmarkCoefficients nm_;
  int meshes_ = 0;
  Eigen::MatrixXd Cg_, K0_, V_, Z_, W_, J_, slope_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_, small_;
  Eigen::VectorXd q_, v_, a_, rhs_, y_, delta_, f_, res_, dashpot_, k_, e_, free_, step_;
  std::vector<ToothPairTable> tooth_pairs_;  // per mesh at the last meshState (one sample)
};

/// Integrates from (q0, v0) (empty: the mean static deflection at rest) until the mesh
/// deflections repeat over a common period.
TrainNonlinearTimeResponse solveTrainNonlinearTime(const GearTrainModel& model, double input_speed,
                                                   const TrainNonlinearTimeOptions& options,
                                                   const Eigen::VectorXd& q0 = {},
                                                   const Eigen::VectorXd& v0 = {});

}  // namespace geardyn
