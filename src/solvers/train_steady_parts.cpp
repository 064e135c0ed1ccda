/// Pieces shared by the linear steady-state solvers of a train (detail/train_steady_parts.h).

#include "geardyn/solvers/detail/train_steady_parts.h"

#include <cmath>
#include <numbers>

#include "geardyn/stiffness/mesh_stiffness_summary.h"

namespace geardyn::detail {

using Complex = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

std::pair<long long, long long> rationalApproximation(double x) {
  long long p0 = 0, q0 = 1, p1 = 1, q1 = 0;
  double r = x;
  for (int i = 0; i < 40; ++i) {
    const long long a = static_cast<long long>(std::floor(r));
    const long long p2 = a * p1 + p0, q2 = a * q1 + q0;
    if (q2 > 1000000) break;
    p0 = p1, q0 = q1, p1 = p2, q1 = q2;
    if (std::abs(x - static_cast<double>(p1) / q1) <= 1e-9 * x) break;
    const double frac = r - a;
    if (frac < 1e-12) break;
    r = 1.0 / frac;
  }
  return {p1, q1};
}

Eigen::MatrixXd rigidModes(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(0.5 * (K + K.transpose()),
                                                                         M);
  const Eigen::VectorXd& w2 = solver.eigenvalues();
  const double largest = std::max(std::abs(w2(w2.size() - 1)), 1e-300);
  int count = 0;
  while (count < w2.size() && std::abs(w2(count)) < 1e-10 * largest) ++count;
  return solver.eigenvectors().leftCols(count);
}

Eigen::VectorXd elementDeformation(const TrainElement& e, const Eigen::VectorXd& q) {
  Eigen::VectorXd local(e.dofs.size());
  for (std::size_t i = 0; i < e.dofs.size(); ++i) local(i) = q(e.dofs[i]);
  return e.jacobian * local;
}

MeshFourier meshFourier(const TrainMesh& mesh, int L) {
  MeshFourier out;
  const MeshStiffnessSummary summary = summarizeMeshStiffness(*mesh.stiffness, L);
  const auto breaks = mesh.stiffness->discontinuities();
  out.k.assign(2 * L + 1, 0.0);
  out.ke.assign(2 * L + 1, 0.0);
  out.e.assign(2 * L + 1, 0.0);
  const bool has_error = !mesh.transmission_error.isZero();
  // ∫₀¹ f(φ) e^{−i2πlφ} dφ, piecewise between the stiffness's jumps.
  const auto coefficient = [&](const auto& f, int l) {
    const double re = integrateOverPeriod(
        [&](double phi) { return f(phi) * std::cos(kTwoPi * l * phi); }, breaks);
    const double im = integrateOverPeriod(
        [&](double phi) { return -f(phi) * std::sin(kTwoPi * l * phi); }, breaks);
    return Complex(re, im);
  };
  for (int l = 0; l <= L; ++l) {
    const Complex c =
        l == 0 ? Complex(summary.mean) : 0.5 * Complex(summary.cosine[l - 1], -summary.sine[l - 1]);
    const Complex shift = std::polar(1.0, kTwoPi * l * mesh.phase);
    out.k[L + l] = c * shift;
    out.k[L - l] = std::conj(c * shift);
    if (!has_error) continue;
    const auto ke = [&](double phi) {
      return mesh.stiffness->stiffness(phi) * mesh.transmission_error.value(phi);
    };
    const auto e = [&](double phi) { return mesh.transmission_error.value(phi); };
    out.ke[L + l] = coefficient(ke, l) * shift;
    out.ke[L - l] = std::conj(out.ke[L + l]);
    out.e[L + l] = coefficient(e, l) * shift;
    out.e[L - l] = std::conj(out.e[L + l]);
  }
  return out;
}

}  // namespace geardyn::detail
