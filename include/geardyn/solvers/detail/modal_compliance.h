#pragma once
/// \file
/// The dynamic compliance of a small linear train at its load vectors W for many frequencies
/// from one eigen-decomposition per speed (docs/theory/torus_harmonic_balance.md, "Cost"):
/// with D(ω) = K − ω²M + iωC and the first-order form of z = (q, q̇/s) (s = √(tr K / tr M),
/// which balances Φ's halves), ż = A z + [0; M⁻¹f / s],
/// A = [0 sI; −M⁻¹K/s −M⁻¹C] = Φ Λ Φ⁻¹ (Φ's top half Φ_q),
///
///   D(ω)⁻¹ W = Φ_q diag(1 / (iω − λ_k)) Y,   Y = Φ⁻¹ [0; M⁻¹ W / s],   B(ω) = Wᵀ D(ω)⁻¹ W,
///
/// (the state-space modal expansion of the receptance through the first-order linearisation of
/// the quadratic eigenvalue problem; Tisseur & Meerbergen 2001, SIAM Review 43(2)), O(2n r²) per
/// frequency instead of an O(n³) factorisation. Rigid-body modes R (K R = 0, M-orthonormal) would
/// make A defective at λ = 0; they are shifted and damped, D̃(ω) = D(ω) + (σ + iω√σ)(MR)(MR)ᵀ, which
/// leaves D(ω)⁻¹W unchanged for ω ≠ 0 when RᵀC = 0 and RᵀW = 0: then
/// Rᵀ M D⁻¹W = −Rᵀ D D⁻¹ W / ω² = 0, so D̃ D⁻¹ W = W. Internal (the torus balance, train_torus.cpp).

#include <Eigen/Dense>
#include <complex>

namespace geardyn::detail {

class ModalCompliance {
 public:
  using Complex = std::complex<double>;
  /// Decomposes the train at one speed: K [N/m], M [kg], C [N s/m] (with ΩG₁), R the rigid-body
  /// modes (n × k, M-orthonormal, may be empty), W the load vectors (n × r). False when the
  /// expansion does not hold or is not accurate: M not positive definite, RᵀC or RᵀW not zero,
  /// or Φ ill-conditioned, or B(ω_check) off the factorised D(ω_check) by more than 1e-10 of
  /// its norm (a near-defective A); the caller then factorises D per frequency.
  bool compute(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, const Eigen::MatrixXd& C,
               const Eigen::MatrixXd& R, const Eigen::MatrixXd& W, double w_check);
  /// B(ω) = Wᵀ D(ω)⁻¹ W (r × r) for ω ≠ 0 [rad/s], into `out` (sized r × r).
  template <typename Out>
  void compliance(double w, Out&& out) const {
    const Eigen::Index r = U_.rows();
    out.setZero();
    for (Eigen::Index k = 0; k < lambda_.size(); ++k) {
      const Complex d = 1.0 / (Complex(0.0, w) - lambda_(k));
      for (Eigen::Index b = 0; b < r; ++b) {
        const Complex y = d * Y_(k, b);
        for (Eigen::Index a = 0; a < r; ++a) out(a, b) += U_(a, k) * y;
      }
    }
  }
  /// q = D(ω)⁻¹ W x (n) for ω ≠ 0; `z` is scratch (2n).
  void response(double w, const Eigen::VectorXcd& x, Eigen::VectorXcd& z,
                Eigen::Ref<Eigen::VectorXcd> q) const;

 private:
  Eigen::VectorXcd lambda_;  // eigenvalues of A
  Eigen::MatrixXcd top_;     // Φ_q (n × 2n)
  Eigen::MatrixXcd U_;       // Wᵀ Φ_q (r × 2n)
  Eigen::MatrixXcd Y_;       // Φ⁻¹ [0; M⁻¹W / s] (2n × r)
};

}  // namespace geardyn::detail
