/// Hill's method for gear trains by the resolvent projection (detail/train_hill.h,
/// trainHillProjection; docs/theory/nonlinear_gear_trains.md "Hill's method: the resolvent
/// projection").

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "geardyn/solvers/detail/train_hill.h"
#include "geardyn/solvers/detail/train_hill_operator.h"

namespace geardyn::detail {
namespace {

using Complex = std::complex<double>;

/// The fraction of Hω within which every exponent of the mean system must lie (by the bound of
/// meanModes). The comb's harmonics |k| <= H see a mode of |λ| well inside Hω as the periodic
/// g_p does; a faster one (a stiff or heavily damped mode) sees f_p(λ) ≈ (2H + 1)/λᵖ instead,
/// and the closed form would alias it into the strip as a slow exponent: measured on a DOF
/// overdamped to λ = −60 = 5Hω (ω = 1.5, H = 8), a spurious −0.0036 + iω/2. The projection
/// declines such trains. Not less: with 1 instead of 0.5 the 3-planet stage at a 1.3 kHz base
/// frequency (its highest mode near 9ω) gave max Re λ = +0.081 ω where Hill's eigenvalues give
/// −0.021 ω, a wrong verdict.
constexpr double kResolvedFraction = 0.5;
/// Reciprocal condition of M₂ (in energy-balanced coordinates) below which the projection
/// declines: f₂ can vanish at isolated λ, and M₂⁻¹M₃ would then return round-off.
constexpr double kMinimumReciprocalCondition = 1e-9;
/// The polish (Newton on f₃/f₂ = ν): converged when a step is below kPolishTolerance ω, given
/// up after kPolishIterations or beyond kPolishReach ω from the closed form's λ (it corrects
/// the truncation of the sums, measured below 0.03 ω on the 3-planet stage's sweep).
constexpr double kPolishTolerance = 1e-13;
constexpr int kPolishIterations = 30;
constexpr double kPolishReach = 0.1;
/// Liouville's formula, det Φ(T) = exp ∫₀ᵀ tr A dt with tr A(t) = −tr(M⁻¹C) for every S(t),
/// makes the 2n exponents sum to Σ Re λ = −tr(M⁻¹C) exactly. The projection's sum departs from
/// it by its truncation error: at most 8.6e-4 ω over the 3-planet sweep's 201 bench points and
/// 5.8e-3 ω on a 29/47 pump drive projected with 18 harmonics at 700 Hz base (the Arnoldi run's:
/// 1.8e-7 ω). A projection whose sum is farther than kLiouvilleTolerance ω is declined: on a
/// 4-planet carrier-frame stage at 544 Hz base, projected with 58 harmonics, every polish
/// converged and the sum was off by 20.6 ω.
constexpr double kLiouvilleTolerance = 0.02;

/// The truncated sums f_p(z) = Σ_{k=−H}^{H} (z − ikω)⁻ᵖ for p = 2, 3, 4.
struct TruncatedSums {
  Complex f2, f3, f4;
};

TruncatedSums truncatedSums(Complex z, double omega, int harmonics) {
  // k and −k together: 1/(z ∓ ikω) = (z ± ikω)/(z² + k²ω²), one division a pair.
  const Complex inverse0 = 1.0 / z, square0 = inverse0 * inverse0;
  TruncatedSums s{square0, square0 * inverse0, square0 * square0};
  const Complex z2 = z * z;
  for (int k = 1; k <= harmonics; ++k) {
    const double kw = k * omega;
    const Complex d = 1.0 / (z2 + kw * kw);
    const Complex a = (z + Complex(0.0, kw)) * d, b = (z - Complex(0.0, kw)) * d;
    const Complex a2 = a * a, b2 = b * b;
    s.f2 += a2 + b2;
    s.f3 += a2 * a + b2 * b;
    s.f4 += a2 * a2 + b2 * b2;
  }
  return s;
}

/// The mean system M x″ + C x′ + (K̄ + V S̄ Vᵀ) x = 0 (S̄ the slopes' means, their Galerkin
/// matrices' (0, 0) entries) as far as the projection needs it: an estimate of each of its 2n
/// exponents [1/s] from its undamped modes and their modal damping (−c_j/2 ± i(ω_j² − c_j²/4)^½,
/// c_j = φ_jᵀC̃φ_j; non-proportional and gyroscopic terms left out), and a bound on their modulus
/// [1/s]. With M = LLᵀ and y = Lᵀx, λ²y + λC̃y + K̃y = 0 (C̃ = L⁻¹CL⁻ᵀ, K̃ = L⁻¹KL⁻ᵀ symmetric,
/// ‖K̃‖₂ = ω_max²), so |λ|² <= |λ| ‖C̃‖ + ω_max²: |λ| <= (c + (c² + 4ω_max²)^½)/2, c = ‖C̃‖_F.
struct MeanModes {
  std::vector<Complex> exponents;
  double bound = 0.0;
  double damping_trace = 0.0;  ///< tr(M⁻¹C) = tr(L⁻¹CL⁻ᵀ) [1/s] (Liouville's formula)
};

MeanModes meanModes(const TrainHillProblem& p) {
  Eigen::MatrixXd stiffness = p.K;
  for (const TrainHillProblem::Block& b : p.slopes) {
    stiffness.noalias() += b.galerkin(0, 0) * p.V.col(b.i) * p.V.col(b.j).transpose();
  }
  const Eigen::LLT<Eigen::MatrixXd> mass(p.M);
  MeanModes out;
  if (mass.info() != Eigen::Success) {  // not positive definite: no bound, the caller declines
    out.bound = HUGE_VAL;
    return out;
  }
  const auto congruent = [&mass](Eigen::MatrixXd A) {  // L⁻¹ A L⁻ᵀ
    mass.matrixL().solveInPlace(A);
    A.transposeInPlace();
    mass.matrixL().solveInPlace(A);
    return A;
  };
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(
      congruent(0.5 * (stiffness + stiffness.transpose())));
  const Eigen::MatrixXd damping = congruent(p.C);
  const Eigen::MatrixXd& Phi = eig.eigenvectors();
  double largest = 0.0;
  for (Eigen::Index j = 0; j < Phi.cols(); ++j) {
    const double w2 = std::max(eig.eigenvalues()(j), 0.0);
    const double half = 0.5 * Phi.col(j).dot(damping * Phi.col(j));
    const Complex root = std::sqrt(Complex(w2 - half * half));  // ω_d, or i·(overdamped)
    out.exponents.push_back(-half + Complex(-root.imag(), root.real()));
    out.exponents.push_back(-half - Complex(-root.imag(), root.real()));
    largest = std::max(largest, w2);
  }
  out.damping_trace = damping.trace();
  const double c = damping.norm();
  out.bound = 0.5 * (c + std::sqrt(c * c + 4.0 * largest));
  return out;
}

/// The copy λ₀ + imω of an exponent λ₀ of the strip nearest (in the complex plane) an estimated
/// exponent of the mean system: where the truncated sums see its mode. For a time-invariant
/// train the projection's eigenvalue is f₃(λ)/f₂(λ) at the mode's own λ, not at its copy in the
/// strip (the window |k| <= H is not symmetric about a mode above ω/2); a wrong copy would move
/// it by that asymmetry (measured up to 8e-4 ω on the two-stage reducer), not to another root.
Complex unfolded(Complex lambda0, const std::vector<Complex>& mean, double omega) {
  double best = HUGE_VAL, m = 0.0;
  for (const Complex& l : mean) {
    const double k = std::round((l.imag() - lambda0.imag()) / omega);
    const double distance =
        std::hypot(l.real() - lambda0.real(), lambda0.imag() + k * omega - l.imag());
    if (distance < best) best = distance, m = k;
  }
  return {lambda0.real(), lambda0.imag() + m * omega};
}

/// The exponent λ with f₃(λ)/f₂(λ) = ν (ν [s]) near λ₀ [1/s] by Newton (f_p′ = −p f_{p+1}),
/// moved into the strip; false when it does not converge within kPolishReach ω of λ₀.
bool polish(Complex nu, Complex lambda0, double omega, int harmonics, Complex& lambda) {
  Complex z = lambda0;
  for (int iteration = 0; iteration < kPolishIterations; ++iteration) {
    const TruncatedSums s = truncatedSums(z, omega, harmonics);
    const Complex ratio = s.f3 / s.f2;
    // d(f₃/f₂)/dz = (f₃′f₂ − f₃f₂′)/f₂² = (−3f₄f₂ + 2f₃²)/f₂².
    const Complex slope = (2.0 * s.f3 * s.f3 - 3.0 * s.f4 * s.f2) / (s.f2 * s.f2);
    const Complex step = (ratio - nu) / slope;
    if (!std::isfinite(step.real()) || !std::isfinite(step.imag())) return false;
    z -= step;
    if (std::abs(z - lambda0) > kPolishReach * omega) return false;
    if (std::abs(step) <= kPolishTolerance * omega) {
      lambda = Complex(z.real(), z.imag() - omega * std::round(z.imag() / omega));
      return true;
    }
  }
  return false;
}

}  // namespace

bool TrainHillSolver::extensionPays(int n, int r, int harmonics, int extended) {
  // Dominant flops, m = 2n states. The projection at H′ (ρ′ = r(2H′ + 1)): the capacitance's
  // LU (2/3)ρ′³ and its three 2n-column solves 3 · 2ρ′²m, the per-harmonic LUs of the m-wide
  // real form with their (m + r)-column solves. The Arnoldi run at H (ρ, N = m(2H + 1)): its
  // capacitance LU, then K ≈ 2.6 (m + 8) applications (its basis, strip_arnoldi.h; measured
  // 112 on the 3-planet stage, more at low frequency), each a capacitance solve 2ρ² and per
  // harmonic the complex products ≈ 8(n + r)m, and the basis's orthogonalisation ≈ 4NK².
  // Measured on the 3-planet stage (n = 17, r = 6, H = 15) at 1.0, 1.3, 1.7 kHz base: projected
  // at H′ = 29, 22, 17 in 6.0, 3.1, 2.0 ms against the Arnoldi run's 19.8, 12.6, 7.0 ms.
  const double m = 2.0 * n;
  const auto harmonicFactors = [&](double H) {
    return (H + 1.0) * ((2.0 / 3.0) * m * m * m + 2.0 * m * m * (m + r));
  };
  const double rho_x = r * (2.0 * extended + 1.0), rho = r * (2.0 * harmonics + 1.0);
  const double projection =
      (2.0 / 3.0) * rho_x * rho_x * rho_x + 6.0 * rho_x * rho_x * m + harmonicFactors(extended);
  const double K = 2.6 * (m + 8.0), N = m * (2.0 * harmonics + 1.0);
  const double arnoldi = (2.0 / 3.0) * rho * rho * rho + harmonicFactors(harmonics) +
                         K * (2.0 * rho * rho + (harmonics + 1.0) * 8.0 * (n + r) * m) +
                         4.0 * N * K * K;
  return projection <= arnoldi;
}

std::optional<TrainHillResult> TrainHillSolver::projection(const TrainHillProblem& problem) {
  const int n2 = 2 * static_cast<int>(problem.M.rows()), harmonics = problem.harmonics;
  const double omega = problem.omega, T = 2.0 * std::numbers::pi / omega;
  const MeanModes mean = meanModes(problem);
  resolving_harmonics_ = harmonics;
  if (!(mean.bound <= kResolvedFraction * harmonics * omega)) {
    if (std::isfinite(mean.bound)) {
      resolving_harmonics_ = static_cast<int>(std::ceil(mean.bound / (kResolvedFraction * omega)));
    }
    return std::nullopt;
  }
  TrainHillShiftSolve& op = *op_;
  op.reset(problem);
  op.set_shift(0.0);
  // 𝓗⁻ᵖ𝛅, p = 1, 2 (C 𝓗⁻³𝛅 directly): the Dirac comb T Σ δ(t − jT) = 1 + 2 Σ cos hωt on each state
  // coordinate.
  Eigen::MatrixXd &first = first_, &second = second_, &third = third_;
  op.applyToComb(first);
  op.apply(first, second);
  op.applyAtZero(second, third);  // M₃ unbalanced: C 𝓗⁻³𝛅
  // C: the Fourier series at t = 0 (the constant and every cosine coefficient).
  const auto atZero = [&](const Eigen::MatrixXd& Y) {
    Eigen::MatrixXd sum = Y.topRows(n2);
    for (int h = 1; h <= harmonics; ++h) sum += Y.middleRows((2 * h - 1) * n2, n2);
    return sum;
  };
  // In energy-balanced state coordinates (√k̄ᵢᵢ xᵢ, √mᵢᵢ x′ᵢ: a similarity, the eigenvalues
  // stay), so that the condition measures the spread of g₂(λ), not the units.
  const int n = n2 / 2;
  Eigen::VectorXd scale(n2);
  scale.head(n) = problem.K.diagonal().cwiseAbs().cwiseSqrt();
  scale.tail(n) = problem.M.diagonal().cwiseAbs().cwiseSqrt();
  const auto balanced = [&](const Eigen::MatrixXd& A) -> Eigen::MatrixXd {
    return scale.asDiagonal() * A * scale.cwiseInverse().asDiagonal();
  };
  const Eigen::PartialPivLU<Eigen::MatrixXd> m2(balanced(atZero(second)));
  if (!(m2.rcond() >= kMinimumReciprocalCondition)) return std::nullopt;
  const Eigen::MatrixXd ratio = m2.solve(balanced(third));  // (T/2) coth(TB/2)
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(ratio, false);
  if (eig.info() != Eigen::Success) return std::nullopt;
  TrainHillResult out;
  out.projected = true;
  out.harmonics = harmonics;
  out.reused_jacobian = op.reusesJacobian();
  out.computed = n2;
  out.operations = 3 * n2;
  // A real matrix's eigenvalues: a complex one's conjugate (next in Eigen's order) maps to the
  // conjugate exponent, polished once for both.
  const Eigen::VectorXcd& values = eig.eigenvalues();
  for (Eigen::Index j = 0; j < values.size(); ++j) {
    const Complex nu = values(j), c = 2.0 * nu / T, mu = (c + 1.0) / (c - 1.0);
    if (!std::isfinite(mu.real()) || !std::isfinite(mu.imag()) || std::abs(mu) == 0.0) {
      return std::nullopt;
    }
    Complex lambda;
    const Complex start = unfolded(std::log(mu) / T, mean.exponents, omega);
    if (!polish(nu, start, omega, harmonics, lambda)) return std::nullopt;
    out.exponents.push_back(lambda);
    out.radius = std::max(out.radius, std::abs(lambda));
    if (nu.imag() != 0.0 && j + 1 < values.size() && values(j + 1) == std::conj(nu)) {
      const Complex mirror(lambda.real(), -lambda.imag());
      out.exponents.emplace_back(mirror.real(),
                                 mirror.imag() - omega * std::round(mirror.imag() / omega));
      ++j;
    }
  }
  double sum = 0.0;
  for (const Complex& l : out.exponents) sum += l.real();
  if (!(std::abs(sum + mean.damping_trace) <= kLiouvilleTolerance * omega)) return std::nullopt;
  std::sort(out.exponents.begin(), out.exponents.end(),
            [](const Complex& a, const Complex& b) { return a.real() > b.real(); });
  return out;
}

}  // namespace geardyn::detail
