/// Steady state of a linear time-varying gear train on the torus of its mesh phases
/// (train_torus.h; docs/theory/torus_harmonic_balance.md): generators, tone set, condensed
/// set and the solver's tables (neighbours, lines, grid). The solve per speed is in
/// train_torus_solve.cpp, the grid evaluation in train_torus_grid.cpp.

#include "geardyn/torus/train_torus.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "geardyn/error.h"
#include "geardyn/solvers/detail/harmonic_blocks.h"
#include "geardyn/solvers/detail/train_steady_parts.h"
#include "geardyn/torus/detail/torus_fft.h"

namespace geardyn {
namespace {

using Complex = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
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
  coupling_start_.assign(1, 0);
  for (std::size_t u = 0; u < static_cast<std::size_t>(T) * r; ++u) {
    const int m = static_cast<int>(u % r);
    for (int l = -L; l <= L; ++l) {
      const int other = neighbourRow(u)[L + l];
      if (other < 0) continue;
      coupling_index_.push_back(other * r + m);
      coupling_value_.push_back(k_hat_[m][L + l]);
    }
    coupling_start_.push_back(static_cast<int>(coupling_index_.size()));
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
  // Every field on the grid in one transform: the mesh deflections, then the element
  // deformations (rows vᵀ, then J over each element's DOFs).
  int fields = r;
  for (const TrainElement& e : model.elements()) fields += static_cast<int>(e.jacobian.rows());
  fields_ = Eigen::MatrixXd::Zero(fields, model.dofCount());
  for (int m = 0; m < r; ++m) fields_.row(m) = model.meshVector(m).transpose();
  Eigen::Index row = r;
  for (const TrainElement& e : model.elements()) {
    for (std::size_t i = 0; i < e.dofs.size(); ++i) {
      fields_.block(row, e.dofs[i], e.jacobian.rows(), 1) += e.jacobian.col(i);
    }
    row += e.jacobian.rows();
  }
  if (k > 0) fft_ = std::make_unique<detail::TorusFft>(samples_, fields, r);
}

TrainTorusSolver::~TrainTorusSolver() = default;

}  // namespace geardyn
