/// Hill's method for gear trains (detail/train_hill.h) and TrainHarmonicBalance's use of it:
/// the Floquet exponents of the variational equation from the Hill eigenproblem, its low-rank
/// periodic part inverted by Woodbury inside shift-invert Arnoldi.

#include "geardyn/solvers/detail/train_hill.h"

#include <Spectra/GenEigsRealShiftSolver.h>
#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geardyn/numerics/strip_arnoldi.h"
#include "geardyn/solvers/detail/aft_jacobian.h"
#include "geardyn/solvers/train_harmonic_balance.h"

namespace geardyn::detail {
namespace {

using Complex = std::complex<double>;
/// Eigenvalues asked for beyond the 2n exponents in the first pass: room for copies of lightly
/// damped exponents just outside the strip that are nearer 0 than a more damped exponent's
/// central copy. Measured on the 3-planet sweep's 201 bench points (n = 17): the first pass
/// holds all 2n at 59 % of them with 4, 99.5 % with 8 (112 operator applications a point,
/// against 128 with 12 and 138 with 16, where all pass).
constexpr Eigen::Index kHillMargin = 8;
/// Arnoldi basis over eigenvalues asked for. Each implicit restart of Spectra's Arnoldi costs a
/// Schur decomposition of the ncv × ncv Hessenberg matrix (~10 ncv³ flops) and a compression of
/// the N × ncv basis, and with ncv = 2 nev + 1 (85) the 42 wanted converge over many restarts
/// that add a few vectors each. With ncv = 2.6 nev + 1 (110) they converge in the first
/// factorisation or after one restart: measured on the 201 bench points (n = 17, N = 1054,
/// TrainStabilityCostPerPoint, CPU time, one run): 15.2 ms a point with 2, 9.4 with 2.6,
/// 10.4 with 2.8, 13.6 with 3.2 and 16.3 with 1.5 (113–137 operator applications in each).
constexpr double kHillBasisRatio = 2.6;
/// The restart-free run (strip_arnoldi.h): first check at kFirstCheckRatio × (2n + kHillMargin)
/// basis vectors, then every kCheckStep, giving up at kMaxDimensionRatio × (2n + kHillMargin).
constexpr double kFirstCheckRatio = 2.2;
constexpr int kCheckStep = 8;
constexpr double kMaxDimensionRatio = 3.2;

/// y = (𝓗 − σI)⁻¹ x in Spectra's operator interface (train_hill.h): per harmonic h the block
/// A₀ − s_h (s_h = σ + ihω) through D(s_h) = s²M + sC + K̄, the periodic part by Woodbury:
/// (𝓓 + 𝓑𝓢𝓒ᵀ)⁻¹ = 𝓓⁻¹ − 𝓓⁻¹𝓑𝓢 (I + 𝓒ᵀ𝓓⁻¹𝓑𝓢)⁻¹ 𝓒ᵀ𝓓⁻¹, 𝓒ᵀ𝓓⁻¹𝓑 = blockdiag(Vᵀ D(s_h)⁻¹ V).
/// Real vectors: coefficient-major (0, cos 1, sin 1, …), the state (x, x′) within; a
/// coefficient pair (a_h, b_h) is the complex a_h − i b_h of Re[(a − ib) e^{ihωt}].
class HillShiftSolve {
 public:
  using Scalar = double;

  explicit HillShiftSolve(const TrainHillProblem& p)
      : p_(p),
        n_(static_cast<int>(p.M.rows())),
        r_(static_cast<int>(p.V.cols())),
        h_(p.harmonics),
        nc_(2 * p.harmonics + 1),
        R_(p.harmonics + 1),
        Z_(p.harmonics + 1),
        s_(p.harmonics + 1),
        ad_(p.harmonics + 1),
        u_(p.harmonics + 1) {
    e_.resize(r_ * nc_);
    w_.resize(r_ * nc_);
    z_.resize(r_ * nc_);
    zc_.resize(r_);
    for (int h = 0; h <= h_; ++h) {
      ad_[h].resize(n_ + r_);
      u_[h].resize(2 * n_);
    }
  }

  Eigen::Index rows() const { return 2 * n_ * nc_; }
  Eigen::Index cols() const { return rows(); }

