/// Static and periodic steady-state response of a gear train (train_response.h).

#include "geardyn/solvers/train_response.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <numeric>
#include <optional>
#include <vector>

#include "geardyn/error.h"
#include "geardyn/solvers/detail/harmonic_blocks.h"
#include "geardyn/solvers/detail/housing_condensation.h"
#include "geardyn/solvers/detail/train_static_bearings.h"
#include "geardyn/solvers/detail/train_steady_parts.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"
#include "geardyn/system/train_housing.h"

namespace geardyn {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
using Complex = std::complex<double>;

using detail::elementDeformation;
using detail::rigidModes;

/// The excitations' harmonics into F (n × (2H + 1), column H + h): Re[F_e e^{i j ω₀ t}] is
/// F_e/2 at j = ±P_e (signed by ν) and its conjugate at −j; a runout's stiffness part rides on
/// its mesh's k(φ) = Σ_l k̂_l e^{i l P_m ω₀ t}, at the sidebands j + l P_m.
void addExcitationHarmonics(const GearTrainModel& model, const TrainBaseFrequency& base,
                            double input_speed, int L, int H,
                            const std::vector<std::vector<Complex>>& k_hat, Eigen::MatrixXcd& F) {
  const auto& terms = model.excitations();
  for (std::size_t e = 0; e < terms.size(); ++e) {
    const TrainExcitationTerm& t = terms[e];
    const int j = (t.order(input_speed) < 0.0 ? -1 : 1) * base.excitation_multiple[e];
    auto place = [&](int h, const Eigen::VectorXcd& value) {
      if (h < -H || h > H) return;
      for (std::size_t i = 0; i < t.dofs.size(); ++i) F(t.dofs[i], h + H) += 0.5 * value(i);
    };
    const Eigen::VectorXcd moving = t.amplitude(input_speed, 0.0);  // without the k(φ) part
    place(j, moving);
    place(-j, moving.conjugate());
    if (t.mesh < 0) continue;
    const int P = base.mesh_multiple[t.mesh];
    for (int l = -L; l <= L; ++l) {
      const Complex k = k_hat[t.mesh][L + l];
      place(j + l * P, k * t.stiffness);
      place(-j + l * P, k * t.stiffness.conjugate());
    }
  }
}

}  // namespace

ElementLoad elementLoad(const TrainElement& element, const Eigen::VectorXd& local_force) {
  ElementLoad load;
  double force2 = 0.0, moment2 = 0.0;
  for (Eigen::Index i = 0; i < local_force.size(); ++i) {
    const bool moment = static_cast<std::size_t>(i) < element.moment_rows.size() &&
                        element.moment_rows[static_cast<std::size_t>(i)];
    (moment ? moment2 : force2) += local_force(i) * local_force(i);
    (moment ? load.has_moment : load.has_force) = true;
  }
  load.force = std::sqrt(force2);
  load.moment = std::sqrt(moment2);
  return load;
}

