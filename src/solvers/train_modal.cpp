/// Modal analysis and Campbell diagram of a gear train (train_modal.h).

#include "geardyn/solvers/train_modal.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <numbers>
#include <optional>
#include <set>
#include <thread>

#include "geardyn/detail/contiguous_ranges.h"
#include "geardyn/error.h"
#include "geardyn/numerics/damped_modes.h"
#include "geardyn/numerics/shift_invert_modes.h"
#include "geardyn/solvers/detail/mode_tracking.h"
#include "geardyn/solvers/detail/whirl_shares.h"
#include "geardyn/system/detail/train_building.h"
#include "geardyn/system/train_housing.h"

namespace geardyn {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// What describe() needs of the model, looked up once per modal analysis rather than per mode
/// (a small train's modes take microseconds), and its work vectors.
struct ModeContext {
  Eigen::VectorXd mass_diagonal;  ///< [kg, kg m²]
  /// Per stage: the body indices of its carrier, sun shaft and ring shaft.
  std::vector<std::array<int, 3>> stage_central;
  Eigen::VectorXd x, y, Mx, My, kinetic;
  std::vector<double> rot, trans, out_of_plane;

  ModeContext(const GearTrainModel& model, const Eigen::SparseMatrix<double>* sparse_mass)
      : mass_diagonal(sparse_mass ? Eigen::VectorXd(sparse_mass->diagonal())
                                  : Eigen::VectorXd(model.mass().diagonal())) {
    const auto& spec = model.spec();
    for (const auto& st : spec.stages) {
      const std::string key = "planetary." + st.name;
      stage_central.push_back(
          {model.bodyIndex(st.carrier),
           model.bodyIndex(spec.gears[detail::gearIndexOf(spec, st.sun, key)].shaft),
           model.bodyIndex(spec.gears[detail::gearIndexOf(spec, st.ring, key)].shaft)});
    }
  }
};

/// Lateral, torsional and axial shares of the diagonal kinetic energy and the whirl
/// (train_modal.h, TrainMode::whirl).
void classifyWhirl(const GearTrainModel& model, TrainMode& mode, const ModeContext& context) {
  const Eigen::VectorXd& md = context.mass_diagonal;
  const int per = model.dofsPerBody();
  detail::WhirlShares shares;
  for (std::size_t b = 0; b < model.bodies().size(); ++b) {
    const TrainBody& body = model.bodies()[b];
    const int r = model.rotationDof(static_cast<int>(b));
    for (int d = body.first_dof; d < body.first_dof + per; ++d) {
      const double e = md(d) * std::norm(mode.shape(d));
      if (d == r) {
        shares.torsional += e;
      } else if (per == 6 && d == body.first_dof + 3) {
        shares.axial += e;
      } else {
        shares.lateral += e;
      }
    }
    if (per == 1) continue;
    shares.addWhirl(md(body.first_dof), mode.shape(body.first_dof), mode.shape(body.first_dof + 1),
                    body.speed_ratio);
  }
  shares.describe(mode);
}

/// Energy fractions and the planetary mode type (Lin & Parker 1999: rotational modes move the
/// central members without translating them, translational modes without rotating them,
/// planet modes not at all). With six DOFs per body, modes of the stage's axial and tilting
/// motion alone are "out_of_plane", and modes with both kinds of motion "mixed".
void describe(const GearTrainModel& model, TrainMode& mode,
              const Eigen::SparseMatrix<double>* sparse_mass, ModeContext& context) {
  // Kinetic energy per DOF, Re(x̄_i (M x)_i) (M is not diagonal with beam elements); a body's
  // rotation is its θ_x, everything else (translations, tilts) counts as translation.
  // Re(x̄ ∘ M x) = x_r ∘ M x_r + x_i ∘ M x_i (M real: no complex copy of it).
  Eigen::VectorXd &x = context.x, &y = context.y, &kinetic = context.kinetic;
  x = mode.shape.real();
  y = mode.shape.imag();
  if (sparse_mass) {
    context.Mx = *sparse_mass * x;
    context.My = *sparse_mass * y;
  } else {
    context.Mx.noalias() = model.mass() * x;
    context.My.noalias() = model.mass() * y;
  }
  kinetic = x.cwiseProduct(context.Mx) + y.cwiseProduct(context.My);
  const int per = model.dofsPerBody();
  const auto& bodies = model.bodies();
  // With six DOFs (y, z, θ_x, x, θ_y, θ_z) the axial and tilting part is also kept apart.
  std::vector<double>&rot = context.rot, &trans = context.trans,
  &out_of_plane = context.out_of_plane;
  rot.assign(bodies.size(), 0.0);
  trans.assign(bodies.size(), 0.0);
  out_of_plane.assign(bodies.size(), 0.0);
  double total = 0.0;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const int r = model.rotationDof(static_cast<int>(b));
    for (int d = bodies[b].first_dof; d < bodies[b].first_dof + per; ++d) {
      (d == r ? rot[b] : trans[b]) += kinetic(d);
      if (per == 6 && d - bodies[b].first_dof >= 3) out_of_plane[b] += kinetic(d);
    }
    total += rot[b] + trans[b];
  }
  // A flexible housing's DOFs follow the bodies' (train_housing.h).
  const int h0 = model.housingFirstDof();
  const double housing = h0 >= 0 ? kinetic.tail(model.dofCount() - h0).sum() : 0.0;
  total += housing;
  mode.housing_fraction = housing / total;
  double translational = 0.0;
  mode.body_kinetic_energy.resize(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    mode.body_kinetic_energy[b] = (rot[b] + trans[b]) / total;
    translational += trans[b] / total;
  }
  mode.translational_fraction = translational;
  classifyWhirl(model, mode, context);
  if (mode.housing_fraction > 0.5) mode.whirl = "housing";

