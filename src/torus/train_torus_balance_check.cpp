/// The torus balance's solutions (train_torus_balance.h): harmonics of every DOF, the state at
/// t = 0, the coordinates along the trajectory, the mesh forces on the grid and their lines, and
/// the Newmark stability check.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geardyn/solvers/detail/harmonic_blocks.h"
#include "geardyn/solvers/train_nonlinear_time.h"
#include "geardyn/torus/detail/torus_fft.h"
#include "geardyn/torus/train_torus_balance.h"

namespace geardyn {

using Complex = std::complex<double>;

Eigen::VectorXcd TrainTorusBalance::coordinateHarmonics(const Eigen::VectorXd& u, int c) const {
  Eigen::VectorXcd x(P_ + 1);
  const double* a = u.data() + static_cast<std::ptrdiff_t>(c) * n_;
  x(0) = a[0];
  for (int p = 1; p <= P_; ++p) x(p) = Complex(a[2 * p - 1], a[2 * p]);
  return x;
}

Eigen::MatrixXd TrainTorusBalance::coordinatesAt(const Eigen::VectorXd& u, double omega,
                                                 const Eigen::VectorXd& times) const {
  Eigen::MatrixXd w(times.size(), r_);
  for (int c = 0; c < r_; ++c) {
    const Eigen::VectorXcd x = coordinateHarmonics(u, c);
    for (Eigen::Index i = 0; i < times.size(); ++i) {
      double sum = x(0).real();
      for (int p = 1; p <= P_; ++p) {
        sum += 2.0 * (x(p) * std::polar(1.0, toneFrequency(p, omega) * times(i))).real();
      }
      w(i, c) = sum;
    }
  }
  return w;
}

Eigen::MatrixXcd TrainTorusBalance::displacementHarmonics(const HarmonicBalancePoint& point) {
  prepare(point.omega);
  gridForces(point.q);
  // X_p = D(ω_p)⁻¹ (F₀ δ_p0 + W (d_p − F̃_p)).
  Eigen::MatrixXcd X(dofs_, P_ + 1);
  Eigen::VectorXcd z(r_);
  for (int p = 0; p <= P_; ++p) {
    for (int c = 0; c < r_; ++c) {
      z(c) = point.omega * dash_unit_(c, p) - half_out_(tone_index_[p], c);
    }
    Eigen::VectorXcd rhs = W_.cast<Complex>() * z;
    if (p == 0) rhs += model_.staticLoad().cast<Complex>();
    blocks_->factorize(p, toneFrequency(p, point.omega));  // prepare() keeps the latest only
    X.col(p) = blocks_->solve(p, rhs);
  }
  X.col(0) = X.col(0).real().cast<Complex>();
  return X;
}

std::pair<Eigen::VectorXd, Eigen::VectorXd> TrainTorusBalance::initialState(
    const HarmonicBalancePoint& point) {
  const Eigen::MatrixXcd X = displacementHarmonics(point);
  Eigen::VectorXd q = X.col(0).real(), v = Eigen::VectorXd::Zero(dofs_);
  for (int p = 1; p <= P_; ++p) {
    q += 2.0 * X.col(p).real();
    v += 2.0 * (Complex(0.0, toneFrequency(p, point.omega)) * X.col(p)).real();
  }
  return {q, v};
}

Eigen::MatrixXd TrainTorusBalance::gridCoordinates(const Eigen::VectorXd& u) {
  gridForces(u);
  return grid_;
}

Eigen::MatrixXd TrainTorusBalance::gridMeshForces(const Eigen::VectorXd& u) {
  gridForces(u);  // grid_ holds the coordinates on the grid afterwards
  const long long points = fft_->points();
  Eigen::MatrixXd f(points, meshes_);
  for (int m = 0; m < meshes_; ++m) {
    const int j = generators_.mesh_generator[m];
    for (long long g = 0; g < points; ++g) {
      const int i = static_cast<int>((g / axis_stride_[j]) % samples_[j]);
      double slope = 0.0;
      f(g, m) = meshForceAt(m, i, grid_(g, m) - e_axis_[m](i), &slope);
    }
  }
  return f;
}

std::vector<std::vector<TorusLine>> TrainTorusBalance::meshForceLines(const Eigen::VectorXd& u,
                                                                      double omega) {
  const Eigen::MatrixXd f = gridMeshForces(u);
  grid_out_.setZero();
  grid_out_.leftCols(meshes_) = f;
  fft_->toSpectrum(grid_out_, half_out_);
  std::vector<int> K;
  std::vector<double> g;
  for (int j = 0; j < k_; ++j) {
    K.push_back(std::min((samples_[j] - 1) / 2, 2 * generators_.harmonics[j]));
    g.push_back(generators_.ratio[j] * std::abs(inputSpeed(omega)));
  }
  std::vector<std::vector<TorusLine>> lines;
  for (int m = 0; m < meshes_; ++m) lines.push_back(detail::torusLines(half_out_, m, *fft_, K, g));
  return lines;
}

TorusNewmarkCheck torusNewmarkCheck(const GearTrainModel& model, TrainTorusBalance& balance,
                                    const HarmonicBalancePoint& point, double window,
                                    int steps_per_mesh_period, double tolerance) {
  TorusNewmarkCheck out;
  const double speed = balance.inputSpeed(point.omega);
  double fastest = 0.0;
  for (const TrainMesh& mesh : model.meshes()) {
    fastest = std::max(fastest, mesh.frequency_ratio * std::abs(speed));
  }
  const double dt = 1.0 / (fastest * steps_per_mesh_period);
  const long long steps = static_cast<long long>(std::ceil(window / dt));
  TrainNonlinearNewmark newmark(model, speed, dt, NewmarkParameters::averageAcceleration(), 6, 0);
  const auto [q0, v0] = balance.initialState(point);
  newmark.reset(0.0, q0, v0);
  const int r = balance.coordinateCount();
  const long long first = steps / 2;
  Eigen::VectorXd times(steps - first + 1);
  Eigen::MatrixXd record(times.size(), r);
  for (long long s = 1; s <= steps; ++s) {
    if (!newmark.step(1e-13, 50)) {
      out.status = "newton_failure";
      return out;
    }
    if (s >= first) {
      times(s - first) = newmark.time();
      record.row(s - first) = newmark.coordinates().head(r).transpose();
    }
  }
  if (!record.allFinite()) {
    out.status = "diverged";
    return out;
  }
  out.status = "completed";
  const Eigen::MatrixXd torus = balance.coordinatesAt(point.q, point.omega, times);
  const Eigen::Index half = times.size() / 2;
  out.stable = true;
  for (int c = 0; c < r; ++c) {
    const double p2p_torus = torus.col(c).maxCoeff() - torus.col(c).minCoeff();
    const double p2p_newmark = record.col(c).maxCoeff() - record.col(c).minCoeff();
    const Eigen::VectorXd error = (record.col(c) - torus.col(c)).cwiseAbs();
    const double scale = std::max(p2p_torus, 1e-300);
    out.deviation.push_back(error.maxCoeff() / scale);
    out.p2p_torus.push_back(p2p_torus);
    out.p2p_newmark.push_back(p2p_newmark);
    const double early = error.head(half).maxCoeff(), late = error.tail(half).maxCoeff();
    out.stable =
        out.stable && late <= 2.0 * early + 1e-12 * scale && out.deviation.back() < tolerance;
  }
  return out;
}

}  // namespace geardyn
