#include "geardyn/stiffness/step_stiffness.h"

#include <fmt/format.h>

#include <cmath>

#include "geardyn/error.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"

namespace geardyn {

StepMeshStiffness::StepMeshStiffness(double k_min, double k_max, double contact_ratio)
    : k_min_(k_min), k_max_(k_max), contact_ratio_(contact_ratio) {
  if (!std::isfinite(contact_ratio) || contact_ratio < 1.0) {
    throw InputError("contact_ratio", fmt::format("{:g}", contact_ratio),
                     "must be >= 1: below 1 the pair does not mesh continuously");
  }
  if (!(k_min > 0.0) || !std::isfinite(k_min)) {
    throw InputError("k_min", fmt::format("{:g}", k_min), "must be finite and > 0 [N/m]");
  }
  if (!(k_max >= k_min) || !std::isfinite(k_max)) {
    throw InputError("k_max", fmt::format("{:g}", k_max),
                     fmt::format("must be finite and >= k_min = {:g} [N/m]", k_min));
  }
  fraction_ = contact_ratio - std::floor(contact_ratio);
}

StepMeshStiffness StepMeshStiffness::fromMean(double mean, double contact_ratio) {
  if (!(mean > 0.0) || !std::isfinite(mean)) {
    throw InputError("mean", fmt::format("{:g}", mean), "must be finite and > 0 [N/m]");
  }
  const double n = std::floor(contact_ratio);
  const double k_pair = mean / contact_ratio;
  return StepMeshStiffness(n * k_pair, (n + 1.0) * k_pair, contact_ratio);
}

StepMeshStiffness StepMeshStiffness::fromModel(const MeshStiffness& source) {
  const double eps = source.contactRatio();
  const double p = eps - std::floor(eps);
  std::vector<double> breaks = source.discontinuities();
  const auto f = [&](double phase) { return source.stiffness(phase); };
  if (p <= 0.0) {  // integer contact ratio: a constant
    const double mean = integrateOverPeriod(f, breaks);
    return StepMeshStiffness(mean, mean, eps);
  }
  breaks.push_back(p);
  std::sort(breaks.begin(), breaks.end());
  const double high =
      integrateOverPeriod([&](double phase) { return phase < p ? f(phase) : 0.0; }, breaks) / p;
  const double low =
      integrateOverPeriod([&](double phase) { return phase >= p ? f(phase) : 0.0; }, breaks) /
      (1.0 - p);
  return StepMeshStiffness(std::min(low, high), std::max(low, high), eps);
}

double StepMeshStiffness::stiffness(double phase) const {
  return wrapPhase(phase) < fraction_ ? k_max_ : k_min_;
}

std::vector<double> StepMeshStiffness::discontinuities() const {
  if (fraction_ <= 0.0 || k_max_ == k_min_) return {};
  return {0.0, fraction_};
}

}  // namespace geardyn