  // Strain energy ½ Re(x̄ᵀ k x) = ½ (x_rᵀ k x_r + x_iᵀ k x_i) over each component's DOFs (no
  // allocation per mode: a modal analysis of a small train takes microseconds).
  auto energy = [&](const std::vector<int>& dofs, const Eigen::MatrixXd& k) {
    double sum = 0.0;
    for (std::size_t i = 0; i < dofs.size(); ++i) {
      for (std::size_t j = 0; j < dofs.size(); ++j) {
        const double kij = k(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
        sum += kij * (x(dofs[i]) * x(dofs[j]) + y(dofs[i]) * y(dofs[j]));
      }
    }
    return 0.5 * sum;
  };
  double strain = 0.0;
  mode.mesh_strain_energy.clear();
  mode.mesh_strain_energy.reserve(model.meshes().size());
  for (const TrainMesh& m : model.meshes()) {
    // k̄ v vᵀ: ½ k̄ ((vᵀx_r)² + (vᵀx_i)²), the mesh deflection squared.
    double dr = 0.0, di = 0.0;
    for (std::size_t i = 0; i < m.dofs.size(); ++i) {
      dr += m.gradient[i] * x(m.dofs[i]);
      di += m.gradient[i] * y(m.dofs[i]);
    }
    mode.mesh_strain_energy.push_back(0.5 * m.mean_stiffness * (dr * dr + di * di));
    strain += mode.mesh_strain_energy.back();
  }
  mode.element_strain_energy.clear();
  mode.element_strain_energy.reserve(model.elements().size());
  for (const TrainElement& e : model.elements()) {
    mode.element_strain_energy.push_back(energy(e.dofs, e.stiffness));
    strain += mode.element_strain_energy.back();
  }
  mode.housing_strain_energy = 0.0;
  if (h0 >= 0) {
    const Eigen::MatrixXd& Kh = model.spec().housing->reduced.K;
    const auto n = model.dofCount() - h0;
    mode.housing_strain_energy =
        0.5 * (x.tail(n).dot(Kh * x.tail(n)) + y.tail(n).dot(Kh * y.tail(n)));
    strain += mode.housing_strain_energy;
    mode.housing_strain_energy = strain > 0 ? mode.housing_strain_energy / strain : 0.0;
  }
  for (double& e : mode.mesh_strain_energy) e = strain > 0 ? e / strain : 0.0;
  for (double& e : mode.element_strain_energy) e = strain > 0 ? e / strain : 0.0;

  mode.stage_type.clear();
  const auto& spec = model.spec();
  for (std::size_t s = 0; s < spec.stages.size(); ++s) {
    // In-plane translation (Lin & Parker's) and the out-of-plane part, of the whole stage.
    double central_rot = 0.0, central_trans = 0.0, stage_out = 0.0, stage_in = 0.0;
    for (const int b : context.stage_central[s]) {
      central_rot += rot[b] / total;
      central_trans += (trans[b] - out_of_plane[b]) / total;
      stage_out += out_of_plane[b] / total;
      stage_in += (rot[b] + trans[b] - out_of_plane[b]) / total;
    }
    // Thresholds: the exact structure gives round-off (~1e-20 of the energy); 1e-8 leaves
    // room for the near-degenerate mixing of a solver without being fooled by real coupling.
    constexpr double kZero = 1e-8;
    double planets = 0.0;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (bodies[b].kind == TrainBodyKind::kPlanet && bodies[b].stage == static_cast<int>(s)) {
        planets += (rot[b] + trans[b]) / total;
        stage_out += out_of_plane[b] / total;
        stage_in += (rot[b] + trans[b] - out_of_plane[b]) / total;
      }
    }
    if (stage_in + stage_out < kZero) {
      mode.stage_type.push_back("outside");  // a mode of the rest of the train
    } else if (stage_in < kZero) {
      mode.stage_type.push_back("out_of_plane");  // axial and tilting motion only (full DOFs)
    } else if (stage_out >= kZero) {
      mode.stage_type.push_back("mixed");  // in and out of plane (helical, or offset members)
    } else if (central_rot + central_trans < kZero) {
      mode.stage_type.push_back("planet");
    } else if (per == 1 || central_trans < kZero) {
      mode.stage_type.push_back("rotational");
    } else if (central_rot < kZero) {
      mode.stage_type.push_back("translational");
    } else {
      mode.stage_type.push_back("mixed");
    }
  }
}