TrainStaticResult solveTrainStatic(const GearTrainModel& model, double input_speed) {
  TrainStaticResult r;
  const Eigen::MatrixXd K = model.meanStiffnessAt(input_speed);
  Eigen::VectorXd F = model.staticLoad();
  std::vector<double> mean_error;
  for (std::size_t m = 0; m < model.meshes().size(); ++m) {
    const TrainMesh& mesh = model.meshes()[m];
    // ē: the mean transmission error over a mesh period.
    const double e =
        integrateOverPeriod([&](double phi) { return mesh.transmission_error.value(phi); }, {});
    mean_error.push_back(e);
    F += mesh.mean_stiffness * e * model.meshVector(static_cast<int>(m));
  }
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(K);
  cod.setThreshold(1e-12);
  r.displacement = cod.solve(F);
  r.rigid_modes = static_cast<int>(K.rows() - cod.rank());
  const double scale = std::max(F.norm(), 1e-300);
  r.residual = (K * r.displacement - F).norm() / scale;
  if (!model.rollingBearings().empty()) {
    detail::solveRollingBearingStatics(model, K, F, r);
  }
  if (r.status == "ok" && F.norm() > 0.0 && r.residual > 1e-8) {
    r.status = "unbalanced";
    r.message = fmt::format(
        "the static loads act on a rigid-body mode of the train ({} rigid "
        "modes; relative residual {:.3g}): support the train or balance "
        "the input and output torques",
        r.rigid_modes, r.residual);
  }
  for (std::size_t m = 0; m < model.meshes().size(); ++m) {
    const TrainMesh& mesh = model.meshes()[m];
    r.mesh_force.push_back(mesh.mean_stiffness * (mesh.deflection(r.displacement) - mean_error[m]));
  }
  for (const TrainElement& e : model.elements()) {
    r.element_load.push_back(
        elementLoad(e, e.local_stiffness * elementDeformation(e, r.displacement)));
  }
  for (std::size_t s = 0; s < model.spec().stages.size(); ++s) {
    TrainStageLoadSharing share;
    share.stage = model.spec().stages[s].name;
    for (std::size_t m = 0; m < model.meshes().size(); ++m) {
      const TrainMesh& mesh = model.meshes()[m];
      if (mesh.stage != static_cast<int>(s)) continue;
      (mesh.kind == TrainMeshKind::kSunPlanet ? share.sun_planet_force : share.ring_planet_force)
          .push_back(r.mesh_force[m]);
    }
    double sum = 0.0, largest = 0.0;
    for (double f : share.sun_planet_force) sum += f, largest = std::max(largest, std::abs(f));
    const double mean = sum / static_cast<double>(share.sun_planet_force.size());
    share.load_sharing_factor = std::abs(mean) > 0.0 ? largest / std::abs(mean) : 1.0;
    r.load_sharing.push_back(std::move(share));
  }
  return r;
}

void TrainSteadyOptions::validate() const {
  if (mesh_harmonics < 1 || mesh_harmonics > 200) {
    throw InputError("steady.mesh_harmonics", std::to_string(mesh_harmonics),
                     "an integer in [1, 200]");
  }
  if (max_base_harmonics < 1) {
    throw InputError("steady.max_base_harmonics", std::to_string(max_base_harmonics),
                     "an integer >= 1");
  }
  if (samples < 0) throw InputError("steady.samples", std::to_string(samples), ">= 0 (0: derived)");
  if (sparse_dofs < 1) {
    throw InputError("steady.sparse_dofs", std::to_string(sparse_dofs), "an integer >= 1");
  }
}

