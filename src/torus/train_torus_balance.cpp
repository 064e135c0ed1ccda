/// Nonlinear steady state of a gear train on the torus of its mesh phases (train_torus_balance.h;
/// docs/theory/torus_harmonic_balance.md): tone set, condensation, AFT on the k-D grid, residual
/// and analytic Jacobian. The recovery and the Newmark check are in train_torus_balance_check.cpp.

#include "geardyn/torus/train_torus_balance.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/solvers/detail/harmonic_blocks.h"
#include "geardyn/solvers/detail/train_steady_parts.h"
#include "geardyn/system/train_excitation.h"
#include "geardyn/torus/detail/tone_block_derivative.h"
#include "geardyn/torus/detail/torus_fft.h"

namespace geardyn {
namespace {

using Complex = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

bool positiveTone(const Eigen::VectorXi& n) {
  for (Eigen::Index j = 0; j < n.size(); ++j) {
    if (n(j) != 0) return n(j) > 0;
  }
  return false;
}

}  // namespace

void TrainTorusBalanceOptions::validate() const {
  if (mesh_harmonics < 1 || mesh_harmonics > 200) {
    throw InputError("nonlinear.mesh_harmonics", std::to_string(mesh_harmonics),
                     "an integer in [1, 200]");
  }
  if (group_harmonics < mesh_harmonics) {
    throw InputError("nonlinear.torus_above", std::to_string(group_harmonics),
                     fmt::format(">= the mesh harmonics ({})", mesh_harmonics));
  }
  if (samples_per_harmonic < 5) {
    throw InputError("nonlinear.torus_samples_per_harmonic", std::to_string(samples_per_harmonic),
                     ">= 5 (the Jacobian needs the tones n ± n' up to 2N without aliasing)");
  }
  if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
    throw InputError("nonlinear.tolerance", fmt::format("{:g}", tolerance), "finite and > 0");
  }
  if (max_iterations < 1) {
    throw InputError("nonlinear.max_iterations", std::to_string(max_iterations), ">= 1");
  }
}

