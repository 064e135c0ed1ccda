/// Harmonic balance of gear trains with nonlinear meshes, condensed onto the mesh deflections
/// (train_harmonic_balance.h).

#include "geardyn/solvers/train_harmonic_balance.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/signal/detail/fftw_planner.h"
#include "geardyn/solvers/detail/aft_jacobian.h"
#include "geardyn/solvers/detail/train_hill.h"
#include "geardyn/solvers/newmark.h"
#include "geardyn/solvers/train_response.h"

namespace geardyn {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
using Complex = std::complex<double>;

inline int cosIndex(int h) {
  return 2 * h - 1;
}
inline int sinIndex(int h) {
  return 2 * h;
}

/// The fraction of the straight segment from tooth deformation y0 to y1 on which the contact law
/// of `mesh` has slope 1 (loaded flank y > 0, back flank y < −j).
double contactFraction(const TrainMesh& mesh, double y0, double y1) {
  if (!mesh.nonlinear()) return 1.0;
  const double back =
      mesh.contact.law == ContactLaw::kBacklash ? -mesh.contact.backlash : -HUGE_VAL;
  if (y0 == y1) return (y0 > 0.0 || y0 < back) ? 1.0 : 0.0;
  // Length of {λ ∈ [0, 1]: y(λ) > 0} plus {y(λ) < back}, y(λ) = y0 + λ (y1 − y0).
  const auto above = [&](double level) {  // measure of y(λ) > level
    const double l = std::clamp((level - y0) / (y1 - y0), 0.0, 1.0);
    return y1 > y0 ? 1.0 - l : l;
  };
  return above(0.0) + (std::isfinite(back) ? 1.0 - above(back) : 0.0);
}

}  // namespace

void TrainHarmonicBalanceOptions::validate() const {
  if (harmonics < 1 || harmonics > 512) {
    throw InputError("nonlinear.harmonics", std::to_string(harmonics), "an integer in [1, 512]");
  }
  if (samples <= 2 * harmonics) {
    throw InputError("nonlinear.samples", std::to_string(samples),
                     fmt::format("more than 2H = {} samples a period: {} harmonics alias "
                                 "otherwise (8H or more for contact loss)",
                                 2 * harmonics, harmonics));
  }
  if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
    throw InputError("nonlinear.tolerance", fmt::format("{:g}", tolerance), "finite and > 0");
  }
  if (max_iterations < 1) {
    throw InputError("nonlinear.max_iterations", std::to_string(max_iterations), ">= 1");
  }
}

