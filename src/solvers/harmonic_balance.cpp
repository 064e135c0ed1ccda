#include "geardyn/solvers/harmonic_balance.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geardyn/error.h"
#include "geardyn/numerics/floquet_strip.h"
#include "geardyn/solvers/detail/aft_jacobian.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"

namespace geardyn {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

inline int cosIndex(int h) {
  return 2 * h - 1;
}
inline int sinIndex(int h) {
  return 2 * h;
}

}  // namespace

void HarmonicBalanceOptions::validate() const {
  if (harmonics < 1 || harmonics > 512) {
    throw InputError("hbm.harmonics", std::to_string(harmonics), "must be in [1, 512]");
  }
  if (samples_per_period <= 2 * harmonics) {
    throw InputError("hbm.samples", std::to_string(samples_per_period),
                     fmt::format("must exceed 2H = {} to resolve {} harmonics without aliasing "
                                 "(at least {}; 8H or more for contact nonlinearities)",
                                 2 * harmonics, harmonics, 2 * harmonics + 1));
  }
  if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
    throw InputError("hbm.tolerance", fmt::format("{:g}", tolerance), "must be finite and > 0");
  }
  if (max_iterations < 1)
    throw InputError("hbm.max_iterations", std::to_string(max_iterations), "must be >= 1");
}

HarmonicBalance::HarmonicBalance(const GearPairModel& model, const HarmonicBalanceOptions& options)
    : model_(model), options_(options) {
  options_.validate();
  if (!model.spec().extra_forces.empty()) {
    throw InputError("model.extra_force_amplitudes", "",
                     "extra forces at other frequencies are not supported by harmonic balance");
  }
  h_ = options_.harmonics;
  n_ = 2 * h_ + 1;
  samples_ = options_.samples_per_period;
  k_mean_ = summarizeMeshStiffness(model.meshStiffness(), 0).mean;
  const double phase0 = model.spec().initial_phase;
  for (int i = 0; i < samples_; ++i) {
    const double phase = phase0 + static_cast<double>(i) / samples_;
    phases_.push_back(phase);
    stiffness_.push_back(model.meshStiffness().stiffness(phase));
    error_.push_back(model.transmissionError().value(phase));
    error_rate_.push_back(model.transmissionError().derivative(phase));  // de/dφ
  }
  if (const MeshContactElements* elements = model.contactElements()) {
    elements_ = elements->count();
    element_stiffness_.resize(static_cast<std::size_t>(samples_) * elements_);
    element_gap_.resize(element_stiffness_.size());
    for (int i = 0; i < samples_; ++i)
      for (int j = 0; j < elements_; ++j)
        elements->element(phases_[i], j, element_stiffness_[i * elements_ + j],
                          element_gap_[i * elements_ + j]);
  }
  real_buffer_ = fftw_alloc_real(samples_);
  complex_buffer_ = fftw_alloc_complex(samples_ / 2 + 1);
  forward_plan_ = fftw_plan_dft_r2c_1d(samples_, real_buffer_, complex_buffer_, FFTW_ESTIMATE);
  inverse_plan_ = fftw_plan_dft_c2r_1d(samples_, complex_buffer_, real_buffer_, FFTW_ESTIMATE);
  f_.resize(samples_);
  df_.resize(samples_);
  // The error and its phase derivative are fixed over the sweep: their coefficients once.
  forward(error_.data(), error_coefficients_, n_);
  forward(error_rate_.data(), error_rate_coefficients_, n_);
}

HarmonicBalance::~HarmonicBalance() {
  fftw_destroy_plan(forward_plan_);
  fftw_destroy_plan(inverse_plan_);
  fftw_free(real_buffer_);
  fftw_free(complex_buffer_);
}

void HarmonicBalance::forward(const double* samples, Eigen::VectorXd& c, int count) {
  // Real FFT: X_m = Σ s_n e^{−2πi mn/N}; a₀ = X₀/N, a_h = 2 Re X_h / N, b_h = −2 Im X_h / N.
  std::copy(samples, samples + samples_, real_buffer_);
  fftw_execute(forward_plan_);
  c.setZero(count);
  c[0] = complex_buffer_[0][0] / samples_;
  for (int h = 1; 2 * h - 1 < count; ++h) {
    c[cosIndex(h)] = 2.0 * complex_buffer_[h][0] / samples_;
    if (sinIndex(h) < count) c[sinIndex(h)] = -2.0 * complex_buffer_[h][1] / samples_;
  }
}

void HarmonicBalance::inverseToBuffer(const Eigen::VectorXd& q) {
  // Inverse real FFT (the plan made once); harmonic h goes to bin h as (a_h − i b_h)/2, so that
  // FFTW's c2r sum gives a₀ + Σ a_h cos hτ + b_h sin hτ in real_buffer_.
  complex_buffer_[0][0] = q[0];
  complex_buffer_[0][1] = 0.0;
  for (int k = 1; k <= samples_ / 2; ++k) {
    complex_buffer_[k][0] = 0.0;
    complex_buffer_[k][1] = 0.0;
  }
  for (int h = 1; h <= h_; ++h) {
    complex_buffer_[h][0] = 0.5 * q[cosIndex(h)];
    complex_buffer_[h][1] = -0.5 * q[sinIndex(h)];
  }
  fftw_execute(inverse_plan_);
}

