/// Lyapunov exponents of a torus solution's variational equation (train_torus_lyapunov.h).

#include "geardyn/torus/train_torus_lyapunov.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>

#include "geardyn/solvers/detail/train_steady_parts.h"
#include "geardyn/solvers/newmark.h"

namespace geardyn {
namespace {

using Sparse = Eigen::SparseMatrix<double>;

Sparse sparseOf(const Eigen::MatrixXd& A) {
  Sparse S = A.sparseView(0.0, 0.0);
  S.makeCompressed();
  return S;
}

// S(t_i) per step and mesh: k(φ) g′(δ − e) − k̄ along the trajectory [N/m].
Eigen::MatrixXd meshSlopes(const GearTrainModel& model, const TrainTorusBalance& balance,
                           const HarmonicBalancePoint& point, const Eigen::VectorXd& times) {
  const Eigen::MatrixXd delta = balance.coordinatesAt(point.q, point.omega, times);
  const double speed = std::abs(balance.inputSpeed(point.omega));
  const TrainTorusGenerators& g = balance.generators();
  const int r = balance.meshCount();
  Eigen::MatrixXd S(times.size(), r);
  for (int m = 0; m < r; ++m) {
    const TrainMesh& mesh = model.meshes()[m];
    const double f = g.mesh_multiple[m] * g.ratio[g.mesh_generator[m]] * speed;  // [Hz]
    for (Eigen::Index i = 0; i < times.size(); ++i) {
      const double phase = f * times(i) + mesh.phase;
      const double k = mesh.stiffness->stiffness(phase);
      double s = 1.0;
      mesh.contactDeflection(delta(i, m) - mesh.transmission_error.value(phase), &s);
      S(i, m) = k * s - mesh.mean_stiffness;
    }
  }
  return S;
}

}  // namespace

TorusLyapunovEstimate torusLyapunovEstimate(const GearTrainModel& model,
                                            const TrainTorusBalance& balance,
                                            const HarmonicBalancePoint& point, double window,
                                            int columns, int steps_per_mesh_period) {
  TorusLyapunovEstimate out;
  if (balance.coordinateCount() != balance.meshCount()) {
    out.status = "unsupported";
    return out;
  }
  for (const TrainMesh& mesh : model.meshes()) {
    if (mesh.toothPairs()) {
      out.status = "unsupported";
      return out;
    }
  }
  const double speed = balance.inputSpeed(point.omega);
  const TrainTorusGenerators& g = balance.generators();
  double fastest = 0.0, slowest = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < g.ratio.size(); ++j) {
    slowest = std::min(slowest, g.ratio[j] * std::abs(speed));
  }
  for (const TrainMesh& mesh : model.meshes()) {
    fastest = std::max(fastest, mesh.frequency_ratio * std::abs(speed));
  }
  const double dt = 1.0 / (fastest * steps_per_mesh_period);
  const long long per_block =
      std::max(1LL, static_cast<long long>(std::ceil(1.0 / (slowest * dt))));
  const long long blocks =
      std::max(2LL, static_cast<long long>(std::ceil(window / (per_block * dt))));
  const int n = model.dofCount(), r = balance.meshCount();
  const Eigen::MatrixXd Kbar_dense = model.meanStiffnessAt(speed);
  const Sparse M = sparseOf(model.mass()), K = sparseOf(Kbar_dense),
               C = sparseOf(model.dampingAt(speed));
  const Eigen::MatrixXd W = model.nonlinearVectors().leftCols(r);
  const NewmarkCoefficients nm(NewmarkParameters::averageAcceleration(), dt);
  Sparse A = K + nm.a0 * M + nm.a1 * C;
  Eigen::SparseLU<Sparse> lu(A);
  Eigen::SimplicialLDLT<Sparse> mass(M);
  if (lu.info() != Eigen::Success || mass.info() != Eigen::Success) {
    out.status = "singular";
    return out;
  }
  const Eigen::MatrixXd Z = lu.solve(W), WtZ = W.transpose() * Z;
  // Rigid-body modes, M-orthogonal projector x − R (RᵀMR)⁻¹ RᵀM x.
  const Eigen::MatrixXd R = detail::rigidModes(Kbar_dense, model.mass());
  const Eigen::MatrixXd MR = M * R;
  const Eigen::MatrixXd RtMR_inv = (R.transpose() * MR).inverse();
  // At most the elastic state's dimension of columns (a small train has fewer).
  const int c = std::min(columns, 2 * (n - static_cast<int>(R.cols())));
  const auto project = [&](Eigen::MatrixXd& x) {
    if (R.cols() > 0) x -= R * (RtMR_inv * (MR.transpose() * x));
  };
  const double s = std::sqrt(Kbar_dense.trace() / model.mass().trace());  // a start's v scale
  // A fixed pseudo-random start (reproducible), made energy-orthonormal at the first block.
  Eigen::MatrixXd x(n, c), v(n, c), a(n, c);
  for (int j = 0; j < c; ++j) {
    for (int i = 0; i < n; ++i) {
      x(i, j) = std::sin(1.0 + 12.9898 * (i + 1) + 78.233 * (j + 1));
      v(i, j) = s * std::cos(2.0 + 39.3468 * (i + 1) + 11.135 * (j + 1));
    }
  }
  Eigen::VectorXd times(per_block), t0(1), s0(r);
  Eigen::MatrixXd y(n, c), rhs(n, c), sum(n, c), a_new(n, c), small(r, r), w(r, c), gram(c, c);
  Eigen::VectorXd log_sum = Eigen::VectorXd::Zero(c);
  double averaged = 0.0;
  long long step = 0;
  for (long long b = 0; b <= blocks; ++b) {
    // Re-orthonormalise the columns in the energy inner product xᵀK̄x' + vᵀMv' (Cholesky QR:
    // G = UᵀU, columns ← columns U⁻¹), in which a lightly damped mode's norm stays nearly
    // constant over its cycle (the Euclidean state norm swings by its frequency's ratio to the
    // scaling, which biases a finite window's average). The growth of block b − 1 is U's
    // diagonal; averaged over the second half of the blocks.
    project(x), project(v);
    gram.noalias() = x.transpose() * (K * x);
    gram.noalias() += v.transpose() * (M * v);
    const Eigen::LLT<Eigen::MatrixXd> llt(gram);
    if (llt.info() != Eigen::Success) {
      out.status = "degenerate";
      return out;
    }
    const Eigen::MatrixXd U = llt.matrixU();
    if (b > 0 && 2 * (b - 1) >= blocks) {
      for (int j = 0; j < c; ++j) log_sum(j) += std::log(U(j, j));
      averaged += per_block * dt;
    }
    if (b == blocks) break;
    x = U.triangularView<Eigen::Upper>().solve<Eigen::OnTheRight>(x);
    v = U.triangularView<Eigen::Upper>().solve<Eigen::OnTheRight>(v);
    for (long long i = 0; i < per_block; ++i) times(i) = (step + i + 1) * dt;
    const Eigen::MatrixXd S = meshSlopes(model, balance, point, times);
    t0(0) = step * dt;
    s0 = meshSlopes(model, balance, point, t0).row(0).transpose();
    a = mass.solve(-(K * x + W * (s0.asDiagonal() * (W.transpose() * x)) + C * v));
    for (long long i = 0; i < per_block; ++i, ++step) {
      sum = nm.a0 * x + nm.a2 * v + a;
      rhs.noalias() = M * sum;
      sum = nm.a1 * x + v;
      rhs.noalias() += C * sum;
      y = lu.solve(rhs);
      // Woodbury: (A + W S Wᵀ)⁻¹ = A⁻¹ − Z (I + S WᵀZ)⁻¹ S Wᵀ A⁻¹.
      small = S.row(i).transpose().asDiagonal() * WtZ;
      small.diagonal().array() += 1.0;
      w = small.partialPivLu().solve(S.row(i).transpose().asDiagonal() * (W.transpose() * y));
      y.noalias() -= Z * w;
      a_new = nm.a0 * (y - x) - nm.a2 * v - a;
      v += 0.5 * dt * (a + a_new);
      a.swap(a_new);
      x.swap(y);
    }
    if (!x.allFinite()) {
      out.status = "diverged";
      return out;
    }
  }
  out.steps = step;
  for (int j = 0; j < c; ++j) out.exponents.push_back(log_sum(j) / averaged);
  std::sort(out.exponents.rbegin(), out.exponents.rend());
  out.max_exponent = out.exponents.front();
  out.stable = out.max_exponent < 0.0;
  out.status = "completed";
  return out;
}

}  // namespace geardyn