using SparseMatrix = Eigen::SparseMatrix<double>;

TrainMode fromDamped(detail::DampedMode&& found) {
  TrainMode mode;
  mode.eigenvalue = found.eigenvalue;
  mode.frequency = found.eigenvalue.imag() / kTwoPi;
  mode.damping_ratio = -found.eigenvalue.real() / std::abs(found.eigenvalue);
  mode.shape = std::move(found.shape);
  mode.divergent = detail::isDivergent(found.eigenvalue);
  return mode;
}

SparseMatrix sparseOf(const Eigen::MatrixXd& A) {
  // Entries below 1e-14 of the largest are round-off of cancelling sums, not couplings.
  return A.sparseView(1.0, 1e-14 * std::max(A.cwiseAbs().maxCoeff(), 1e-300));
}

/// K x = ω² M x for symmetric K (its symmetric part) and M: the eigenvalues ω² ascending and
/// M-normalised vectors. A diagonal M (lumped bodies: every small train without beams) is
/// scaled out, K̃ = M^-½ K M^-½, x = M^-½ z: the standard symmetric problem, without the
/// generalised solver's Cholesky factor and its two triangular solves and back-substitution
/// (measured on Lin & Parker's 18 DOFs: 10.7 µs against 14.7 µs, the same spectrum).
void symmetricModes(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, Eigen::VectorXd& w2,
                    Eigen::MatrixXd& shapes) {
  const Eigen::VectorXd m = M.diagonal();
  const bool diagonal =
      (m.array() > 0.0).all() && (M - Eigen::MatrixXd(m.asDiagonal())).cwiseAbs().maxCoeff() == 0.0;
  if (diagonal) {
    const Eigen::VectorXd scale = m.cwiseSqrt().cwiseInverse();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(
        scale.asDiagonal() * (0.5 * (K + K.transpose())) * scale.asDiagonal());
    if (solver.info() != Eigen::Success) {
      throw std::runtime_error("modal analysis: the eigenvalue solver did not converge");
    }
    w2 = solver.eigenvalues();
    shapes = scale.asDiagonal() * solver.eigenvectors();
    return;
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(0.5 * (K + K.transpose()),
                                                                         M);
  if (solver.info() != Eigen::Success) {
    throw std::runtime_error("modal analysis: the eigenvalue solver did not converge");
  }
  w2 = solver.eigenvalues();
  shapes = solver.eigenvectors();
}

/// The model's matrices as sparse ones, built once per analysis of a large train.
struct SparseTrain {
  SparseMatrix M, K, Komega, C, G;
  explicit SparseTrain(const GearTrainModel& model)
      : M(sparseOf(model.mass())),
        K(sparseOf(model.stiffness() + model.meanMeshStiffness())),
        Komega(sparseOf(model.centripetal())),
        C(sparseOf(model.damping())),
        G(sparseOf(model.gyroscopic())) {}
};

bool fewOfMany(const GearTrainModel& model, const TrainModalOptions& options) {
  const int n = model.dofCount();
  return n >= kSparseModalDofs && options.modes > 0 && 4 * options.modes < n;
}

/// The rigid-body threshold [Hz]: options.rigid_frequency, or 1e-6 of `highest` [Hz].
double rigidThreshold(const TrainModalOptions& options, double highest) {
  return options.rigid_frequency >= 0 ? options.rigid_frequency : 1e-6 * highest;
}

/// A few modes of a large (FE) train: shift-invert Arnoldi nearest σ < 0, just below the
/// rigid-body modes at 0: 1e-3 of the softest uncoupled DOF's sqrt(K_ii / M_ii), a Rayleigh
/// quotient, hence at or above the lowest elastic modes' scale. `highest` gets the stiffest
/// uncoupled DOF's frequency [Hz] (the scale of the rigid-body threshold). At least
/// options.modes elastic modes (not rigid, damping ratio within options.max_damping_ratio)
/// are returned when the train has that many.
std::vector<TrainMode> fewModes(const SparseTrain& sparse, double speed,
                                const TrainModalOptions& options, double& highest,
                                Eigen::VectorXd* krylov_start) {
  const SparseMatrix K = sparse.K + (speed * speed) * sparse.Komega;
  const SparseMatrix D = sparse.C + speed * sparse.G;
  const Eigen::VectorXd m = sparse.M.diagonal(), k = K.diagonal();
  double softest = HUGE_VAL, stiffest = 0.0;
  for (Eigen::Index i = 0; i < m.size(); ++i) {
    if (m(i) > 0.0 && k(i) > 0.0) {
      softest = std::min(softest, k(i) / m(i));
      stiffest = std::max(stiffest, k(i) / m(i));
    }
  }
  if (!std::isfinite(softest)) softest = 1.0;
  highest = std::sqrt(stiffest) / kTwoPi;
  const double rigid = rigidThreshold(options, highest);
  const int count = options.modes;
  const int most = 2 * static_cast<int>(sparse.M.rows()) - 3;
  // Each elastic mode is a conjugate pair; rigid-body (λ ≈ 0) and overdamped eigenvalues near
  // σ come first. The Arnoldi cost grows with the square of the eigenvalues asked for, so the
  // pairs plus a margin of 4 are asked for, and again with the margin widened by what was
  // missing when fewer elastic modes come back (a fixed margin of 12 cost 30 % on a Campbell
  // diagram of a 624-DOF train).
  for (int margin = 4;;) {
    const int asked = std::min(2 * count + margin, most);
    std::vector<TrainMode> modes;
    int elastic = 0;
    for (detail::DampedMode& found : detail::shiftInvertModes(
             sparse.M, D, K, asked, -1e-3 * std::sqrt(softest), krylov_start)) {
      modes.push_back(fromDamped(std::move(found)));
      const TrainMode& mode = modes.back();
      elastic += std::abs(mode.eigenvalue) / kTwoPi >= rigid && !mode.divergent &&
                 mode.damping_ratio <= options.max_damping_ratio;
    }
    if (elastic >= count || asked == most) return modes;
    margin += 2 * (count - elastic) + 2;
    // The start vector now lies in this problem's own invariant subspace: start afresh.
    if (krylov_start != nullptr) krylov_start->resize(0);
  }
}

/// The modes at `input_speed`; `sparse` and `krylov_start` (see detail::shiftInvertModes)
/// serve the shift-invert path of large trains, as in a Campbell diagram.
std::vector<TrainMode> modesAt(const GearTrainModel& model, double input_speed,
                               const TrainModalOptions& options, const SparseTrain* sparse,
                               Eigen::VectorXd* krylov_start = nullptr);

}  // namespace