std::vector<double> HarmonicBalance::timeSignal(const Eigen::VectorXd& q) const {
  auto* self = const_cast<HarmonicBalance*>(this);  // the FFT buffers are scratch space
  self->inverseToBuffer(q);
  return std::vector<double>(real_buffer_, real_buffer_ + samples_);
}

std::vector<double> HarmonicBalance::meshForceSignal(const Eigen::VectorXd& q, double) const {
  const std::vector<double> x = timeSignal(q);
  std::vector<double> f(samples_);
  for (int i = 0; i < samples_; ++i) f[i] = sampleForce(i, x[i] - error_[i], nullptr);
  return f;
}

double HarmonicBalance::sampleForce(int i, double y, double* slope) const {
  if (elements_ == 0) {
    double s = 1.0;
    const double g = linearized_ ? y - linear_shift_ : model_.contactLaw(y, &s);
    if (slope) *slope = stiffness_[i] * s;
    return stiffness_[i] * g;
  }
  // Σ_j k_j max(0, y − g_j); linearised (the start): every element in its window in contact.
  double force = 0.0, d = 0.0;
  for (int j = 0; j < elements_; ++j) {
    const double k = element_stiffness_[i * elements_ + j], gap = element_gap_[i * elements_ + j];
    if (linearized_ ? k > 0.0 : y > gap) {
      force += k * (y - gap);
      d += k;
    }
  }
  if (slope) *slope = d;
  return force;
}

void HarmonicBalance::externalForce(double omega, Eigen::VectorXd& f,
                                    Eigen::VectorXd* df_domega) const {
  // F + c e′(t) with e′ = (ω/2π) de/dφ: its coefficients are linear in ω.
  const double c = model_.damping();
  f = (c * omega / kTwoPi) * error_rate_coefficients_;
  f[0] += model_.meanForce();
  if (df_domega) *df_domega = (c / kTwoPi) * error_rate_coefficients_;
}

Eigen::VectorXd HarmonicBalance::linearGuess(double omega) {
  // The response with the teeth held in contact (g(y) = y − shift on the loaded flank): a linear
  // time-varying problem, solved exactly by one Newton step from the static deflection. Far
  // from contact loss it is the answer; near it, the best start for the nonlinear solve.
  Eigen::VectorXd q = error_coefficients_;
  double shift = 0.0;
  if (model_.contact() == ContactLaw::kBacklash) {
    shift = model_.meanForce() >= 0 ? model_.backlash() : -model_.backlash();
  }
  q[0] += model_.meanForce() / k_mean_ + shift;
  linear_shift_ = shift;
  linearized_ = true;
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  for (int iteration = 0; iteration < 2; ++iteration) {
    residual(q, omega, r, &J, nullptr);
    const Eigen::VectorXd step = J.partialPivLu().solve(-r);
    if (!step.allFinite()) break;
    q += step;
  }
  linearized_ = false;
  return q;
}

void HarmonicBalance::residual(const Eigen::VectorXd& q, double omega, Eigen::VectorXd& r,
                               Eigen::MatrixXd* dr_dq, Eigen::VectorXd* dr_domega) {
  const double m = model_.mass(), c = model_.damping();
  // AFT: coefficients → samples (inverse real FFT), force in the time domain, back.
  inverseToBuffer(q);
  for (int i = 0; i < samples_; ++i) f_[i] = sampleForce(i, real_buffer_[i] - error_[i], &df_[i]);
  forward(f_.data(), fnl_, n_);
  externalForce(omega, fext_, dr_domega ? &dfext_ : nullptr);

  r = fnl_ - fext_;
  for (int h = 1; h <= h_; ++h) {
    const double a = q[cosIndex(h)], b = q[sinIndex(h)], w = h * omega;
    r[cosIndex(h)] += -w * w * m * a + c * w * b;
    r[sinIndex(h)] += -w * w * m * b - c * w * a;
  }
  if (dr_domega) {
    *dr_domega = -dfext_;
    for (int h = 1; h <= h_; ++h) {
      const double a = q[cosIndex(h)], b = q[sinIndex(h)];
      (*dr_domega)[cosIndex(h)] += -2.0 * h * h * omega * m * a + c * h * b;
      (*dr_domega)[sinIndex(h)] += -2.0 * h * h * omega * m * b - c * h * a;
    }
  }
  if (dr_dq) {
    // FFT of df/dy: D_m = (1/N) Σ df cos mτ, E_m = (1/N) Σ df sin mτ, any integer m (periodic
    // in N, D even, E odd). Products of trigonometric functions give the Toeplitz + Hankel
    // structure of the Jacobian of the sampled force coefficients.
    std::copy(df_.begin(), df_.end(), real_buffer_);
    fftw_execute(forward_plan_);
    // D_m, E_m for m = −2H..2H once: every Jacobian entry is a sum of two.
    detail::aftSlopeTables(complex_buffer_, samples_, h_, de_d_, de_e_);
    Eigen::MatrixXd& J = *dr_dq;
    J.resize(n_, n_);
    detail::aftJacobian(de_d_, de_e_, h_, J);
    for (int h = 1; h <= h_; ++h) {
      const double w = h * omega;
      J(cosIndex(h), cosIndex(h)) += -w * w * m;
      J(cosIndex(h), sinIndex(h)) += c * w;
      J(sinIndex(h), sinIndex(h)) += -w * w * m;
      J(sinIndex(h), cosIndex(h)) += -c * w;
    }
  }
}

