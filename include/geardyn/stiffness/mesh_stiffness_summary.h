#pragma once
/// \file
/// Statistics and Fourier coefficients of any mesh-stiffness curve over one mesh period,
/// integrated piecewise between its discontinuities with Gauss–Legendre quadrature (exact for
/// piecewise-polynomial curves, to round-off for smooth ones).

#include <vector>

#include "geardyn/stiffness/mesh_stiffness.h"

namespace geardyn {

/// k(φ) = mean + Σ_{i≥1} [a_i cos(2π i φ) + b_i sin(2π i φ)]
///      = mean + Σ amplitude_i cos(2π i φ − phase_i)    (Visnadi eq. 8: s_i = amplitude_i / mean).
struct MeshStiffnessSummary {
  double mean = 0.0;              ///< [N/m]
  double min = 0.0;               ///< [N/m] (over the sampled phases and both sides of every jump)
  double max = 0.0;               ///< [N/m]
  double std = 0.0;               ///< standard deviation over a period [N/m]
  std::vector<double> cosine;     ///< a_i, i = 1..order [N/m] (index 0 holds i = 1)
  std::vector<double> sine;       ///< b_i [N/m]
  std::vector<double> amplitude;  ///< √(a_i² + b_i²) [N/m]
  std::vector<double> phase;      ///< atan2(b_i, a_i) [rad]
};

/// Summarises k over one period: Fourier coefficients up to `order` (>= 0), min/max from
/// `samples` evenly spaced phases plus both sides of each discontinuity.
MeshStiffnessSummary summarizeMeshStiffness(const MeshStiffness& k, int order, int samples = 2000);

/// ∫₀¹ f(φ) dφ for a function that is smooth between `breaks` (ascending, in [0, 1)).
/// Composite 20-point Gauss–Legendre with `panels` panels per piece.
template <typename F>
double integrateOverPeriod(const F& f, const std::vector<double>& breaks, int panels = 16);

}  // namespace geardyn

#include "geardyn/stiffness/detail/integrate_over_period.h"
