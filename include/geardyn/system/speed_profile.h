#pragma once
/// \file
/// The input speed of a run at constant speed or along a linear ramp (run-up / run-down).

#include <algorithm>
#include <cmath>

namespace geardyn {

/// Input (pinion) speed Ω(t) [rad/s]: constant `start` before `ramp_start`, a linear ramp to
/// `end` at `ramp_end`, then constant. start = end is a constant speed.
struct SpeedProfile {
  double start = 0.0, end = 0.0;
  double ramp_start = 0.0, ramp_end = 0.0;  ///< [s]
  double speed(double t) const;
  double acceleration(double t) const;
  /// θ(t) = ∫₀ᵗ Ω dt [rad], exact for the piecewise-linear speed.
  double angle(double t) const;
  bool constant() const { return start == end; }
  double maxSpeed() const { return std::max(std::abs(start), std::abs(end)); }
};

}  // namespace geardyn