TrainHarmonicBalance::TrainHarmonicBalance(const GearTrainModel& model,
                                           const TrainHarmonicBalanceOptions& options)
    : model_(model), options_(options) {
  options_.validate();
  refuseExcitations(model, "the nonlinear harmonic balance");
  if (model.meshes().empty()) throw InputError("meshes", "", "a train with at least one mesh");
  h_ = options_.harmonics;
  n_ = 2 * h_ + 1;
  samples_ = options_.samples;
  meshes_ = static_cast<int>(model.meshes().size());
  bearings_ = static_cast<int>(model.clearanceBearings().size());
  r_ = meshes_;
  int slope_columns = 0;
  laws_ = trainBearingLaws(model);
  for (const TrainBearingLaw& law : laws_) {
    const int w = law.width();
    bearing_first_.push_back(r_);
    for (int k = 0; k < w * w; ++k) {  // column-major: entry (k % w, k / w)
      bearing_blocks_.push_back({r_ + k % w, r_ + k / w, slope_columns + k});
    }
    r_ += w;
    slope_columns += w * w;
  }
  dofs_ = model.dofCount();
  const TrainBaseFrequency base = trainBaseFrequency(model, 1, 1000000000);
  multiple_ = base.mesh_multiple;
  const int largest = *std::max_element(multiple_.begin(), multiple_.end());
  if (largest > h_) {
    throw InputError(
        "nonlinear.harmonics", std::to_string(h_),
        fmt::format(
            "at least {}: the meshes repeat over a common period of {} periods of the "
            "fastest mesh, which needs {} harmonics of the common frequency for one of "
            "its own (trains without a short common period: nonlinear.method = \"torus\" or time "
            "integration)",
            largest, largest, largest));
  }
  base_ratio_ = kTwoPi * base.ratio;
  speed_sign_ = model.inputSpeed() < 0.0 ? -1.0 : 1.0;
  V_ = model.nonlinearVectors();  // W = [V, bearing selections]: the condensation's columns
  // Rigid-body modes of the mean stiffness (rolling, which no mesh deflects): fixed at h = 0 by
  // their mass-weighted amplitude, as in TrainSteadySolver. Computed at the operating speed
  // (K_Ω acts on planet translations, held by their pins: it does not change them).
  const Eigen::MatrixXd K = model.meanStiffnessAt(model.inputSpeed());
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(0.5 * (K + K.transpose()),
                                                                        model.mass());
  const Eigen::VectorXd& w2 = modes.eigenvalues();
  int count = 0;
  while (count < w2.size() && std::abs(w2(count)) < 1e-10 * std::abs(w2(w2.size() - 1))) ++count;
  rigid_ = model.mass() * modes.eigenvectors().leftCols(count);
  // The elastic subspace: an orthonormal basis of the null space of rigid_ᵀ.
  if (count == 0) {
    elastic_ = Eigen::MatrixXd::Identity(dofs_, dofs_);
  } else {
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(rigid_);
    elastic_ =
        (qr.householderQ() * Eigen::MatrixXd::Identity(dofs_, dofs_)).rightCols(dofs_ - count);
  }

  k_.resize(samples_, meshes_);
  e_.resize(samples_, meshes_);
  slope_.resize(samples_, meshes_);
  bearing_slope_.resize(samples_, static_cast<Eigen::Index>(bearing_blocks_.size()));
  force_.resize(samples_, r_);
  delta_.resize(samples_, r_);
  Eigen::MatrixXd rate(samples_, meshes_);
  tooth_pairs_.resize(meshes_);
  std::vector<double> phases(samples_);
  for (int m = 0; m < meshes_; ++m) {
    const TrainMesh& mesh = model.meshes()[m];
    for (int i = 0; i < samples_; ++i) {
      const double phi = mesh.phase + multiple_[m] * static_cast<double>(i) / samples_;
      phases[i] = phi;
      k_(i, m) = mesh.stiffness->stiffness(phi);
      e_(i, m) = mesh.transmission_error.value(phi);
      rate(i, m) = mesh.transmission_error.derivative(phi);
    }
    if (mesh.toothPairs())
      tooth_pairs_[m].tabulate(*mesh.contact.tooth_pairs, phases.data(), samples_);
  }
  real_buffer_ = fftw_alloc_real(samples_);
  complex_buffer_ = fftw_alloc_complex(samples_ / 2 + 1);
  {  // FFTW's planner is not thread-safe: every plan under the library's one lock
    const std::lock_guard<std::mutex> lock(detail::fftwPlannerMutex());
    forward_plan_ = fftw_plan_dft_r2c_1d(samples_, real_buffer_, complex_buffer_, FFTW_ESTIMATE);
    inverse_plan_ = fftw_plan_dft_c2r_1d(samples_, complex_buffer_, real_buffer_, FFTW_ESTIMATE);
  }
  rate_coefficients_.resize(n_, meshes_);
  for (int m = 0; m < meshes_; ++m) forward(rate.col(m).data(), rate_coefficients_.col(m).data());
  B_.resize(h_ + 1);
  dB_.resize(h_ + 1);
  lu_.resize(h_ + 1);
}

TrainHarmonicBalance::~TrainHarmonicBalance() {
  const std::lock_guard<std::mutex> lock(detail::fftwPlannerMutex());
  fftw_destroy_plan(forward_plan_);
  fftw_destroy_plan(inverse_plan_);
  fftw_free(real_buffer_);
  fftw_free(complex_buffer_);
}

double TrainHarmonicBalance::baseFrequency(double input_speed) const {
  return base_ratio_ * std::abs(input_speed);
}

