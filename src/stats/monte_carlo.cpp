#include "geardyn/stats/monte_carlo.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <random>

#include "geardyn/detail/contiguous_ranges.h"
#include "geardyn/error.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"

namespace geardyn {
namespace {

/// SplitMix64: a well-mixed seed for sample i's own generator.
std::uint64_t streamSeed(std::uint64_t seed, std::uint64_t index) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (index + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

}  // namespace

void MonteCarloOptions::validate() const {
  if (samples < 1) throw InputError("monte_carlo.samples", std::to_string(samples), "must be >= 1");
  if (teeth < 1) throw InputError("monte_carlo.teeth", std::to_string(teeth), "must be >= 1");
  if (threads < 1) throw InputError("--threads", std::to_string(threads), "must be >= 1");
  for (const auto& [key, value] : {std::pair{"monte_carlo.pitch_error_std", pitch_error_std},
                                   std::pair{"monte_carlo.profile_error_std", profile_error_std},
                                   std::pair{"monte_carlo.stiffness_std", stiffness_std}}) {
    if (!(value >= 0.0) || !std::isfinite(value)) {
      throw InputError(key, fmt::format("{:g}", value), "must be finite and >= 0");
    }
  }
  if (stiffness_std >= 0.3) {
    throw InputError("monte_carlo.stiffness_std", fmt::format("{:g}", stiffness_std),
                     "must be < 0.3 (κ = 1 ± 3σ must stay positive)");
  }
  if (!(baseload > 0.0))
    throw InputError("stats.baseload", fmt::format("{:g}", baseload), "must be > 0");
}

MeanExcitation meanExcitationOfRevolution(const GearPairModel& model, double baseload,
                                          const std::vector<double>& pitch,
                                          const std::vector<double>& profile,
                                          const std::vector<double>& stiffness_factor,
                                          double phase) {
  const MeshStiffness& stiffness = model.meshStiffness();
  const TransmissionError& error = model.transmissionError();
  const std::vector<double> breaks = stiffness.discontinuities();
  const double k_mean =
      integrateOverPeriod([&](double p) { return stiffness.stiffness(p); }, breaks);
  const double x0 = baseload / k_mean, a = model.meanForce() / baseload;
  const double zeta = model.damping() / (2.0 * std::sqrt(k_mean * model.mass()));
  // Window moments over the revolution: means of k, e_f, k², e_f², k e_f and ė.
  double s_k = 0, s_e = 0, s_kk = 0, s_ee = 0, s_ke = 0;
  const std::size_t n = pitch.size();
  for (std::size_t j = 0; j < n; ++j) {
    const auto k = [&](double p) { return stiffness_factor[j] * stiffness.stiffness(p) / k_mean; };
    const auto ef = [&](double p) {
      return (error.value(p + phase) + pitch[j] + profile[j] * (p - 0.5)) / x0 + a / k(p);
    };
    s_k += integrateOverPeriod(k, breaks, 4);
    s_e += integrateOverPeriod(ef, breaks, 4);
    s_kk += integrateOverPeriod([&](double p) { return k(p) * k(p); }, breaks, 4);
    s_ee += integrateOverPeriod([&](double p) { return ef(p) * ef(p); }, breaks, 4);
    s_ke += integrateOverPeriod([&](double p) { return k(p) * ef(p); }, breaks, 4);
  }
  const double m_k = s_k / n, m_e = s_e / n;
  // m₁(ė) over the revolution is (e(end) − e(start)) / duration = 0: the error repeats every
  // revolution, so the slopes within the periods and the jumps between teeth cancel exactly.
  return meanExcitationFromCovariance(m_k, m_e, s_kk / n - m_k * m_k, s_ee / n - m_e * m_e,
                                      s_ke / n - m_k * m_e, 0.0, a, zeta);
}

std::vector<MonteCarloSample> runMeanExcitationMonteCarlo(const GearPairModel& model,
                                                          const MonteCarloOptions& options) {
  options.validate();
  std::vector<MonteCarloSample> samples(options.samples);
  std::atomic<long long> finished{0};
  // Contiguous ranges, the first on the calling thread, which alone reports progress: a
  // callback that throws (an interrupted run) stops every range before the exception leaves.
  detail::runContiguousRanges(
      static_cast<std::size_t>(options.samples), static_cast<std::size_t>(options.threads),
      [&](std::size_t first, std::size_t last, bool on_caller, const std::atomic<bool>& stop) {
        std::vector<double> pitch(options.teeth), profile(options.teeth), kappa(options.teeth);
        for (std::size_t i = first; i < last && !stop.load(std::memory_order_relaxed); ++i) {
          std::mt19937_64 rng(streamSeed(options.seed, static_cast<std::uint64_t>(i)));
          std::normal_distribution<double> normal(0.0, 1.0);
          std::uniform_real_distribution<double> uniform(0.0, 1.0);
          for (int j = 0; j < options.teeth; ++j) {
            pitch[j] = options.pitch_error_std * normal(rng);
            profile[j] = options.profile_error_std * normal(rng);
            kappa[j] = 1.0 + options.stiffness_std * normal(rng);
          }
          const double phase = options.random_phase ? uniform(rng) : 0.0;
          const MeanExcitation s =
              meanExcitationOfRevolution(model, options.baseload, pitch, profile, kappa, phase);
          samples[i] = {s.ratio, s.dynamic_mean_excitation, s.r_ke, s.d_k, s.d_e, s.delta_m1_ef,
                        phase};
          const long long done = ++finished;
          if (on_caller && options.progress) options.progress(done, options.samples);
        }
      });
  return samples;
}

Distribution describe(std::vector<double> values) {
  Distribution d;
  if (values.empty()) return d;
  const double n = static_cast<double>(values.size());
  for (double v : values) d.mean += v / n;
  for (double v : values) d.std += (v - d.mean) * (v - d.mean);
  d.std = values.size() > 1 ? std::sqrt(d.std / (n - 1)) : 0.0;
  std::sort(values.begin(), values.end());
  const auto quantile = [&](double q) {
    const double position = q * (n - 1);
    const std::size_t i = static_cast<std::size_t>(position);
    const double w = position - i;
    return i + 1 < values.size() ? values[i] * (1 - w) + values[i + 1] * w : values.back();
  };
  d.q05 = quantile(0.05);
  d.q50 = quantile(0.5);
  d.q95 = quantile(0.95);
  d.min = values.front();
  d.max = values.back();
  return d;
}

}  // namespace geardyn