  /// Per harmonic the factors the operator applies (set once, so that perform_op only
  /// multiplies): R = [D(s)⁻¹[C + sM, M]; Vᵀ D(s)⁻¹[C + sM, M]] ((n + r) × 2n: a and Vᵀa in one
  /// product), Z = D(s)⁻¹V; and the capacitance's LU.
  void set_shift(double sigma) {
    if (shifted_ && sigma == sigma_) return;
    shifted_ = true, sigma_ = sigma;
    const Eigen::MatrixXcd Mc = p_.M.cast<Complex>(), Cc = p_.C.cast<Complex>();
    const Eigen::MatrixXcd Vc = p_.V.cast<Complex>();
    std::vector<Eigen::MatrixXcd> G(h_ + 1);
    Eigen::PartialPivLU<Eigen::MatrixXcd> lu;
    for (int h = 0; h <= h_; ++h) {
      const Complex s(sigma, h * p_.omega);
      s_[h] = s;
      lu.compute(s * s * Mc + s * Cc + p_.K.cast<Complex>());
      Eigen::MatrixXcd rhs(n_, 2 * n_);
      rhs << Cc + s * Mc, Mc;
      R_[h].resize(n_ + r_, 2 * n_);
      R_[h].topRows(n_) = lu.solve(rhs);
      R_[h].bottomRows(r_).noalias() = Vc.transpose() * R_[h].topRows(n_);
      Z_[h] = lu.solve(Vc);
      G[h] = Vc.transpose() * Z_[h];
    }
    // Capacitance I + 𝓖𝓢 (coordinate-major, 2H + 1 coefficients each): G(h) acts per harmonic
    // as the 2 × 2 real form of a complex number on the rows of 𝓢's blocks.
    const int rho = r_ * nc_;
    Eigen::MatrixXd K = Eigen::MatrixXd::Identity(rho, rho);
    for (const TrainHillProblem::Block& b : p_.slopes) {
      const Eigen::MatrixXd& JF = b.galerkin;
      for (int mr = 0; mr < r_; ++mr) {
        auto block = K.block(mr * nc_, b.j * nc_, nc_, nc_);
        block.row(0) += G[0](mr, b.i).real() * JF.row(0);
        for (int h = 1; h <= h_; ++h) {
          const double gr = G[h](mr, b.i).real(), gi = G[h](mr, b.i).imag();
          block.row(2 * h - 1) += gr * JF.row(2 * h - 1) + gi * JF.row(2 * h);
          block.row(2 * h) += -gi * JF.row(2 * h - 1) + gr * JF.row(2 * h);
        }
      }
    }
    capacitance_.compute(K);
  }

  /// Allocation-free: every buffer is sized in the constructor.
  void perform_op(const double* x_in, double* y_out) const {
    const int n = n_, n2 = 2 * n_;
    // g = 𝓓⁻¹ f: (A₀ − s)(a, b) = (f_x, f_v) ⇔ a = −D(s)⁻¹(M f_v + (C + sM) f_x), b = f_x + sa.
    for (int h = 0; h <= h_; ++h) {
      Eigen::VectorXcd& u = u_[h];  // (f_x, f_v)
      if (h == 0) {
        for (int i = 0; i < n2; ++i) u(i) = x_in[i];
      } else {
        const double *c = x_in + (2 * h - 1) * n2, *s = x_in + 2 * h * n2;
        for (int i = 0; i < n2; ++i) u(i) = Complex(c[i], -s[i]);
      }
      // (a, Vᵀa) in one product; e = 𝓒ᵀ g = Vᵀ a per harmonic, coordinate-major real.
      ad_[h].noalias() = -R_[h] * u;
      const auto d = ad_[h].tail(r_);
      for (int m = 0; m < r_; ++m) {
        if (h == 0) {
          e_(m * nc_) = d(m).real();
        } else {
          e_(m * nc_ + 2 * h - 1) = d(m).real();
          e_(m * nc_ + 2 * h) = -d(m).imag();
        }
      }
    }
    // w = (I + 𝓖𝓢)⁻¹ 𝓒ᵀ g, z = 𝓢 w.
    w_ = capacitance_.solve(e_);
    z_.setZero();
    for (const TrainHillProblem::Block& b : p_.slopes) {
      z_.segment(b.i * nc_, nc_).noalias() += b.galerkin * w_.segment(b.j * nc_, nc_);
    }
    // y = g − 𝓓⁻¹𝓑 z: 𝓑 z = (0, −M⁻¹V z) gives a = D(s)⁻¹ V z, b = s a.
    for (int h = 0; h <= h_; ++h) {
      for (int m = 0; m < r_; ++m) {
        zc_(m) =
            h == 0 ? Complex(z_(m * nc_)) : Complex(z_(m * nc_ + 2 * h - 1), -z_(m * nc_ + 2 * h));
      }
      auto a = ad_[h].head(n);
      a.noalias() -= Z_[h] * zc_;
      const Complex s = s_[h];
      double *yc = y_out + (h == 0 ? 0 : (2 * h - 1) * n2), *ys = y_out + 2 * h * n2;
      for (int i = 0; i < n; ++i) {
        const Complex b = u_[h](i) + s * a(i);
        yc[i] = a(i).real();
        yc[n + i] = b.real();
        if (h > 0) ys[i] = -a(i).imag(), ys[n + i] = -b.imag();
      }
    }
  }