double TrainHarmonicBalance::inputSpeed(double omega) const {
  return speed_sign_ * omega / base_ratio_;
}

void TrainHarmonicBalance::forward(const double* samples, double* c) {
  std::copy(samples, samples + samples_, real_buffer_);
  fftw_execute(forward_plan_);
  c[0] = complex_buffer_[0][0] / samples_;
  for (int h = 1; h <= h_; ++h) {
    c[cosIndex(h)] = 2.0 * complex_buffer_[h][0] / samples_;
    c[sinIndex(h)] = -2.0 * complex_buffer_[h][1] / samples_;
  }
}

void TrainHarmonicBalance::inverse(const double* c, double* samples) {
  for (int k = 0; k <= samples_ / 2; ++k) complex_buffer_[k][0] = complex_buffer_[k][1] = 0.0;
  complex_buffer_[0][0] = c[0];
  for (int h = 1; h <= h_; ++h) {
    complex_buffer_[h][0] = 0.5 * c[cosIndex(h)];
    complex_buffer_[h][1] = -0.5 * c[sinIndex(h)];
  }
  fftw_execute(inverse_plan_);
  std::copy(real_buffer_, real_buffer_ + samples_, samples);
}

void TrainHarmonicBalance::prepare(double omega) {
  if (omega == cached_omega_) return;
  const double speed = inputSpeed(omega), dspeed = speed_sign_ / base_ratio_;
  const Eigen::MatrixXd& M = model_.mass();
  const Eigen::MatrixXd Kbar = model_.meanStiffnessAt(speed);
  const Eigen::MatrixXd C = model_.dampingAt(speed);
  const Eigen::MatrixXd dK = 2.0 * speed * dspeed * model_.centripetal();
  const Eigen::MatrixXd dC = dspeed * model_.gyroscopic();
  // h = 0: the statics (rigid-body modes held by a penalty on their mass-weighted amplitude).
  Eigen::MatrixXd D0 = Kbar;
  if (rigid_.cols() > 0) {
    const double penalty = std::max(Kbar.diagonal().cwiseAbs().maxCoeff(), 1e-300);
    D0 += penalty * rigid_ * rigid_.transpose();
  }
  lu0_.compute(D0);
  const Eigen::MatrixXd Z0 = lu0_.solve(V_);
  B_[0] = (V_.transpose() * Z0).cast<Complex>();
  dB_[0] = (-V_.transpose() * lu0_.solve(dK * Z0)).cast<Complex>();
  const Eigen::VectorXd x0 = lu0_.solve(model_.staticLoad());
  b0_ = V_.transpose() * x0;
  db0_ = -V_.transpose() * lu0_.solve(dK * x0);
  const Eigen::MatrixXcd Vc = V_.cast<Complex>();
  for (int h = 1; h <= h_; ++h) {
    const double w = h * omega;
    const Eigen::MatrixXcd D = (Kbar - w * w * M).cast<Complex>() + Complex(0.0, w) * C;
    lu_[h].compute(D);
    const Eigen::MatrixXcd Z = lu_[h].solve(Vc);
    B_[h] = Vc.transpose() * Z;
    const Eigen::MatrixXcd dD = (dK - 2.0 * h * h * omega * M).cast<Complex>() +
                                Complex(0.0, h) * C.cast<Complex>() +
                                Complex(0.0, w) * dC.cast<Complex>();
    dB_[h] = -Vc.transpose() * lu_[h].solve(dD * Z);
  }
  cached_omega_ = omega;
}