void TrainModalOptions::validate() const {
  if (modes < 0) throw InputError("modal.modes", std::to_string(modes), "an integer >= 0");
  if (!(max_damping_ratio > 0.0 && max_damping_ratio <= 1.0)) {
    throw InputError("modal.max_damping_ratio", fmt::format("{:g}", max_damping_ratio),
                     "a ratio in (0, 1]");
  }
  if (!std::isfinite(rigid_frequency)) {
    throw InputError("modal.rigid_frequency", fmt::format("{:g} Hz", rigid_frequency),
                     "a finite frequency (< 0: derived)");
  }
}

std::vector<TrainMode> trainModes(const GearTrainModel& model, double input_speed,
                                  const TrainModalOptions& options) {
  return modesAt(model, input_speed, options, nullptr);
}

namespace {

std::vector<TrainMode> modesAt(const GearTrainModel& model, double input_speed,
                               const TrainModalOptions& options, const SparseTrain* sparse,
                               Eigen::VectorXd* krylov_start) {
  options.validate();
  std::vector<TrainMode> modes;
  const bool few = fewOfMany(model, options);
  std::optional<SparseTrain> own;
  if (few && !sparse) sparse = &own.emplace(model);
  double sparse_highest = 0.0;
  bool undamped = false;
  if (few) {
    modes = fewModes(*sparse, input_speed, options, sparse_highest, krylov_start);
  } else {
    const Eigen::MatrixXd K = model.meanStiffnessAt(input_speed);
    const Eigen::MatrixXd D = model.dampingAt(input_speed);
    const Eigen::MatrixXd& M = model.mass();
    undamped = D.cwiseAbs().maxCoeff() == 0.0;
    if (undamped) {
      // Undamped, no Coriolis: the symmetric problem gives exact real modes (multiplicities to
      // round-off) and keeps the rigid-body modes.
      Eigen::VectorXd w2s;
      Eigen::MatrixXd shapes;
      symmetricModes(K, M, w2s, shapes);
      for (Eigen::Index j = 0; j < K.rows(); ++j) {
        TrainMode mode;
        const double w2 = w2s(j);
        const double w = std::sqrt(std::abs(w2));
        mode.divergent = w2 < 0.0;
        mode.eigenvalue =
            mode.divergent ? std::complex<double>(w, 0.0) : std::complex<double>(0.0, w);
        mode.frequency = mode.divergent ? 0.0 : w / kTwoPi;
        mode.damping_ratio = mode.divergent ? -1.0 : 0.0;
        mode.shape = shapes.col(j).cast<std::complex<double>>();
        Eigen::Index largest = 0;
        mode.shape.cwiseAbs().maxCoeff(&largest);
        mode.shape /= mode.shape(largest);
        modes.push_back(std::move(mode));
      }
    } else {
      for (detail::DampedMode& found : detail::dampedModes(M, D, K)) {
        modes.push_back(fromDamped(std::move(found)));
      }
    }
  }
  std::sort(modes.begin(), modes.end(),
            [](const TrainMode& a, const TrainMode& b) { return a.frequency < b.frequency; });
  // The rigid-body threshold: 1e-6 of the highest frequency found (the sparse path finds only
  // the low ones: 1e-6 of the stiffest uncoupled DOF's frequency instead).
  const double highest = std::max(sparse_highest, modes.empty() ? 0.0 : modes.back().frequency);
  const double rigid = rigidThreshold(options, highest);
  // Divergent modes first (frequency 0), then the oscillating ones.
  std::stable_partition(modes.begin(), modes.end(),
                        [](const TrainMode& mode) { return mode.divergent; });
  std::vector<TrainMode> kept;
  int divergent = 0;
  for (TrainMode& mode : modes) {
    if (mode.damping_ratio > options.max_damping_ratio) continue;
    const bool is_rigid = std::abs(mode.eigenvalue) / kTwoPi < rigid;
    if (is_rigid) {
      // The damped eigensolver returns a rigid-body pair at λ ≈ 0 with either sign of Im λ:
      // only the symmetric path reports them, deterministically.
      if (!options.keep_rigid || !undamped) continue;
      mode.frequency = 0.0;
      mode.damping_ratio = 0.0;
      mode.divergent = false;  // a rigid-body mode whose w² round-off made negative
    }
    divergent += mode.divergent;
    kept.push_back(std::move(mode));
  }
  for (std::size_t i = 0; i < kept.size(); ++i) {
    int count = 0;
    for (const TrainMode& other : kept) {
      if (other.divergent != kept[i].divergent) continue;
      if (std::abs(other.frequency - kept[i].frequency) <=
          1e-6 * std::max(kept[i].frequency, rigid)) {
        ++count;
      }
    }
    kept[i].multiplicity = count;
  }
  if (options.modes > 0 && static_cast<int>(kept.size()) > divergent + options.modes) {
    kept.resize(divergent + options.modes);
  }
  const Eigen::SparseMatrix<double>* sparse_mass = sparse ? &sparse->M : nullptr;
  ModeContext context(model, sparse_mass);
  for (TrainMode& mode : kept) describe(model, mode, sparse_mass, context);
  return kept;
}

}  // namespace