TrainTorusBalance::TrainTorusBalance(const GearTrainModel& model,
                                     const TrainTorusBalanceOptions& options)
    : model_(model), options_(options) {
  options_.validate();
  refuseExcitations(model, "the nonlinear torus balance");
  if (model.meshes().empty()) throw InputError("meshes", "", "a train with at least one mesh");
  const int L = options_.mesh_harmonics;
  generators_ = trainTorusGenerators(model, L, options_.group_harmonics);
  const std::vector<int>& N = generators_.harmonics;
  k_ = static_cast<int>(N.size());
  meshes_ = static_cast<int>(model.meshes().size());
  setUpBearings();
  dofs_ = model.dofCount();
  speed_sign_ = model.inputSpeed() < 0.0 ? -1.0 : 1.0;
  // T⁺: the zero tone, then every positive tone of the box.
  long long box = 1;
  for (int Nj : N) box *= 2 * Nj + 1;
  if (box > 200000) {
    throw InputError(
        "nonlinear.mesh_harmonics", std::to_string(L),
        fmt::format("fewer harmonics: the torus of {} generators needs {} tones", k_, box));
  }
  std::vector<Eigen::VectorXi> list{Eigen::VectorXi::Zero(k_)};
  Eigen::VectorXi n(k_);
  for (long long index = 0; index < box; ++index) {
    long long rest = index;
    for (int j = 0; j < k_; ++j) {
      n(j) = static_cast<int>(rest % (2 * N[j] + 1)) - N[j];
      rest /= 2 * N[j] + 1;
    }
    if (positiveTone(n)) list.push_back(n);
  }
  P_ = static_cast<int>(list.size()) - 1;
  n_ = 2 * P_ + 1;
  tones_.resize(k_, P_ + 1);
  for (int p = 0; p <= P_; ++p) tones_.col(p) = list[p];
  Eigen::VectorXd rho(k_);
  for (int j = 0; j < k_; ++j) rho(j) = generators_.ratio[j] / generators_.ratio[0];
  tone_ratio_ = tones_.cast<double>().transpose() * rho;
  // The grid: M_j = samples_per_harmonic × N_j (at least 16, even).
  long long points = 1;
  for (int j = 0; j < k_; ++j) {
    int M = std::max(16, options_.samples_per_harmonic * N[j]);
    M += M % 2;
    samples_.push_back(M);
    axis_stride_.push_back(points);
    points *= M;
  }
  if (points > (1LL << 22)) {
    throw InputError("nonlinear.mesh_harmonics", std::to_string(L),
                     fmt::format("fewer harmonics: the torus grid would hold {} points", points));
  }
  fft_ = std::make_unique<detail::TorusFft>(samples_, r_, r_ + slopes_);
  const auto code = [&](const Eigen::VectorXi& d) -> long long {
    if (d(0) >= 0) return fft_->halfIndex(d) + 1;
    return -(fft_->halfIndex(-d) + 1);
  };
  tone_index_.resize(P_ + 1);
  tone_conj_index_.resize(P_ + 1);
  for (int p = 0; p <= P_; ++p) {
    tone_index_[p] = fft_->halfIndex(tones_.col(p));
    const Eigen::VectorXi minus = -tones_.col(p);
    tone_conj_index_[p] = minus(0) >= 0 ? fft_->halfIndex(minus) : -1;  // n₀ = 0: both in it
  }
  diff_code_.resize(static_cast<std::size_t>(P_ + 1) * (P_ + 1));
  sum_code_.resize(diff_code_.size());
  for (int p = 0; p <= P_; ++p) {
    for (int q = 0; q <= P_; ++q) {
      const std::size_t at = static_cast<std::size_t>(p) * (P_ + 1) + q;
      diff_code_[at] = code(tones_.col(p) - tones_.col(q));
      sum_code_[at] = code(tones_.col(p) + tones_.col(q));
    }
  }
  // Meshes along their own generator's axis: k, e at φ = P_m s / M_j + φ_m0; tooth pairs there.
  tooth_pairs_.resize(meshes_);
  dash_unit_ = Eigen::MatrixXcd::Zero(r_, P_ + 1);
  for (int m = 0; m < meshes_; ++m) {
    const TrainMesh& mesh = model.meshes()[m];
    const int j = generators_.mesh_generator[m], Pm = generators_.mesh_multiple[m];
    Eigen::VectorXd k_axis(samples_[j]), e_axis(samples_[j]);
    std::vector<double> phases(samples_[j]);
    for (int i = 0; i < samples_[j]; ++i) {
      phases[i] = static_cast<double>(Pm) * i / samples_[j] + mesh.phase;
      k_axis(i) = mesh.stiffness->stiffness(phases[i]);
      e_axis(i) = mesh.transmission_error.value(phases[i]);
    }
    k_axis_.push_back(k_axis);
    e_axis_.push_back(e_axis);
    if (mesh.toothPairs()) {
      tooth_pairs_[m].tabulate(*mesh.contact.tooth_pairs, phases.data(), samples_[j]);
    }
    // The dashpot forcing c ė at the tones l P_m e_j: c i ω_n ê_l (ω_n = ω tone_ratio).
    const detail::MeshFourier fourier = detail::meshFourier(mesh, L);
    for (int p = 1; p <= P_; ++p) {
      Eigen::VectorXi t = tones_.col(p);
      const int along = t(j);
      t(j) = 0;
      if (!t.isZero() || along % Pm != 0) continue;
      const int l = along / Pm;
      if (l < 1 || l > L) continue;
      dash_unit_(m, p) = mesh.damping * Complex(0.0, tone_ratio_(p)) * fourier.e[L + l];
    }
  }
  W_ = model.nonlinearVectors();
  derivative_ = std::make_unique<detail::ToneBlockDerivative>(model.mass(), model.centripetal(),
                                                              model.gyroscopic());
  rigid_ = detail::rigidModes(model.meanStiffnessAt(model.inputSpeed()), model.mass());
  half_in_.resize(fft_->halfSize(), r_);
  half_out_.resize(fft_->halfSize(), r_ + slopes_);
  grid_.resize(points, r_);
  grid_out_.resize(points, r_ + slopes_);
  B_.resize(P_ + 1);
  dB_.resize(P_ + 1);
}

TrainTorusBalance::~TrainTorusBalance() = default;

