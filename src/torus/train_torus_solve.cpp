/// The torus balance at one speed (train_torus.h; docs/theory/torus_harmonic_balance.md): the
/// compliances B_n of every tone, the condensed system on the mesh deflections (GMRES with the
/// line preconditioner, from the previous speeds' solutions; a sparse LU when it stalls) and the
/// recovery of every DOF. The buffers are the thread's TrainTorusWorkspace.

#include <fmt/format.h>

#include <Eigen/SparseLU>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geardyn/error.h"
#include "geardyn/solvers/detail/harmonic_blocks.h"
#include "geardyn/solvers/detail/train_steady_parts.h"
#include "geardyn/torus/train_torus.h"
#include "train_torus_workspace.h"

namespace geardyn {
namespace {

using Complex = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
// GMRES restart length and iteration budget of the condensed system: the line preconditioner
// leaves only the coupling between mesh groups, which converges in a few tens of iterations
// away from the sharpest parametric resonances; past the budget the direct LU takes over.
constexpr int kRestart = 60;
constexpr int kMaxIterations = 300;

}  // namespace

namespace detail {

void SmallLu::factor() {
  const Eigen::Index m = lu.rows();
  pivot.resize(static_cast<std::size_t>(m));
  for (Eigen::Index k = 0; k < m; ++k) {
    Eigen::Index p = k;
    double largest = std::norm(lu(k, k));
    for (Eigen::Index i = k + 1; i < m; ++i) {
      const double a = std::norm(lu(i, k));
      if (a > largest) largest = a, p = i;
    }
    pivot[k] = static_cast<int>(p);
    if (p != k) lu.row(k).swap(lu.row(p));
    if (largest == 0.0) continue;  // singular: left to GMRES's residual check
    const Complex inverse = 1.0 / lu(k, k);
    lu.col(k).tail(m - k - 1) *= inverse;
    for (Eigen::Index j = k + 1; j < m; ++j) {
      lu.col(j).tail(m - k - 1) -= lu(k, j) * lu.col(k).tail(m - k - 1);
    }
  }
}

void SmallLu::solveInPlace(Eigen::Ref<Eigen::VectorXcd> x) const {
  const Eigen::Index m = lu.rows();
  for (Eigen::Index k = 0; k < m; ++k) {
    if (pivot[k] != k) std::swap(x(k), x(pivot[k]));
  }
  lu.triangularView<Eigen::UnitLower>().solveInPlace(x);
  lu.triangularView<Eigen::Upper>().solveInPlace(x);
}

}  // namespace detail

TrainTorusWorkspace::TrainTorusWorkspace() : impl_(std::make_unique<detail::TorusWorkspace>()) {}
TrainTorusWorkspace::~TrainTorusWorkspace() = default;
TrainTorusWorkspace::TrainTorusWorkspace(TrainTorusWorkspace&&) noexcept = default;
TrainTorusWorkspace& TrainTorusWorkspace::operator=(TrainTorusWorkspace&&) noexcept = default;

TrainTorusState TrainTorusSolver::solve(double input_speed) const {
  TrainTorusWorkspace workspace;
  return solve(input_speed, workspace);
}

TrainTorusState TrainTorusSolver::solve(double input_speed, TrainTorusWorkspace& workspace) const {
  if (!(std::abs(input_speed) > 0.0) || !std::isfinite(input_speed)) {
    throw InputError("operating_point.speed_rpm", fmt::format("{:g} rad/s", input_speed),
                     "a speed != 0: the steady state of a train at rest is its static response");
  }
  detail::TorusWorkspace& ws = *workspace.impl_;
  if (ws.owner != this) {
    ws.owner = this;
    ws.previous_speed[0] = ws.previous_speed[1] = 0.0;
    ws.factor_speed = 0.0;
  }
  const int k = static_cast<int>(generators_.ratio.size());
  TrainTorusState s;
  s.input_speed = input_speed;
  s.mesh_generator = generators_.mesh_generator;
  s.mesh_multiple = generators_.mesh_multiple;
  s.tones = tones_;
  Eigen::VectorXd g(k);
  for (int j = 0; j < k; ++j) g(j) = generators_.ratio[j] * std::abs(input_speed);
  s.generator_frequency.assign(g.data(), g.data() + k);
  s.tone_frequency = tones_.cast<double>().transpose() * g;
  compliances(s, ws);
  // The condensed system δ_n + B_n Σ_m e_m Σ_{l≠0} k̂_{m,l} δ_{m, n − l P_m e_j} = B_n φ_n (+ F₀).
  solveCondensed(ws, s);
  recover(s, ws);
  postProcess(s, ws);
  std::swap(ws.previous[0], ws.previous[1]);
  ws.previous[1] = ws.delta;
  ws.previous_speed[0] = ws.previous_speed[1];
  ws.previous_speed[1] = input_speed;
  return s;
}

void TrainTorusSolver::compliances(TrainTorusState& s, detail::TorusWorkspace& ws) const {
  const GearTrainModel& model = model_;
  const auto& meshes = model.meshes();
  const int n = model.dofCount();
  const int r = static_cast<int>(meshes.size());
  const int T = static_cast<int>(tones_.cols());
  const int L = options_.mesh_harmonics;
  const double speed = s.input_speed;
  const double highest = std::max(s.tone_frequency.cwiseAbs().maxCoeff(), 1e-300);
  const Eigen::MatrixXd Kbar = model.meanStiffnessAt(speed);
  const Eigen::MatrixXd C = model.dampingAt(speed);
  const Eigen::MatrixXd rigid =
      rigid_at_every_speed_ ? rigid_ : detail::rigidModes(Kbar, model.mass());
  detail::HarmonicBlocks blocks(Kbar, model.mass(), C, rigid, options_.sparse_dofs);
  Eigen::MatrixXd Vr(n, r);
  for (int m = 0; m < r; ++m) Vr.col(m) = model.meshVector(m);
  const Eigen::MatrixXcd V = Vr.cast<Complex>();
  // The mesh loads of every tone, F_n = F₀ δ_n0 + V φ_n: k e and the mesh dashpot on ė.
  ws.phi.setZero(r, T);
  for (int m = 0; m < r; ++m) {
    for (int l = -L; l <= L; ++l) {
      // The tone l P_m e_j: the neighbour of the zero tone through harmonic −l.
      const int t = l == 0 ? 0 : neighbourRow(m)[L - l];
      if (t < 0) continue;
      const double w = kTwoPi * s.tone_frequency(t);
      ws.phi(m, t) += ke_hat_[m][L + l] + Complex(0.0, w) * meshes[m].damping * e_hat_[m][L + l];
    }
  }
  // B_n for every tone pair ±n: from the modal decomposition of the train at this speed
  // (detail/modal_compliance.h) when it is small and the decomposition holds, else D(n·ω)
  // factorised per pair with D⁻¹V kept for the recovery. A tone of zero frequency is always
  // factorised (the rigid-body constraint of the static balance).
  ws.modal_ok = options_.modal_compliance && n < options_.sparse_dofs &&
                ws.modal.compute(Kbar, model.mass(), C, rigid, Vr, kTwoPi * highest);
  const int pairs = (T + 1) / 2 + 1;
  ws.DinvV.resize(n, static_cast<Eigen::Index>(pairs) * r);
  ws.modal_tone.assign(static_cast<std::size_t>(pairs), 0);
  ws.B.resize(r, static_cast<Eigen::Index>(T) * r);
  ws.rhs.resize(static_cast<Eigen::Index>(T) * r);
  for (int t = 0; t < T; ++t) {
    const int b = block_[t];
    if (b < 0) continue;
    const double w =
        std::abs(s.tone_frequency(t)) <= 1e-9 * highest ? 0.0 : kTwoPi * s.tone_frequency(t);
    auto Bt = ws.B.middleCols(static_cast<Eigen::Index>(t) * r, r);
    if (w != 0.0 && ws.modal_ok) {
      ws.modal.compliance(w, Bt);
      ws.modal_tone[b] = 1;
    } else {
      blocks.factorize(b, w);
      auto DinvV = ws.DinvV.middleCols(static_cast<Eigen::Index>(b) * r, r);
      DinvV = blocks.solve(b, V);
      Bt.noalias() = V.transpose() * DinvV;
    }
    auto rhs = ws.rhs.segment(static_cast<Eigen::Index>(t) * r, r);
    rhs.noalias() = Bt * ws.phi.col(t);
    if (t == 0) {
      ws.DinvF0 = blocks.solve(0, model.staticLoad().cast<Complex>());
      rhs.noalias() += V.transpose() * ws.DinvF0;
    }
    if (t > 0) {
      const Eigen::Index neg = static_cast<Eigen::Index>(negative_[t]) * r;
      ws.B.middleCols(neg, r) = Bt.conjugate();
      ws.rhs.segment(neg, r) = rhs.conjugate();
    }
  }
}

void TrainTorusSolver::applyCondensed(detail::TorusWorkspace& ws,
                                      const Eigen::Ref<const Eigen::VectorXcd>& x,
                                      Eigen::VectorXcd& y) const {
  const int r = static_cast<int>(model_.meshes().size());
  const Eigen::Index T = tones_.cols();
  y.resize(x.size());
  ws.scratch.resize(r);
  const int* start = coupling_start_.data();
  const int* index = coupling_index_.data();
  const Complex* value = coupling_value_.data();
  for (Eigen::Index t = 0; t < T; ++t) {
    for (int m = 0; m < r; ++m) {
      const Eigen::Index u = t * r + m;
      Complex sum = 0.0;
      for (int e = start[u]; e < start[u + 1]; ++e) sum += value[e] * x(index[e]);
      ws.scratch(m) = sum;
    }
    const Complex* B = ws.B.data() + t * r * r;  // column-major r × r
    for (int i = 0; i < r; ++i) {
      Complex sum = x(t * r + i);
      for (int m = 0; m < r; ++m) sum += B[m * r + i] * ws.scratch(m);
      y(t * r + i) = sum;
    }
  }
}

void TrainTorusSolver::solveCondensed(detail::TorusWorkspace& ws, TrainTorusState& s) const {
  const int r = static_cast<int>(model_.meshes().size());
  const int L = options_.mesh_harmonics;
  const Eigen::MatrixXcd& B = ws.B;
  // Block-Jacobi preconditioner: the exact solve of every line of one mesh group's tones,
  // rows (n, i) and columns (n − l P_m e_j, m) of the line: B_n(i, m) k̂_{m,l}, and the identity.
  // Kept from an earlier speed of this thread while the solves with it take at most
  // preconditioner_reuse_iterations more than the one it was factorised for and the speed is
  // within 5 % of its
  // (any preconditioner gives the same δ; a stale one costs iterations, a fresh one ~1/5 of
  // the solve).
  const double speed = s.input_speed;
  const bool refactor =
      ws.factor_speed == 0.0 || ws.lines.size() != lines_.size() ||
      std::abs(speed - ws.factor_speed) > 0.05 * std::abs(ws.factor_speed) ||
      options_.preconditioner_reuse_iterations < 0 ||
      ws.latest_iterations > ws.factor_iterations + options_.preconditioner_reuse_iterations;
  ws.lines.resize(lines_.size());
  std::size_t longest = 0;
  for (std::size_t id = 0; id < lines_.size(); ++id) {
    const std::vector<int>& line = lines_[id];
    longest = std::max(longest, line.size());
    if (!refactor) continue;
    Eigen::MatrixXcd& block = ws.lines[id].lu;
    block.setIdentity(static_cast<Eigen::Index>(line.size()),
                      static_cast<Eigen::Index>(line.size()));
    for (std::size_t a = 0; a < line.size(); ++a) {
      const int t = line[a] / r, i = line[a] % r;
      for (int m = 0; m < r; ++m) {
        const int* nb = neighbourRow(static_cast<std::size_t>(t) * r + m);
        for (int l = -L; l <= L; ++l) {
          const int u = nb[L + l] * r + m;
          if (nb[L + l] < 0 || line_of_[u] != static_cast<int>(id)) continue;
          block(a, local_of_[u]) += B(i, t * r + m) * k_hat_[m][L + l];
        }
      }
    }
    ws.lines[id].factor();
  }
  const detail::ComplexOperator apply = [&](const Eigen::Ref<const Eigen::VectorXcd>& x,
                                            Eigen::VectorXcd& y) { applyCondensed(ws, x, y); };
  Eigen::VectorXcd local(static_cast<Eigen::Index>(longest));
  const detail::ComplexOperator precondition = [&](const Eigen::Ref<const Eigen::VectorXcd>& x,
                                                   Eigen::VectorXcd& y) {
    y.resize(x.size());
    for (std::size_t id = 0; id < lines_.size(); ++id) {
      const std::vector<int>& line = lines_[id];
      auto part = local.head(static_cast<Eigen::Index>(line.size()));
      for (std::size_t a = 0; a < line.size(); ++a) part(a) = x(line[a]);
      ws.lines[id].solveInPlace(part);
      for (std::size_t a = 0; a < line.size(); ++a) y(line[a]) = part(a);
    }
  };
  // The initial guess: the thread's previous solution, linearly extrapolated in speed from the
  // two latest when the step to this speed is no longer than twice theirs.
  const Eigen::Index size = ws.rhs.size();
  const double s1 = ws.previous_speed[1], s0 = ws.previous_speed[0];
  const bool guess = s1 != 0.0 && ws.previous[1].size() == size;
  if (guess) {
    ws.delta = ws.previous[1];
    if (s0 != 0.0 && s0 != s1 && ws.previous[0].size() == size &&
        std::abs(speed - s1) <= 2.0 * std::abs(s1 - s0)) {
      ws.delta += ((speed - s1) / (s1 - s0)) * (ws.previous[1] - ws.previous[0]);
    }
  }
  const detail::GmresResult gmres =
      detail::preconditionedGmres(apply, precondition, ws.rhs, ws.delta, options_.tolerance,
                                  kRestart, kMaxIterations, guess, ws.gmres);
  s.iterations = gmres.iterations;
  s.residual = gmres.residual;
  s.linear_solver = "gmres";
  ws.latest_iterations = gmres.iterations;
  if (refactor) ws.factor_speed = speed, ws.factor_iterations = gmres.iterations;
  if (!gmres.converged) {
    // The sparse LU of the assembled condensed matrix.
    const int T = static_cast<int>(tones_.cols());
    std::vector<Eigen::Triplet<Complex>> entries;
    for (int t = 0; t < T; ++t) {
      for (int i = 0; i < r; ++i) entries.emplace_back(t * r + i, t * r + i, 1.0);
      for (int m = 0; m < r; ++m) {
        const int* nb = neighbourRow(static_cast<std::size_t>(t) * r + m);
        for (int l = -L; l <= L; ++l) {
          if (nb[L + l] < 0) continue;
          for (int i = 0; i < r; ++i) {
            entries.emplace_back(t * r + i, nb[L + l] * r + m, B(i, t * r + m) * k_hat_[m][L + l]);
          }
        }
      }
    }
    Eigen::SparseMatrix<Complex> A(size, size);
    A.setFromTriplets(entries.begin(), entries.end());
    A.makeCompressed();
    Eigen::SparseLU<Eigen::SparseMatrix<Complex>> lu(A);
    if (lu.info() == Eigen::Success) ws.delta = lu.solve(ws.rhs);
    s.linear_solver = "direct";
    s.iterations = 0;
    s.residual = (A * ws.delta - ws.rhs).norm() / std::max(ws.rhs.norm(), 1e-300);
  }
  if (!ws.delta.allFinite()) {
    throw std::runtime_error(fmt::format(
        "torus steady state at {:g} rad/s: the condensed harmonic-balance system is singular",
        s.input_speed));
  }
}

void TrainTorusSolver::recover(TrainTorusState& s, detail::TorusWorkspace& ws) const {
  // X_n = D⁻¹ (F_n − V w_n), w_{m,n} = φ_{m,n} − Σ_{l≠0} k̂_{m,l} δ_{m, n − l P_m e_j}.
  const int n = model_.dofCount();
  const int r = static_cast<int>(model_.meshes().size());
  const int T = static_cast<int>(tones_.cols());
  const int L = options_.mesh_harmonics;
  s.harmonic.resize(n, T);
  ws.w.resize(r);
  for (int t = 0; t < T; ++t) {
    const int b = block_[t];
    if (b < 0) continue;
    ws.w = ws.phi.col(t);
    for (int m = 0; m < r; ++m) {
      for (int l = -L; l <= L; ++l) {
        const int other = neighbourRow(static_cast<std::size_t>(t) * r + m)[L + l];
        if (other >= 0) ws.w(m) -= k_hat_[m][L + l] * ws.delta(other * r + m);
      }
    }
    if (ws.modal_tone[b]) {
      ws.modal.response(kTwoPi * s.tone_frequency(t), ws.w, ws.z, s.harmonic.col(t));
    } else {
      s.harmonic.col(t).noalias() = ws.DinvV.middleCols(static_cast<Eigen::Index>(b) * r, r) * ws.w;
    }
    if (t == 0) s.harmonic.col(0) += ws.DinvF0;
    if (t > 0) s.harmonic.col(negative_[t]) = s.harmonic.col(t).conjugate();
  }
}

}  // namespace geardyn
