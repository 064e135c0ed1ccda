#include "geardyn/stiffness/fourier_stiffness.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"

namespace geardyn {

FourierMeshStiffness::FourierMeshStiffness(double mean, std::vector<double> relative_amplitudes,
                                           std::vector<double> phases, double contact_ratio)
    : mean_(mean),
      s_(std::move(relative_amplitudes)),
      phases_(std::move(phases)),
      contact_ratio_(contact_ratio) {
  if (!(mean > 0.0) || !std::isfinite(mean)) {
    throw InputError("mean", fmt::format("{:g}", mean), "must be finite and > 0 [N/m]");
  }
  if (s_.size() != phases_.size()) {
    throw InputError("phases", fmt::format("{} values", phases_.size()),
                     fmt::format("need one phase per amplitude ({} amplitudes)", s_.size()));
  }
  double total = 0.0;
  for (std::size_t i = 0; i < s_.size(); ++i) {
    if (!(s_[i] >= 0.0) || !std::isfinite(s_[i]) || !std::isfinite(phases_[i])) {
      throw InputError(fmt::format("amplitudes[{}]", i), fmt::format("{:g}", s_[i]),
                       "relative amplitudes must be finite and >= 0 (put the sign in the phase)");
    }
    total += s_[i];
  }
  if (total >= 1.0) {
    throw InputError("amplitudes", fmt::format("sum {:g}", total),
                     "the relative amplitudes must add up to less than 1, or k would reach zero or "
                     "become negative");
  }
}

FourierMeshStiffness FourierMeshStiffness::fit(const MeshStiffness& source, int order,
                                               double mean) {
  const MeshStiffnessSummary summary = summarizeMeshStiffness(source, order, 64);
  std::vector<double> s, phases;
  for (int i = 0; i < order; ++i) {
    s.push_back(summary.amplitude[i] / summary.mean);
    phases.push_back(summary.phase[i]);
  }
  return FourierMeshStiffness(mean > 0.0 ? mean : summary.mean, s, phases, source.contactRatio());
}

double FourierMeshStiffness::stiffness(double phase) const {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double sum = 1.0;
  for (std::size_t i = 0; i < s_.size(); ++i) {
    sum += s_[i] * std::cos(kTwoPi * (i + 1) * phase - phases_[i]);
  }
  return mean_ * sum;
}

}  // namespace geardyn
