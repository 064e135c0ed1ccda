#pragma once
/// \file
/// Newmark time integration of a gear train at constant input speed with the time-varying
/// stiffness of every mesh:
///
///   M q̈ + (C + Ω G₁) q̇ + (K + Ω² K_Ω + Σ_m k_m(φ_m(t)) v_m v_mᵀ) q
///       = F₀ + Σ_m (k_m e_m + c_m ė_m) v_m
/// (the mesh dashpot acts on the rate of the tooth deformation (δ − e)˙, as in the SDOF model).
///
/// Cost: the effective matrix A = K̄ + a₀ M + a₁ (C + Ω G₁) (K̄ with the mean meshes) is
/// factorised once; the r meshes vary it by V D(t) Vᵀ with D = diag(k_m(t) − k̄_m), which the
/// Woodbury identity solves with the precomputed Z = A⁻¹ V and one r × r system per step
/// (the model's excitations, GearTrainModel::excitations(), are added to f(t) at every step):
///   x = y − Z (I + D Vᵀ Z)⁻¹ D Vᵀ y,   y = A⁻¹ b.
/// A step is one back-substitution, a few matrix–vector products and an r × r LU, and allocates
/// nothing: small trains use dense matrices; from kSparseTrainDofs DOFs on (flexible shafts)
/// M, C + ΩG₁ and A are sparse and A is factorised by Eigen's SparseLU, whose factors are
/// solved with in a preallocated vector (detail::SparseLuFactors).
///
/// Along a speed ramp (TrainSpeedRamp: a run-up or run-down, train_runup.h) the input speed
/// Ω(t) is prescribed and the DOFs stay vibrations about the rigid rotation it implies: every
/// mesh phase is φ_m(t) = (f_m/|Ω|) ∫₀ᵗ |Ω| dτ + φ_m0 (exact for the linear ramp) and ė uses
/// the speed at t. The speed-dependent matrices Ω G₁ and Ω² K_Ω (and with them A, Z and W) are
/// refactorised when the speed has moved by more than `speed_tolerance` × the ramp's largest
/// |Ω| since the last factorisation (the FE rotor's gyroscopic term likewise): G₁ is
/// then within that relative tolerance of its exact value and K_Ω within twice it. Trains
/// without G₁ and K_Ω (fixed-axis lumped trains) are never refactorised. Dense refactorisation
/// allocates nothing; the sparse path's (SparseLU's pattern analysis) allocates, the steps
/// between do not.

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geardyn/numerics/sparse_lu_factors.h"
#include "geardyn/progress.h"
#include "geardyn/solvers/newmark.h"
#include "geardyn/solvers/train_transient.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {

/// How `time` integrates: Newmark's fixed step (any train), or Dormand–Prince's error control
/// (linear trains; train_dormand_prince.h) sampled at the same times.
enum class TrainTimeMethod { kNewmark, kDormandPrince };

struct TrainTimeOptions {
  TrainTimeMethod method = TrainTimeMethod::kNewmark;
  /// Dormand–Prince's relative tolerance (and absolute, in units of the response scale).
  double relative_tolerance = 1e-8;
  NewmarkParameters newmark = NewmarkParameters::averageAcceleration();
  double time_step = 0.0;  ///< Δt [s]; 0: the fastest mesh period / steps_per_mesh_period
  int steps_per_mesh_period = 128;
  double duration = 0.0;  ///< [s]; 0: derived (transient decay + `record_periods`)
  /// Common periods recorded at the end (the steady-state window).
  int record_periods = 1;
  bool start_from_static = true;  ///< q(0) from the mean static deflection, else rest
  /// Also record q̇ and q̈ at every recorded step (simulated velocity/acceleration probes, and
  /// the cubic Hermite interpolation of q between steps).
  bool record_rates = false;
  void validate() const;
};

struct TrainTimeResponse {
  Eigen::VectorXd t;             ///< recorded times [s]
  Eigen::MatrixXd displacement;  ///< rows: recorded samples, cols: DOFs
  /// q̇ [m/s, rad/s] and q̈ [m/s², rad/s²] like `displacement` (TrainTimeOptions::record_rates;
  /// else empty).
  Eigen::MatrixXd velocity, acceleration;
  Eigen::MatrixXd mesh_force;  ///< rows: samples, cols: meshes [N]
  double time_step = 0.0;      ///< Newmark's Δt, the record's sample interval [s]
  long long steps = 0;         ///< steps of Δt up to the record's end
  /// Dormand–Prince's accepted (adaptive) steps (TrainTimeMethod::kDormandPrince; else 0).
  long long integrator_steps = 0;
  std::string status = "completed";  ///< or "diverged"
  std::string message;
  /// The transient estimate the derived duration came from (TrainTimeOptions::duration = 0).
  std::optional<TrainTransient> transient;
};

