/// Damped complex modes in the balanced modal first-order form (detail/damped_modes.h).

#include "geardyn/solvers/detail/damped_modes.h"

#include <stdexcept>

namespace geardyn::detail {

std::vector<DampedMode> dampedModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D,
                                    const Eigen::MatrixXd& K) {
  const Eigen::Index n = M.rows();
  const Eigen::LLT<Eigen::MatrixXd> chol(M);
  if (chol.info() != Eigen::Success) {
    throw std::runtime_error("modal analysis: the mass matrix is not positive definite");
  }
  const Eigen::MatrixXd Linv = chol.matrixL().solve(Eigen::MatrixXd::Identity(n, n));
  const Eigen::MatrixXd Kt = Linv * K * Linv.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> undamped(0.5 * (Kt + Kt.transpose()));
  const Eigen::MatrixXd& Phi = undamped.eigenvectors();
  const Eigen::VectorXd w = undamped.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  const Eigen::MatrixXd Dh = Phi.transpose() * Linv * D * Linv.transpose() * Phi;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n) = w.asDiagonal();
  A.bottomLeftCorner(n, n) = -Eigen::MatrixXd(w.asDiagonal());
  A.bottomRightCorner(n, n) = -Dh;
  Eigen::EigenSolver<Eigen::MatrixXd> solver(A, true);
  if (solver.info() != Eigen::Success) {
    throw std::runtime_error("modal analysis: the eigenvalue solver did not converge");
  }
  const Eigen::MatrixXcd back = (Linv.transpose() * Phi).cast<std::complex<double>>();
  std::vector<DampedMode> modes;
  for (Eigen::Index j = 0; j < 2 * n; ++j) {
    const std::complex<double> lambda = solver.eigenvalues()(j);
    if (lambda.imag() <= 0.0) continue;
    DampedMode mode{lambda, back * (solver.eigenvectors().col(j).tail(n) / lambda)};  // z = ż/λ
    normalizeToLargest(mode.shape);
    modes.push_back(std::move(mode));
  }
  return modes;
}

}  // namespace geardyn::detail
