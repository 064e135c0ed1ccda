#pragma once
/// \file
/// The damped complex modes of M q̈ + D q̇ + K q = 0 (M symmetric positive definite, K
/// symmetric, D any) in the balanced modal first-order form: with M = L Lᵀ and
/// L⁻¹ K L⁻ᵀ = Φ diag(w²) Φᵀ (undamped modes, symmetric and accurate), z = Φᵀ Lᵀ q obeys
/// z̈ + D̂ ż + diag(w²) z = 0, D̂ = Φᵀ L⁻¹ D L⁻ᵀ Φ, and the state [diag(w) z; ż] has the matrix
/// [[0, diag(w)], [−diag(w), −D̂]], whose entries are all frequencies. (The textbook
/// [[0, I], [−M⁻¹K, −M⁻¹D]] mixes 1 with ‖M⁻¹K‖ ~ 1e14 for stiff bearings and loses the low
/// modes to round-off: 0.25 % on the FE rotor's tilting-disk test.)

#include <Eigen/Dense>
#include <complex>
#include <vector>

namespace geardyn::detail {

struct DampedMode {
  /// λ [1/s]: Im λ > 0 (one of each conjugate pair), or real and > 0 (a divergence).
  std::complex<double> eigenvalue;
  Eigen::VectorXcd shape;  ///< displacement part, largest entry 1
};

/// Scales a shape so that its largest entry is 1.
inline void normalizeToLargest(Eigen::VectorXcd& shape) {
  Eigen::Index largest = 0;
  shape.cwiseAbs().maxCoeff(&largest);
  shape /= shape(largest);
}

/// A real eigenvalue λ > 0: a static divergence (a negative stiffness that neither damping nor
/// gyroscopic coupling holds), growing as e^{λt} without oscillating.
inline bool isDivergent(std::complex<double> lambda) {
  return lambda.imag() == 0.0 && lambda.real() > 0.0;
}

/// Every eigenvalue with Im λ > 0, and every divergent one (real, > 0; K may be indefinite);
/// overdamped real eigenvalues (< 0) are dropped. In solver order.
/// Throws std::runtime_error when the eigenvalue solver fails.
std::vector<DampedMode> dampedModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D,
                                    const Eigen::MatrixXd& K);

}  // namespace geardyn::detail