void TrainHarmonicBalance::meshForceSamples(const Eigen::VectorXd& u) {
  for (int c = 0; c < r_; ++c) inverse(u.data() + c * n_, delta_.col(c).data());
  for (int m = 0; m < meshes_; ++m) {
    const TrainMesh& mesh = model_.meshes()[m];
    const ToothPairTable& pairs = tooth_pairs_[m];
    for (int i = 0; i < samples_; ++i) {
      const double y = delta_(i, m) - e_(i, m);
      double f = 0.0, s = 1.0;
      if (pairs.elementCount() > 0) {  // Σ_j k_j max(0, y − g_j) (linearised: all in window)
        f = linearized_ ? pairs.linearForce(i, y, &s) : pairs.force(i, y, &s);
      } else {
        f = k_(i, m) * (linearized_ ? y : mesh.contactDeflection(y, &s));
        s *= k_(i, m);
      }
      force_(i, m) = f - mesh.mean_stiffness * delta_(i, m);
      slope_(i, m) = s - mesh.mean_stiffness;
    }
  }
  // Clearance bearings: f̃ = f(u) − k u and its w × w Jacobian (column-major in bearing_slope_);
  // linearised: the linear bearing of K, f̃ = 0.
  int column = 0;
  for (int b = 0; b < bearings_; ++b) {
    const TrainBearingLaw& law = laws_[b];
    const int c = bearing_first_[b], w = law.width();
    TrainBearingLaw::Vector u(w), f(w);
    TrainBearingLaw::Matrix J(w, w);
    for (int i = 0; i < samples_; ++i) {
      for (int k = 0; k < w; ++k) u(k) = delta_(i, c + k);
      if (linearized_) {
        f.setZero();
        J.setZero();
      } else {
        f = law.correctionForce(u, &J);
      }
      for (int k = 0; k < w; ++k) force_(i, c + k) = f(k);
      for (int k = 0; k < w * w; ++k) bearing_slope_(i, column + k) = J(k % w, k / w);
    }
    column += w * w;
  }
}

void TrainHarmonicBalance::residual(const Eigen::VectorXd& u, double omega, Eigen::VectorXd& R,
                                    Eigen::MatrixXd* dr_du, Eigen::VectorXd* dr_domega) {
  prepare(omega);
  meshForceSamples(u);
  const Eigen::MatrixXd G = forceCoefficients(omega);
  const auto dashpotRate = [&](int m, int j) {  // ∂(F̃ − d)/∂ω₀ = −d/ω₀ (meshes only)
    return m >= meshes_
               ? 0.0
               : -model_.meshes()[m].damping * multiple_[m] / kTwoPi * rate_coefficients_(j, m);
  };
  R = u;
  if (dr_domega) dr_domega->setZero(size());
  Eigen::VectorXcd z(r_), dz(r_);
  for (int h = 0; h <= h_; ++h) {
    for (int m = 0; m < r_; ++m) {
      z(m) = h == 0 ? Complex(G(0, m)) : Complex(G(cosIndex(h), m), -G(sinIndex(h), m));
      dz(m) = h == 0 ? Complex(dashpotRate(m, 0))
                     : Complex(dashpotRate(m, cosIndex(h)), -dashpotRate(m, sinIndex(h)));
    }
    const Eigen::VectorXcd w = B_[h] * z;
    Eigen::VectorXcd dw;
    if (dr_domega) dw = dB_[h] * z + B_[h] * dz;
    for (int m = 0; m < r_; ++m) {
      if (h == 0) {
        R(m * n_) += w(m).real() - b0_(m);
        if (dr_domega) (*dr_domega)(m * n_) = dw(m).real() - db0_(m);
      } else {
        R(m * n_ + cosIndex(h)) += w(m).real();
        R(m * n_ + sinIndex(h)) -= w(m).imag();
        if (dr_domega) {
          (*dr_domega)(m * n_ + cosIndex(h)) = dw(m).real();
          (*dr_domega)(m * n_ + sinIndex(h)) = -dw(m).imag();
        }
      }
    }
  }
  if (!dr_du) return;
  // ∂F̃_i/∂u_j (i = j for a mesh; every pair of a clearance bearing's coordinates):
  // D_k = (1/N) Σ ∂f̃_i/∂u_j cos kτ, E_k = (1/N) Σ ∂f̃_i/∂u_j sin kτ for k = −2H..2H.
  Eigen::MatrixXd& J = *dr_du;
  J.setIdentity(size(), size());
  std::vector<double> Dt, Et;
  Eigen::MatrixXd JF(n_, n_);
  const auto add = [&](int i, int j, const double* slope) {
    std::copy(slope, slope + samples_, real_buffer_);
    fftw_execute(forward_plan_);
    detail::aftSlopeTables(complex_buffer_, samples_, h_, Dt, Et);
    detail::aftJacobian(Dt, Et, h_, JF);
    // Rows of coordinate mr: per harmonic, the 2 × 2 real form of B(h)(mr, i) times JF's rows.
    for (int mr = 0; mr < r_; ++mr) {
      auto block = J.block(mr * n_, j * n_, n_, n_);
      block.row(0) += B_[0](mr, i).real() * JF.row(0);
      for (int h = 1; h <= h_; ++h) {
        const double br = B_[h](mr, i).real(), bi = B_[h](mr, i).imag();
        block.row(cosIndex(h)) += br * JF.row(cosIndex(h)) + bi * JF.row(sinIndex(h));
        block.row(sinIndex(h)) += -bi * JF.row(cosIndex(h)) + br * JF.row(sinIndex(h));
      }
    }
  };
  for (int m = 0; m < meshes_; ++m) add(m, m, slope_.col(m).data());
  for (const auto& [i, j, column] : bearing_blocks_) add(i, j, bearing_slope_.col(column).data());
}

