#pragma once
/// \file
/// Static and periodic steady-state response of a gear train at a constant input speed.
///
/// Statics: (K + Ω² K_Ω + Σ k̄ v vᵀ) q = F₀ + Σ k̄ ē v, solved for the minimum-norm q when the
/// train has rigid-body modes (the loads are balanced: lossless torques), with the residual
/// checked; mesh forces, bearing forces, coupling torques and planet load sharing. With
/// bearings from their geometry (GearTrainModel::rollingBearings) it is a nonlinear system
/// deflection: K̄ q + Σ_b J_bᵀ F_b(J_b q) = F by Newton on all DOFs (meshes at their mean
/// stiffness), damped (Levenberg–Marquardt) where a bearing's contacts have no stiffness yet.
///
/// Steady state: the exact periodic solution of the linear time-periodic equations of
/// gear_train_model.h by harmonic balance over the train's common period. Every mesh
/// frequency is an integer multiple P_m of a base frequency f₀ (the greatest common divisor of
/// the mesh frequencies, from the tooth counts); with q(t) = Σ_{|h|≤H} X_h e^{i h ω₀ t},
///
///   [K + Ω²K_Ω + i h ω₀ (C + ΩG₁) − h²ω₀² M] X_h + Σ_m v_m v_mᵀ Σ_j k̂_{m,j} X_{h−j}
///       = F₀ δ_h0 + Σ_m v_m [(k e)^_{m,h} + i h ω₀ c_m ê_{m,h}],
/// (the mesh dashpot acts on the rate of the tooth deformation, (δ − e)˙, as in the SDOF model),
///
/// plus the excitations Re[F_e e^{i ν_e α}] of GearTrainModel::excitations() (unbalances,
/// runouts, prescribed bearing displacements: F_e/2 at h = ±P_e, a runout's k(φ) F_e at the
/// sidebands h = ±P_e + l P_m), where k̂_{m,j} = c_l e^{i 2π l φ_m0} for j = l P_m (c_l the Fourier
/// coefficients of k_m over one mesh period, exact for piecewise models), truncated at |l| <= L
/// mesh harmonics and |h| <= H = L max P_m. The time-invariant part is block-diagonal over
/// harmonics and the stiffness variation acts only through the mesh deflections δ_m = v_mᵀ q, so
/// the system is condensed exactly onto r (2H + 1) mesh-deflection harmonics (r meshes): per speed,
/// one n × n LU per harmonic and one dense solve of the condensed system. This is the linear case
/// of the harmonic balance (no AFT needed): the parametric excitation of the static load
/// through the stiffness variation and the transmission-error excitation are both in it.

#include <Eigen/Dense>
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "geardyn/system/gear_train_model.h"