/// DOF count from which the Newmark stepper works with sparse matrices.
inline constexpr int kSparseTrainDofs = 64;

/// A prescribed input speed: Ω(t) = Ω₀ for t <= t₀, Ω₀ + (Ω₁ − Ω₀) (t − t₀) / T for
/// t₀ <= t <= t₀ + T, Ω₁ after [rad/s]. Ω₀ and Ω₁ have the same sign (or one is 0): the train
/// does not reverse.
struct TrainSpeedRamp {
  double start = 0.0;     ///< Ω₀ [rad/s]
  double end = 0.0;       ///< Ω₁ [rad/s]
  double duration = 0.0;  ///< T [s] (> 0)
  double begin = 0.0;     ///< t₀ [s] (>= 0): the ramp starts here, Ω₀ before
  void validate() const;  ///< InputError naming runup.speed_*_rpm / runup.duration
  double speed(double t) const noexcept;
  /// ∫₀ᵗ |Ω| dτ [rad]: the input shaft's rotation, exact for the ramp.
  double angle(double t) const noexcept;
  double maxSpeed() const noexcept { return std::max(std::abs(start), std::abs(end)); }
};

/// Relative speed change that triggers refactorisation along a ramp (TrainNewmarkStepper).
inline constexpr double kTrainSpeedTolerance = 1e-3;

/// What a TrainNewmarkStepper integrates beside the train's own description (all optional).
struct TrainStepperSetup {
  /// The DOFs integrated, in the order of the stepper's state vectors; every other DOF is held
  /// at zero (a constraint: exact for DOFs nothing couples to the rest, such as the axial DOFs
  /// of a spur train, and the clamped axial DOFs of a rotor model without them). Empty: all.
  std::vector<int> dofs;
  /// The constant load over the integrated DOFs instead of the train's F₀ [N, N m]; empty: F₀.
  Eigen::VectorXd static_load;
  /// f(t) added to the loads at every step and at reset (over the integrated DOFs; `f` comes
  /// zeroed and must not be resized) [N, N m]; empty: none. Must not allocate.
  std::function<void(double t, Eigen::Ref<Eigen::VectorXd> f)> force;
};

/// One Newmark step at a time (for benchmarks, and the building block of the solvers).
///
/// Dense path: once 4n steps have run on the same factors (a fast path chosen automatically:
/// computing the products costs about 100 plain steps of the 60-DOF rotor, which ~2n faster
/// steps pay back, so a run-up that refactorises every ~100 steps keeps the plain step), the
/// step's solve is the product with
/// the precomputed [A⁻¹M  A⁻¹(C + ΩG₁)] (n × 2n) plus A⁻¹F₀ and Z ke: 2n² instead of two
/// products and two triangular solves (4n²). With one mesh the Woodbury correction is
/// Sherman–Morrison, with no r × r factorisation. bench/fe_rotor_bench.cpp has the timings.
class TrainNewmarkStepper {
 public:
  /// `sparse`: force the sparse (true) or dense (false) path; absent: sparse from
  /// kSparseTrainDofs DOFs on.
  TrainNewmarkStepper(const GearTrainModel& model, double input_speed, double time_step,
                      NewmarkParameters newmark, std::optional<bool> sparse = std::nullopt,
                      TrainStepperSetup setup = {});
  /// Along a speed ramp; `speed_tolerance` in (0, 1) (see the file comment).
  TrainNewmarkStepper(const GearTrainModel& model, const TrainSpeedRamp& ramp, double time_step,
                      NewmarkParameters newmark, double speed_tolerance = kTrainSpeedTolerance,
                      std::optional<bool> sparse = std::nullopt, TrainStepperSetup setup = {});
  /// Sets the state at time t (over the integrated DOFs) and the consistent acceleration.
  void reset(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot);
  void step();  ///< allocation-free (the force callback too)
  double time() const noexcept { return t_; }
  /// The input speed Ω at the current time [rad/s].
  double speed() const noexcept { return speed_; }
  /// The state over the integrated DOFs (TrainStepperSetup::dofs; all by default).
  const Eigen::VectorXd& displacement() const noexcept { return q_; }
  const Eigen::VectorXd& velocity() const noexcept { return v_; }
  const Eigen::VectorXd& acceleration() const noexcept { return a_; }
  /// k_m(φ_m)(v_mᵀ q − e_m(φ_m)) [N] at the current state.
  double meshForce(int mesh) const;
  /// k_m(φ_m) [N/m] at the current time.
  double meshStiffness(int mesh) const { return k_(mesh); }
  /// The static deflection under the constant loads (F₀ or TrainStepperSetup::static_load, not
  /// the time-dependent force) with every mesh's stiffness and transmission error at its phase
  /// at t (minimum norm: rigid-body modes left at zero); over the integrated DOFs. Allocates.
  Eigen::VectorXd staticDeflection(double t);
  /// Factorisations of the Newmark matrix so far (1 at constant speed).
  int factorisations() const noexcept { return factorisations_; }
  int dofCount() const noexcept { return static_cast<int>(q_.size()); }

