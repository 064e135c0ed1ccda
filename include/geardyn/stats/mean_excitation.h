#pragma once
/// \file
/// The statistics of the dynamic mean excitation of a gear pair (Gelman, Giurgiutiu & Bayoumi
/// 2005): the mean excitation ratio R = L_d / L_t of the normalised dynamic mean excitation to
/// the normalised transmitted load (eqs. 4–7), its variable term V (eq. 10) and the simplified
/// forms (eqs. 11, 15), from the normalised mesh stiffness k = K/K̄ and static transmission
/// error e_f = E_f/x₀ = e + a/k (x₀ = F₀/K̄, a = F/F₀; eqs. 1–3).

#include <string>
#include <vector>

#include "geardyn/models/transmission_error.h"
#include "geardyn/stiffness/mesh_stiffness.h"

namespace geardyn {

/// Every quantity of Gelman's eqs. 5–15, normalised.
struct MeanExcitation {
  double m1_k = 0.0;                     ///< mean of k
  double m1_ef = 0.0;                    ///< mean of e_f
  double d_k = 0.0;                      ///< standard deviation of k
  double d_e = 0.0;                      ///< standard deviation of e_f
  double r_ke = 0.0;                     ///< cross-correlation coefficient of k and e_f
  double m1_edot = 0.0;                  ///< mean of de/dt₁
  double a = 0.0;                        ///< normalised transmitted load L_t = F/F₀ (eq. 6)
  double zeta = 0.0;                     ///< damping ratio
  double delta_m1_ef = 0.0;              ///< Δm₁(e_f) = m₁(e_f) − a (eq. 9)
  double dynamic_mean_excitation = 0.0;  ///< L_d = m₁(k)m₁(e_f) + r d_k d_e + 2ζ m₁(ė) (eq. 5)
  double ratio = 0.0;                    ///< R = L_d / a (eq. 7)
  double variable_term = 0.0;  ///< V = [Δm₁(e_f) + r d_k d_e + 2ζ m₁(ė)] / a (eq. 10)
  double ratio_eq15 = 0.0;     ///< R = 1 + [Δm₁(e_f) + r d_k d_e] / a (eq. 15, m₁(ė) = 0)
  double ratio_eq11 = 0.0;     ///< R = 1 + r d_k d_e / a (eq. 11)
  /// "greater than", "less than" or "equal to" (the transmitted mean load), from the sign of
  /// the numerator of V (the criteria after eq. 13), with |V| <= 1e-12 counting as equal.
  std::string classification() const;
};

/// From the moments directly (as the paper's examples give them). m1_k = 1 for k = K/K̄.
MeanExcitation meanExcitationFromMoments(double m1_k, double m1_ef, double d_k, double d_e,
                                         double r_ke, double m1_edot, double a, double zeta);

/// From the means, variances and covariance of k and e_f (the step every estimator shares):
/// d = √var (negative round-off clipped), r_ke = cov / (d_k d_e) clamped to [−1, 1], 0 when a
/// process is constant.
MeanExcitation meanExcitationFromCovariance(double m1_k, double m1_ef, double var_k, double var_e,
                                            double cov_ke, double m1_edot, double a, double zeta);

/// From curves over one mesh period: the normalised stiffness k(φ) = K/K̄ (its mean need not be
/// exactly 1: it is used as given), the normalised gear error e(φ) = E/x₀, the load a and ζ; the
/// mesh frequency ratio Ω = ω_m/ω_n converts de/dφ into de/dt₁ = (Ω/2π) de/dφ.
MeanExcitation meanExcitationFromCurves(const MeshStiffness& k, const TransmissionError& e,
                                        double a, double zeta, double frequency_ratio);

/// From samples evenly spaced over whole mesh periods (a measured or computed record): the
/// normalised k and e_f at the same instants; m₁(ė) = 0 (Gelman eq. 14; exact for whole periods
/// of a periodic error).
MeanExcitation meanExcitationFromSamples(const std::vector<double>& k,
                                         const std::vector<double>& e_f, double a, double zeta);

class GearPairModel;
/// From a dimensional gear-pair model and the baseload F₀ [N] (the load the profile
/// modification was designed for): k = K/K̄, e = E/x₀ with x₀ = F₀/K̄, a = F/F₀, ζ and
/// Ω = ω_m/ω_n from the model.
MeanExcitation meanExcitationFromModel(const GearPairModel& model, double baseload);

}  // namespace geardyn
