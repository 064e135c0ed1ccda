#pragma once
/// \file
/// Monte Carlo of the mean excitation ratio (Gelman et al. 2005, "processes with deterministic
/// and random components and random initial time"): over one pinion revolution (z₁ mesh
/// periods) each tooth pair j gets a pitch error p_j, a profile (slope) error q_j and a
/// stiffness factor κ_j drawn from normal distributions, and the gear error a random phase φ₀
/// relative to the stiffness:
///   K_j(φ) = κ_j K(φ),   E_j(φ) = E(φ + φ₀) + p_j + q_j (φ − ½),   φ ∈ [0, 1) in period j.
/// Each sample gives R and L_d (eqs. 5, 7) over the revolution. Samples run on a thread pool;
/// sample i draws from its own stream seeded by (seed, i), so results are bit-identical
/// whatever the number of threads.

#include <cstdint>
#include <vector>

#include "geardyn/progress.h"
#include "geardyn/stats/mean_excitation.h"
#include "geardyn/system/gear_pair_model.h"

namespace geardyn {

struct MonteCarloOptions {
  int samples = 1000;
  std::uint64_t seed = 1;
  int teeth = 1;                   ///< mesh periods per sample (pinion teeth z₁)
  double pitch_error_std = 0.0;    ///< σ of p_j [m] (model units)
  double profile_error_std = 0.0;  ///< σ of q_j [m] (slope error over a mesh period)
  double stiffness_std = 0.0;      ///< σ of κ_j (mean 1) [-]
  bool random_phase = true;        ///< φ₀ ~ U(0, 1)
  double baseload = 0.0;           ///< F₀ [N] (model units)
  int threads = 1;
  ProgressCallback progress;  ///< (samples done, samples), from the first worker thread
  void validate() const;
};

struct MonteCarloSample {
  double ratio = 0.0;                    ///< R
  double dynamic_mean_excitation = 0.0;  ///< L_d (normalised)
  double r_ke = 0.0, d_k = 0.0, d_e = 0.0, delta_m1_ef = 0.0, phase = 0.0;
};

/// All samples in index order.
std::vector<MonteCarloSample> runMeanExcitationMonteCarlo(const GearPairModel& model,
                                                          const MonteCarloOptions& options);

/// The mean excitation of one sample (exposed for tests): the model's curves with the given
/// per-tooth values (vectors of length teeth) and phase.
MeanExcitation meanExcitationOfRevolution(const GearPairModel& model, double baseload,
                                          const std::vector<double>& pitch,
                                          const std::vector<double>& profile,
                                          const std::vector<double>& stiffness_factor,
                                          double phase);

/// Summary of a distribution: mean, std, 5/50/95 % quantiles (linear interpolation).
struct Distribution {
  double mean = 0.0, std = 0.0, q05 = 0.0, q50 = 0.0, q95 = 0.0, min = 0.0, max = 0.0;
};
Distribution describe(std::vector<double> values);

}  // namespace geardyn
