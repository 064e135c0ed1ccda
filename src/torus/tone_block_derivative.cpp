/// The speed derivative of a torus tone's harmonic block as sparse real operators
/// (detail/tone_block_derivative.h).

#include "geardyn/torus/detail/tone_block_derivative.h"

namespace geardyn::detail {
namespace {

Eigen::SparseMatrix<double> sparseOf(const Eigen::MatrixXd& A) {
  if (A.size() == 0) return {};
  Eigen::SparseMatrix<double> S = A.sparseView(0.0, 0.0);  // exact zeros only
  S.makeCompressed();
  return S;
}

}  // namespace

ToneBlockDerivative::ToneBlockDerivative(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K_omega,
                                         const Eigen::MatrixXd& G)
    : M_(sparseOf(M)), K_omega_(sparseOf(K_omega)), G_(sparseOf(G)) {}

void ToneBlockDerivative::setSpeed(const Eigen::MatrixXd& C, double speed, double dspeed_domega) {
  C_ = sparseOf(C);
  speed_ = speed;
  dspeed_ = dspeed_domega;
}

// The parts of dD/dω that are real (2Ω dΩ K_Ω − 2 w ρ M) and imaginary (dΩ w G₁ + ρ C) applied to
// a real x: returns [real part · x, imaginary part · x] side by side.
Eigen::MatrixXd ToneBlockDerivative::applyReal(double w, double rate,
                                               const Eigen::MatrixXd& x) const {
  const Eigen::Index n = x.rows(), k = x.cols();
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, 2 * k);
  if (rate != 0.0) {
    out.leftCols(k).noalias() = (-2.0 * w * rate) * (M_ * x);
    out.rightCols(k).noalias() = rate * (C_ * x);
  }
  if (K_omega_.nonZeros() > 0)
    out.leftCols(k).noalias() += (2.0 * speed_ * dspeed_) * (K_omega_ * x);
  if (G_.nonZeros() > 0 && w != 0.0) out.rightCols(k).noalias() += (dspeed_ * w) * (G_ * x);
  return out;
}

Eigen::MatrixXcd ToneBlockDerivative::times(const Eigen::MatrixXcd& Z, double w,
                                            double rate) const {
  const Eigen::Index k = Z.cols();
  // (A + iB)(Zr + iZi) = (A Zr − B Zi) + i (B Zr + A Zi).
  const Eigen::MatrixXd re = applyReal(w, rate, Z.real());
  const Eigen::MatrixXd im = applyReal(w, rate, Z.imag());
  Eigen::MatrixXcd out(Z.rows(), k);
  out.real() = re.leftCols(k) - im.rightCols(k);
  out.imag() = re.rightCols(k) + im.leftCols(k);
  return out;
}

Eigen::VectorXd ToneBlockDerivative::stiffnessTimes(const Eigen::VectorXd& x) const {
  if (K_omega_.nonZeros() == 0) return Eigen::VectorXd::Zero(x.size());
  return (2.0 * speed_ * dspeed_) * (K_omega_ * x);
}

}  // namespace geardyn::detail
