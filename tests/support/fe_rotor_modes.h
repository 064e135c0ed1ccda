#pragma once
/// \file
/// The FE geared rotor's damped modes straight from its own matrices (M, C + Ω G₁,
/// K + k̄ v vᵀ; detail::dampedModes), described on its own DOFs: the reference the gear train's
/// modal solver on the translated rotor is checked against (the FE rotor has no modal solver
/// of its own: `rotor` and Python use the train's, analysis/fe_rotor_modes.h).

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <vector>

#include "geardyn/numerics/damped_modes.h"
#include "geardyn/solvers/detail/whirl_shares.h"
#include "geardyn/system/fe_rotor_model.h"

namespace geardyn::testing {

struct FeReferenceMode {
  double frequency = 0.0;      ///< [Hz]
  double damping_ratio = 0.0;  ///< [-]
  double lateral_fraction = 0.0, torsional_fraction = 0.0, axial_fraction = 0.0;
  double forward_fraction = 0.0;
  std::string whirl;
};

/// The lowest `count` elastic modes at pinion speed Ω [rad/s], ascending in frequency: rigid
/// (|λ|/2π < 0.01 Hz) and overdamped (ζ > 0.99) roots skipped.
inline std::vector<FeReferenceMode> feReferenceModes(const FeRotorModel& m, double speed,
                                                     std::size_t count) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  const Eigen::VectorXd& v = m.meshVector();
  const Eigen::MatrixXd K = m.stiffness() + m.meanMeshStiffness() * v * v.transpose();
  const Eigen::MatrixXd D = m.damping() + speed * m.gyroscopic();
  const Eigen::VectorXd md = m.mass().diagonal();
  std::vector<FeReferenceMode> modes;
  for (const detail::DampedMode& found : detail::dampedModes(m.mass(), D, K)) {
    const std::complex<double> l = found.eigenvalue;
    if (std::abs(l) / kTwoPi < 1e-2 || -l.real() / std::abs(l) > 0.99) continue;
    FeReferenceMode mode;
    mode.frequency = l.imag() / kTwoPi;
    mode.damping_ratio = -l.real() / std::abs(l);
    detail::WhirlShares shares;
    for (int i = 0; i < m.dofCount(); ++i) {
      const double e = md(i) * std::norm(found.shape(i));
      const int type = m.typeOf(i);
      (type == kUx ? shares.axial : type == kRx ? shares.torsional : shares.lateral) += e;
      if (type != kUy) continue;
      const int iz = m.dofIndex(m.shaftOf(i), m.nodeOf(i), kUz);
      shares.addWhirl(md(i), found.shape(i), found.shape(iz), m.spinRatio(m.shaftOf(i)));
    }
    shares.describe(mode);
    modes.push_back(mode);
  }
  std::sort(modes.begin(), modes.end(),
            [](const auto& a, const auto& b) { return a.frequency < b.frequency; });
  if (modes.size() > count) modes.resize(count);
  return modes;
}

}  // namespace geardyn::testing
