#pragma once
/// \file
/// A Lyapunov-type stability estimate of a quasi-periodic torus solution
/// (train_torus_balance.h; docs/theory/torus_harmonic_balance.md, "Stability by Lyapunov
/// exponents"): the variational equation along the solution's trajectory θ_j = 2π g_j t,
///
///   M x″ + C(Ω) x′ + (K̄(Ω) + W S(t) Wᵀ) x = 0,   S(t) = diag(k_m(φ_m) g′_m(δ_m − e_m) − k̄_m),
///
/// integrated for a few perturbation columns (Benettin, Galgani, Giorgilli & Strelcyn 1980,
/// "standard method"): average-acceleration Newmark with K̄ + a₀M + a₁C factorised once (sparse)
/// and S(t) by Woodbury on the r mesh coordinates, the columns re-orthonormalised in the energy
/// inner product xᵀK̄x′ + vᵀMv′ (Cholesky QR) every period of the slowest generator and the logs
/// of the triangular factor's diagonal summed over the second half of the window. The rigid-body
/// modes (rolling: K̄R = 0, exponent 0) are projected out M-orthogonally at every
/// re-orthonormalisation.
/// A quasi-periodic trajectory fills the torus, so the window's average is the exponent of the
/// solution, not of one phase relation; the largest of the columns' exponents estimates the
/// largest Lyapunov exponent λ₁ (stable when < 0).

#include <limits>
#include <string>
#include <vector>

#include "geardyn/torus/train_torus_balance.h"

namespace geardyn {

struct TorusLyapunovEstimate {
  /// The columns' exponents, largest first [1/s]; exponents[0] estimates λ₁.
  std::vector<double> exponents;
  double max_exponent = std::numeric_limits<double>::quiet_NaN();  ///< [1/s]
  bool stable = false;                                             ///< max_exponent < 0
  long long steps = 0;                                             ///< Newmark steps taken
  /// "completed", or why not: "unsupported" (clearance bearings or tooth pairs: only the meshes'
  /// contact laws are linearised here).
  std::string status;
};

/// λ estimate of a torus solution over `window` [s] (two halves: the first lets the columns
/// align with the leading directions, the second is averaged), `columns` perturbations (at most
/// the elastic state's dimension) from a fixed pseudo-random start, `steps_per_mesh_period`
/// Newmark steps per period of the fastest mesh.
TorusLyapunovEstimate torusLyapunovEstimate(const GearTrainModel& model,
                                            const TrainTorusBalance& balance,
                                            const HarmonicBalancePoint& point, double window,
                                            int columns = 4, int steps_per_mesh_period = 64);

}  // namespace geardyn
