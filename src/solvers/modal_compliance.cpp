/// The dynamic compliance from one eigen-decomposition per speed (detail/modal_compliance.h).

#include "geardyn/solvers/detail/modal_compliance.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace geardyn::detail {

bool ModalCompliance::compute(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M,
                              const Eigen::MatrixXd& C, const Eigen::MatrixXd& R,
                              const Eigen::MatrixXd& W, double w_check) {
  const Eigen::Index n = K.rows(), r = W.cols();
  // Exactness of the shift (the header): the rigid-body modes neither damped nor loaded.
  if (R.cols() > 0) {
    const double scale = R.norm();
    if ((R.transpose() * C).norm() > 1e-12 * C.norm() * scale ||
        (R.transpose() * W).norm() > 1e-12 * W.norm() * scale) {
      return false;
    }
  }
  const Eigen::LLT<Eigen::MatrixXd> mass(M);
  if (mass.info() != Eigen::Success) return false;
  // σ: a typical squared frequency of the train, trace K / trace M [rad²/s²]; the shifted
  // rigid-body modes also get the damping ratio 1/2 (c = √σ, exact by the same argument), so
  // that no tone meets them: λ = √σ (−1/2 ± i √3/2).
  const double sigma = K.trace() / M.trace(), s = std::sqrt(sigma);
  Eigen::MatrixXd shifted = K, damped = C;
  if (R.cols() > 0) {
    const Eigen::MatrixXd MR = M * R;
    shifted += sigma * MR * MR.transpose();
    damped += s * MR * MR.transpose();
  }
  // The state z = (q, q̇ / s): both halves of an eigenvector of one size (with z = (q, q̇) the
  // velocity half is |λ| times the displacement half, and Φ's condition number on the
  // hunting-tooth reducer is 3e6 instead of 500).
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).diagonal().setConstant(s);
  A.bottomLeftCorner(n, n) = -mass.solve(shifted) / s;
  A.bottomRightCorner(n, n) = -mass.solve(damped);
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(A, true);
  if (eigen.info() != Eigen::Success) return false;
  lambda_ = eigen.eigenvalues();
  const Eigen::MatrixXcd phi = eigen.eigenvectors();
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(phi);
  if (!(lu.rcond() > 1e-10)) return false;
  Eigen::MatrixXcd load = Eigen::MatrixXcd::Zero(2 * n, r);
  load.bottomRows(n) = (mass.solve(W) / s).cast<Complex>();
  Y_ = lu.solve(load);
  top_ = phi.topRows(n);
  U_ = W.transpose().cast<Complex>() * top_;
  // A posteriori: B(ω_check) against the factorised D(ω_check).
  const Eigen::MatrixXcd D =
      (K - w_check * w_check * M).cast<Complex>() + Complex(0.0, w_check) * C.cast<Complex>();
  const Eigen::MatrixXcd direct =
      W.transpose().cast<Complex>() * D.partialPivLu().solve(W.cast<Complex>());
  Eigen::MatrixXcd modal(r, r);
  compliance(w_check, modal);
  return (modal - direct).norm() <= 1e-10 * direct.norm();
}

void ModalCompliance::response(double w, const Eigen::VectorXcd& x, Eigen::VectorXcd& z,
                               Eigen::Ref<Eigen::VectorXcd> q) const {
  z.noalias() = Y_ * x;
  for (Eigen::Index k = 0; k < lambda_.size(); ++k) z(k) /= Complex(0.0, w) - lambda_(k);
  q.noalias() = top_ * z;
}

}  // namespace geardyn::detail