 private:
  void meshState(double t);  // fills dk_ (k − k̄) and ke_ (k e + c ė) of every mesh at t
  /// fx_ = the setup's force plus the model's excitations at t (after meshState(t)).
  void externalForce(double t);
  void factorise(double speed);
  void precomputeProducts();
  void restrict(const std::vector<int>& dofs);

  const GearTrainModel& model_;
  std::optional<TrainSpeedRamp> ramp_;
  double speed_, dt_, gamma_, t_ = 0.0;
  double tolerance_ = kTrainSpeedTolerance, speed_factorised_ = 0.0;
  int factorisations_ = 0;
  bool speed_dependent_ = false;  // G₁ or K_Ω nonzero
  NewmarkCoefficients nm_;
  bool sparse_ = false;
  // The train's matrices over the integrated DOFs: the model's own, or restricted copies.
  bool restricted_ = false;
  Eigen::MatrixXd Mr_, Kr_, Cr_, Gr_, Kcr_, Kmeshr_;
  const Eigen::MatrixXd& M() const { return restricted_ ? Mr_ : model_.mass(); }
  const Eigen::MatrixXd& K() const { return restricted_ ? Kr_ : model_.stiffness(); }
  const Eigen::MatrixXd& C() const { return restricted_ ? Cr_ : model_.damping(); }
  const Eigen::MatrixXd& G() const { return restricted_ ? Gr_ : model_.gyroscopic(); }
  const Eigen::MatrixXd& Kc() const { return restricted_ ? Kcr_ : model_.centripetal(); }
  const Eigen::MatrixXd& Kmesh() const {
    return restricted_ ? Kmeshr_ : model_.meanMeshStiffness();
  }
  Eigen::VectorXd F0_;
  std::function<void(double, Eigen::Ref<Eigen::VectorXd>)> force_;
  bool external_ = false;       // force_ or the model's excitations (unbalances, ...)
  std::vector<int> dofs_;       // the integrated DOFs when restricted
  Eigen::VectorXd excitation_;  // the excitations over all the model's DOFs
  Eigen::MatrixXd Cg_, K0_, A_, V_, Z_, S_, small_matrix_;
  Eigen::MatrixXd PQ_;       // dense path: [A⁻¹M  A⁻¹(C + ΩG₁)], n × 2n
  Eigen::VectorXd g0_, pc_;  // dense path: A⁻¹F₀; the step's [p; c]
  bool products_ = false;    // PQ_ and g0_ are those of the current factors
  Eigen::Index steps_on_factors_ = 0;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_, small_;
  Eigen::SparseMatrix<double> Msp_, Cgsp_;
  detail::SparseLuFactors slu_;
  Eigen::VectorXd q_, v_, a_, f_, fx_, rhs_, y_, w_, w_solved_, dk_, ke_, k_, e_;
};

/// Steps beyond which a time run is refused (InputError naming time.duration).
inline constexpr long long kMaxTrainTimeSteps = 200000000LL;

/// What a time run will do, before it allocates: the step (whole steps per common period), the
/// duration (derived from the transient when TrainTimeOptions::duration = 0) and the steps.
struct TrainTimePlan {
  double period = 0.0;     ///< the common period of the meshes [s]
  double time_step = 0.0;  ///< Δt [s]
  long long steps_per_period = 0;
  double duration = 0.0;  ///< [s]; +inf when a mode the meshes excite has no damping
  long long steps = 0;    ///< saturates at the largest long long
  std::optional<TrainTransient> transient;  ///< when the duration is derived
};
TrainTimePlan planTrainTimeResponse(const GearTrainModel& model, double input_speed,
                                    const TrainTimeOptions& options);

/// The run `plan` describes (InputError when it has no finite duration or more than
/// kMaxTrainTimeSteps steps). `progress` (steps done, all) is called once per common period.
TrainTimeResponse solveTrainTimeResponse(const GearTrainModel& model, double input_speed,
                                         const TrainTimeOptions& options, const TrainTimePlan& plan,
                                         const ProgressCallback& progress = {});
/// planTrainTimeResponse, then the run.
TrainTimeResponse solveTrainTimeResponse(const GearTrainModel& model, double input_speed,
                                         const TrainTimeOptions& options,
                                         const ProgressCallback& progress = {});

}  // namespace geardyn
