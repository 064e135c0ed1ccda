#pragma once
/// \file
/// Dormand–Prince 5(4) time integration of a linear gear train at constant input speed (issue
/// #31: "Dormand–Prince stays for smooth models"): the adaptive embedded Runge–Kutta pair of
/// Dormand & Prince (1980, J. Comput. Appl. Math. 6(1) 19–26), as Boost.Odeint's
/// runge_kutta_dopri5 with its dense output (the method of MATLAB's ode45 and scipy's RK45), on
///
///   M q̈ + (C + Ω G₁) q̇ + (K + Ω² K_Ω + Σ_m k_m(φ_m(t)) v_m v_mᵀ) q
///       = F₀ + Σ_m (k_m e_m + c_m ė_m) v_m + f_exc(t)
///
/// (the equation TrainNewmarkStepper integrates, train_time.h), from rest at t = 0. It suits
/// trains whose coefficients and forces are smooth in t (harmonic mesh stiffness and
/// transmission error, unbalances, runouts, prescribed bearing motions): its error control
/// then gives a stated accuracy where Newmark's fixed step gives a stated step.
///
/// Exactly reduced: a DOF that no force reaches through the nonzero pattern of M, C̄ and K̄
/// (connected components of their graph, seeded by the DOFs that F₀, a transmission error or an
/// excitation loads) stays at rest from rest, and is not integrated (e.g. the free rotations of
/// a lateral rotor). At constant speed the excitations are summed once per distinct order into
/// complex amplitudes F_k over the integrated DOFs, f_exc(t) = Σ_k Re[F_k e^{i ν_k |Ω| t}]
/// (train_excitation.h); a runout on a mesh, whose force follows that mesh's k(φ), is evaluated
/// at each t.
///
/// The state is scaled, s = (q / L, q̇ / (L ω)), with L a displacement scale and ω the highest
/// forcing frequency, so that one absolute tolerance means the same for displacements and
/// velocities (as a per-component atol = tol·(L, Lω) would in scipy's solve_ivp).

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "geardyn/progress.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {

struct TrainDormandPrinceOptions {
  double relative_tolerance = 1e-8;
  /// In units of L (displacements) and L ω (velocities).
  double absolute_tolerance = 1e-8;
  /// L [m]; 0: derived, the largest translation of the static deflection under F₀ and of the
  /// quasi-static response to each excitation order and transmission error (trainResponseScale).
  double displacement_scale = 0.0;
  /// ω [rad/s]; 0: derived, the highest excitation or mesh frequency (trainForcingFrequency).
  double velocity_frequency = 0.0;
  /// q(0) over all the model's DOFs [m, rad]; empty: rest. q̇(0) = 0.
  Eigen::VectorXd initial_displacement;
  /// Also hand q̇ [m/s, rad/s] and q̈ [m/s², rad/s²] of the observed DOFs to the observer (else
  /// they are empty).
  bool rates = false;
  /// (simulated time, end time) [s], about 100 times over the run.
  ProgressCallback progress;
  void validate() const;  ///< InputError naming time.relative_tolerance / absolute_tolerance
};

/// Receives sample i: q, and q̇, q̈ when TrainDormandPrinceOptions::rates (else empty).
using TrainDormandPrinceObserver =
    std::function<void(std::size_t i, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                       const Eigen::VectorXd& qddot)>;

/// What a run did.
struct TrainDormandPrinceRun {
  long long steps = 0;            ///< accepted steps
  long long rhs_evaluations = 0;  ///< right-hand side evaluations
  int integrated_dofs = 0;        ///< after the exact reduction (file comment)
  bool finite = true;             ///< false once a sample held NaN or Inf (the run stops there)
};

/// The derived L of TrainDormandPrinceOptions::displacement_scale for input speed Ω [m].
double trainResponseScale(const GearTrainModel& model, double input_speed);
/// The derived ω of TrainDormandPrinceOptions::velocity_frequency [rad/s].
double trainForcingFrequency(const GearTrainModel& model, double input_speed);

/// Integrates the train at input speed Ω [rad/s] from rest (or options.initial_displacement)
/// at t = 0 and calls observe(i, q, q̇, q̈) with q the displacements of `dofs` [m, rad] at
/// times[i] (finite, ≥ 0, increasing: InputError naming `times` otherwise). Trains with
/// nonlinear elements (backlash, clearances, rolling bearings given by geometry) are refused
/// (InputError naming the first).
TrainDormandPrinceRun integrateTrainDormandPrince(const GearTrainModel& model, double input_speed,
                                                  const std::vector<double>& times,
                                                  const std::vector<int>& dofs,
                                                  const TrainDormandPrinceOptions& options,
                                                  const TrainDormandPrinceObserver& observe);

}  // namespace geardyn
