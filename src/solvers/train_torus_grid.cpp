/// The torus steady state on its k-dimensional grid of generator phases (train_torus.h): mesh
/// forces and their peaks, per-tone spectra, element forces; and q(t) along the trajectory.
/// The grid transforms are separable, one axis at a time (a k-dimensional DFT as k matrix
/// products: cheap at the sizes the tone sets have, and free of shared plans between threads).

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geardyn/solvers/detail/train_steady_parts.h"
#include "geardyn/solvers/train_torus.h"

namespace geardyn {
namespace {

using Complex = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
/// Lines below this fraction of a mesh force's largest line are not listed (round-off).
constexpr double kLineFloor = 1e-9;

/// Transforms axis `axis` of a tensor (sizes `dims`, axis 0 fastest) by E (out × dims[axis]).
Eigen::VectorXcd transformAxis(const Eigen::VectorXcd& in, std::vector<int>& dims, int axis,
                               const Eigen::MatrixXcd& E) {
  long long before = 1, after = 1;
  for (int a = 0; a < axis; ++a) before *= dims[a];
  for (int a = axis + 1; a < static_cast<int>(dims.size()); ++a) after *= dims[a];
  const long long d = dims[axis], m = E.rows();
  Eigen::VectorXcd out(before * m * after);
  for (long long c = 0; c < after; ++c) {
    const Eigen::Map<const Eigen::MatrixXcd> x(in.data() + before * d * c, before, d);
    Eigen::Map<Eigen::MatrixXcd> y(out.data() + before * m * c, before, m);
    y.noalias() = x * E.transpose();
  }
  dims[axis] = static_cast<int>(m);
  return out;
}

/// The grid of generator phases θ_j = 2π s / M_j and the box of tones |n_j| <= K_j its
/// samples resolve.
struct TorusGrid {
  std::vector<int> M, N, K;
  std::vector<Eigen::MatrixXcd> to_grid, from_grid;  // M_j × (2N_j+1), (2K_j+1) × M_j
  long long points = 1;