double TrainTorusBalance::baseFrequency(double input_speed) const {
  return kTwoPi * generators_.ratio[0] * std::abs(input_speed);
}

double TrainTorusBalance::inputSpeed(double omega) const {
  return speed_sign_ * omega / (kTwoPi * generators_.ratio[0]);
}

void TrainTorusBalance::prepare(double omega) {
  if (omega == cached_omega_) return;
  const double speed = inputSpeed(omega);
  const double dspeed = speed_sign_ / (kTwoPi * generators_.ratio[0]);
  Kbar_ = model_.meanStiffnessAt(speed);
  C_ = model_.dampingAt(speed);
  // One sparse pattern analysis per speed: each tone's block is factorised, used for B_p and
  // dB_p, and dropped before the next (keep_factors false).
  blocks_ = std::make_unique<detail::HarmonicBlocks>(Kbar_, model_.mass(), C_, rigid_,
                                                     options_.sparse_dofs, false);
  derivative_->setSpeed(C_, speed, dspeed);
  const Eigen::MatrixXcd Wc = W_.cast<Complex>();
  for (int p = 0; p <= P_; ++p) {
    const double w = toneFrequency(p, omega);
    blocks_->factorize(p, w);
    const Eigen::MatrixXcd Z = blocks_->solve(p, Wc);
    B_[p] = Wc.transpose() * Z;
    dB_[p] = -Wc.transpose() * blocks_->solve(p, derivative_->times(Z, w, tone_ratio_(p)));
    if (p > 0) continue;
    // The static balance at the same block: b₀ = Wᵀ D(0)⁻¹ F₀, db₀ = −Wᵀ D(0)⁻¹ dK D(0)⁻¹ F₀.
    const Eigen::VectorXd x0 = blocks_->solve(0, model_.staticLoad().cast<Complex>()).real();
    b0_ = W_.transpose() * x0;
    db0_ = Eigen::VectorXd::Zero(r_);
    if (derivative_->stiffnessMoves()) {
      const Eigen::VectorXcd dKx0 = derivative_->stiffnessTimes(x0).cast<Complex>();
      db0_ = -(W_.transpose() * blocks_->solve(0, dKx0).real());
    }
  }
  cached_omega_ = omega;
}

double TrainTorusBalance::meshForceAt(int m, int i, double y, double* slope) const {
  const ToothPairTable& pairs = tooth_pairs_[m];
  if (pairs.elementCount() > 0) {
    return linearized_ ? pairs.linearForce(i, y, slope) : pairs.force(i, y, slope);
  }
  const double k = k_axis_[m](i);
  double s = 1.0;
  const double f = k * (linearized_ ? y : model_.meshes()[m].contactDeflection(y, &s));
  *slope = k * s;
  return f;
}

Complex TrainTorusBalance::spectrumAt(int column, long long code) const {
  return code > 0 ? half_out_(code - 1, column) : std::conj(half_out_(-code - 1, column));
}

void TrainTorusBalance::gridForces(const Eigen::VectorXd& u) {
  // w on the grid: the half spectrum of every coordinate, one multi-dimensional c2r.
  half_in_.setZero();
  for (int c = 0; c < r_; ++c) {
    const double* x = u.data() + static_cast<std::ptrdiff_t>(c) * n_;
    half_in_(tone_index_[0], c) = x[0];
    for (int p = 1; p <= P_; ++p) {
      const Complex z(x[2 * p - 1], x[2 * p]);
      half_in_(tone_index_[p], c) = z;
      if (tone_conj_index_[p] >= 0) half_in_(tone_conj_index_[p], c) = std::conj(z);
    }
  }
  fft_->toGrid(half_in_, grid_);
  const long long points = fft_->points();
  for (int m = 0; m < meshes_; ++m) {
    const TrainMesh& mesh = model_.meshes()[m];
    const int j = generators_.mesh_generator[m];
    const long long stride = axis_stride_[j];
    const int Mj = samples_[j];
    for (long long g = 0; g < points; ++g) {
      const int i = static_cast<int>((g / stride) % Mj);
      const double delta = grid_(g, m);
      double s = 1.0;
      const double f = meshForceAt(m, i, delta - e_axis_[m](i), &s);
      grid_out_(g, m) = f - mesh.mean_stiffness * delta;
      grid_out_(g, r_ + m) = s - mesh.mean_stiffness;
    }
  }
  gridBearingForces();
  fft_->toSpectrum(grid_out_, half_out_);
}

