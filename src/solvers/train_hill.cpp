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
#include "geardyn/solvers/detail/train_hill_operator.h"
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

}  // namespace

TrainHillSolver::TrainHillSolver() : op_(std::make_unique<TrainHillShiftSolve>()) {}
TrainHillSolver::~TrainHillSolver() = default;

TrainHillResult trainHillExponents(const TrainHillProblem& problem) {
  return TrainHillSolver().arnoldi(problem);
}

std::optional<TrainHillResult> trainHillProjection(const TrainHillProblem& problem) {
  return TrainHillSolver().projection(problem);
}

TrainHillResult TrainHillSolver::arnoldi(const TrainHillProblem& problem) {
  TrainHillShiftSolve& op = *op_;
  op.reset(problem);
  op.set_shift(0.0);  // once for both passes (the solvers' own set_shift(0) is then a no-op)
  const Eigen::Index n = problem.M.rows(), N = op.rows();
  TrainHillResult out;
  out.reused_jacobian = op.reusesJacobian();
  out.harmonics = problem.harmonics;
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
    Spectra::GenEigsRealShiftSolver<TrainHillShiftSolve> solver(op, nev, ncv, 0.0);
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
                                                           bool samples_current, int harmonics) {
  const int H = harmonics > 0 ? harmonics : h_;
  if (H > h_ && H > samples_ / 4) {  // (the balance's own H is as its Jacobian has it)
    throw std::invalid_argument(fmt::format(
        "Hill's method: {} harmonics from {} samples (at most N/4: the slopes' 2H alias)", H,
        samples_));
  }
  if (!samples_current) meshForceSamples(point.q);
  detail::TrainHillProblem p;
  const double speed = inputSpeed(point.omega);
  p.M = elastic_.transpose() * model_.mass() * elastic_;
  p.K = elastic_.transpose() * model_.meanStiffnessAt(speed) * elastic_;
  p.C = elastic_.transpose() * model_.dampingAt(speed) * elastic_;
  p.V = elastic_.transpose() * V_;
  p.omega = point.omega;
  p.harmonics = H;
  std::vector<double> Dt, Et;
  const auto add = [&](int i, int j, const double* slope) {
    std::copy(slope, slope + samples_, real_buffer_);
    fftw_execute(forward_plan_);
    detail::aftSlopeTables(complex_buffer_, samples_, H, Dt, Et);
    detail::TrainHillProblem::Block block{i, j, Eigen::MatrixXd(2 * H + 1, 2 * H + 1)};
    detail::aftJacobian(Dt, Et, H, block.galerkin);
    p.slopes.push_back(std::move(block));
  };
  for (int m = 0; m < meshes_; ++m) add(m, m, slope_.col(m).data());
  for (const auto& [i, j, column] : bearing_blocks_) add(i, j, bearing_slope_.col(column).data());
  // The balance's last factors, if they are of this Jacobian: factorised at this ω, with every
  // sample's slope as now (a piecewise-linear contact law's Jacobian changes only where a
  // sample changes contact state, so Newton's last step usually leaves it as it is).
  if (H == h_ && factored_omega_ == point.omega && cached_omega_ == point.omega &&
      factored_slope_ == slope_ && factored_bearing_slope_ == bearing_slope_) {
    p.jacobian = &jacobian_lu_;
    p.jacobian_blocks = &B_;
  }
  return p;
}

const Eigen::PartialPivLU<Eigen::MatrixXd>& TrainHarmonicBalance::factorJacobian(
    const Eigen::MatrixXd& dr_du) {
  factored_omega_ = -1.0;  // until the factors are there
  ContinuationProblem::factorJacobian(dr_du);
  factored_omega_ = cached_omega_;
  factored_slope_ = slope_;
  factored_bearing_slope_ = bearing_slope_;
  return jacobian_lu_;
}

void TrainHarmonicBalance::classifyHill(HarmonicBalancePoint& point, bool samples_current) {
  // The resolvent projection; where the balance's H does not resolve the train's fastest mode,
  // the projection with as many harmonics as do (from the same samples, at most N/4) when that
  // costs less than the Arnoldi run; the Arnoldi run on the strip otherwise, or when the
  // projection declines for another reason.
  const detail::TrainHillProblem problem = hillProblem(point, samples_current);
  if (!hill_) hill_ = std::make_unique<detail::TrainHillSolver>();
  std::optional<detail::TrainHillResult> projected = hill_->projection(problem);
  const int resolving = hill_->resolvingHarmonics();
  if (!projected && resolving > h_ && resolving <= samples_ / 4 &&
      detail::TrainHillSolver::extensionPays(static_cast<int>(problem.M.rows()), r_, h_,
                                             resolving)) {
    const detail::TrainHillProblem extended = hillProblem(point, true, resolving);
    projected = hill_->projection(extended);
  }
  const detail::TrainHillResult hill = projected ? std::move(*projected) : hill_->arnoldi(problem);
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
