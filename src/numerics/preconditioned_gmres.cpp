/// Restarted right-preconditioned GMRES (detail/preconditioned_gmres.h).

#include "geardyn/numerics/preconditioned_gmres.h"

#include <cmath>
#include <complex>
#include <vector>

namespace geardyn::detail {

using Complex = std::complex<double>;

GmresResult preconditionedGmres(const ComplexOperator& apply, const ComplexOperator& precondition,
                                const Eigen::VectorXcd& b, Eigen::VectorXcd& x, double tolerance,
                                int restart, int max_iterations) {
  GmresWorkspace workspace;
  return preconditionedGmres(apply, precondition, b, x, tolerance, restart, max_iterations, false,
                             workspace);
}

GmresResult preconditionedGmres(const ComplexOperator& apply, const ComplexOperator& precondition,
                                const Eigen::VectorXcd& b, Eigen::VectorXcd& x, double tolerance,
                                int restart, int max_iterations, bool initial_guess,
                                GmresWorkspace& ws) {
  GmresResult result;
  const Eigen::Index n = b.size();
  const double b_norm = b.norm();
  if (!initial_guess || x.size() != n || b_norm == 0.0) x = Eigen::VectorXcd::Zero(n);
  if (b_norm == 0.0) {
    result.converged = true;
    return result;
  }
  ws.Q.resize(n, restart + 1);  // Arnoldi basis of A P⁻¹
  ws.H.resize(restart + 1, restart);
  ws.g.resize(restart + 1);
  ws.cs.resize(restart);
  ws.sn.resize(restart);
  ws.z.resize(n);
  ws.w.resize(n);
  Eigen::MatrixXcd &Q = ws.Q, &H = ws.H;
  Eigen::VectorXcd &g = ws.g, &cs = ws.cs, &sn = ws.sn, &z = ws.z, &w = ws.w, &r = ws.r;
  if (x.isZero(0.0)) {
    r = b;
  } else {
    apply(x, w);
    r = b - w;
  }
  double r_norm = r.norm();
  if (r_norm > b_norm) {  // a guess worse than none
    x.setZero();
    r = b;
    r_norm = b_norm;
  }
  result.residual = r_norm / b_norm;
  if (result.residual <= tolerance) {
    result.converged = true;
    return result;
  }
  while (result.iterations < max_iterations) {
    H.setZero();
    g.setZero();
    g(0) = r_norm;
    Q.col(0) = r / r_norm;
    int j = 0;
    for (; j < restart && result.iterations < max_iterations; ++j, ++result.iterations) {
      precondition(Q.col(j), z);
      apply(z, w);
      for (int i = 0; i <= j; ++i) {  // modified Gram–Schmidt
        H(i, j) = Q.col(i).dot(w);
        w -= H(i, j) * Q.col(i);
      }
      H(j + 1, j) = w.norm();
      if (std::abs(H(j + 1, j)) > 0.0) Q.col(j + 1) = w / H(j + 1, j);
      // Givens rotations keep H upper triangular; |g(j + 1)| is the residual norm.
      for (int i = 0; i < j; ++i) {
        const Complex t = std::conj(cs(i)) * H(i, j) + std::conj(sn(i)) * H(i + 1, j);
        H(i + 1, j) = -sn(i) * H(i, j) + cs(i) * H(i + 1, j);
        H(i, j) = t;
      }
      const double h = std::sqrt(std::norm(H(j, j)) + std::norm(H(j + 1, j)));
      cs(j) = h > 0.0 ? H(j, j) / h : Complex(1.0);
      sn(j) = h > 0.0 ? H(j + 1, j) / h : Complex(0.0);
      H(j, j) = h;
      H(j + 1, j) = 0.0;
      g(j + 1) = -sn(j) * g(j);
      g(j) = std::conj(cs(j)) * g(j);
      if (std::abs(g(j + 1)) <= tolerance * b_norm) {
        ++j, ++result.iterations;
        break;
      }
    }
    // x += P⁻¹ Q y with H y = g (upper triangular j × j).
    ws.y = g.head(j);
    H.topLeftCorner(j, j).triangularView<Eigen::Upper>().solveInPlace(ws.y);
    r.noalias() = Q.leftCols(j) * ws.y;
    precondition(r, z);
    x += z;
    apply(x, w);
    r = b - w;
    r_norm = r.norm();
    result.residual = r_norm / b_norm;
    if (result.residual <= tolerance) {
      result.converged = true;
      return result;
    }
  }
  return result;
}

}  // namespace geardyn::detail