Eigen::MatrixXd TrainHarmonicBalance::forceCoefficients(double omega) {
  // F̃ − d (real layout, per coordinate): the nonlinear force less the mesh dashpot forcing c ė.
  Eigen::MatrixXd G(n_, r_);
  for (int c = 0; c < r_; ++c) {
    forward(force_.col(c).data(), G.col(c).data());
    if (c >= meshes_) continue;
    G.col(c) -=
        model_.meshes()[c].damping * multiple_[c] * omega / kTwoPi * rate_coefficients_.col(c);
  }
  return G;
}

double TrainHarmonicBalance::residualNorm(const Eigen::VectorXd& u, const Eigen::VectorXd& r,
                                          double) const {
  const double scale = u.norm() + b0_.norm();
  return r.norm() / (scale > 0.0 ? scale : 1.0);
}

Eigen::VectorXd TrainHarmonicBalance::startingGuess(double omega) {
  prepare(omega);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(size());
  for (int m = 0; m < r_; ++m) u(m * n_) = b0_(m);
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
  for (int b = 0; b < bearings_; ++b) {  // the journal onto the bearing surface (header)
    const TrainBearingLaw& law = laws_[b];
    const int c = bearing_first_[b], w = law.width();
    TrainBearingLaw::Vector mean(w);
    for (int k = 0; k < w; ++k) mean(k) = u((c + k) * n_);
    mean = law.loadedDisplacement(mean);
    for (int k = 0; k < w; ++k) u((c + k) * n_) = mean(k);
  }
  return u;
}

void TrainHarmonicBalance::solve(HarmonicBalancePoint& point) {
  solveAtFixedFrequency(*this, point, options_.tolerance, options_.max_iterations);
}

Eigen::MatrixXd TrainHarmonicBalance::meshDeflections(const Eigen::VectorXd& u) {
  Eigen::MatrixXd d(samples_, meshes_);
  for (int m = 0; m < meshes_; ++m) inverse(u.data() + m * n_, d.col(m).data());
  return d;
}

Eigen::MatrixXd TrainHarmonicBalance::bearingDisplacements(const Eigen::VectorXd& u) {
  Eigen::MatrixXd d(samples_, 2 * bearings_);  // (u_y, u_z): each bearing's first two
  for (int b = 0; b < bearings_; ++b) {
    for (int k = 0; k < 2; ++k)
      inverse(u.data() + (bearing_first_[b] + k) * n_, d.col(2 * b + k).data());
  }
  return d;
}

Eigen::MatrixXd TrainHarmonicBalance::meshContactForces(const Eigen::VectorXd& u) {
  meshForceSamples(u);  // f̃ = k g − k̄ δ
  Eigen::MatrixXd f = force_.leftCols(meshes_);
  for (int m = 0; m < meshes_; ++m) f.col(m) += model_.meshes()[m].mean_stiffness * delta_.col(m);
  return f;
}

