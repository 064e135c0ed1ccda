#pragma once
/// \file
/// Arnoldi without restarts for the Floquet strip of a Hill eigenproblem (issue #39,
/// docs/theory/nonlinear_gear_trains.md "Hill's method: one Arnoldi run"): the Krylov basis of a
/// shift-invert operator y = (𝓗 − σ)⁻¹x (σ = 0) grows, and at checkpoints the Ritz values of the
/// Hessenberg matrix are computed (eigenvalues only) with the residual of those in the strip
/// |Im λ| <= ω/2 (one inverse-iteration solve each). It stops as soon as the converged ones hold
/// 2n strip values: the strip holds one copy of each of the 2n exponents, so 2n converged strip
/// eigenvalues are all of them, whichever they are.

#include <Eigen/Dense>
#include <complex>
#include <functional>
#include <vector>

namespace geardyn::detail {

struct StripArnoldiOptions {
  int first_check = 0;    ///< basis size of the first check
  int check_step = 8;     ///< vectors added between checks
  int max_dimension = 0;  ///< basis size at which it gives up (not certified)
  double tolerance = 1e-10;  ///< ‖(𝓗 − σ)⁻¹x − θx‖ <= tolerance |θ| (as Spectra's test)
};

struct StripArnoldiResult {
  /// Converged eigenvalues λ = 1/θ of 𝓗 [1/s] whose |Im λ| <= ω/2 (with floquetStrip's 1e-3 ω
  /// margin): the 2n Floquet exponents when `certified` (then in any order).
  std::vector<std::complex<double>> strip;
  int operations = 0;   ///< applications of the operator
  int dimension = 0;    ///< Krylov basis size at the last check
  double radius = 0.0;  ///< largest |λ| among the converged strip values [1/s]
  bool certified = false;
};

/// The strip exponents of 𝓗 from the operator `apply` (x ↦ (𝓗 − 0)⁻¹x on ℝᴺ): classical
/// Gram–Schmidt with a second pass (CGS2, Giraud et al. 2005, Numer. Math. 101:87) from a fixed
/// pseudo-random start vector; `n` the number of degrees of freedom (2n exponents), ω [rad/s].
StripArnoldiResult stripArnoldi(const std::function<void(const double*, double*)>& apply,
                                Eigen::Index N, double omega, int n,
                                const StripArnoldiOptions& options);

}  // namespace geardyn::detail