  TorusGrid(const std::vector<int>& samples, const std::vector<int>& harmonics)
      : M(samples), N(harmonics) {
    for (std::size_t j = 0; j < M.size(); ++j) {
      K.push_back(std::min(M[j] / 2 - 1, 2 * N[j]));
      Eigen::MatrixXcd E(M[j], 2 * N[j] + 1), F(2 * K[j] + 1, M[j]);
      for (int s = 0; s < M[j]; ++s) {
        const double theta = kTwoPi * s / M[j];
        for (int i = 0; i <= 2 * N[j]; ++i) E(s, i) = std::polar(1.0, (i - N[j]) * theta);
        for (int i = 0; i <= 2 * K[j]; ++i) {
          F(i, s) = std::polar(1.0 / M[j], -(i - K[j]) * theta);
        }
      }
      to_grid.push_back(std::move(E));
      from_grid.push_back(std::move(F));
      points *= M[j];
    }
  }
  /// The real fields Σ_t C(t, f) e^{i n_t·θ} at every grid point (rows: fields), all fields
  /// through each axis's transform at once.
  Eigen::MatrixXd evaluate(const Eigen::MatrixXi& tones, const Eigen::MatrixXcd& C) const {
    const int fields = static_cast<int>(C.cols());
    std::vector<int> dims{fields};
    long long box = fields;
    for (int Nj : N) dims.push_back(2 * Nj + 1), box *= 2 * Nj + 1;
    Eigen::VectorXcd tensor = Eigen::VectorXcd::Zero(box);
    for (Eigen::Index t = 0; t < tones.cols(); ++t) {
      const long long at = boxIndex(tones.col(t), N) * fields;
      for (int f = 0; f < fields; ++f) tensor(at + f) = C(t, f);
    }
    for (int j = 0; j < static_cast<int>(N.size()); ++j) {
      tensor = transformAxis(tensor, dims, j + 1, to_grid[j]);
    }
    return Eigen::Map<const Eigen::MatrixXcd>(tensor.data(), fields, points).real();
  }
  /// Fourier coefficients c_n, |n_j| <= K_j, of real fields on the grid (rows: fields).
  Eigen::MatrixXcd spectrum(const Eigen::MatrixXd& fields) const {
    std::vector<int> dims{static_cast<int>(fields.rows())};
    dims.insert(dims.end(), M.begin(), M.end());
    Eigen::VectorXcd tensor =
        Eigen::Map<const Eigen::VectorXd>(fields.data(), fields.size()).cast<Complex>();
    for (int j = 0; j < static_cast<int>(M.size()); ++j) {
      tensor = transformAxis(tensor, dims, j + 1, from_grid[j]);
    }
    return Eigen::Map<const Eigen::MatrixXcd>(tensor.data(), fields.rows(),
                                              tensor.size() / fields.rows());
  }
  static long long boxIndex(const Eigen::Ref<const Eigen::VectorXi>& n, const std::vector<int>& B) {
    long long index = 0, stride = 1;
    for (std::size_t j = 0; j < B.size(); ++j) {
      index += (n(j) + B[j]) * stride;
      stride *= 2 * B[j] + 1;
    }
    return index;
  }
  /// The sample index s_j of grid point p along axis j.
  int sample(long long p, int j) const {
    for (int a = 0; a < j; ++a) p /= M[a];
    return static_cast<int>(p % M[j]);
  }
};

/// The lines of a spectrum over the box |n_j| <= K_j at positive frequencies.
std::vector<TorusLine> linesOf(const Eigen::VectorXcd& c, const TorusGrid& grid,
                               const std::vector<double>& g) {
  std::vector<TorusLine> lines;
  const int k = static_cast<int>(grid.K.size());
  Eigen::VectorXi n(k);
  for (Eigen::Index i = 0; i < c.size(); ++i) {
    long long rest = i;
    double frequency = 0.0;
    for (int j = 0; j < k; ++j) {
      n(j) = static_cast<int>(rest % (2 * grid.K[j] + 1)) - grid.K[j];
      rest /= 2 * grid.K[j] + 1;
      frequency += n(j) * g[j];
    }
    if (frequency <= 1e-9 * g[0]) continue;
    lines.push_back({std::vector<int>(n.data(), n.data() + k), frequency, 2.0 * std::abs(c(i))});
  }
  double largest = 0.0;
  for (const TorusLine& line : lines) largest = std::max(largest, line.amplitude);
  std::erase_if(lines,
                [&](const TorusLine& line) { return line.amplitude < kLineFloor * largest; });
  std::sort(lines.begin(), lines.end(),
            [](const TorusLine& a, const TorusLine& b) { return a.frequency < b.frequency; });
  return lines;
}

}  // namespace

void TrainTorusSolver::postProcess(TrainTorusState& s) const {
  const auto& meshes = model_.meshes();
  const int r = static_cast<int>(meshes.size());
  const int L = options_.mesh_harmonics;
  const TorusGrid grid(samples_, generators_.harmonics);
  // Every field on the grid in one pass: the mesh deflections, then the element deformations.
  Eigen::Index rows = r;
  for (const TrainElement& e : model_.elements()) rows += e.jacobian.rows();
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(rows, model_.dofCount());
  for (int m = 0; m < r; ++m) S.row(m) = model_.meshVector(m).transpose();
  Eigen::Index row = r;
  for (const TrainElement& e : model_.elements()) {
    for (std::size_t i = 0; i < e.dofs.size(); ++i) {
      S.block(row, e.dofs[i], e.jacobian.rows(), 1) += e.jacobian.col(i);
    }
    row += e.jacobian.rows();
  }
  const Eigen::MatrixXd fields =
      grid.evaluate(s.tones, (S.cast<Complex>() * s.harmonic).transpose());
  Eigen::MatrixXd force(r, grid.points);
  for (int m = 0; m < r; ++m) {
    const TrainMesh& mesh = meshes[m];
    const int j = generators_.mesh_generator[m], P = generators_.mesh_multiple[m];
    // k and e along the mesh's own generator: φ = P_m s / M_j + φ_m0 [mesh periods].
    Eigen::VectorXd k_axis(grid.M[j]), e_axis(grid.M[j]);
    for (int i = 0; i < grid.M[j]; ++i) {
      const double phase = static_cast<double>(P) * i / grid.M[j] + mesh.phase;
      k_axis(i) = mesh.stiffness->stiffness(phase);
      e_axis(i) = mesh.transmission_error.value(phase);
    }
    for (long long p = 0; p < grid.points; ++p) {
      const int i = grid.sample(p, j);
      force(m, p) = k_axis(i) * mesh.contactDeflection(fields(m, p) - e_axis(i));
    }
    const double mean = force.row(m).mean();
    s.mesh_force_mean.push_back(mean);
    s.mesh_force_max.push_back(force.row(m).maxCoeff());
    s.mesh_force_min.push_back(force.row(m).minCoeff());
    s.dynamic_factor.push_back(
        std::abs(mean) > 0.0 ? force.row(m).cwiseAbs().maxCoeff() / std::abs(mean) : 0.0);
  }
  const Eigen::MatrixXcd c = grid.spectrum(force);
  for (int m = 0; m < r; ++m) {
    const int j = generators_.mesh_generator[m], P = generators_.mesh_multiple[m];
    std::vector<double> orders;
    Eigen::VectorXi n = Eigen::VectorXi::Zero(static_cast<int>(grid.K.size()));
    for (int l = 1; l <= L; ++l) {
      n(j) = l * P;
      orders.push_back(n(j) <= grid.K[j] ? 2.0 * std::abs(c(m, TorusGrid::boxIndex(n, grid.K)))
                                         : 0.0);
    }
    s.mesh_force_harmonics.push_back(std::move(orders));
    s.mesh_force_lines.push_back(linesOf(c.row(m).transpose(), grid, s.generator_frequency));
  }
  row = r;
  for (const TrainElement& e : model_.elements()) {
    const Eigen::MatrixXd forces = e.local_stiffness * fields.middleRows(row, e.jacobian.rows());
    row += e.jacobian.rows();
    const Eigen::VectorXd mean = forces.rowwise().mean();
    s.element_dynamic_force.push_back((forces.colwise() - mean).colwise().norm().maxCoeff());
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
