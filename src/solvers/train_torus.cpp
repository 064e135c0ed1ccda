/// Steady state of a linear time-varying gear train on the torus of its mesh phases
/// (train_torus.h; docs/theory/torus_harmonic_balance.md): generators, tone set, condensed
/// solve. The grid evaluation and the result tables are in train_torus_grid.cpp.

#include "geardyn/solvers/train_torus.h"

#include <fmt/format.h>

#include <Eigen/SparseLU>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "geardyn/error.h"
#include "geardyn/solvers/detail/harmonic_blocks.h"
#include "geardyn/solvers/detail/preconditioned_gmres.h"
#include "geardyn/solvers/detail/torus_fft.h"
#include "geardyn/solvers/detail/train_steady_parts.h"

namespace geardyn {
namespace {

using Complex = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
// GMRES restart length and iteration budget of the condensed system: the line preconditioner
// leaves only the coupling between mesh groups, which converges in a few tens of iterations
// away from the sharpest parametric resonances; past the budget the direct LU takes over.
constexpr int kRestart = 60;
constexpr int kMaxIterations = 300;

/// Position of tone n in the box Π (2N_j + 1), axis 0 fastest.
long long boxIndex(const Eigen::Ref<const Eigen::VectorXi>& n, const std::vector<int>& N) {
  long long index = 0, stride = 1;
  for (std::size_t j = 0; j < N.size(); ++j) {
    index += (n(j) + N[j]) * stride;
    stride *= 2 * N[j] + 1;
  }
  return index;
}

/// The tone is on the positive side: its first nonzero component is > 0.
bool positive(const Eigen::VectorXi& n) {
  for (Eigen::Index j = 0; j < n.size(); ++j) {
    if (n(j) != 0) return n(j) > 0;
  }
  return false;
}

/// The smallest 2^a 3^b 5^c >= n (a size FFTW transforms fastest).
int smoothSize(int n) {
  for (int size = std::max(n, 1);; ++size) {
    int rest = size;
    for (int p : {2, 3, 5}) {
      while (rest % p == 0) rest /= p;
    }
    if (rest == 1) return size;
  }
}

/// Per generator j, harmonics n = 0..N_j: the product truncation's weight a_j(n)
/// (TrainTorusOptions::mesh_order_weights); all ones for the box and the diamond.
std::vector<std::vector<double>> generatorWeights(const TrainTorusOptions& options,
                                                  const TrainTorusGenerators& g) {
  std::vector<std::vector<double>> out;
  if (options.truncation == TorusTruncation::kProduct &&
      options.mesh_order_weights.size() != g.mesh_generator.size()) {
    throw std::invalid_argument("TrainTorusOptions::mesh_order_weights: one list per mesh");
  }
  for (std::size_t j = 0; j < g.harmonics.size(); ++j) {
    std::vector<double> a(g.harmonics[j] + 1, 1.0);
    if (options.truncation == TorusTruncation::kProduct) {
      for (int n = 1; n <= g.harmonics[j]; ++n) {
        a[n] = 0.0;
        for (std::size_t m = 0; m < g.mesh_generator.size(); ++m) {
          if (g.mesh_generator[m] != static_cast<int>(j)) continue;
          const std::vector<double>& w = options.mesh_order_weights[m];
          const int l = (n + g.mesh_multiple[m] - 1) / g.mesh_multiple[m];
          if (l <= static_cast<int>(w.size())) a[n] = std::max(a[n], w[l - 1]);
        }
      }
      // Non-increasing (a kept tone keeps every tone between it and the origin), and never
      // below the floor (the pure harmonics of the box).
      for (int n = g.harmonics[j] - 1; n >= 1; --n) a[n] = std::max(a[n], a[n + 1]);
      for (double& v : a) v = std::min(1.0, std::max(v, options.product_floor));
    }
    out.push_back(std::move(a));
  }
  return out;
}

}  // namespace

void TrainTorusOptions::validate() const {
  if (mesh_harmonics < 1 || mesh_harmonics > 200) {
    throw InputError("forced.mesh_harmonics", std::to_string(mesh_harmonics),
                     "an integer in [1, 200]");
  }
  if (group_harmonics < mesh_harmonics) {
    throw InputError("forced.torus_above", std::to_string(group_harmonics),
                     fmt::format("an integer >= forced.mesh_harmonics = {} (a mesh alone needs "
                                 "that many harmonics of its own frequency)",
                                 mesh_harmonics));
  }
  if (samples != 0 && samples < 8) {
    throw InputError("forced.torus_samples", std::to_string(samples), "0 (derived) or >= 8");
  }
  for (int Lm : per_mesh_harmonics) {
    if (Lm < 1 || Lm > mesh_harmonics) {
      throw InputError("forced.mesh_harmonics", std::to_string(Lm),
                       fmt::format("per mesh an integer in [1, {}] (the largest)", mesh_harmonics));
    }
  }
  if (truncation == TorusTruncation::kProduct ||
      product_floor != TrainTorusOptions{}.product_floor) {
    if (!(product_floor > 0.0 && product_floor < 1.0)) {
      throw InputError("forced.torus_floor", fmt::format("{:g}", product_floor), "in (0, 1)");
    }
  }
  if (!(tolerance > 0.0 && tolerance < 1e-3)) {
    throw InputError("forced.torus_tolerance", fmt::format("{:g}", tolerance), "in (0, 1e-3)");
  }
}

TrainTorusGenerators trainTorusGenerators(const GearTrainModel& model, int mesh_harmonics,
                                          int group_harmonics) {
  return trainTorusGenerators(model, std::vector<int>(model.meshes().size(), mesh_harmonics),
                              group_harmonics);
}

TrainTorusGenerators trainTorusGenerators(const GearTrainModel& model,
                                          const std::vector<int>& mesh_harmonics,
                                          int group_harmonics) {
  // Greedy grouping in mesh order: a mesh joins the first group whose common base with it
  // (gcd of the reduced fractions p/q = gcd(p) / lcm(q)) keeps the largest L_m × multiple
  // within group_harmonics; else it starts a generator of its own.
  struct Group {
    long long g = 0, l = 1;
    std::vector<int> members;
  };
  std::vector<std::pair<long long, long long>> fraction;
  std::vector<Group> groups;
  const auto largestMultiple = [&](const Group& group, long long g, long long l) {
    long long largest = 0;
    for (int m : group.members) {
      const auto [p, q] = fraction[m];
      largest = std::max(largest, (p / g) * (l / q) * mesh_harmonics[m]);
    }
    return largest;
  };
  for (std::size_t m = 0; m < model.meshes().size(); ++m) {
    fraction.push_back(detail::rationalApproximation(model.meshes()[m].frequency_ratio * kTwoPi));
    const auto [p, q] = fraction.back();
    bool placed = false;
    for (Group& group : groups) {
      const long long g = std::gcd(group.g, p), l = std::lcm(group.l, q);
      Group joined = group;
      joined.members.push_back(static_cast<int>(m));
      if (l > 1000000000LL || largestMultiple(joined, g, l) > group_harmonics) {
        continue;
      }
      group = joined;
      group.g = g, group.l = l;
      placed = true;
      break;
    }
    if (!placed) groups.push_back(Group{p, q, {static_cast<int>(m)}});
  }
  TrainTorusGenerators out;
  out.mesh_generator.assign(model.meshes().size(), 0);
  out.mesh_multiple.assign(model.meshes().size(), 1);
  for (std::size_t j = 0; j < groups.size(); ++j) {
    const Group& group = groups[j];
    out.ratio.push_back(static_cast<double>(group.g) / static_cast<double>(group.l) / kTwoPi);
    int largest = 0;
    for (int m : group.members) {
      const auto [p, q] = fraction[m];
      out.mesh_generator[m] = static_cast<int>(j);
      out.mesh_multiple[m] = static_cast<int>((p / group.g) * (group.l / q));
      largest = std::max(largest, out.mesh_multiple[m] * mesh_harmonics[m]);
    }
    out.harmonics.push_back(largest);
  }
  return out;
}

TrainTorusSolver::TrainTorusSolver(const GearTrainModel& model, const TrainTorusOptions& options)
    : model_(model), options_(options) {
  options.validate();
  refuseExcitations(model, "the multi-frequency (torus) steady state");
  const int L = options.mesh_harmonics;
  generators_ =
      options.per_mesh_harmonics.empty()
          ? trainTorusGenerators(model, L, options.group_harmonics)
          : trainTorusGenerators(model, options.per_mesh_harmonics, options.group_harmonics);
  const std::vector<int>& N = generators_.harmonics;
  const int k = static_cast<int>(N.size());
  const int r = static_cast<int>(model.meshes().size());
  long long box = 1;
  for (int Nj : N) box *= 2 * Nj + 1;
  if (box > 4000000) {
    throw InputError(
        "forced.mesh_harmonics", std::to_string(L),
        fmt::format("fewer harmonics: the torus of {} generators needs {} tones", k, box));
  }
  const std::vector<std::vector<double>> weight = generatorWeights(options, generators_);
  // The tone set: the zero tone, then every positive tone n followed by −n.
  std::vector<Eigen::VectorXi> list;
  if (k > 0) list.push_back(Eigen::VectorXi::Zero(k));
  Eigen::VectorXi n(k);
  for (long long index = 0; index < box; ++index) {
    long long rest = index;
    double radius = 0.0;  // of the diamond
    for (int j = 0; j < k; ++j) {
      n(j) = static_cast<int>(rest % (2 * N[j] + 1)) - N[j];
      rest /= 2 * N[j] + 1;
      radius += std::abs(n(j)) / static_cast<double>(N[j]);
    }
    if (!positive(n)) continue;
    if (options.truncation == TorusTruncation::kDiamond && radius > 1.0 + 1e-12) continue;
    if (options.truncation == TorusTruncation::kProduct) {
      double product = 1.0;
      for (int j = 0; j < k; ++j) product *= weight[j][std::abs(n(j))];
      if (product < options.product_floor) continue;
    }
    list.push_back(n);
    list.push_back(-n);
  }
  const int T = static_cast<int>(list.size());
  tones_.resize(k, T);
  std::vector<int> position(static_cast<std::size_t>(box), -1);
  for (int t = 0; t < T; ++t) {
    tones_.col(t) = list[t];
    position[boxIndex(list[t], N)] = t;
  }
  negative_.resize(T);
  block_.resize(T);
  for (int t = 0; t < T; ++t) {
    negative_[t] = t == 0 ? 0 : (t % 2 == 1 ? t + 1 : t - 1);
    block_[t] = t == 0 ? 0 : (t % 2 == 1 ? (t + 1) / 2 : -(t / 2));
  }
  // Neighbours n − l P_m e_{j(m)} through mesh m's stiffness harmonic l.
  stride_ = 2 * L + 1;
  neighbour_.assign(static_cast<std::size_t>(T) * r * stride_, -1);
  for (int t = 0; t < T; ++t) {
    for (int m = 0; m < r; ++m) {
      const int j = generators_.mesh_generator[m], P = generators_.mesh_multiple[m];
      for (int l = -L; l <= L; ++l) {
        Eigen::VectorXi other = tones_.col(t);
        other(j) -= l * P;
        if (l == 0 || std::abs(other(j)) > N[j]) continue;
        neighbour_[(static_cast<std::size_t>(t) * r + m) * stride_ + L + l] =
            position[boxIndex(other, N)];
      }
    }
  }
  // Lines of the preconditioner: the unknowns (n, m) of one mesh group whose tones differ only
  // along its generator.
  line_of_.assign(static_cast<std::size_t>(T) * r, -1);
  local_of_.assign(static_cast<std::size_t>(T) * r, -1);
  std::vector<int> line_id(static_cast<std::size_t>(box) * std::max(k, 1), -1);
  for (int t = 0; t < T; ++t) {
    for (int m = 0; m < r; ++m) {
      const int j = generators_.mesh_generator[m];
      Eigen::VectorXi base = tones_.col(t);
      base(j) = 0;
      int& id = line_id[static_cast<std::size_t>(boxIndex(base, N)) * k + j];
      if (id < 0) {
        id = static_cast<int>(lines_.size());
        lines_.emplace_back();
      }
      const int u = t * r + m;
      line_of_[u] = id;
      local_of_[u] = static_cast<int>(lines_[id].size());
      lines_[id].push_back(u);
    }
  }
  for (const TrainMesh& mesh : model.meshes()) {
    detail::MeshFourier fourier = detail::meshFourier(mesh, L);
    k_hat_.push_back(std::move(fourier.k));
    ke_hat_.push_back(std::move(fourier.ke));
    e_hat_.push_back(std::move(fourier.e));
  }
  rigid_ = detail::rigidModes(model.meanStiffnessAt(0.0), model.mass());
  const Eigen::MatrixXd& Komega = model.centripetal();
  rigid_at_every_speed_ = rigid_.cols() == 0 || Komega.size() == 0 ||
                          (Komega * rigid_).norm() <= 1e-12 * Komega.norm() * rigid_.norm();
  // Grid points per generator: enough for the products k δ up to 2 N_j without aliasing
  // (4 N_j + 2) and 80 per period of the group's fastest mesh (8 per period of its 10th order:
  // the mesh force's peak to ~0.05 %), at least 32, rounded up to a 2^a 3^b 5^c size; the grid
  // capped at 2^20 points.
  long long points = 1;
  for (int j = 0; j < k; ++j) {
    int fastest = 1;
    for (int m = 0; m < r; ++m) {
      if (generators_.mesh_generator[m] == j) {
        fastest = std::max(fastest, generators_.mesh_multiple[m]);
      }
    }
    samples_.push_back(options.samples > 0
                           ? options.samples
                           : smoothSize(std::max({32, 4 * N[j] + 2, 80 * fastest})));
    if (samples_.back() < 2 * N[j] + 2) {
      throw InputError("forced.torus_samples", std::to_string(options.samples),
                       fmt::format(">= {} (2 × the {} harmonics of generator {} + 2)", 2 * N[j] + 2,
                                   N[j], j + 1));
    }
    points *= samples_.back();
  }
  while (points > (1LL << 20)) {  // halve the finest axis that keeps 2 N_j + 2 points
    int finest = -1;
    for (int j = 0; j < k; ++j) {
      if (samples_[j] / 2 >= 2 * N[j] + 2 && (finest < 0 || samples_[j] > samples_[finest])) {
        finest = j;
      }
    }
    if (finest < 0) break;
    points = points / samples_[finest] * (samples_[finest] / 2);
    samples_[finest] /= 2;
  }
  int fields = r;
  for (const TrainElement& e : model.elements()) fields += static_cast<int>(e.jacobian.rows());
  if (k > 0) fft_ = std::make_unique<detail::TorusFft>(samples_, fields, r);
}

TrainTorusSolver::~TrainTorusSolver() = default;

TrainTorusState TrainTorusSolver::solve(double input_speed) const {
  if (!(std::abs(input_speed) > 0.0) || !std::isfinite(input_speed)) {
    throw InputError("operating_point.speed_rpm", fmt::format("{:g} rad/s", input_speed),
                     "a speed != 0: the steady state of a train at rest is its static response");
  }
  const GearTrainModel& model = model_;
  const auto& meshes = model.meshes();
  const int n = model.dofCount();
  const int r = static_cast<int>(meshes.size());
  const int k = static_cast<int>(generators_.ratio.size());
  const int T = static_cast<int>(tones_.cols());
  const int L = options_.mesh_harmonics;
  TrainTorusState s;
  s.input_speed = input_speed;
  s.mesh_generator = generators_.mesh_generator;
  s.mesh_multiple = generators_.mesh_multiple;
  s.tones = tones_;
  Eigen::VectorXd g(k);
  for (int j = 0; j < k; ++j) g(j) = generators_.ratio[j] * std::abs(input_speed);
  s.generator_frequency.assign(g.data(), g.data() + k);
  s.tone_frequency = tones_.cast<double>().transpose() * g;
  const double highest = std::max(s.tone_frequency.cwiseAbs().maxCoeff(), 1e-300);

  const Eigen::MatrixXd Kbar = model.meanStiffnessAt(input_speed);
  const Eigen::MatrixXd C = model.dampingAt(input_speed);
  detail::HarmonicBlocks blocks(
      Kbar, model.mass(), C,
      rigid_at_every_speed_ ? rigid_ : detail::rigidModes(Kbar, model.mass()),
      options_.sparse_dofs);
  Eigen::MatrixXcd V(n, r);
  for (int m = 0; m < r; ++m) V.col(m) = model.meshVector(m).cast<Complex>();
  // The mesh loads of every tone, F_n = F₀ δ_n0 + V φ_n: k e and the mesh dashpot on ė.
  Eigen::MatrixXcd phi = Eigen::MatrixXcd::Zero(r, T);
  std::vector<int> position_of(T);
  for (int m = 0; m < r; ++m) {
    for (int l = -L; l <= L; ++l) {
      // The tone l P_m e_j: the neighbour of the zero tone through harmonic −l.
      const int t = l == 0 ? 0 : neighbourRow(m)[L - l];
      if (t < 0) continue;
      const double w = kTwoPi * s.tone_frequency(t);
      phi(m, t) += ke_hat_[m][L + l] + Complex(0.0, w) * meshes[m].damping * e_hat_[m][L + l];
    }
  }
  // Per tone pair ±n: D(n·ω) factorised once, B_n = Vᵀ D⁻¹ V and D⁻¹V kept for the recovery.
  std::vector<Eigen::MatrixXcd> B(T), DinvV((T + 1) / 2 + 1);
  Eigen::VectorXcd rhs(static_cast<Eigen::Index>(T) * r);
  Eigen::VectorXcd DinvF0;
  for (int t = 0; t < T; ++t) {
    if (block_[t] < 0) continue;
    const double w =
        std::abs(s.tone_frequency(t)) <= 1e-9 * highest ? 0.0 : kTwoPi * s.tone_frequency(t);
    blocks.factorize(block_[t], w);
    DinvV[block_[t]] = blocks.solve(block_[t], V);
    B[t] = V.transpose() * DinvV[block_[t]];
    Eigen::VectorXcd b = B[t] * phi.col(t);
    if (t == 0) {
      DinvF0 = blocks.solve(0, model.staticLoad().cast<Complex>());
      b += V.transpose() * DinvF0;
    }
    rhs.segment(static_cast<Eigen::Index>(t) * r, r) = b;
    if (t > 0) {
      B[negative_[t]] = B[t].conjugate();
      rhs.segment(static_cast<Eigen::Index>(negative_[t]) * r, r) = b.conjugate();
    }
  }
  // The condensed system δ_n + B_n Σ_m e_m Σ_{l≠0} k̂_{m,l} δ_{m, n − l P_m e_j} = B_n φ_n (+ F₀).
  const Eigen::VectorXcd delta = solveCondensed(B, rhs, s);
  recover(s, DinvV, DinvF0, phi, delta);
  postProcess(s);
  return s;
}

void TrainTorusSolver::applyCondensed(const std::vector<Eigen::MatrixXcd>& B,
                                      const Eigen::VectorXcd& x, Eigen::VectorXcd& y) const {
  const int r = static_cast<int>(model_.meshes().size());
  const int L = options_.mesh_harmonics;
  y.resize(x.size());
  Eigen::VectorXcd w(r);
  for (Eigen::Index t = 0; t < static_cast<Eigen::Index>(B.size()); ++t) {
    for (int m = 0; m < r; ++m) {
      const int* nb = neighbourRow(static_cast<std::size_t>(t) * r + m);
      Complex sum = 0.0;
      for (int l = -L; l <= L; ++l) {
        if (nb[L + l] >= 0) sum += k_hat_[m][L + l] * x(nb[L + l] * r + m);
      }
      w(m) = sum;
    }
    y.segment(t * r, r) = x.segment(t * r, r);
    y.segment(t * r, r).noalias() += B[t] * w;  // no temporary
  }
}

Eigen::VectorXcd TrainTorusSolver::solveCondensed(const std::vector<Eigen::MatrixXcd>& B,
                                                  const Eigen::VectorXcd& rhs,
                                                  TrainTorusState& s) const {
  const int r = static_cast<int>(model_.meshes().size());
  const int L = options_.mesh_harmonics;
  // Block-Jacobi preconditioner: the exact solve of every line of one mesh group's tones,
  // rows (n, i) and columns (n − l P_m e_j, m) of the line: B_n(i, m) k̂_{m,l}, and the identity.
  std::vector<Eigen::PartialPivLU<Eigen::MatrixXcd>> line_lu(lines_.size());
  for (std::size_t id = 0; id < lines_.size(); ++id) {
    const std::vector<int>& line = lines_[id];
    Eigen::MatrixXcd block = Eigen::MatrixXcd::Identity(line.size(), line.size());
    for (std::size_t a = 0; a < line.size(); ++a) {
      const int t = line[a] / r, i = line[a] % r;
      for (int m = 0; m < r; ++m) {
        const int* nb = neighbourRow(static_cast<std::size_t>(t) * r + m);
        for (int l = -L; l <= L; ++l) {
          const int u = nb[L + l] * r + m;
          if (nb[L + l] < 0 || line_of_[u] != static_cast<int>(id)) continue;
          block(a, local_of_[u]) += B[t](i, m) * k_hat_[m][L + l];
        }
      }
    }
    line_lu[id].compute(block);
  }
  const detail::ComplexOperator apply = [&](const Eigen::VectorXcd& x, Eigen::VectorXcd& y) {
    applyCondensed(B, x, y);
  };
  std::size_t longest = 0;
  for (const std::vector<int>& line : lines_) longest = std::max(longest, line.size());
  Eigen::VectorXcd scratch(static_cast<Eigen::Index>(longest));
  const detail::ComplexOperator precondition = [&](const Eigen::VectorXcd& x, Eigen::VectorXcd& y) {
    y.resize(x.size());
    for (std::size_t id = 0; id < lines_.size(); ++id) {
      const std::vector<int>& line = lines_[id];
      auto local = scratch.head(static_cast<Eigen::Index>(line.size()));
      for (std::size_t a = 0; a < line.size(); ++a) local(a) = x(line[a]);
      const Eigen::PartialPivLU<Eigen::MatrixXcd>& lu = line_lu[id];
      local = lu.permutationP() * local;  // in place (Eigen permutes by cycles)
      lu.matrixLU().triangularView<Eigen::UnitLower>().solveInPlace(local);
      lu.matrixLU().triangularView<Eigen::Upper>().solveInPlace(local);
      for (std::size_t a = 0; a < line.size(); ++a) y(line[a]) = local(a);
    }
  };
  Eigen::VectorXcd delta;
  const detail::GmresResult gmres = detail::preconditionedGmres(
      apply, precondition, rhs, delta, options_.tolerance, kRestart, kMaxIterations);
  s.iterations = gmres.iterations;
  s.residual = gmres.residual;
  s.linear_solver = "gmres";
  if (!gmres.converged) {
    // The sparse LU of the assembled condensed matrix.
    const int T = static_cast<int>(B.size());
    std::vector<Eigen::Triplet<Complex>> entries;
    for (int t = 0; t < T; ++t) {
      for (int i = 0; i < r; ++i) entries.emplace_back(t * r + i, t * r + i, 1.0);
      for (int m = 0; m < r; ++m) {
        const int* nb = neighbourRow(static_cast<std::size_t>(t) * r + m);
        for (int l = -L; l <= L; ++l) {
          if (nb[L + l] < 0) continue;
          for (int i = 0; i < r; ++i) {
            entries.emplace_back(t * r + i, nb[L + l] * r + m, B[t](i, m) * k_hat_[m][L + l]);
          }
        }
      }
    }
    Eigen::SparseMatrix<Complex> A(rhs.size(), rhs.size());
    A.setFromTriplets(entries.begin(), entries.end());
    A.makeCompressed();
    Eigen::SparseLU<Eigen::SparseMatrix<Complex>> lu(A);
    if (lu.info() == Eigen::Success) delta = lu.solve(rhs);
    s.linear_solver = "direct";
    s.iterations = 0;
    s.residual = (A * delta - rhs).norm() / std::max(rhs.norm(), 1e-300);
  }
  if (!delta.allFinite()) {
    throw std::runtime_error(fmt::format(
        "torus steady state at {:g} rad/s: the condensed harmonic-balance system is singular",
        s.input_speed));
  }
  return delta;
}

void TrainTorusSolver::recover(TrainTorusState& s, const std::vector<Eigen::MatrixXcd>& DinvV,
                               const Eigen::VectorXcd& DinvF0, const Eigen::MatrixXcd& phi,
                               const Eigen::VectorXcd& delta) const {
  // X_n = D⁻¹ (F_n − V w_n), w_{m,n} = φ_{m,n} − Σ_{l≠0} k̂_{m,l} δ_{m, n − l P_m e_j}.
  const int n = model_.dofCount();
  const int r = static_cast<int>(model_.meshes().size());
  const int T = static_cast<int>(tones_.cols());
  const int L = options_.mesh_harmonics;
  s.harmonic.resize(n, T);
  for (int t = 0; t < T; ++t) {
    if (block_[t] < 0) continue;
    Eigen::VectorXcd w = phi.col(t);
    for (int m = 0; m < r; ++m) {
      for (int l = -L; l <= L; ++l) {
        const int other = neighbourRow(static_cast<std::size_t>(t) * r + m)[L + l];
        if (other >= 0) w(m) -= k_hat_[m][L + l] * delta(other * r + m);
      }
    }
    s.harmonic.col(t) = DinvV[block_[t]] * w;
    if (t == 0) s.harmonic.col(0) += DinvF0;
    if (t > 0) s.harmonic.col(negative_[t]) = s.harmonic.col(t).conjugate();
  }
}

}  // namespace geardyn
