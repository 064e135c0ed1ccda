#include "geardyn/stiffness/mesh_stiffness_summary.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "geardyn/error.h"
#include "geardyn/stiffness/api_stiffness.h"

namespace geardyn {

MeshStiffnessSummary summarizeMeshStiffness(const MeshStiffness& k, int order, int samples) {
  if (order < 0) throw InputError("fourier_order", std::to_string(order), "must be >= 0");
  if (samples < 2) throw InputError("samples", std::to_string(samples), "must be >= 2");
  MeshStiffnessSummary s;
  if (dynamic_cast<const ConstantMeshStiffness*>(&k) != nullptr) {
    // A constant k: its summary exactly, without quadrature (a train built many times with
    // changed constant stiffnesses summarises every mesh each time).
    s.mean = s.min = s.max = k.stiffness(0.0);
    s.cosine = s.sine = s.amplitude = s.phase = std::vector<double>(order, 0.0);
    return s;
  }
  const std::vector<double> breaks = k.discontinuities();
  const auto value = [&](double phase) { return k.stiffness(phase); };

  s.mean = integrateOverPeriod(value, breaks);
  const double variance = integrateOverPeriod(
      [&](double phase) {
        const double d = k.stiffness(phase) - s.mean;
        return d * d;
      },
      breaks);
  // A constant curve leaves only quadrature round-off in the variance: report 0, not noise.
  s.std = variance > 1e-24 * s.mean * s.mean ? std::sqrt(variance) : 0.0;

  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  for (int i = 1; i <= order; ++i) {
    const double a =
        2.0 * integrateOverPeriod(
                  [&](double phase) { return k.stiffness(phase) * std::cos(kTwoPi * i * phase); },
                  breaks);
    const double b =
        2.0 * integrateOverPeriod(
                  [&](double phase) { return k.stiffness(phase) * std::sin(kTwoPi * i * phase); },
                  breaks);
    s.cosine.push_back(a);
    s.sine.push_back(b);
    s.amplitude.push_back(std::hypot(a, b));
    s.phase.push_back(std::atan2(b, a));
  }

  s.min = s.max = k.stiffness(0.0);
  const auto visit = [&](double phase) {
    const double v = k.stiffness(phase);
    s.min = std::min(s.min, v);
    s.max = std::max(s.max, v);
  };
  for (int i = 0; i < samples; ++i) visit(static_cast<double>(i) / samples);
  for (double b : breaks) {
    visit(b);                                // right-hand limit
    visit(std::nextafter(b, -1.0) - 1e-12);  // left-hand limit
  }
  return s;
}

}  // namespace geardyn
