/// Arnoldi without restarts for the Floquet strip of a Hill eigenproblem (detail/strip_arnoldi.h).

#include "geardyn/numerics/strip_arnoldi.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "geardyn/numerics/floquet_strip.h"

namespace geardyn::detail {
namespace {

using Complex = std::complex<double>;
using RowMatrixXd = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// The eigenvalues of the upper Hessenberg H (m × m) from its real Schur form T (eigenvalues
/// only: no Schur vectors), read off T's 1 × 1 and 2 × 2 diagonal blocks as Eigen's EigenSolver
/// does. Empty when the QR iteration does not converge.
Eigen::VectorXcd hessenbergEigenvalues(const Eigen::MatrixXd& H) {
  const Eigen::Index m = H.rows();
  Eigen::RealSchur<Eigen::MatrixXd> schur(m);
  schur.computeFromHessenberg(H, H, false);  // the second argument (Q) is unused without U
  if (schur.info() != Eigen::Success) return {};
  const Eigen::MatrixXd& T = schur.matrixT();
  Eigen::VectorXcd values(m);
  for (Eigen::Index i = 0; i < m;) {
    if (i == m - 1 || T(i + 1, i) == 0.0) {
      values(i) = T(i, i);
      ++i;
      continue;
    }
    const double p = 0.5 * (T(i, i) - T(i + 1, i + 1));
    const double scale = std::max({std::abs(p), std::abs(T(i + 1, i)), std::abs(T(i, i + 1))});
    const double p0 = p / scale, t0 = T(i + 1, i) / scale, t1 = T(i, i + 1) / scale;
    const double z = scale * std::sqrt(std::abs(p0 * p0 + t0 * t1));
    values(i) = Complex(T(i + 1, i + 1) + p, z);
    values(i + 1) = Complex(T(i + 1, i + 1) + p, -z);
    i += 2;
  }
  return values;
}

/// |e_mᵀ y| of the unit eigenvector y of the upper Hessenberg H (m × m, row-major) for its
/// eigenvalue θ: one inverse-iteration solve U y = (1, …, 1) with the LU of H − θI by
/// adjacent-row pivoting (O(m²): only the Hessenberg part is copied and eliminated; the first
/// step of LAPACK's xLAEIN), a pivot below ε‖H‖ replaced by ε‖H‖.
double lastComponent(const RowMatrixXd& H, Complex theta, double small, std::vector<Complex>& A,
                     Eigen::VectorXcd& y) {
  const Eigen::Index m = H.rows();
  A.resize(static_cast<std::size_t>(m * m));
  for (Eigen::Index i = 0; i < m; ++i) {
    Complex* row = A.data() + i * m;
    const double* h = H.data() + i * m;
    for (Eigen::Index j = std::max<Eigen::Index>(i - 1, 0); j < m; ++j) row[j] = h[j];
    row[i] -= theta;
  }
  const double small2 = small * small;
  for (Eigen::Index k = 0; k + 1 < m; ++k) {
    Complex *rk = A.data() + k * m, *rk1 = rk + m;
    if (std::norm(rk1[k]) > std::norm(rk[k])) std::swap_ranges(rk + k, rk + m, rk1 + k);
    if (std::norm(rk[k]) < small2) rk[k] = small;
    const Complex l = rk1[k] / rk[k];
    for (Eigen::Index j = k + 1; j < m; ++j) rk1[j] -= l * rk[j];
  }
  Complex* last = A.data() + (m - 1) * m + (m - 1);
  if (std::norm(*last) < small2) *last = small;
  y.setOnes(m);
  for (Eigen::Index i = m - 1; i >= 0; --i) {
    const Complex* row = A.data() + i * m;
    Complex sum = y(i);
    for (Eigen::Index j = i + 1; j < m; ++j) sum -= row[j] * y(j);
    y(i) = sum / row[i];
    if (std::norm(y(i)) > 1e200) y.segment(i, m - i) /= std::abs(y(i));  // a near-singular pivot
  }
  return std::abs(y(m - 1)) / y.norm();
}

/// The converged strip values of the Arnoldi factorisation (H: (m + 1) × m, its last row β e_mᵀ):
/// Ritz values θ of H_m whose λ = 1/θ lies in the strip, with ‖residual‖ = β |e_mᵀ y| <=
/// tolerance · max(|θ|, ε^{2/3}) (Spectra's test).
std::vector<Complex> convergedStrip(const Eigen::MatrixXd& H, double omega, double tolerance,
                                    double& radius) {
  const Eigen::Index m = H.cols();
  const Eigen::MatrixXd Hm = H.topRows(m);
  const double beta = std::abs(H(m, m - 1));
  const Eigen::VectorXcd theta = hessenbergEigenvalues(Hm);
  std::vector<Complex> out;
  radius = 0.0;
  if (theta.size() != m) return out;
  const double eps = std::numeric_limits<double>::epsilon();
  const double small = eps * Hm.cwiseAbs().rowwise().sum().maxCoeff();
  const double eps23 = std::pow(eps, 2.0 / 3.0);
  const RowMatrixXd Hr = Hm;
  std::vector<Complex> A;
  Eigen::VectorXcd y(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    if (theta(i).imag() < 0.0) continue;  // a conjugate pair's residuals are equal: test once
    if (std::abs(theta(i)) == 0.0) continue;
    const Complex lambda = 1.0 / theta(i);
    if (std::abs(lambda.imag()) - 0.5 * omega > 1e-3 * omega) continue;  // floquetStrip's margin
    const double residual = beta * lastComponent(Hr, theta(i), small, A, y);
    if (residual > tolerance * std::max(std::abs(theta(i)), eps23)) continue;
    out.push_back(lambda);
    if (theta(i).imag() > 0.0) out.push_back(std::conj(lambda));
    radius = std::max(radius, std::abs(lambda));
  }
  return out;
}

}  // namespace

StripArnoldiResult stripArnoldi(const std::function<void(const double*, double*)>& apply,
                                Eigen::Index N, double omega, int n,
                                const StripArnoldiOptions& options) {
  StripArnoldiResult out;
  const Eigen::Index mmax = std::min<Eigen::Index>(options.max_dimension, N - 1);
  Eigen::MatrixXd V(N, mmax + 1);
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(mmax + 1, mmax);
  // A fixed pseudo-random start (splitmix64 → [−0.5, 0.5)): every eigenvector present.
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  for (Eigen::Index i = 0; i < N; ++i) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    V(i, 0) = static_cast<double>(z >> 11) * 0x1.0p-53 - 0.5;
  }
  V.col(0).normalize();
  Eigen::VectorXd w(N), h(mmax), c(mmax);
  Eigen::Index next = std::max(options.first_check, 1);
  for (Eigen::Index j = 0; j < mmax; ++j) {
    apply(V.col(j).data(), w.data());
    ++out.operations;
    const auto Vj = V.leftCols(j + 1);
    // CGS2: two classical Gram–Schmidt passes, each a pair of matrix–vector products.
    h.head(j + 1).noalias() = Vj.transpose() * w;
    w.noalias() -= Vj * h.head(j + 1);
    c.head(j + 1).noalias() = Vj.transpose() * w;
    w.noalias() -= Vj * c.head(j + 1);
    H.col(j).head(j + 1) = h.head(j + 1) + c.head(j + 1);
    const double beta = w.norm();
    H(j + 1, j) = beta;
    const Eigen::Index m = j + 1;
    // An invariant subspace (β at round-off): the Ritz values are exact, so check and stop.
    const bool invariant = beta <= 1e-14 * H.col(j).head(j + 1).norm();
    if (m == next || invariant || m == mmax) {
      out.dimension = static_cast<int>(m);
      const std::vector<Complex> strip =
          convergedStrip(H.topLeftCorner(m + 1, m), omega, options.tolerance, out.radius);
      Eigen::VectorXcd values(static_cast<Eigen::Index>(strip.size()));
      for (std::size_t k = 0; k < strip.size(); ++k)
        values(static_cast<Eigen::Index>(k)) = strip[k];
      out.strip = floquetStrip(values, omega, n);
      if (static_cast<int>(out.strip.size()) == 2 * n) {
        out.certified = true;
        return out;
      }
      next += options.check_step;
    }
    if (invariant) break;
    V.col(j + 1) = w / beta;
  }
  return out;
}

}  // namespace geardyn::detail