TrainBaseFrequency trainBaseFrequency(const GearTrainModel& model, int mesh_harmonics,
                                      int max_base_harmonics) {
  TrainBaseFrequency base;
  const auto& excitations = model.excitations();
  if (model.meshes().empty() && excitations.empty()) {
    base.ratio = 1.0 / kTwoPi;
    return base;
  }
  long long g = 0, l = 1;
  std::vector<std::pair<long long, long long>> fractions;
  auto add = [&](double events_per_revolution) {
    const auto [p, q] = detail::rationalApproximation(events_per_revolution);
    fractions.push_back({p, q});
    g = std::gcd(g, p);
    l = std::lcm(l, q);
  };
  // Mesh events per input revolution: z |ω/Ω|, a ratio of tooth counts; an excitation's |ν|.
  for (const TrainMesh& m : model.meshes()) add(m.frequency_ratio * kTwoPi);
  for (const TrainExcitationTerm& e : excitations) add(std::abs(e.ratio));
  // gcd of p_i/q_i (reduced) = gcd(p_i) / lcm(q_i).
  base.ratio = static_cast<double>(g) / static_cast<double>(l) / kTwoPi;
  long long largest = 0;
  for (std::size_t i = 0; i < fractions.size(); ++i) {
    const auto [p, q] = fractions[i];
    const long long multiple = (p / g) * (l / q);
    const int clipped = static_cast<int>(std::min<long long>(multiple, 1 << 30));
    if (i < model.meshes().size()) {
      base.mesh_multiple.push_back(clipped);
      largest = std::max(largest, multiple);
    } else {
      base.excitation_multiple.push_back(clipped);
      if (multiple > max_base_harmonics) {
        const TrainExcitationTerm& e = excitations[i - model.meshes().size()];
        throw InputError(
            "steady.max_base_harmonics", std::to_string(max_base_harmonics),
            fmt::format("at least {}: {} (order {:.9g}) is harmonic {} of the common period of "
                        "the meshes and excitations; use the time analysis for this train",
                        multiple, e.name, std::abs(e.ratio), multiple));
      }
    }
  }
  if (largest * mesh_harmonics > max_base_harmonics) {
    throw InputError(
        "steady.mesh_harmonics", std::to_string(mesh_harmonics),
        fmt::format("fewer harmonics: the mesh frequencies share a common period of {} mesh "
                    "periods of the fastest mesh, so {} harmonics of each mesh need {} harmonics "
                    "of the common period (limit steady.max_base_harmonics = {}); use the time "
                    "analysis for this train",
                    largest, mesh_harmonics, largest * mesh_harmonics, max_base_harmonics));
  }
  return base;
}

Eigen::MatrixXd TrainSteadyState::displacement(const Eigen::VectorXd& times) const {
  const double w0 = kTwoPi * base_frequency;
  // Only the harmonics that are there (an excitation at a shaft order fills a few of many).
  std::vector<int> present;
  for (int h = 1; h <= harmonics; ++h)
    if (harmonic.col(h).cwiseAbs().maxCoeff() > 0.0) present.push_back(h);
  // Re[2 X_h e^{iθ}] = 2 Re X_h cos θ − 2 Im X_h sin θ: one real product of the sampled
  // (cos, sin) basis with the coefficients.
  const Eigen::Index p = static_cast<Eigen::Index>(present.size());
  Eigen::MatrixXd coefficients(2 * p, harmonic.rows());
  // e^{i h_j θ} = e^{i h_{j−1} θ} e^{i (h_j − h_{j−1}) θ}: one sincos per distinct gap between
  // present harmonics (one when they are evenly spaced) instead of one per harmonic; the
  // products' round-off grows as h ε (1e-14 at h = 100).
  std::vector<int> gaps, gap_of(present.size());
  for (std::size_t j = 0; j < present.size(); ++j) {
    const int gap = present[j] - (j == 0 ? 0 : present[j - 1]);
    auto found = std::find(gaps.begin(), gaps.end(), gap);
    if (found == gaps.end()) found = gaps.insert(gaps.end(), gap);
    gap_of[j] = static_cast<int>(found - gaps.begin());
  }
  for (Eigen::Index j = 0; j < p; ++j) {
    const int h = present[static_cast<std::size_t>(j)];
    coefficients.row(2 * j) = 2.0 * harmonic.col(h).real().transpose();
    coefficients.row(2 * j + 1) = -2.0 * harmonic.col(h).imag().transpose();
  }
  Eigen::MatrixXd q = Eigen::VectorXd::Ones(times.size()) * harmonic.col(0).real().transpose();
  if (p == 0) return q;
  // The basis in blocks of times: a whole time record's basis (10⁶ steps × 2p columns) would
  // be gigabytes.
  constexpr Eigen::Index kBlock = 1024;
  Eigen::MatrixXd basis(std::min<Eigen::Index>(kBlock, times.size()), 2 * p);
  std::vector<std::complex<double>> factor(gaps.size());
  for (Eigen::Index first = 0; first < times.size(); first += kBlock) {
    const Eigen::Index rows = std::min<Eigen::Index>(kBlock, times.size() - first);
    for (Eigen::Index k = 0; k < rows; ++k) {
      const double theta = w0 * times(first + k);
      for (std::size_t g = 0; g < gaps.size(); ++g) factor[g] = std::polar(1.0, gaps[g] * theta);
      std::complex<double> power = 1.0;
      for (Eigen::Index j = 0; j < p; ++j) {
        power *= factor[static_cast<std::size_t>(gap_of[static_cast<std::size_t>(j)])];
        basis(k, 2 * j) = power.real();
        basis(k, 2 * j + 1) = power.imag();
      }
    }
    q.middleRows(first, rows).noalias() += basis.topRows(rows) * coefficients;
  }
  return q;
}

