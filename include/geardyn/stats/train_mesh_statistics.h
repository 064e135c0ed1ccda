#pragma once
/// \file
/// Gelman, Giurgiutiu & Bayoumi's (2005) mean-excitation statistics at every mesh of a gear
/// train, and the statistics of each mesh's dynamic force and transmission error from a time
/// run (docs/theory/dynamics.md, "Mean excitation at a train mesh").
///
/// Mesh m of a train is Gelman's eq. 1 with its own quantities: K(t) = k_m(φ_m(t)) [N/m], the
/// gear error E(t) = e_m(φ_m(t)) [m], the transmitted mean load F = F_m, the mesh's static force
/// along its line of action [N] (solveTrainStatic), the equivalent mass m_e of its two rotations
/// [kg] (TrainMesh::equivalent_mass) and its dashpot c_m [N s/m]. R_m = L_d / a (eqs. 5–7) with
/// k = K/K̄, e_f = E/x₀ + a/k, x₀ = F₀/K̄, a = F_m/F₀ (eqs. 2–3, 6): the pair's
/// meanExcitationFromModel on that SDOF pair, so that a one-pair torsional train gives exactly
/// `geardyn stats`'s numbers. Since m₁(ė) = 0 over a period (eq. 14), R_m = 1 + m₁(K E)/F_m
/// whatever the baseload F₀.

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "geardyn/solvers/train_time.h"
#include "geardyn/stats/mean_excitation.h"
#include "geardyn/system/gear_pair_model.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {

/// Mean, RMS, standard deviation and extremes of a sampled record (in the record's unit).
struct RecordStatistics {
  double mean = 0.0, rms = 0.0, std = 0.0, min = 0.0, max = 0.0;
  double peakToPeak() const noexcept { return max - min; }
};
/// Of equally weighted samples (a record over whole periods); all zero when empty.
RecordStatistics recordStatistics(const Eigen::Ref<const Eigen::VectorXd>& values);

/// The SDOF gear pair (Gelman eq. 1) of train mesh `mesh` at input speed Ω [rad/s]: m = m_e,
/// c = c_m, F = `static_force` [N], k(φ), e(φ) and f_m = frequency_ratio |Ω| [Hz]. For a
/// one-pair torsional train it is the pair of the train's SDOF reduction (TrainReduction test).
GearPairModelSpec meshPairSpec(const TrainMesh& mesh, double static_force, double input_speed);

/// Statistics of one mesh of a train.
struct TrainMeshStatistics {
  std::string mesh;
  double static_force = 0.0;  ///< F_m along the line of action [N]
  double baseload = 0.0;      ///< F₀ [N] (Gelman's baseload; the design load)
  /// Gelman's statistics; absent when F_m <= 0 (no load, or the mesh's other flank loaded by a
  /// reversed torque): R, a ratio to the transmitted load, is then undefined.
  std::optional<MeanExcitation> excitation;
  RecordStatistics force;  ///< elastic mesh force k(φ)(vᵀq − e(φ)) [N]
  RecordStatistics dte;    ///< dynamic transmission error δ = vᵀq along the line of action [m]
  double dynamic_factor = 0.0;  ///< max |F| / F_m [-] (0 when F_m = 0)
  /// The simulated dynamic mean excitation m₁(k y) = m₁(K δ)/F₀ [-] (Gelman's L_d, eq. 5, as
  /// the mean of the left-hand side of eq. 3 over whole periods), and R = m₁(K δ)/F_m [-].
  double simulated_dynamic_mean_excitation = 0.0;
  double simulated_ratio = 0.0;
};

/// Every mesh's statistics from a constant-speed time record `record` (whole common periods,
/// solveTrainTimeResponse) at input speed Ω [rad/s], the static mesh forces F_m [N] and the
/// baseloads F₀ = `baseload_scale` × F_m (the design load over the operating load, > 0).
std::vector<TrainMeshStatistics> trainMeshStatistics(const GearTrainModel& model,
                                                     double input_speed,
                                                     const TrainTimeResponse& record,
                                                     const std::vector<double>& static_force,
                                                     double baseload_scale);

}  // namespace geardyn