Eigen::MatrixXd TrainHarmonicBalance::displacementCoefficients(const HarmonicBalancePoint& point) {
  prepare(point.omega);
  meshForceSamples(point.q);
  const Eigen::MatrixXd G = forceCoefficients(point.omega);
  // X_h = D(h)⁻¹ (F₀ δ_h0 − V (F̃_h − d_h)).
  Eigen::MatrixXd X(dofs_, n_);
  X.col(0) = lu0_.solve(model_.staticLoad() - V_ * G.row(0).transpose());
  Eigen::VectorXcd z(r_);
  for (int h = 1; h <= h_; ++h) {
    for (int m = 0; m < r_; ++m) z(m) = Complex(G(cosIndex(h), m), -G(sinIndex(h), m));
    const Eigen::VectorXcd x = lu_[h].solve(-(V_.cast<Complex>() * z));
    X.col(cosIndex(h)) = x.real();
    X.col(sinIndex(h)) = -x.imag();
  }
  return X;
}

std::pair<Eigen::VectorXd, Eigen::VectorXd> TrainHarmonicBalance::initialState(
    const HarmonicBalancePoint& point) {
  const Eigen::MatrixXd X = displacementCoefficients(point);
  Eigen::VectorXd q = X.col(0), v = Eigen::VectorXd::Zero(X.rows());
  for (int h = 1; h <= h_; ++h) {  // q = Σ (a_h cos hτ + b_h sin hτ), τ = ω₀ t
    q += X.col(cosIndex(h));
    v += h * point.omega * X.col(sinIndex(h));
  }
  return {q, v};
}