namespace {

/// One past the last DOF any mesh reads: the bodies' DOFs, which come before a housing's.
int meshSpan(const GearTrainModel& model) {
  int span = 0;
  for (const TrainMesh& mesh : model.meshes()) {
    for (int d : mesh.dofs) span = std::max(span, d + 1);
  }
  return span;
}

/// q(t) at s.t on the DOFs the meshes and elements read: `q` (rows: samples) holds DOF d in
/// column `column[d]` (−1: not sampled). Without a housing every DOF, in order; a housed train's
/// bodies' DOFs (first, in order: the meshes read them) and the housing's the elements read;
/// its modal coordinates only feed its response points, from s.harmonic.
struct SampledDofs {
  Eigen::MatrixXd q;
  std::vector<int> column;
};
SampledDofs sampledDisplacement(const TrainSteadyState& s, const GearTrainModel& model) {
  const int n = model.dofCount(), n_t = model.housingFirstDof();
  SampledDofs out;
  out.column.resize(static_cast<std::size_t>(n));
  if (n_t < 0) {
    std::iota(out.column.begin(), out.column.end(), 0);
    out.q = s.displacement(s.t);
    return out;
  }
  std::fill(out.column.begin(), out.column.end(), -1);
  std::iota(out.column.begin(), out.column.begin() + n_t, 0);
  std::vector<Eigen::Index> rows(static_cast<std::size_t>(n_t));
  std::iota(rows.begin(), rows.end(), Eigen::Index{0});
  for (const TrainElement& e : model.elements()) {
    for (int d : e.dofs) {
      if (out.column[static_cast<std::size_t>(d)] >= 0) continue;
      out.column[static_cast<std::size_t>(d)] = static_cast<int>(rows.size());
      rows.push_back(d);
    }
  }
  TrainSteadyState part;
  part.base_frequency = s.base_frequency;
  part.harmonics = s.harmonics;
  part.harmonic = s.harmonic(rows, Eigen::all);
  out.q = part.displacement(s.t);
  return out;
}

/// F_h, h = −H … H (column h + H): the static load at h = 0, every mesh's k·e and c ė at its
/// harmonics, and the excitations (addExcitationHarmonics).
Eigen::MatrixXcd forcingHarmonics(const GearTrainModel& model, const TrainBaseFrequency& base,
                                  double input_speed, int L, int H, double w0,
                                  const std::vector<std::vector<Complex>>& k_hat,
                                  const std::vector<std::vector<Complex>>& ke_hat,
                                  const std::vector<std::vector<Complex>>& e_hat,
                                  const Eigen::MatrixXcd& V) {
  const int n = model.dofCount(), r = static_cast<int>(V.cols());
  const auto& meshes = model.meshes();
  Eigen::MatrixXcd F = Eigen::MatrixXcd::Zero(n, 2 * H + 1);
  F.col(H) = model.staticLoad().cast<Complex>();
  // v_m is zero past the last DOF any mesh reads (the bodies' come before a housing's).
  const int span = meshSpan(model);
  for (int m = 0; m < r; ++m) {
    for (int l = -L; l <= L; ++l) {
      const int j = l * base.mesh_multiple[m];
      // k e, and the mesh dashpot on the tooth deformation rate: c_m ė (ė at i j ω₀).
      if (std::abs(j) <= H) {
        F.col(j + H).head(span) +=
            (ke_hat[m][L + l] + Complex(0.0, j * w0) * meshes[m].damping * e_hat[m][L + l]) *
            V.col(m).head(span);
      }
    }
  }
  addExcitationHarmonics(model, base, input_speed, L, H, k_hat, F);
  return F;
}

/// One base period of the steady state s sampled (`samples` points; 0: derived from H): mesh
/// forces, their extremes, dynamic factors and harmonics 1 … L, and the elements' dynamic forces.
void sampleSteadyForces(TrainSteadyState& s, const GearTrainModel& model, double input_speed,
                        int samples, int L, const std::vector<int>& mesh_multiple) {
  const int H = s.harmonics;
  const auto& meshes = model.meshes();
  if (samples == 0) {
    samples = 64;
    while (samples < 8 * H) samples *= 2;
  }
  s.t = Eigen::VectorXd::LinSpaced(samples, 0.0, (samples - 1.0) / samples / s.base_frequency);
  const SampledDofs sampled = sampledDisplacement(s, model);
  const Eigen::MatrixXd& q = sampled.q;
  s.mesh_force.resize(samples, static_cast<Eigen::Index>(meshes.size()));
  // q(t_k) on the DOFs up to the last one a mesh reads (the bodies', q's first columns in
  // order), contiguous for the mesh forces.
  const int mesh_span = meshSpan(model);
  Eigen::VectorXd q_k(mesh_span);
  for (int k = 0; k < samples; ++k) {
    q_k = q.row(k).head(mesh_span).transpose();
    for (std::size_t m = 0; m < meshes.size(); ++m) {
      s.mesh_force(k, m) = meshes[m].force(s.t(k), input_speed, q_k);
    }
  }
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const Eigen::VectorXd f = s.mesh_force.col(m);
    s.mesh_force_mean.push_back(f.mean());
    s.mesh_force_max.push_back(f.maxCoeff());
    s.mesh_force_min.push_back(f.minCoeff());
    s.dynamic_factor.push_back(
        std::abs(f.mean()) > 0.0 ? f.cwiseAbs().maxCoeff() / std::abs(f.mean()) : 0.0);
    std::vector<double> amplitudes;
    for (int l = 1; l <= L; ++l) {
      Complex sum = 0.0;
      const double step = kTwoPi * l * mesh_multiple[m] / samples;
      for (int k = 0; k < samples; ++k) sum += f(k) * std::polar(1.0, -step * k);
      amplitudes.push_back(2.0 * std::abs(sum) / samples);
    }
    s.mesh_force_harmonics.push_back(std::move(amplitudes));
  }
  // Element forces k J q(t): linear in q, one product per element with the samples of its DOFs.
  Eigen::MatrixXd local;
  for (const TrainElement& e : model.elements()) {
    local.resize(samples, static_cast<Eigen::Index>(e.dofs.size()));
    for (std::size_t i = 0; i < e.dofs.size(); ++i) {
      local.col(static_cast<Eigen::Index>(i)) =
          q.col(sampled.column[static_cast<std::size_t>(e.dofs[i])]);
    }
    Eigen::MatrixXd forces = local * (e.local_stiffness * e.jacobian).transpose();
    forces.rowwise() -= forces.colwise().mean();
    s.element_dynamic_force.push_back(forces.rowwise().norm().maxCoeff());
  }
}

}  // namespace