 private:
  const TrainHillProblem& p_;
  int n_, r_, h_, nc_;
  bool shifted_ = false;
  double sigma_ = 0.0;
  std::vector<Eigen::MatrixXcd> R_, Z_;  // (D(s_h)⁻¹ and Vᵀ D(s_h)⁻¹)[C + s_h M, M], D(s_h)⁻¹V
  std::vector<Complex> s_;
  Eigen::PartialPivLU<Eigen::MatrixXd> capacitance_;
  mutable std::vector<Eigen::VectorXcd> ad_, u_;  // (a, Vᵀa) and (f_x, f_v) per harmonic
  mutable Eigen::VectorXcd zc_;
  mutable Eigen::VectorXd e_, w_, z_;
};

}  // namespace

TrainHillResult trainHillExponents(const TrainHillProblem& problem) {
  HillShiftSolve op(problem);
  op.set_shift(0.0);  // once for both passes (the solvers' own set_shift(0) is then a no-op)
  const Eigen::Index n = problem.M.rows(), N = op.rows();
  TrainHillResult out;
  // One Arnoldi run without restarts, stopped when its converged Ritz values hold the 2n strip
  // values (strip_arnoldi.h); Spectra's restarted passes below only when it gives up.
  StripArnoldiOptions fast;
  const int wanted = static_cast<int>(2 * n + kHillMargin);
  fast.first_check = static_cast<int>(kFirstCheckRatio * wanted);
  fast.check_step = kCheckStep;
  fast.max_dimension = static_cast<int>(kMaxDimensionRatio * wanted);
  const StripArnoldiResult run =
      stripArnoldi([&op](const double* x, double* y) { op.perform_op(x, y); }, N, problem.omega,
                   static_cast<int>(n), fast);
  out.operations += run.operations;
  if (run.certified) {
    out.exponents = run.strip;
    out.computed = run.dimension;
    out.radius = run.radius;
    out.restart_free = true;
    return out;
  }
  // First the 2n + kHillMargin nearest 0. The strip |Im| <= ω/2 holds exactly one copy of each
  // of the 2n exponents, so 2n strip eigenvalues among them are all the exponents (a certificate,
  // docs/theory/nonlinear_gear_trains.md "Hill's method: the nearest 2n"); fewer (an exponent
  // damped by more than about ω/2, whose central copy is farther than others' neighbours) fall
  // back to the 4n nearest 0: every copy λ + ikω inside |λ| < ω/√2 (at most two per exponent).
  for (const Eigen::Index wanted : {std::min<Eigen::Index>(2 * n + kHillMargin, 4 * n), 4 * n}) {
    const Eigen::Index nev = std::min<Eigen::Index>(wanted, N - 3);
    const Eigen::Index ncv = std::min<Eigen::Index>(
        N, std::max<Eigen::Index>(static_cast<Eigen::Index>(kHillBasisRatio * nev) + 1, 20));
    Spectra::GenEigsRealShiftSolver<HillShiftSolve> solver(op, nev, ncv, 0.0);
    solver.init();
    solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10);
    out.operations += static_cast<int>(solver.num_operations());
    const bool last = wanted == 4 * n || nev == N - 3;
    if (solver.info() != Spectra::CompInfo::Successful) {
      if (!last) continue;
      throw std::runtime_error(fmt::format(
          "Hill's method: shift-invert Arnoldi did not converge at ω = {:g} rad/s ({} of {} "
          "eigenvalues)",
          problem.omega, solver.num_iterations(), nev));
    }
    const Eigen::VectorXcd values = solver.eigenvalues();
    double radius = 0.0;
    for (const Complex& v : values) radius = std::max(radius, std::abs(v));
    std::vector<Complex> strip = floquetStrip(values, problem.omega, static_cast<int>(n));
    if (!last && static_cast<Eigen::Index>(strip.size()) < 2 * n) continue;
    out.computed = static_cast<int>(nev);
    out.radius = radius;
    out.exponents = std::move(strip);
    break;
  }
  return out;
}