void TrainTorusBalance::setUpBearings() {
  // Coordinates: the meshes, then each bearing's w (2, or 5 for a full-DOF rolling bearing's
  // full law; the order of GearTrainModel::nonlinearVectors). Slope columns after the r_
  // forces: the meshes' dF/dδ, then each bearing's w × w Jacobian, column-major.
  laws_ = trainBearingLaws(model_);
  bearings_ = static_cast<int>(laws_.size());
  r_ = meshes_;
  slopes_ = meshes_;
  bearing_of_.assign(meshes_, -1);
  for (int b = 0; b < bearings_; ++b) {
    const int w = laws_[b].width();
    bearing_first_.push_back(r_);
    slope_first_.push_back(slopes_);
    bearing_of_.insert(bearing_of_.end(), w, b);
    r_ += w;
    slopes_ += w * w;
  }
}

void TrainTorusBalance::gridBearingForces() {
  // f̃ = f(u) − K_lin u and ∂f̃/∂u at every grid point (linearised: the bearings of K, f̃ = 0).
  const long long points = fft_->points();
  for (int b = 0; b < bearings_; ++b) {
    const TrainBearingLaw& law = laws_[b];
    const int c = bearing_first_[b], w = law.width(), s = r_ + slope_first_[b];
    TrainBearingLaw::Vector u(w), f = TrainBearingLaw::Vector::Zero(w);
    TrainBearingLaw::Matrix J = TrainBearingLaw::Matrix::Zero(w, w);
    for (long long g = 0; g < points; ++g) {
      if (!linearized_) {
        for (int k = 0; k < w; ++k) u(k) = grid_(g, c + k);
        f = law.correctionForce(u, &J);
      }
      for (int k = 0; k < w; ++k) grid_out_(g, c + k) = f(k);
      for (int k = 0; k < w * w; ++k) grid_out_(g, s + k) = J(k % w, k / w);
    }
  }
}

void TrainTorusBalance::coupledCoordinates(int a, int* first, int* count) const {
  const int b = bearing_of_[a];
  *first = b < 0 ? a : bearing_first_[b];
  *count = b < 0 ? 1 : laws_[b].width();
}

int TrainTorusBalance::slopeColumn(int b, int a) const {
  const int bearing = bearing_of_[a];
  if (bearing < 0) return r_ + a;  // a mesh: b == a
  const int c = bearing_first_[bearing], w = laws_[bearing].width();
  return r_ + slope_first_[bearing] + (b - c) + w * (a - c);
}