TrainSteadySolver::TrainSteadySolver(const GearTrainModel& model, const TrainSteadyOptions& options)
    : model_(model), options_(options) {
  options.validate();
  base_ = trainBaseFrequency(model, options.mesh_harmonics, options.max_base_harmonics);
  // K̄(Ω) = K̄(0) + Ω²K_Ω: the modes of K̄(0) stay rigid at every speed when K_Ω R = 0 (the
  // planets' centripetal term spares the rolling mode, docs/theory/gear_trains.md), and the
  // dense generalized eigensolve (a fifth of a 270-DOF forced sweep) is not repeated per speed.
  rigid_ = rigidModes(model.meanStiffnessAt(0.0), model.mass());
  const Eigen::MatrixXd& Komega = model.centripetal();
  rigid_at_every_speed_ = rigid_.cols() == 0 || Komega.size() == 0 ||
                          (Komega * rigid_).norm() <= 1e-12 * Komega.norm() * rigid_.norm();
  if (options.condense_housing) housing_ = detail::HousingCondensation::of(model);
  if (housing_) {
    for (Eigen::Index i : housing_->read_rows) housing_read_dofs_.push_back(housing_->first + i);
  }
  if (rigid_.cols() > 0) rigid_mass_ = model.mass() * rigid_;
  const int L = options.mesh_harmonics;
  for (int p : base_.mesh_multiple) harmonics_ = std::max(harmonics_, p * L);
  for (int p : base_.excitation_multiple) harmonics_ = std::max(harmonics_, p);
  // Fourier coefficients of every mesh's k and k·e over its own period, with its phase.
  for (const TrainMesh& mesh : model.meshes()) {
    detail::MeshFourier fourier = detail::meshFourier(mesh, L);
    k_hat_.push_back(std::move(fourier.k));
    ke_hat_.push_back(std::move(fourier.ke));
    e_hat_.push_back(std::move(fourier.e));
  }
}

