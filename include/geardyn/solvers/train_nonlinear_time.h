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
/// in one step.
///
/// Events. Where the force jumps in time inside a step (a mesh stiffness k(φ) with jumps:
/// MeshStiffness::discontinuities; a tooth pair in contact entering or leaving the path of
/// contact) the trapezoidal rule's local error is O(Δt) and fixed steps are first order. Where a
/// contact changes state (a mesh's tooth deformation crosses 0 or −j, a tooth-pair element's
/// y − g_j crosses 0, a journal reaches its clearance) only the force's slope jumps: the local
/// error is O(Δt²) times the jump at a bounded number of steps a period, and fixed steps stay
/// second order. A step with such an event is taken again as two half steps, recursively, down
/// to Δt / 2^event_refinement (jumps) or Δt / 2^contact_refinement (contact changes): bisection
/// brackets the event (Dieci & Lopez 2012 survey this and the alternatives for discontinuous
/// right-hand sides), so its error falls by 2^levels (jumps) or 4^levels (kinks). Every step
/// size's factorisation (A, Z, W) is built once (for jumps only if some mesh's k(φ) jumps or
/// has tooth pairs): a refined step allocates and factorises nothing. Measured in
/// docs/theory/nonlinear_gear_trains.md.

#include <Eigen/Dense>
#include <string>

#include "geardyn/solvers/newmark.h"
#include "geardyn/system/bearing_law.h"
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
  /// Halvings of a step in which the force jumps: a mesh stiffness k(φ) jumps, a tooth pair in
  /// contact enters or leaves the path of contact (0: fixed steps; at most kMaxEventRefinement,
  /// and steps_per_mesh_period × 2^refinement at most 2^kMaxFinestStepsLog2).
  int event_refinement = 6;
  /// Halvings of a step in which a contact changes state. Only the force's slope jumps there:
  /// fixed steps stay second order, and refining changed the errors by 0.67–1.8× either way
  /// for 2–16 % more steps (2 levels; helical tooth pairs in 20 slices: 1.3–2×), so 0.
  int contact_refinement = 0;
  static constexpr int kMaxEventRefinement = 8;
  static constexpr int kMaxFinestStepsLog2 = 19;
  void validate() const;
};

struct TrainNonlinearTimeResponse {
  Eigen::VectorXd t;                ///< the last common period's step times [s]
  Eigen::MatrixXd displacement;     ///< q at those times (rows: samples, cols: DOFs)
  Eigen::MatrixXd mesh_deflection;  ///< δ_m (rows: samples, cols: meshes) [m]
  Eigen::MatrixXd mesh_force;  ///< k g(δ − e); tooth pairs: Σ_j k_j max(0, δ − e − g_j) [N]
  /// (u_y, u_z) of every clearance bearing (cols: y then z of bearing 0, 1, …; a full-DOF
  /// rolling bearing's radial pair) [m].
  Eigen::MatrixXd bearing_displacement;
  double period = 0.0;       ///< common period [s]
  int periods = 0;           ///< common periods integrated
  double last_change = 0.0;  ///< relative change over the last period
  long long steps = 0;
  long long refined_steps = 0;  ///< steps taken again in halves at events (all levels)
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
  /// `event_refinement`, `contact_refinement`: halvings of a step at a jump of the force and at
  /// a contact change (TrainNonlinearTimeOptions).
  TrainNonlinearNewmark(const GearTrainModel& model, double input_speed, double time_step,
                        NewmarkParameters newmark, int event_refinement = 0,
                        int contact_refinement = 0);
  void reset(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot);
  /// One step of time_step (in halves where an event falls); false when Newton on the mesh
  /// deflections failed.
  bool step(double newton_tolerance, int max_iterations);
  double time() const noexcept { return t_; }
  /// Steps taken again in halves since construction (all levels).
  long long refinedSteps() const noexcept { return refined_; }
  const Eigen::VectorXd& displacement() const noexcept { return q_; }
  const Eigen::VectorXd& velocity() const noexcept { return v_; }
  const Eigen::VectorXd& acceleration() const noexcept { return a_; }
  /// Mesh m's force k g(δ − e) (tooth pairs: Σ_j k_j max(0, δ − e − g_j)) at the last step [N].
  double meshForce(int mesh) const;
  /// The nonlinear coordinates: the mesh deflections δ, then (u_y, u_z) of every clearance
  /// bearing (a full-DOF rolling bearing: its five (u_y, u_z, u_x, θ_y, θ_z)) [m, rad].
  const Eigen::VectorXd& coordinates() const noexcept { return delta_; }
  /// f̃ = k g(δ − e) − k̄ δ of every mesh at the time of the last meshState, then f(u) − k u of
  /// every clearance bearing; ∂f̃/∂(δ, u) (block diagonal; only its blocks written) in *slope.
  void nonlinearForces(const Eigen::VectorXd& delta, Eigen::VectorXd& f,
                       Eigen::MatrixXd* slope) const;

 private:
  /// A step size's Newmark coefficients and factorisation: A = K̄ + a₀M + a₁(C + ΩG₁),
  /// Z = A⁻¹V, W = VᵀZ.
  struct Level {
    double dt = 0.0;
    NewmarkCoefficients nm;
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
    Eigen::MatrixXd Z, W;
  };
  /// The state before a step at some level, to take it again in halves.
  struct Saved {
    double t = 0.0;
    Eigen::VectorXd q, v, a, delta;
    std::vector<long long> events;
  };
  void meshState(double t);  // k, e and c ė of every mesh at t
  bool advance(int level, double newton_tolerance, int max_iterations);
  bool trial(const Level& level, double newton_tolerance, int max_iterations);
  // The discrete state whose change marks an event, at (t_, δ) after meshState(t_): per mesh
  // its contact region and its stiffness segment (tooth pairs: the contact and engaged sets),
  // per clearance bearing whether the journal touches.
  void eventState(std::vector<long long>& out) const;
  // The levels a step from `before` to `after` must be refined to (0: none).
  int refinementBetween(const std::vector<long long>& before,
                        const std::vector<long long>& after) const;

  const GearTrainModel& model_;
  double speed_, gamma_, t_ = 0.0;
  int meshes_ = 0, jump_levels_ = 0, contact_levels_ = 0;
  std::vector<TrainBearingLaw> laws_;  // per clearance bearing: its law (bearing_law.h)
  std::vector<int> bearing_first_;     // per clearance bearing: its first nonlinear coordinate
  long long refined_ = 0;
  std::vector<Level> levels_;                // time_step / 2^l
  std::vector<Saved> saved_;                 // per level but the finest
  std::vector<std::vector<double>> breaks_;  // per mesh: stiffness jumps in [0, 1)
  std::vector<long long> events_;
  Eigen::MatrixXd Cg_, K0_, V_, J_, slope_;
  Eigen::PartialPivLU<Eigen::MatrixXd> small_;
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