void TrainTorusBalance::residual(const Eigen::VectorXd& u, double omega, Eigen::VectorXd& R,
                                 Eigen::MatrixXd* dr_du, Eigen::VectorXd* dr_domega) {
  prepare(omega);
  gridForces(u);
  R = u;
  if (dr_domega) dr_domega->setZero(size());
  Eigen::VectorXcd z(r_), dz(r_), w(r_), dw(r_);
  for (int p = 0; p <= P_; ++p) {
    for (int c = 0; c < r_; ++c) {
      z(c) = omega * dash_unit_(c, p) - half_out_(tone_index_[p], c);  // d − F̃
      dz(c) = dash_unit_(c, p);
    }
    w.noalias() = B_[p] * z;
    if (dr_domega) dw.noalias() = dB_[p] * z + B_[p] * dz;
    for (int c = 0; c < r_; ++c) {
      const std::ptrdiff_t at = static_cast<std::ptrdiff_t>(c) * n_;
      if (p == 0) {
        R(at) -= w(c).real() + b0_(c);
        if (dr_domega) (*dr_domega)(at) = -dw(c).real() - db0_(c);
      } else {
        R(at + 2 * p - 1) -= w(c).real();
        R(at + 2 * p) -= w(c).imag();
        if (dr_domega) {
          (*dr_domega)(at + 2 * p - 1) = -dw(c).real();
          (*dr_domega)(at + 2 * p) = -dw(c).imag();
        }
      }
    }
  }
  if (!dr_du) return;
  // ∂R_p/∂x = I + B_p ∂F̃_p/∂x. Column (a, q, part) of coordinate a's unknowns: through the
  // slope spectra S_ba of the coordinates b it acts on (a itself for a mesh, both directions of
  // a bearing): ∂F̃_{b,p}/∂x_{a,0} = S(n_p); ∂/∂Re x_{a,q} = S(n_p − n_q) + S(n_p + n_q);
  // ∂/∂Im x_{a,q} = i (S(n_p − n_q) − S(n_p + n_q)).
  Eigen::MatrixXd& J = *dr_du;
  J.setIdentity(size(), size());
  for (int a = 0; a < r_; ++a) {
    int first = a, count = 1;
    coupledCoordinates(a, &first, &count);
    for (int q = 0; q <= P_; ++q) {
      for (int part = 0; part < (q == 0 ? 1 : 2); ++part) {
        const std::ptrdiff_t col =
            static_cast<std::ptrdiff_t>(a) * n_ + (q == 0 ? 0 : 2 * q - 1 + part);
        for (int p = 0; p <= P_; ++p) {
          const std::size_t at = static_cast<std::size_t>(p) * (P_ + 1) + q;
          Complex dF[5];  // up to a full-DOF bearing's five coordinates
          for (int bi = 0; bi < count; ++bi) {
            const int s = slopeColumn(first + bi, a);
            if (q == 0) {
              dF[bi] = spectrumAt(s, tone_index_[p] + 1);
            } else {
              const Complex minus = spectrumAt(s, diff_code_[at]);
              const Complex plus = spectrumAt(s, sum_code_[at]);
              dF[bi] = part == 0 ? minus + plus : Complex(0.0, 1.0) * (minus - plus);
            }
          }
          for (int c = 0; c < r_; ++c) {
            Complex v = 0.0;
            for (int bi = 0; bi < count; ++bi) v += B_[p](c, first + bi) * dF[bi];
            const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(c) * n_;
            if (p == 0) {
              J(row, col) += v.real();
            } else {
              J(row + 2 * p - 1, col) += v.real();
              J(row + 2 * p, col) += v.imag();
            }
          }
        }
      }
    }
  }
}

double TrainTorusBalance::residualNorm(const Eigen::VectorXd& u, const Eigen::VectorXd& r,
                                       double) const {
  const double scale = u.norm() + b0_.norm();
  return r.norm() / (scale > 0.0 ? scale : 1.0);
}

Eigen::VectorXd TrainTorusBalance::startingGuess(double omega) {
  prepare(omega);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(size());
  for (int c = 0; c < r_; ++c) u(static_cast<std::ptrdiff_t>(c) * n_) = b0_(c);
  linearized_ = true;
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  for (int iteration = 0; iteration < 2; ++iteration) {  // linear: exact in one step
    residual(u, omega, r, &J, nullptr);
    const Eigen::VectorXd step = J.partialPivLu().solve(-r);
    if (!step.allFinite()) break;
    u += step;
  }
  linearized_ = false;
  for (int b = 0; b < bearings_; ++b) {  // the journal onto the bearing surface
    // ū (1 + c/|ū|) for the clearance law; a full-law bearing's Newton on f(u) = K_s ū in its
    // 2 or 5 coordinates (bearing_law.h).
    const TrainBearingLaw& law = laws_[b];
    const std::ptrdiff_t c = bearing_first_[b];
    const int w = law.width();
    TrainBearingLaw::Vector mean(w);
    for (int k = 0; k < w; ++k) mean(k) = u((c + k) * n_);
    mean = law.loadedDisplacement(mean);
    for (int k = 0; k < w; ++k) u((c + k) * n_) = mean(k);
  }
  return u;
}

void TrainTorusBalance::solve(HarmonicBalancePoint& point) {
  solveAtFixedFrequency(*this, point, options_.tolerance, options_.max_iterations);
}

void TrainTorusBalance::classify(HarmonicBalancePoint& point, StabilityMethod, bool) {
  point.max_floquet_real = std::numeric_limits<double>::quiet_NaN();
}

}  // namespace geardyn
