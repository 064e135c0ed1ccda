#include "geardyn/stats/mean_excitation.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"
#include "geardyn/system/gear_pair_model.h"

namespace geardyn {

std::string MeanExcitation::classification() const {
  if (std::abs(variable_term) <= 1e-12) return "equal to";
  return variable_term > 0.0 ? "greater than" : "less than";
}

MeanExcitation meanExcitationFromMoments(double m1_k, double m1_ef, double d_k, double d_e,
                                         double r_ke, double m1_edot, double a, double zeta) {
  for (const auto& [key, value] :
       {std::pair{"m1_k", m1_k}, std::pair{"m1_ef", m1_ef}, std::pair{"d_k", d_k},
        std::pair{"d_e", d_e}, std::pair{"r_ke", r_ke}, std::pair{"m1_edot", m1_edot},
        std::pair{"a", a}, std::pair{"zeta", zeta}}) {
    if (!std::isfinite(value)) throw InputError(key, fmt::format("{}", value), "must be finite");
  }
  if (!(a > 0.0)) throw InputError("a", fmt::format("{:g}", a), "the normalised load must be > 0");
  if (d_k < 0.0 || d_e < 0.0)
    throw InputError(d_k < 0.0 ? "d_k" : "d_e", "", "standard deviations must be >= 0");
  if (std::abs(r_ke) > 1.0 + 1e-12) {
    throw InputError("r_ke", fmt::format("{:g}", r_ke),
                     "a correlation coefficient lies in [-1, 1]");
  }
  MeanExcitation s;
  s.m1_k = m1_k;
  s.m1_ef = m1_ef;
  s.d_k = d_k;
  s.d_e = d_e;
  s.r_ke = r_ke;
  s.m1_edot = m1_edot;
  s.a = a;
  s.zeta = zeta;
  s.delta_m1_ef = m1_ef - a;
  s.dynamic_mean_excitation = m1_k * m1_ef + r_ke * d_k * d_e + 2.0 * zeta * m1_edot;  // eq. 5
  s.ratio = s.dynamic_mean_excitation / a;                                             // eq. 7
  s.variable_term = (s.delta_m1_ef + r_ke * d_k * d_e + 2.0 * zeta * m1_edot) / a;     // eq. 10
  s.ratio_eq15 = 1.0 + (s.delta_m1_ef + r_ke * d_k * d_e) / a;
  s.ratio_eq11 = 1.0 + r_ke * d_k * d_e / a;
  return s;
}

namespace {

/// The moments of k(φ) and e_f(φ) = e(φ) + a/k(φ) over one period; e′ is de/dφ and
/// `phase_rate` = dφ/dt₁ = Ω/2π.
template <typename K, typename E, typename Edot>
MeanExcitation fromFunctions(const K& k, const E& e, const Edot& edot,
                             const std::vector<double>& breaks, double a, double zeta,
                             double phase_rate) {
  if (!(a > 0.0) || !std::isfinite(a))
    throw InputError("a", fmt::format("{:g}", a), "must be finite and > 0");
  const auto ef = [&](double phase) { return e(phase) + a / k(phase); };
  const double m1_k = integrateOverPeriod(k, breaks);
  const double m1_ef = integrateOverPeriod(ef, breaks);
  const double var_k =
      integrateOverPeriod([&](double p) { return std::pow(k(p) - m1_k, 2); }, breaks);
  const double var_e =
      integrateOverPeriod([&](double p) { return std::pow(ef(p) - m1_ef, 2); }, breaks);
  const double cov =
      integrateOverPeriod([&](double p) { return (k(p) - m1_k) * (ef(p) - m1_ef); }, breaks);
  // Over a whole period the mean of a periodic error's derivative is (e(1) − e(0)) dφ/dt₁ = 0:
  // Gelman's assumption 14 holds exactly here; integrated all the same.
  const double m1_edot = phase_rate * integrateOverPeriod(edot, breaks);
  return meanExcitationFromCovariance(m1_k, m1_ef, var_k, var_e, cov, m1_edot, a, zeta);
}

}  // namespace

MeanExcitation meanExcitationFromCovariance(double m1_k, double m1_ef, double var_k, double var_e,
                                            double cov_ke, double m1_edot, double a, double zeta) {
  const double d_k = std::sqrt(std::max(var_k, 0.0)), d_e = std::sqrt(std::max(var_e, 0.0));
  const double r = d_k > 0.0 && d_e > 0.0 ? std::clamp(cov_ke / (d_k * d_e), -1.0, 1.0) : 0.0;
  return meanExcitationFromMoments(m1_k, m1_ef, d_k, d_e, r, m1_edot, a, zeta);
}

MeanExcitation meanExcitationFromCurves(const MeshStiffness& k, const TransmissionError& e,
                                        double a, double zeta, double frequency_ratio) {
  return fromFunctions([&](double p) { return k.stiffness(p); },
                       [&](double p) { return e.value(p); },
                       [&](double p) { return e.derivative(p); }, k.discontinuities(), a, zeta,
                       frequency_ratio / (2.0 * std::numbers::pi));
}

MeanExcitation meanExcitationFromSamples(const std::vector<double>& k,
                                         const std::vector<double>& e_f, double a, double zeta) {
  if (k.size() != e_f.size() || k.size() < 2) {
    throw InputError("samples", fmt::format("{} and {}", k.size(), e_f.size()),
                     "k and e_f need the same number of samples (at least 2)");
  }
  const double n = static_cast<double>(k.size());
  double m_k = 0, m_e = 0;
  for (std::size_t i = 0; i < k.size(); ++i) {
    m_k += k[i] / n;
    m_e += e_f[i] / n;
  }
  double var_k = 0, var_e = 0, cov = 0;
  for (std::size_t i = 0; i < k.size(); ++i) {
    var_k += (k[i] - m_k) * (k[i] - m_k) / n;
    var_e += (e_f[i] - m_e) * (e_f[i] - m_e) / n;
    cov += (k[i] - m_k) * (e_f[i] - m_e) / n;
  }
  return meanExcitationFromCovariance(m_k, m_e, var_k, var_e, cov, 0.0, a, zeta);
}

MeanExcitation meanExcitationFromModel(const GearPairModel& model, double baseload) {
  if (!(baseload > 0.0) || !std::isfinite(baseload)) {
    throw InputError("stats.baseload", fmt::format("{:g}", baseload), "must be finite and > 0 [N]");
  }
  const MeshStiffness& stiffness = model.meshStiffness();
  const std::vector<double> breaks = stiffness.discontinuities();
  const double k_mean =
      integrateOverPeriod([&](double p) { return stiffness.stiffness(p); }, breaks);
  const double x0 = baseload / k_mean;
  const double omega_n = std::sqrt(k_mean / model.mass());
  const double zeta = model.damping() / (2.0 * std::sqrt(k_mean * model.mass()));
  const TransmissionError& e = model.transmissionError();
  return fromFunctions([&](double p) { return stiffness.stiffness(p) / k_mean; },
                       [&](double p) { return e.value(p) / x0; },
                       [&](double p) { return e.derivative(p) / x0; }, breaks,
                       model.meanForce() / baseload, zeta, model.meshFrequency() / omega_n);
}

}  // namespace geardyn
