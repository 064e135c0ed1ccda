/// Damped complex modes in the balanced modal first-order form (detail/damped_modes.h).

#include "geardyn/numerics/damped_modes.h"

#include <Eigen/Eigenvalues>
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
  // w = sqrt|w²|, and the state [w z; ż]: z̈ = −w² z − D̂ ż reads d(ż)/dt = −sgn(w²) w (w z) − D̂ ż,
  // so a negative stiffness (w² < 0: a divergence) keeps the form's scaling instead of being
  // clipped to a rigid-body mode.
  const Eigen::VectorXd& w2 = undamped.eigenvalues();
  const Eigen::VectorXd w = w2.cwiseAbs().cwiseSqrt();
  const Eigen::VectorXd signed_w =
      w2.binaryExpr(w, [](double a, double b) { return a < 0.0 ? -b : b; });
  const Eigen::MatrixXd Dh = Phi.transpose() * Linv * D * Linv.transpose() * Phi;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n) = w.asDiagonal();
  A.bottomLeftCorner(n, n) = -Eigen::MatrixXd(signed_w.asDiagonal());
  A.bottomRightCorner(n, n) = -Dh;
  // Eigen's default of 40 QR sweeps per row is not enough near a gyroscopic system's stability
  // boundary (an indefinite K held by Coriolis coupling, eigenvalues meeting at 0: the planets
  // on soft pins of TrainModes.SolveNearTheGyroscopicStabilityBoundary, 16 797 rpm): 400, and where
  // the real QR still stagnates, the complex QR, whose real eigenvalues are then those with |Im λ|
  // at round-off.
  Eigen::VectorXcd values;
  Eigen::MatrixXcd vectors;
  Eigen::EigenSolver<Eigen::MatrixXd> solver;
  solver.setMaxIterations(400 * A.rows());
  solver.compute(A, true);
  if (solver.info() == Eigen::Success) {
    values = solver.eigenvalues();
    vectors = solver.eigenvectors();
  } else {
    const Eigen::ComplexEigenSolver<Eigen::MatrixXcd> complex(A.cast<std::complex<double>>(), true);
    if (complex.info() != Eigen::Success) {
      throw std::runtime_error("modal analysis: the eigenvalue solver did not converge");
    }
    values = complex.eigenvalues();
    vectors = complex.eigenvectors();
    const double round_off = 1e-12 * A.cwiseAbs().maxCoeff();
    for (auto& lambda : values) {
      if (std::abs(lambda.imag()) <= round_off) lambda.imag(0.0);
    }
  }
  const Eigen::MatrixXcd back = (Linv.transpose() * Phi).cast<std::complex<double>>();
  std::vector<DampedMode> modes;
  for (Eigen::Index j = 0; j < 2 * n; ++j) {
    const std::complex<double> lambda = values(j);
    if (!(lambda.imag() > 0.0 || isDivergent(lambda))) continue;
    DampedMode mode{lambda, back * (vectors.col(j).tail(n) / lambda)};  // z = ż/λ
    normalizeToLargest(mode.shape);
    modes.push_back(std::move(mode));
  }
  return modes;
}

}  // namespace geardyn::detail