Eigen::MatrixXd trainHillMatrix(const TrainHillProblem& p) {
  // The balanced state (W z, z′) of the mass-normalised undamped modes x = Φz (ΦᵀMΦ = I,
  // ΦᵀK̄Φ = W², as in damped_modes.h): every entry a frequency, where the textbook
  // [0 I; −M⁻¹K̄ −M⁻¹C] mixes 1 with ‖M⁻¹K̄‖ and loses the low exponents to round-off.
  const int n = static_cast<int>(p.M.rows()), nc = 2 * p.harmonics + 1, n2 = 2 * n;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(
      0.5 * (p.K + p.K.transpose()), p.M);
  const Eigen::MatrixXd& Phi = modes.eigenvectors();
  const Eigen::VectorXd w = modes.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  const Eigen::MatrixXd Vm = Phi.transpose() * p.V;
  Eigen::MatrixXd A0 = Eigen::MatrixXd::Zero(n2, n2);
  A0.topRightCorner(n, n) = w.asDiagonal();
  A0.bottomLeftCorner(n, n) = -Eigen::MatrixXd(w.asDiagonal());
  A0.bottomRightCorner(n, n) = -Phi.transpose() * p.C * Phi;
  Eigen::MatrixXd Hm = Eigen::MatrixXd::Zero(n2 * nc, n2 * nc);
  for (int c = 0; c < nc; ++c) Hm.block(c * n2, c * n2, n2, n2) = A0;
  for (int h = 1; h <= p.harmonics; ++h) {  // −𝓓ₜ: (a_h, b_h) → −hω (b_h, −a_h)
    const double f = h * p.omega;
    Hm.block((2 * h - 1) * n2, 2 * h * n2, n2, n2).diagonal().array() -= f;
    Hm.block(2 * h * n2, (2 * h - 1) * n2, n2, n2).diagonal().array() += f;
  }
  const Eigen::VectorXd winv = w.cwiseInverse();
  for (const TrainHillProblem::Block& b : p.slopes) {  // 𝓑𝓢𝓒ᵀ: z″ rows, (W z) columns
    const Eigen::MatrixXd outer = -Vm.col(b.i) * Vm.col(b.j).cwiseProduct(winv).transpose();
    for (int c = 0; c < nc; ++c) {
      for (int d = 0; d < nc; ++d) {
        if (b.galerkin(c, d) == 0.0) continue;
        Hm.block(c * n2 + n, d * n2, n, n) += b.galerkin(c, d) * outer;
      }
    }
  }
  return Hm;
}

}  // namespace geardyn::detail

namespace geardyn {

detail::TrainHillProblem TrainHarmonicBalance::hillProblem(const HarmonicBalancePoint& point,
                                                           bool samples_current) {
  if (!samples_current) meshForceSamples(point.q);
  detail::TrainHillProblem p;
  const double speed = inputSpeed(point.omega);
  p.M = elastic_.transpose() * model_.mass() * elastic_;
  p.K = elastic_.transpose() * model_.meanStiffnessAt(speed) * elastic_;
  p.C = elastic_.transpose() * model_.dampingAt(speed) * elastic_;
  p.V = elastic_.transpose() * V_;
  p.omega = point.omega;
  p.harmonics = h_;
  std::vector<double> Dt, Et;
  const auto add = [&](int i, int j, const double* slope) {
    std::copy(slope, slope + samples_, real_buffer_);
    fftw_execute(forward_plan_);
    detail::aftSlopeTables(complex_buffer_, samples_, h_, Dt, Et);
    detail::TrainHillProblem::Block block{i, j, Eigen::MatrixXd(n_, n_)};
    detail::aftJacobian(Dt, Et, h_, block.galerkin);
    p.slopes.push_back(std::move(block));
  };
  for (int m = 0; m < meshes_; ++m) add(m, m, slope_.col(m).data());
  for (const auto& [i, j, column] : bearing_blocks_) add(i, j, bearing_slope_.col(column).data());
  return p;
}

void TrainHarmonicBalance::classifyHill(HarmonicBalancePoint& point, bool samples_current) {
  const detail::TrainHillResult hill =
      detail::trainHillExponents(hillProblem(point, samples_current));
  if (hill.exponents.empty()) {  // cannot be (the strip's central copies are nearest 0)
    throw std::runtime_error(
        fmt::format("Hill's method: no Floquet exponent in the strip |Im| <= ω/2 at ω = {:g} rad/s",
                    point.omega));
  }
  const std::complex<double> critical = hill.exponents.front();
  const double T = 2.0 * std::numbers::pi / point.omega;
  point.max_floquet_real = critical.real();
  point.critical_multiplier = detail::floquetMultiplier(critical, point.omega);
  // The monodromy's threshold |μ| <= 1 + kNeutralMultiplier, as an exponent.
  point.stable = point.max_floquet_real <= kNeutralMultiplier / T;
}

}  // namespace geardyn