std::vector<TrainOrderLine> trainOrderLines(const GearTrainModel& model, int mesh_harmonics) {
  std::vector<TrainOrderLine> lines;
  auto add = [&](std::string name, double slope) {
    if (!(slope > 0.0)) return;
    for (const auto& l : lines) {
      if (std::abs(l.slope - slope) <= 1e-9 * slope) return;
    }
    lines.push_back({std::move(name), slope});
  };
  for (const TrainBody& b : model.bodies()) {
    if (b.kind == TrainBodyKind::kPlanet && b.planet > 0) continue;
    add(fmt::format("1x {}", b.kind == TrainBodyKind::kPlanet
                                 ? model.spec().stages[b.stage].name + " planets"
                                 : b.name),
        std::abs(b.speed_ratio) / kTwoPi);
  }
  for (int h = 1; h <= mesh_harmonics; ++h) {
    for (const TrainMesh& m : model.meshes()) {
      const std::string name = m.stage >= 0 ? model.spec().stages[m.stage].name : m.name;
      add(h == 1 ? "mesh " + name : fmt::format("{}x mesh {}", h, name), h * m.frequency_ratio);
    }
  }
  return lines;
}

TrainCampbell trainCampbell(const GearTrainModel& model, const std::vector<double>& speeds,
                            const TrainModalOptions& options,
                            const std::vector<TrainOrderLine>& lines,
                            const ProgressCallback& progress) {
  if (speeds.size() < 2) throw InputError("campbell.speeds", "", "at least two speeds");
  for (std::size_t i = 1; i < speeds.size(); ++i) {
    if (!(speeds[i] > speeds[i - 1])) {
      throw InputError("campbell.speeds", fmt::format("{:g} rad/s", speeds[i]), "ascending speeds");
    }
  }
  TrainCampbell d;
  d.speeds = speeds;
  d.lines = lines;
  TrainModalOptions candidates = options;
  candidates.keep_rigid = false;
  const int wanted = options.modes > 0 ? options.modes : model.dofCount();
  candidates.modes = std::min(2 * wanted, model.dofCount());
  // Large trains (shift-invert Arnoldi, whose cost grows with the square of the modes asked
  // for): 1.5× the tracked modes as candidates.
  if (fewOfMany(model, candidates)) candidates.modes = wanted + std::max(4, wanted / 2);
  candidates.validate();
  std::optional<SparseTrain> sparse;
  const SparseTrain* sparse_train = fewOfMany(model, candidates) ? &sparse.emplace(model) : nullptr;
  // The speeds are independent eigenproblems: solved on every core (the model and its sparse
  // matrices are read-only), each core a contiguous run of speeds so that every Arnoldi run
  // starts from the previous speed's eigenvectors; then tracked in order. An exception in a
  // worker is rethrown here.
  std::vector<std::vector<TrainMode>> solved(speeds.size());
  std::exception_ptr failure;
  std::mutex failure_mutex;
  std::atomic<std::size_t> finished{0};
  const std::size_t threads = std::max(1u, std::thread::hardware_concurrency());
  detail::runContiguousRanges(
      speeds.size(), threads,
      [&](std::size_t first, std::size_t last, bool on_caller, const std::atomic<bool>& stop) {
        Eigen::VectorXd krylov_start;
        for (std::size_t i = first; i < last && !stop; ++i) {
          try {
            solved[i] = modesAt(model, speeds[i], candidates, sparse_train, &krylov_start);
          } catch (...) {
            const std::lock_guard<std::mutex> lock(failure_mutex);
            if (!failure) failure = std::current_exception();
            return;
          }
          const std::size_t done = ++finished;
          if (on_caller && progress)
            progress(static_cast<double>(done), static_cast<double>(speeds.size()));
        }
      });
  if (failure) std::rethrow_exception(failure);
  if (progress) progress(static_cast<double>(speeds.size()), static_cast<double>(speeds.size()));
  d.divergence_rate.assign(speeds.size(), 0.0);
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    std::vector<TrainMode> found = std::move(solved[i]);
    // Divergent modes (frequency 0, no oscillation) are reported per speed, not tracked.
    for (const TrainMode& mode : found) {
      if (mode.divergent) {
        d.divergence_rate[i] = std::max(d.divergence_rate[i], mode.eigenvalue.real());
      }
    }
    found.erase(std::remove_if(found.begin(), found.end(),
                               [](const TrainMode& mode) { return mode.divergent; }),
                found.end());
    if (i == 0) {
      if (static_cast<int>(found.size()) > wanted) found.resize(wanted);
      d.modes.push_back(std::move(found));
    } else {
      d.modes.push_back(detail::trackByMac(d.modes.back(), found));
    }
  }
  for (const TrainOrderLine& line : lines) {
    detail::findCrossings(
        d.speeds, d.modes, line.slope,
        [&](std::size_t j, std::size_t i, double speed, double f, double s) {
          d.critical_speeds.push_back({static_cast<int>(j), line.name, speed, f,
                                       (s < 0.5 ? d.modes[i - 1][j] : d.modes[i][j]).whirl});
        });
  }
  std::sort(
      d.critical_speeds.begin(), d.critical_speeds.end(),
      [](const TrainCriticalSpeed& a, const TrainCriticalSpeed& b) { return a.speed < b.speed; });
  return d;
}

}  // namespace geardyn