TrainSteadyState solveTrainSteadyState(const GearTrainModel& model, double input_speed,
                                       const TrainSteadyOptions& options) {
  return TrainSteadySolver(model, options).solve(input_speed);
}

TrainSteadyState TrainSteadySolver::solve(double input_speed, bool housing_rows) const {
  const GearTrainModel& model = model_;
  const TrainBaseFrequency& base = base_;
  const auto& k_hat = k_hat_;
  const auto& ke_hat = ke_hat_;
  if (!(std::abs(input_speed) > 0.0) || !std::isfinite(input_speed)) {
    throw InputError("operating_point.speed_rpm", fmt::format("{:g} rad/s", input_speed),
                     "a speed != 0: the steady state of a train at rest is its static response");
  }
  TrainSteadyState s;
  s.input_speed = input_speed;
  s.base_frequency = base.ratio * std::abs(input_speed);
  s.mesh_multiple = base.mesh_multiple;
  const int L = options_.mesh_harmonics;
  const int H = harmonics_;
  s.harmonics = H;
  const int n = model.dofCount();
  const int blocks = 2 * H + 1;
  const double w0 = kTwoPi * s.base_frequency;
  const auto& meshes = model.meshes();

  // Exact condensation onto the mesh deflections. With D(h) = K + Ω²K_Ω + Σ k̄ v vᵀ
  // + i h ω₀ (C + ΩG₁) − h²ω₀² M (time-invariant, one n × n block per harmonic) and
  // k̃ = k − k̄ the varying part, the balance reads D(h) X_h + V Σ_j K̃_j δ_{h−j} = F_h with
  // δ_h = Vᵀ X_h the mesh deflections (r per harmonic) and K̃_j = diag(k̃_{m,j}). So
  //   δ_h + (Vᵀ D(h)⁻¹ V) Σ_j K̃_j δ_{h−j} = Vᵀ D(h)⁻¹ F_h,
  // a dense system of r (2H + 1) unknowns, and then X_h = D(h)⁻¹ (F_h − V Σ_j K̃_j δ_{h−j}).
  const int r = static_cast<int>(meshes.size());
  const Eigen::MatrixXd& M = model.mass();
  Eigen::MatrixXd Kbar, C;  // K̄ and C at the speed, or their train blocks (housing condensed)
  std::optional<detail::HarmonicBlocks> harmonic_blocks;
  if (housing_ && rigid_at_every_speed_ &&
      detail::HarmonicBlocks::condenses(*housing_, M, rigid_, options_.sparse_dofs)) {
    // The housing's block of K̄ and C (constant, n_h wide) is never read: only the train's
    // blocks are summed per speed, as meanStiffnessAt and dampingAt sum them, and K̄'s diagonal.
    const int n_t = housing_->first;
    const double s2 = input_speed * input_speed;
    Kbar = model.stiffness().topLeftCorner(n_t, n_t) +
           model.meanMeshStiffness().topLeftCorner(n_t, n_t) +
           s2 * model.centripetal().topLeftCorner(n_t, n_t);
    C = model.damping().topLeftCorner(n_t, n_t) +
        input_speed * model.gyroscopic().topLeftCorner(n_t, n_t);
    const double penalty =
        std::max((model.stiffness().diagonal() + model.meanMeshStiffness().diagonal() +
                  s2 * model.centripetal().diagonal())
                     .cwiseAbs()
                     .maxCoeff(),
                 1e-300);
    harmonic_blocks.emplace(Kbar, M, C, rigid_mass_, penalty, housing_);
  } else {
    Kbar = model.meanStiffnessAt(input_speed);
    C = model.dampingAt(input_speed);
    harmonic_blocks.emplace(Kbar, M, C, rigid_at_every_speed_ ? rigid_ : rigidModes(Kbar, M),
                            options_.sparse_dofs, false, housing_);
  }
  detail::HarmonicBlocks& blocks_of = *harmonic_blocks;
  Eigen::MatrixXcd V(n, r);
  for (int m = 0; m < r; ++m) V.col(m) = model.meshVector(m).cast<Complex>();
  const Eigen::MatrixXcd F =
      forcingHarmonics(model, base, input_speed, L, H, w0, k_hat, ke_hat, e_hat_, V);
  // K̄, M and C are real: D(−h) = conj D(h), so only h ≥ 0 is factorised (detail::HarmonicBlocks),
  // one block at a time: D(h)⁻¹ [V, F_h, conj F_−h] in one solve, D(h)⁻¹V and D(h)⁻¹F_h kept
  // for the recovery X_h = D(h)⁻¹F_h − D(h)⁻¹V g_h (g_h the mesh terms below), so the sparse
  // path analyses D's pattern once per speed and refactorises it per harmonic.
  // With the housing condensed and no load on it (the meshes' vectors never reach it), the
  // solves stay on the train's n_t DOFs and the housing's rows are recovered from the final
  // train rows of all harmonics at once (below), not for each of the r + 2 columns.
  const int n_t = blocks_of.trainDofs();
  const bool train_only = n_t < n && F.bottomRows(n - n_t).isZero(0.0);
  const int n_s = train_only ? n_t : n;  // the rows solved for
  const auto Vs = V.topRows(n_s);
  Eigen::MatrixXcd A = Eigen::MatrixXcd::Identity(r * blocks, r * blocks);
  Eigen::VectorXcd b(r * blocks);
  std::vector<Eigen::MatrixXcd> DinvV(H + 1);
  Eigen::MatrixXcd DinvF(n_s, H + 1);
  Eigen::MatrixXcd rhs(n_s, r + 2);
  rhs.leftCols(r) = Vs;
  std::vector<double> frequencies(H + 1);
  for (int h = 0; h <= H; ++h) frequencies[h] = h * w0;
  blocks_of.prepare(frequencies);  // the housing's receptances at every harmonic in one product
  for (int h = 0; h <= H; ++h) {
    blocks_of.factorize(h, h * w0);
    rhs.col(r) = F.col(h + H).head(n_s);
    rhs.col(r + 1) = F.col(H - h).head(n_s).conjugate();
    const Eigen::MatrixXcd solved =
        train_only ? blocks_of.solveTrain(h, rhs) : blocks_of.solve(h, rhs);
    DinvV[h] = solved.leftCols(r);
    DinvF.col(h) = solved.col(r);
    const Eigen::MatrixXcd B = Vs.transpose() * DinvV[h];  // Vᵀ D(h)⁻¹ V (r × r)
    for (const int sign : {1, -1}) {
      if (h == 0 && sign < 0) continue;
      const int hh = sign * h;
      const bool conjugate = sign < 0;
      // D(−h)⁻¹ F_−h = conj(D(h)⁻¹ conj F_−h).
      b.segment((hh + H) * r, r) =
          Vs.transpose() * (conjugate ? Eigen::VectorXcd(solved.col(r + 1).conjugate())
                                      : Eigen::VectorXcd(solved.col(r)));
      for (int m = 0; m < r; ++m) {
        const int P = base.mesh_multiple[m];
        const Eigen::VectorXcd Bm =
            conjugate ? Eigen::VectorXcd(B.col(m).conjugate()) : Eigen::VectorXcd(B.col(m));
        for (int l = -L; l <= L; ++l) {
          const int g = hh - l * P;
          if (l == 0 || g < -H || g > H) continue;
          // Row block hh, column (g, m): B(:, m) k̃_{m,l}.
          A.block((hh + H) * r, (g + H) * r + m, r, 1) += Bm * k_hat[m][L + l];
        }
      }
    }
  }
  // No meshes (a train excited by unbalances or bearing displacements only): nothing to condense.
  const Eigen::VectorXcd delta = r > 0 ? Eigen::VectorXcd(A.partialPivLu().solve(b)) : b;
  if (!delta.allFinite()) {
    throw std::runtime_error(
        fmt::format("steady state at {:g} rad/s: the condensed harmonic-balance system is singular",
                    input_speed));
  }
  s.harmonic.resize(n, H + 1);
  Eigen::VectorXcd g_sum(r);
  for (int h = 0; h <= H; ++h) {
    for (int m = 0; m < r; ++m) {
      const int P = base.mesh_multiple[m];
      g_sum(m) = 0.0;
      for (int l = -L; l <= L; ++l) {
        const int g = h - l * P;
        if (l == 0 || g < -H || g > H) continue;
        g_sum(m) += k_hat[m][L + l] * delta((g + H) * r + m);
      }
    }
    s.harmonic.col(h).head(n_s) = DinvF.col(h);
    if (r > 0) s.harmonic.col(h).head(n_s).noalias() -= DinvV[h] * g_sum;
  }
  // The housing's rows of every harmonic from the train's modal amplitudes y, one product for
  // all: every row (Φ y), or those the elements read, and the response points (R Φ y).
  if (train_only) {
    const Eigen::MatrixXcd y = blocks_of.housingModesOfBlocks(s.harmonic.topRows(n_t).eval());
    if (housing_rows) {
      s.harmonic.bottomRows(n - n_t) = housing_->physical(y);
      if (housing_->points_Phi.rows() > 0) s.housing_points = housing_->points(y);
    } else {
      const Eigen::MatrixXcd kept = housing_->keptRows(y);
      const Eigen::Index read = static_cast<Eigen::Index>(housing_read_dofs_.size());
      s.harmonic.bottomRows(n - n_t).setZero();
      s.harmonic(housing_read_dofs_, Eigen::all) = kept.topRows(read);
      if (housing_->points_Phi.rows() > 0) s.housing_points = kept.bottomRows(kept.rows() - read);
    }
  } else if (model.housingFirstDof() >= 0 && !model.spec().housing->reduced.points.empty()) {
    s.housing_points =
        model.spec().housing->reduced.recovery * s.harmonic.bottomRows(n - model.housingFirstDof());
  }

  sampleSteadyForces(s, model, input_speed, options_.samples, L, base.mesh_multiple);
  return s;
}

}  // namespace geardyn