void TrainHarmonicBalance::classify(HarmonicBalancePoint& point, StabilityMethod method,
                                    bool samples_current) {
  if (method == StabilityMethod::kHill) return classifyHill(point, samples_current);
  if (!samples_current) meshForceSamples(point.q);
  // Variational equation M x″ + C x′ + (K̄ + V S(t) Vᵀ) x = 0, S = diag(df̃/dδ) held over each
  // sample interval, by average-acceleration Newmark on the 2n columns of the state
  // (x, x′) = I at t = 0; per step the constant A = K̄ + a₀M + a₁C is corrected by Woodbury.
  // On the elastic subspace x = E ξ (Rᵀ M x = 0): the rigid-body modes (rolling; no mesh,
  // support or damper acts on them) would add multipliers 1 that hide a fold's.
  const double speed = inputSpeed(point.omega);
  const double T = kTwoPi / point.omega, dt = T / samples_;
  const NewmarkCoefficients nm(NewmarkParameters::averageAcceleration(), dt);
  const double a0 = nm.a0, a1 = nm.a1, a2 = nm.a2;
  const Eigen::MatrixXd M = elastic_.transpose() * model_.mass() * elastic_;
  const Eigen::MatrixXd Kbar = elastic_.transpose() * model_.meanStiffnessAt(speed) * elastic_;
  const Eigen::MatrixXd C = elastic_.transpose() * model_.dampingAt(speed) * elastic_;
  const Eigen::MatrixXd V = elastic_.transpose() * V_;
  const Eigen::PartialPivLU<Eigen::MatrixXd> A(Kbar + a0 * M + a1 * C);
  const int n = static_cast<int>(elastic_.cols());
  // y = A⁻¹ (M (a₀x + a₂v + a) + C (a₁x + v)) as one product [A⁻¹M, A⁻¹C] [·; ·] (a₃ = a₄ = 1,
  // a₅ = 0: β = 1/4, γ = 1/2), then the Woodbury correction for the meshes' S.
  Eigen::MatrixXd PQ(n, 2 * n);
  PQ << A.solve(M), A.solve(C);
  const Eigen::MatrixXd Z = A.solve(V), Vt = V.transpose();
  const Eigen::MatrixXd W = Vt * Z;
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(n, 2 * n), v = x, a(n, 2 * n), y(n, 2 * n);
  Eigen::MatrixXd rhs(2 * n, 2 * n);
  x.leftCols(n).setIdentity();
  v.rightCols(n).setIdentity();
  const Eigen::LLT<Eigen::MatrixXd> mass(M);
  // S(t): the meshes' slopes on the diagonal, w × w blocks ∂f̃/∂u of the clearance bearings.
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(r_, r_);
  for (int m = 0; m < meshes_; ++m) S(m, m) = slope_(0, m);
  for (const auto& [i, j, column] : bearing_blocks_) S(i, j) = bearing_slope_(0, column);
  a = -mass.solve(Kbar * x + V * (S * (Vt * x)) + C * v);
  Eigen::MatrixXd small(r_, r_), w(r_, 2 * n), sw(r_, 2 * n);
  Eigen::PartialPivLU<Eigen::MatrixXd> small_lu(r_);
  // The right-hand side carries the acceleration: with β = 1/4, γ = 1/2 a step gives
  // v' = a₁(x' − x) − v and a' = a₀(x' − x) − a₂v − a, so a₀x' + a₂v' + a' = 2a₀x' + a₂v' − (a₀x +
  // a₂v + a): a itself is never formed after the start.
  rhs.topRows(n) = a0 * x + a2 * v + a;
  rhs.bottomRows(n) = a1 * x + v;
  for (int i = 1; i <= samples_; ++i) {
    // The slope over the interval (t_{i−1}, t_i): the contact law's slope averaged along the
    // straight line between the sampled tooth deformations (the fraction of the interval in
    // contact, so that a contact change inside it counts in proportion: second order in the
    // switching instant instead of first), times the mean of the end stiffnesses, less k̄.
    const int i0 = i - 1, i1 = i % samples_;
    // Tooth pairs: the same per element, ½ (k_j(t_{i−1}) + k_j(t_i)) times the fraction of the
    // interval with y > g_j (y and g_j linear between the samples).
    for (int m = 0; m < meshes_; ++m) {
      const TrainMesh& mesh = model_.meshes()[m];
      const double y0 = delta_(i0, m) - e_(i0, m), y1 = delta_(i1, m) - e_(i1, m);
      const double k = 0.5 * (k_(i0, m) + k_(i1, m));
      S(m, m) = (tooth_pairs_[m].elementCount() > 0 ? tooth_pairs_[m].meanSlope(i0, y0, i1, y1)
                                                    : k * contactFraction(mesh, y0, y1)) -
                mesh.mean_stiffness;
    }
    // A clearance bearing: ∂f/∂u averaged along the straight segment between the samples (the
    // same second-order treatment of a contact change inside the interval), less k I.
    for (int b = 0; b < bearings_; ++b) {
      const TrainBearingLaw& law = laws_[b];
      const int c = bearing_first_[b], width = law.width();
      TrainBearingLaw::Vector u0(width), u1(width);
      for (int k = 0; k < width; ++k) u0(k) = delta_(i0, c + k), u1(k) = delta_(i1, c + k);
      S.block(c, c, width, width) = law.meanStiffness(u0, u1) - law.linear();
    }
    y.noalias() = PQ * rhs;
    w.noalias() = Vt * y;
    sw.noalias() = S * w;
    small.noalias() = S * W;
    small.diagonal().array() += 1.0;
    small_lu.compute(small);
    w = small_lu.solve(sw);
    y.noalias() -= Z * w;
    v = a1 * (y - x) - v;
    rhs.topRows(n) = 2.0 * a0 * y + a2 * v - rhs.topRows(n);
    rhs.bottomRows(n) = a1 * y + v;
    x.swap(y);
  }
  Eigen::MatrixXd phi(2 * n, 2 * n);
  phi << x, v;
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(phi, false);
  double largest = 0.0;
  for (Eigen::Index j = 0; j < eig.eigenvalues().size(); ++j) {
    if (std::abs(eig.eigenvalues()[j]) >= largest) {
      largest = std::abs(eig.eigenvalues()[j]);
      point.critical_multiplier = eig.eigenvalues()[j];
    }
  }
  point.max_floquet_real = std::log(largest) / T;
  point.stable = largest <= 1.0 + kNeutralMultiplier;
}

}  // namespace geardyn
