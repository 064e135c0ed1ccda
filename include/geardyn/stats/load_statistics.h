#pragma once
/// \file
/// Gelman's statistics of the dynamic mean excitation (stats/mean_excitation.h; Gelman et al.
/// 2005, eqs. 5–15) as functions of the transmitted load, from a loaded tooth contact analysis:
/// at a load F the mesh is locally linear, F = K(φ)(δ − E(φ)) with K the tangent stiffness
/// dF/dδ and E = δ − F/K the equivalent gear error, so that E_f = E + F/K is the loaded STE δ
/// itself (the quantity of a Harris map). Normalisation at the design load F₀ (the baseload):
/// K̄ = the mean of K at F₀, x₀ = F₀/K̄, k = K/K̄, e_f = δ/x₀, a = F/F₀.

#include <vector>

#include "geardyn/contact/loaded_contact.h"
#include "geardyn/stats/mean_excitation.h"
#include "geardyn/system/gear_pair_model.h"

namespace geardyn {

struct LoadStatistics {
  double a = 0.0;             ///< F / F₀
  MeanExcitation statistics;  ///< m₁(k), m₁(e_f), d_k, d_e, r_ke, R (eq. 7), R (eq. 11), ...
  std::vector<double> phase, tangent, ste;  ///< the curves over one period [N/m], [m]
};

/// The statistics at each normalised load (ζ = 0, m₁(ė) = 0 over whole periods); `progress`:
/// loads done of all.
std::vector<LoadStatistics> meanExcitationAgainstLoad(
    const LoadedToothContact& contact, double design_load, const std::vector<double>& loads,
    int positions, double* mean_stiffness = nullptr, const ProgressCallback& progress = {});

/// The SDOF gear-pair model (Gelman eq. 1) of one load: the tangent stiffness as a table and
/// E = δ − F/K as a table error, with the given mass, damping and mesh frequency.
GearPairModelSpec gearPairModelAtLoad(const LoadStatistics& load, double force, double mass,
                                      double damping, double mesh_frequency, double contact_ratio);

}  // namespace geardyn