namespace geardyn {
namespace detail {
struct HousingCondensation;
}  // namespace detail

struct TrainStageLoadSharing {
  std::string stage;
  std::vector<double> sun_planet_force, ring_planet_force;  ///< per planet [N]
  double load_sharing_factor = 1.0;                         ///< max sun–planet force / mean [-]
};

/// What an element transmits: the resultant of the forces of its displacement rows [N] and
/// of the moments of its rotation rows [N m] (TrainElement::moment_rows), each when it has such
/// rows.
struct ElementLoad {
  double force = 0.0;   ///< [N]
  double moment = 0.0;  ///< [N m]
  bool has_force = false, has_moment = false;
};

/// The load of `element` at its deformation d: |k d| over its force rows and its moment rows.
ElementLoad elementLoad(const TrainElement& element, const Eigen::VectorXd& local_force);

struct TrainStaticResult {
  Eigen::VectorXd displacement;    ///< q [m, rad]
  std::vector<double> mesh_force;  ///< k̄ (vᵀq − ē) along each line of action [N]
  /// Per element of model.elements(): its force and moment resultants.
  std::vector<ElementLoad> element_load;
  std::vector<TrainStageLoadSharing> load_sharing;
  int rigid_modes = 0;        ///< dimension of the null space of the stiffness
  double residual = 0.0;      ///< ‖K q − F‖ / ‖F‖
  std::string status = "ok";  ///< "ok", "unbalanced" (loads on a rigid-body mode), "max_iterations"
  std::string message;
  /// Bearings from their geometry, in model.rollingBearings() order: deflection, load,
  /// tangent stiffness, element loads, largest contact pressure, L10r.
  std::vector<RollingBearingState> rolling_bearings;
  int iterations = 0;  ///< Newton iterations (0: linear)
};

TrainStaticResult solveTrainStatic(const GearTrainModel& model, double input_speed);

struct TrainSteadyOptions {
  int mesh_harmonics = 10;  ///< L: harmonics of each mesh frequency kept (>= 1)
  /// H above which the common period is refused (memory and time grow with it): trains whose
  /// mesh frequencies have no small common divisor should use time integration.
  int max_base_harmonics = 4000;
  /// Samples of one base period for the time-domain quantities (mesh-force peaks); 0: derived
  /// (at least 8 per highest harmonic, a power of two).
  int samples = 0;
  /// DOF count from which the harmonic blocks are factorised sparse (Eigen::SparseLU) rather
  /// than dense; FE trains' banded matrices make that far cheaper (detail/harmonic_blocks.h).
  int sparse_dofs = 64;
  /// A flexible housing (GearTrainModel::housingFirstDof) is condensed out of each harmonic block
  /// exactly through its modes (detail/housing_condensation.h) rather than factorised with the
  /// train; false: the whole block (the reference the fast path is tested against).
  bool condense_housing = true;
  void validate() const;
};

/// The base frequency of a train per unit input speed and the multiples P_m of every mesh:
/// f_m = P_m f₀ [Hz per rad/s], and those of its excitations (GearTrainModel::excitations(),
/// e.g. an unbalance at a shaft's speed): |ν| |Ω| / 2π = P_e f₀. InputError (key
/// "steady.mesh_harmonics") when the mesh frequencies have no common divisor within
/// `max_base_harmonics` (key "steady.max_base_harmonics" when an excitation's order has none).
struct TrainBaseFrequency {
  double ratio = 0.0;                    ///< f₀ / |Ω| [Hz per rad/s]
  std::vector<int> mesh_multiple;        ///< P_m
  std::vector<int> excitation_multiple;  ///< P_e
};
TrainBaseFrequency trainBaseFrequency(const GearTrainModel& model, int mesh_harmonics,
                                      int max_base_harmonics);

struct TrainSteadyState {
  double input_speed = 0.0;     ///< Ω [rad/s]
  double base_frequency = 0.0;  ///< f₀ [Hz]
  int harmonics = 0;            ///< H
  std::vector<int> mesh_multiple;
  /// X_h for h = 0..H (column h); q(t) = Re[X_0 + 2 Σ_{h≥1} X_h e^{i h ω₀ t}]. A flexible
  /// housing's rows are all there unless solve() was asked for the rows its elements read only
  /// (then the others are zero).
  Eigen::MatrixXcd harmonic;
  /// The flexible housing's response points (GearTrainModel::spec().housing->reduced.points):
  /// displacement harmonics like `harmonic`'s, x, y, z of each point (3 P × (H + 1)) [m];
  /// empty without points.
  Eigen::MatrixXcd housing_points;
  /// One base period sampled: t [s], mesh forces k(φ)(vᵀq − e) [N] per mesh (rows: samples).
  Eigen::VectorXd t;
  Eigen::MatrixXd mesh_force;
  std::vector<double> mesh_force_mean, mesh_force_max, mesh_force_min;  ///< [N]
  /// Dynamic factor max F / mean F per mesh [-] (1 without dynamics).
  std::vector<double> dynamic_factor;
  /// Amplitude of the mesh force at harmonics 1..L of each mesh's own frequency [N].
  std::vector<std::vector<double>> mesh_force_harmonics;
  /// Peak dynamic force of each element over the period, |k d(t) − k d̄| max [N, N m].
  std::vector<double> element_dynamic_force;
  /// q(t) at the samples (rows: samples, cols: DOFs).
  Eigen::MatrixXd displacement(const Eigen::VectorXd& times) const;
};

/// The steady-state solver of one model: what does not depend on the speed (the base
/// frequency, the Fourier coefficients of every mesh's k and k·e, the rigid-body modes when no
/// centripetal term acts on them) is computed once, so a speed sweep pays one sparse LU per
/// speed. Thread-safe for concurrent solve() calls.
class TrainSteadySolver {
 public:
  TrainSteadySolver(const GearTrainModel& model, const TrainSteadyOptions& options = {});
  /// The steady state at `input_speed` [rad/s]. `housing_rows` false: of a condensed flexible
  /// housing only the rows the train's elements read (the bearing seats) and the response points
  /// are recovered, not every reduced coordinate of every harmonic (a forced sweep's saving,
  /// issue 37: one n_h × n_h product per speed).
  TrainSteadyState solve(double input_speed, bool housing_rows = true) const;
  const TrainBaseFrequency& base() const noexcept { return base_; }

 private:
  const GearTrainModel& model_;
  TrainSteadyOptions options_;
  TrainBaseFrequency base_;
  int harmonics_ = 0;
  // [mesh][L + l]: Fourier coefficient l of k_m and of k_m e_m, with the mesh phase applied.
  std::vector<std::vector<std::complex<double>>> k_hat_, ke_hat_, e_hat_;
  // Rigid-body modes of (K̄(0), M), valid at every speed when K_Ω does not act on them.
  Eigen::MatrixXd rigid_;
  Eigen::MatrixXd rigid_mass_;  // M R (n × k), empty without rigid-body modes
  bool rigid_at_every_speed_ = false;
  // A flexible housing's exact condensation (detail/housing_condensation.h); null: none.
  std::shared_ptr<const detail::HousingCondensation> housing_;
  // Its rows the train's elements read, as DOFs of the train (n_t + HousingCondensation's).
  std::vector<Eigen::Index> housing_read_dofs_;
};

/// One speed: TrainSteadySolver(model, options).solve(input_speed).
TrainSteadyState solveTrainSteadyState(const GearTrainModel& model, double input_speed,
                                       const TrainSteadyOptions& options = {});

}  // namespace geardyn
