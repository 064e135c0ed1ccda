/// The derived number of mesh harmonics of a train's frequency-domain steady state
/// (train_truncation.h; docs/theory/torus_harmonic_balance.md, "The default truncation").

#include "geardyn/solvers/train_truncation.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/solvers/detail/train_steady_parts.h"

namespace geardyn {
namespace {

using Complex = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
/// Orders below this fraction of the mean loaded deflection's force k̄ |ε₀| are the DFT's
/// round-off (1e-16 per sample, summed over a few thousand samples), not content.
constexpr double kRoundOff = 1e-12;

}  // namespace

void MeshHarmonicsOptions::validate() const {
  if (!(fraction > 0.0 && fraction < 1.0)) {
    throw InputError("forced.harmonics_fraction", fmt::format("{:g}", fraction), "in (0, 1)");
  }
  if (min_harmonics < 1 || max_harmonics < min_harmonics) {
    throw InputError("forced.mesh_harmonics", fmt::format("{}..{}", min_harmonics, max_harmonics),
                     "1 <= smallest <= largest");
  }
}

MeshHarmonicsEstimate estimateMeshHarmonics(const GearTrainModel& model,
                                            const std::vector<double>& speeds,
                                            const MeshHarmonicsOptions& options) {
  options.validate();
  const auto& meshes = model.meshes();
  const int r = static_cast<int>(meshes.size());
  const int orders = options.max_harmonics;  // E: orders of the estimate
  MeshHarmonicsEstimate out;
  out.per_mesh.assign(r, options.min_harmonics);
  out.worst_speed_index.assign(r, 0);
  out.relative_orders.assign(r, std::vector<double>(orders, 0.0));
  out.per_speed.assign(speeds.size(), std::vector<int>(r, options.min_harmonics));
  out.envelope.assign(r, std::vector<double>(orders, 0.0));
  if (r == 0) return out;
  // The static mean state under the mean meshes (rigid-body modes held by a mass-weighted
  // penalty, as in the balances) and each mesh's mean force W_m = k̄_m (δ̄_m − ē_m) [N].
  const double operating = model.inputSpeed();
  const Eigen::MatrixXd K = model.meanStiffnessAt(operating);
  const Eigen::MatrixXd& M = model.mass();
  const Eigen::MatrixXd rigid = detail::rigidModes(K, M);
  Eigen::MatrixXd D0 = K;
  if (rigid.cols() > 0) {
    const Eigen::MatrixXd Mr = M * rigid;
    D0 += std::max(K.diagonal().cwiseAbs().maxCoeff(), 1e-300) * Mr * Mr.transpose();
  }
  const Eigen::VectorXd x0 = D0.partialPivLu().solve(model.staticLoad());
  // The undamped modes of the mean train and their modal damping φᵢᵀCφᵢ (mass-normalised;
  // the gyroscopic part is skew and drops out of the diagonal) [rad/s, 1/s].
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(0.5 * (K + K.transpose()),
                                                                        M);
  const Eigen::VectorXd w2 = modes.eigenvalues();
  const Eigen::MatrixXd& phi = modes.eigenvectors();
  const Eigen::MatrixXd C = model.dampingAt(operating);
  const double largest_w2 = std::max(std::abs(w2(w2.size() - 1)), 1e-300);
  std::vector<int> elastic;
  for (Eigen::Index i = 0; i < w2.size(); ++i) {
    if (w2(i) > 1e-10 * largest_w2) elastic.push_back(static_cast<int>(i));
  }
  Eigen::VectorXd modal_damping(static_cast<Eigen::Index>(elastic.size()));
  Eigen::VectorXd modal_w2(modal_damping.size());
  Eigen::MatrixXd participation(r, modal_damping.size());  // (v_mᵀ φᵢ)²
  for (std::size_t a = 0; a < elastic.size(); ++a) {
    const Eigen::VectorXd mode = phi.col(elastic[a]);
    modal_w2(a) = w2(elastic[a]);
    modal_damping(a) = mode.dot(C * mode);
    for (int m = 0; m < r; ++m) participation(m, a) = std::pow(model.meshVector(m).dot(mode), 2);
  }
  // Each mesh alone: its one-generator balance to E orders with the train's compliance at the
  // mesh, δ_l + B(lω) Σ_{l'≠l} k̂_{l−l'} δ_{l'} = B(lω) (φ_l − k̂_l δ̄) for l = 1..E (δ_{−l} =
  // conj δ_l, δ₀ = δ̄ the static mean), in real form, then the force orders
  // F_l = Σ_{l'} k̂_{l−l'} δ_{l'} − (k e)^_l.
  const int E = orders;
  Eigen::MatrixXd A(2 * E, 2 * E);
  Eigen::VectorXd b(2 * E);
  Eigen::PartialPivLU<Eigen::MatrixXd> lu(2 * E);
  Eigen::VectorXcd delta(2 * E + 1), Bl(E + 1);
  std::vector<double> force(E + 1);
  for (int m = 0; m < r; ++m) {
    const TrainMesh& mesh = meshes[m];
    const detail::MeshFourier fourier = detail::meshFourier(mesh, 2 * E);
    const auto k_hat = [&](int l) { return fourier.k[2 * E + l]; };
    const double mean_force = std::abs(mesh.mean_stiffness * mesh.deflection(x0));
    const Complex d0 = mesh.deflection(x0);
    int needed = options.min_harmonics;
    for (std::size_t s = 0; s < speeds.size(); ++s) {
      const double omega = kTwoPi * mesh.frequency_ratio * std::abs(speeds[s]);
      if (!(omega > 0.0)) continue;
      for (int l = 1; l <= E; ++l) {
        const double w = l * omega;
        Complex B = 0.0;
        for (Eigen::Index a = 0; a < modal_w2.size(); ++a) {
          B += participation(m, a) / Complex(modal_w2(a) - w * w, w * modal_damping(a));
        }
        Bl(l) = B;
      }
      A.setIdentity();
      for (int l = 1; l <= E; ++l) {
        const Complex rhs =
            Bl(l) * (fourier.ke[2 * E + l] +
                     Complex(0.0, l * omega) * mesh.damping * fourier.e[2 * E + l] - k_hat(l) * d0);
        b(2 * l - 2) = rhs.real();
        b(2 * l - 1) = rhs.imag();
        for (int q = 1; q <= E; ++q) {
          // B k̂_{l−q} δ_q + B k̂_{l+q} conj δ_q on (Re δ_q, Im δ_q).
          const Complex c1 = q == l ? 0.0 : Bl(l) * k_hat(l - q), c2 = Bl(l) * k_hat(l + q);
          A(2 * l - 2, 2 * q - 2) += c1.real() + c2.real();
          A(2 * l - 1, 2 * q - 2) += c1.imag() + c2.imag();
          A(2 * l - 2, 2 * q - 1) += -c1.imag() + c2.imag();
          A(2 * l - 1, 2 * q - 1) += c1.real() - c2.real();
        }
      }
      lu.compute(A);
      const Eigen::VectorXd x = lu.solve(b);
      delta(E) = d0;
      for (int q = 1; q <= E; ++q) {
        delta(E + q) = Complex(x(2 * q - 2), x(2 * q - 1));
        delta(E - q) = std::conj(delta(E + q));
      }
      double largest = 0.0;
      for (int l = 1; l <= E; ++l) {
        Complex f = -fourier.ke[2 * E + l];
        for (int q = -E; q <= E; ++q) f += k_hat(l - q) * delta(E + q);
        force[l] = 2.0 * std::abs(f);
        largest = std::max(largest, force[l]);
      }
      // Round-off (a mesh whose k and e do not vary): nothing to keep.
      const double floor = std::max(options.fraction * largest, kRoundOff * mean_force);
      if (!(largest > floor) && largest <= kRoundOff * mean_force) continue;
      int L = E;  // the smallest L with every order above it below the floor
      while (L > 1 && force[L] <= floor) --L;
      out.per_speed[s][m] = std::clamp(L, options.min_harmonics, options.max_harmonics);
      for (int l = 1; l <= E; ++l) {
        out.envelope[m][l - 1] = std::max(out.envelope[m][l - 1], force[l] / largest);
      }
      if (L >= needed) {
        needed = L;
        out.worst_speed_index[m] = static_cast<int>(s);
        for (int l = 1; l <= E; ++l) out.relative_orders[m][l - 1] = force[l] / largest;
      }
    }
    out.capped = out.capped || needed >= E;
    out.per_mesh[m] = std::clamp(needed, options.min_harmonics, options.max_harmonics);
  }
  out.harmonics = *std::max_element(out.per_mesh.begin(), out.per_mesh.end());
  return out;
}

}  // namespace geardyn
