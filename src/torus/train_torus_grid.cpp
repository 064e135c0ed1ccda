/// The torus steady state on its k-dimensional grid of generator phases (train_torus.h): mesh
/// forces and their peaks, per-tone spectra, element forces (FFTW's real multi-dimensional
/// transforms, detail/torus_fft.h); and q(t) along the trajectory.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geardyn/torus/detail/torus_fft.h"
#include "geardyn/torus/train_torus.h"
#include "train_torus_workspace.h"

namespace geardyn {
namespace {

using Complex = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

}  // namespace

void TrainTorusSolver::postProcess(TrainTorusState& s, detail::TorusWorkspace& ws) const {
  const auto& meshes = model_.meshes();
  const int r = static_cast<int>(meshes.size());
  const int L = options_.mesh_harmonics;
  const detail::TorusFft& fft = *fft_;
  const std::vector<int>& M = fft.samples();
  // Every field on the grid in one transform: the mesh deflections, then the element
  // deformations (fields_: rows vᵀ, then J over each element's DOFs).
  const Eigen::Index rows = fields_.rows();
  ws.C.noalias() = (fields_.cast<Complex>() * s.harmonic).transpose();  // tones × fields
  Eigen::MatrixXcd& half = ws.half;
  half.setZero(fft.halfSize(), rows);
  for (Eigen::Index t = 0; t < s.tones.cols(); ++t) {
    if (s.tones(0, t) >= 0) half.row(fft.halfIndex(s.tones.col(t))) = ws.C.row(t);
  }
  Eigen::MatrixXd& fields = ws.fields;
  fft.toGrid(half, fields);
  Eigen::MatrixXd& force = ws.force;
  force.resize(fft.points(), r);
  for (int m = 0; m < r; ++m) {
    const TrainMesh& mesh = meshes[m];
    const int j = generators_.mesh_generator[m], P = generators_.mesh_multiple[m];
    // k and e along the mesh's own generator: φ = P_m s / M_j + φ_m0 [mesh periods].
    Eigen::VectorXd k_axis(M[j]), e_axis(M[j]);
    for (int i = 0; i < M[j]; ++i) {
      const double phase = static_cast<double>(P) * i / M[j] + mesh.phase;
      k_axis(i) = mesh.stiffness->stiffness(phase);
      e_axis(i) = mesh.transmission_error.value(phase);
    }
    long long stride = 1;
    for (int a = 0; a < j; ++a) stride *= M[a];
    for (long long p = 0; p < fft.points(); ++p) {
      const int i = static_cast<int>((p / stride) % M[j]);
      force(p, m) = k_axis(i) * mesh.contactDeflection(fields(p, m) - e_axis(i));
    }
    const double mean = force.col(m).mean();
    s.mesh_force_mean.push_back(mean);
    s.mesh_force_max.push_back(force.col(m).maxCoeff());
    s.mesh_force_min.push_back(force.col(m).minCoeff());
    s.dynamic_factor.push_back(
        std::abs(mean) > 0.0 ? force.col(m).cwiseAbs().maxCoeff() / std::abs(mean) : 0.0);
  }
  Eigen::Index row = r;
  for (const TrainElement& e : model_.elements()) {
    const Eigen::MatrixXd forces =
        e.local_stiffness * fields.middleCols(row, e.jacobian.rows()).transpose();
    row += e.jacobian.rows();
    const Eigen::VectorXd mean = forces.rowwise().mean();
    s.element_dynamic_force.push_back((forces.colwise() - mean).colwise().norm().maxCoeff());
  }
  // The spectra: lines up to twice the kept harmonics (the products k δ) that the grid resolves.
  std::vector<int> K;
  for (std::size_t j = 0; j < M.size(); ++j) {
    K.push_back(std::min((M[j] - 1) / 2, 2 * generators_.harmonics[j]));
  }
  Eigen::MatrixXcd& spectrum = ws.spectrum;
  fft.toSpectrum(force, spectrum);
  Eigen::VectorXi n = Eigen::VectorXi::Zero(static_cast<int>(M.size()));
  for (int m = 0; m < r; ++m) {
    const int j = generators_.mesh_generator[m], P = generators_.mesh_multiple[m];
    std::vector<double> orders;
    n.setZero();
    for (int l = 1; l <= L; ++l) {
      n(j) = l * P;
      orders.push_back(n(j) <= K[j] ? 2.0 * std::abs(spectrum(fft.halfIndex(n), m)) : 0.0);
    }
    s.mesh_force_harmonics.push_back(std::move(orders));
    s.mesh_force_lines.push_back(detail::torusLines(spectrum, m, fft, K, s.generator_frequency));
  }
}

Eigen::MatrixXd TrainTorusState::displacement(const Eigen::VectorXd& times) const {
  Eigen::MatrixXd q(times.size(), harmonic.rows());
  for (Eigen::Index k = 0; k < times.size(); ++k) {
    Eigen::VectorXcd sum = Eigen::VectorXcd::Zero(harmonic.rows());
    for (Eigen::Index t = 0; t < harmonic.cols(); ++t) {
      sum += harmonic.col(t) * std::polar(1.0, kTwoPi * tone_frequency(t) * times(k));
    }
    q.row(k) = sum.real().transpose();
  }
  return q;
}

}  // namespace geardyn