double HarmonicBalance::residualNorm(const Eigen::VectorXd& q, const Eigen::VectorXd& r,
                                     double omega) const {
  Eigen::VectorXd fext;
  externalForce(omega, fext, nullptr);
  const double scale = std::abs(model_.meanForce()) + k_mean_ * q.norm() + fext.norm();
  return r.norm() / (scale > 0.0 ? scale : 1.0);
}

void HarmonicBalance::solve(HarmonicBalancePoint& point) {
  solveAtFixedFrequency(*this, point, options_.tolerance, options_.max_iterations);
}

void HarmonicBalance::stability(HarmonicBalancePoint& point) {
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  residual(point.q, point.omega, r, &J, nullptr);
  const double m = model_.mass(), c = model_.damping();
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n_, n_);
  for (int h = 1; h <= h_; ++h) {
    D(cosIndex(h), sinIndex(h)) = h * point.omega;
    D(sinIndex(h), cosIndex(h)) = -h * point.omega;
  }
  // λ² m p + λ (c I + 2 m D) p + J p = 0  →  first-order companion form.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n_, 2 * n_);
  A.topRightCorner(n_, n_).setIdentity();
  A.bottomLeftCorner(n_, n_) = -J / m;
  A.bottomRightCorner(n_, n_) = -(c * Eigen::MatrixXd::Identity(n_, n_) + 2.0 * m * D) / m;
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(A, false);
  // One DOF: the two exponents of the strip |Im λ| <= ω/2, one copy each on its edge (where a
  // real negative multiplier puts them: "the two closest to the real axis" could take both
  // copies a ± iω/2 of the stable one there, as round-off had it).
  const std::vector<std::complex<double>> strip =
      detail::floquetStrip(eig.eigenvalues(), point.omega, 1);
  if (strip.empty()) {
    throw std::runtime_error(
        fmt::format("Hill's method: no Floquet exponent in the strip at ω = {:g}", point.omega));
  }
  const std::complex<double> critical = strip.front();
  point.max_floquet_real = critical.real();
  point.critical_multiplier = detail::floquetMultiplier(critical, point.omega);
  point.stable = point.max_floquet_real < 1e-9 * point.omega;
}

void HarmonicBalance::classify(HarmonicBalancePoint& point, StabilityMethod method,
                               bool samples_current) {
  if (method == StabilityMethod::kHill) {
    stability(point);
  } else {
    stabilityMonodromy(point, samples_current);
  }
}

void HarmonicBalance::stabilityMonodromy(HarmonicBalancePoint& point, bool samples_current) {
  // df/dy at the samples of the solution (left by the last residual evaluation at point.q).
  if (!samples_current) {
    Eigen::VectorXd r;
    residual(point.q, point.omega, r, nullptr, nullptr);
  }
  const double m = model_.mass(), c = model_.damping();
  const double T = kTwoPi / point.omega, h = T / samples_;
  const double half_gamma = 0.5 * c / m;
  Eigen::Matrix2d phi = Eigen::Matrix2d::Identity();
  for (int i = 0; i < samples_; ++i) {
    // exp(A h), A = [[0, 1], [−κ, −γ]]: e^{−γh/2} [C I + S (A + γ/2 I)] with s² = γ²/4 − κ,
    // C = cosh(sh) or cos, S = sinh(sh)/s or sin(|s|h)/|s|.
    const double kappa = df_[i] / m;
    const double s2 = half_gamma * half_gamma - kappa;
    double cs, sn;
    if (s2 > 1e-300) {
      const double s = std::sqrt(s2);
      cs = std::cosh(s * h);
      sn = std::sinh(s * h) / s;
    } else if (s2 < -1e-300) {
      const double s = std::sqrt(-s2);
      cs = std::cos(s * h);
      sn = std::sin(s * h) / s;
    } else {
      cs = 1.0;
      sn = h;
    }
    Eigen::Matrix2d step;
    step << cs + sn * half_gamma, sn, -sn * kappa, cs - sn * half_gamma;
    phi = (std::exp(-half_gamma * h) * step) * phi;
  }
  const Eigen::EigenSolver<Eigen::Matrix2d> eig(phi, false);
  double largest = 0.0;
  for (int j = 0; j < 2; ++j) {
    if (std::abs(eig.eigenvalues()[j]) >= largest) {
      largest = std::abs(eig.eigenvalues()[j]);
      point.critical_multiplier = eig.eigenvalues()[j];
    }
  }
  point.max_floquet_real = std::log(largest) / T;
  point.stable = largest < 1.0 + 1e-9;
}

}  // namespace geardyn
