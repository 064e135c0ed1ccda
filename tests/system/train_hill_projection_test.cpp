// Hill's method by the resolvent projection (issue 39, detail/train_hill.h trainHillProjection):
// exact for a time-invariant train (every exponent against the state matrix's eigenvalues), its
// convergence with the harmonics on a damped Mathieu equation against a fourth-order
// Runge–Kutta monodromy (inside and outside the principal instability tongue), against the
// Arnoldi run on the strip (the Hill eigenvalues themselves) along the planetary sweep, and the
// cases it declines.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

#include "geardyn/solvers/continuation.h"
#include "geardyn/solvers/detail/train_hill.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "system/floquet_distance.h"
#include "system/nonlinear_trains.h"

namespace geardyn {
namespace {

using Complex = std::complex<double>;
using namespace testing::nonlinear;
using testing::farthestExponent;

/// The eigenvalues of the first-order state matrix [0 I; −M⁻¹K −M⁻¹C] [1/s].
std::vector<Complex> stateExponents(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C,
                                    const Eigen::MatrixXd& K) {
  const Eigen::Index n = M.rows();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  A.bottomLeftCorner(n, n) = -M.lu().solve(K);
  A.bottomRightCorner(n, n) = -M.lu().solve(C);
  std::vector<Complex> out;
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(A, false);
  for (const Complex& l : eig.eigenvalues()) {
    out.push_back(l);
  }
  return out;
}

/// A time-invariant S(t) makes 𝓗 block diagonal: the projection's M₂⁻¹M₃ is then exactly
/// Σ_{|k|<=H}(A − ikω)⁻³ against Σ(A − ikω)⁻², whose truncation the polish inverts exactly at
/// each mode's own λ (unfolded: the modes above ω/2 too). On the two-stage reducer's Hill
/// problem (H = 15; simple eigenvalues, unlike the planetary stage's cyclic pairs) with every
/// mesh slope replaced by a constant c (S = 0, then c = 2e8 N/m, which stiffens the meshes:
/// K̄ + c VVᵀ), all 2n exponents are the state matrix's eigenvalues to 1e-8 ω (round-off of the
/// small eigenproblems; measured 5e-9).
TEST(TrainHillProjection, IsExactForATimeInvariantTrain) {
  const GearTrainModel model(twoStage(2e-5));
  TrainHarmonicBalance hbm(model, planetaryHbmOptions());
  HarmonicBalancePoint point;
  point.omega = 2.0 * std::numbers::pi * 1500.0;
  point.q = hbm.startingGuess(point.omega);
  detail::TrainHillProblem problem = hbm.hillProblem(point, false);
  const int nc = 2 * problem.harmonics + 1;
  int above = 0;  // modes above ω/2 (their copy in the strip is not where the sums see them)
  for (const double c : {0.0, 2e8}) {
    for (detail::TrainHillProblem::Block& b : problem.slopes) {
      b.galerkin = b.i == b.j ? Eigen::MatrixXd(c * Eigen::MatrixXd::Identity(nc, nc))
                              : Eigen::MatrixXd::Zero(nc, nc);
    }
    const std::optional<detail::TrainHillResult> projected = detail::trainHillProjection(problem);
    ASSERT_TRUE(projected.has_value());
    EXPECT_TRUE(projected->projected);
    const Eigen::MatrixXd K = problem.K + c * problem.V * problem.V.transpose();
    const std::vector<Complex> exact = stateExponents(problem.M, problem.C, K);
    for (const Complex& l : exact) above += std::abs(l.imag()) > 0.5 * point.omega;
    ASSERT_EQ(projected->exponents.size(), exact.size());
    const double worst = std::max(farthestExponent(projected->exponents, exact, point.omega),
                                  farthestExponent(exact, projected->exponents, point.omega));
    EXPECT_LT(worst, 1e-8 * point.omega) << "c = " << c;
    std::printf("time-invariant train (c = %g N/m): %zu exponents, worst %.3g ω\n", c, exact.size(),
                worst / point.omega);
  }
  EXPECT_GT(above, 4);
}

/// The damped Mathieu equation x″ + c x′ + (k + a cos ωt) x = 0 as a Hill problem (one DOF,
/// V = 1, S(t) = a cos ωt: its Galerkin matrix on (1, cos hωt, sin hωt) is exact, no AFT).
detail::TrainHillProblem mathieu(double k, double c, double a, double omega, int harmonics) {
  detail::TrainHillProblem p;
  p.M = Eigen::MatrixXd::Ones(1, 1);
  p.C = c * Eigen::MatrixXd::Ones(1, 1);
  p.K = k * Eigen::MatrixXd::Ones(1, 1);
  p.V = Eigen::MatrixXd::Ones(1, 1);
  p.omega = omega;
  p.harmonics = harmonics;
  const int nc = 2 * harmonics + 1;
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(nc, nc);  // a cos ωt times (1, cos h, sin h)
  if (harmonics >= 1) G(1, 0) = a, G(0, 1) = 0.5 * a;
  for (int h = 1; h <= harmonics; ++h) {
    if (h > 1) G(2 * h - 3, 2 * h - 1) = 0.5 * a, G(2 * h - 2, 2 * h) = 0.5 * a;
    if (h < harmonics) G(2 * h + 1, 2 * h - 1) = 0.5 * a, G(2 * h + 2, 2 * h) = 0.5 * a;
  }
  p.slopes.push_back({0, 0, G});
  return p;
}

/// Its largest Floquet exponent [1/s] from the monodromy by classical Runge–Kutta with 20000
/// steps a period (error ~ (ωΔt)⁴, about 1e-14 here).
double mathieuReference(double k, double c, double a, double omega) {
  const double T = 2.0 * std::numbers::pi / omega;
  const int steps = 20000;
  const double dt = T / steps;
  const auto f = [&](double t, const Eigen::Matrix2d& y) {
    Eigen::Matrix2d A;
    A << 0.0, 1.0, -(k + a * std::cos(omega * t)), -c;
    return Eigen::Matrix2d(A * y);
  };
  Eigen::Matrix2d y = Eigen::Matrix2d::Identity();
  for (int i = 0; i < steps; ++i) {
    const double t = i * dt;
    const Eigen::Matrix2d k1 = f(t, y), k2 = f(t + 0.5 * dt, y + 0.5 * dt * k1);
    const Eigen::Matrix2d k3 = f(t + 0.5 * dt, y + 0.5 * dt * k2), k4 = f(t + dt, y + dt * k3);
    y += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  const Eigen::Vector2cd mu = Eigen::EigenSolver<Eigen::Matrix2d>(y, false).eigenvalues();
  return std::log(std::max(std::abs(mu(0)), std::abs(mu(1)))) / T;
}

/// k = 1, c = 0.02, a = 0.3: at ω = 1.5 stable, at ω = 2.0 inside the principal tongue (a real
/// negative multiplier: the exponent on the strip's edge). With this smooth coefficient the
/// Hill eigenvalues (the Arnoldi run) converge exponentially: at round-off from H = 4 on. The
/// projection converges algebraically, as the comb's truncation beyond the time-invariant part
/// its polish corrects (about H⁻³): its error against the Runge–Kutta reference falls at least
/// sixfold from H = 2 to 4 and is below 1e-6 ω at H = 12 (measured below).
TEST(TrainHillProjection, ConvergesOnTheDampedMathieuEquation) {
  const double k = 1.0, c = 0.02, a = 0.3;
  for (const double omega : {1.5, 2.0}) {
    const double reference = mathieuReference(k, c, a, omega);
    std::vector<double> errors;
    for (const int harmonics : {2, 4, 12}) {
      const detail::TrainHillProblem p = mathieu(k, c, a, omega, harmonics);
      const std::optional<detail::TrainHillResult> projected = detail::trainHillProjection(p);
      ASSERT_TRUE(projected.has_value());
      ASSERT_EQ(projected->exponents.size(), 2u);
      const double arnoldi = detail::trainHillExponents(p).exponents.front().real();
      const double e = std::abs(projected->exponents.front().real() - reference) / omega;
      errors.push_back(e);
      std::printf(
          "Mathieu ω = %.1f, H = %2d: max Re λ %.12f (reference %.12f), error %.2e ω "
          "(Hill eigenvalues %.2e ω)\n",
          omega, harmonics, projected->exponents.front().real(), reference, e,
          std::abs(arnoldi - reference) / omega);
      if (harmonics >= 4) EXPECT_LT(std::abs(arnoldi - reference), 1e-10 * omega);
    }
    EXPECT_LT(errors[1], errors[0] / 6.0) << omega;
    EXPECT_LT(errors[2], 1e-6) << omega;
  }
  EXPECT_GT(mathieuReference(k, c, a, 2.0), 0.0);  // the tongue: unstable
  EXPECT_LT(mathieuReference(k, c, a, 1.5), 0.0);
}

/// Along the planetary sweep (4–13 kHz, contact loss, every 16th point): the projection against
/// the Arnoldi run on the strip, two truncations of the same infinite Hill problem. They agree
/// closely inside the strip and less on its edge, where Hill's truncation errs most: max Re λ
/// within 1e-3 ω (measured 4.9e-4, an edge exponent), every exponent within 1e-2 ω (measured
/// 6.6e-3, a damped one at −0.08 ω on the edge), those with |Im λ| < 0.4 ω within 2e-3 ω
/// (measured 7.3e-4; most agree to 1e-8). Against
/// the monodromy both differ by up to 2e-3 ω in max Re λ
/// (TrainHill.PlanetaryLoopAgreesWithTheMonodromy). The verdicts agree wherever
/// |max Re λ| > 1e-3 ω.
TEST(TrainHillProjection, MatchesTheHillEigenvaluesAlongThePlanetarySweep) {
  const GearTrainModel model(planetary(4e-6));
  TrainHarmonicBalance hbm(model, planetaryHbmOptions());
  const ContinuationResult sweep = continueInFrequency(hbm, planetarySweep(false));
  ASSERT_TRUE(sweep.completed) << sweep.message;
  double worst_max = 0.0, worst_any = 0.0, worst_inside = 0.0;
  int compared = 0, unstable = 0;
  for (std::size_t i = 8; i < sweep.points.size(); i += 16) {
    HarmonicBalancePoint point = sweep.points[i].solution;
    const double omega = point.omega;
    const detail::TrainHillProblem problem = hbm.hillProblem(point, false);
    const std::optional<detail::TrainHillResult> projected = detail::trainHillProjection(problem);
    ASSERT_TRUE(projected.has_value()) << omega;
    const detail::TrainHillResult arnoldi = detail::trainHillExponents(problem);
    ASSERT_EQ(projected->exponents.size(), arnoldi.exponents.size());
    const double a = projected->exponents.front().real(), b = arnoldi.exponents.front().real();
    worst_max = std::max(worst_max, std::abs(a - b) / omega);
    for (const Complex& e : projected->exponents) {
      const double d = farthestExponent({e}, arnoldi.exponents, omega) / omega;
      worst_any = std::max(worst_any, d);
      if (std::abs(e.imag()) < 0.4 * omega) worst_inside = std::max(worst_inside, d);
    }
    if (std::abs(b) > 1e-3 * omega) {
      ++compared;
      EXPECT_EQ(a > 0.0, b > 0.0) << omega;
    }
    unstable += b > 0.0;
  }
  EXPECT_LT(worst_max, 1e-3);
  EXPECT_LT(worst_any, 1e-2);
  EXPECT_LT(worst_inside, 2e-3);
  EXPECT_GT(unstable, 10);
  EXPECT_GT(compared, 50);
  std::printf(
      "planetary sweep, %d verdicts compared (%d unstable): worst |Δ max Re λ| %.3g ω, "
      "worst exponent %.3g ω (%.3g ω with |Im| < 0.4 ω)\n",
      compared, unstable, worst_max, worst_any, worst_inside);
}

/// A mode far faster than the comb's harmonics resolve (a second, uncoupled DOF overdamped to
/// λ = −30 − √899 ≈ −60 = 5Hω at ω = 1.5, H = 8): the truncated sums see it as (2H + 1)/λᵖ, not
/// as the periodic g_p, and the closed form would alias it into the strip (measured: −0.0036 +
/// iω/2, a spurious near-neutral exponent). The projection declines (std::nullopt) and the
/// Arnoldi run, which classifyHill then uses, finds the Mathieu DOF's largest exponent: the
/// one-DOF problem's to 1e-10 ω (uncoupled), which the projection also finds there.
TEST(TrainHillProjection, DeclinesAModeBeyondItsHarmonics) {
  const double omega = 1.5;
  detail::TrainHillProblem p = mathieu(1.0, 0.02, 0.3, omega, 8);
  p.M = Eigen::Matrix2d::Identity();
  p.C = Eigen::Vector2d(0.02, 60.0).asDiagonal();
  p.K = Eigen::Vector2d(1.0, 1.0).asDiagonal();
  p.V = Eigen::Vector2d(1.0, 0.0);
  EXPECT_FALSE(detail::trainHillProjection(p).has_value());
  const double both = detail::trainHillExponents(p).exponents.front().real();
  const detail::TrainHillProblem single = mathieu(1.0, 0.02, 0.3, omega, 8);
  EXPECT_NEAR(both, detail::trainHillExponents(single).exponents.front().real(), 1e-10 * omega);
  const std::optional<detail::TrainHillResult> one = detail::trainHillProjection(single);
  ASSERT_TRUE(one.has_value());
  EXPECT_NEAR(one->exponents.front().real(), both, 1e-6 * omega);
}

/// The same through the gear train's classification: the planetary stage with its carrier's
/// torsional damper raised to 1e7 N m s/rad (a mode damped at |λ| far beyond 15 ω₀/2) is
/// declined by the projection, and classify(kHill) gives the Arnoldi run's exponent exactly and
/// the monodromy's verdict.
TEST(TrainHillProjection, TheClassificationFallsBackToTheArnoldiRun) {
  GearTrainSpec spec = planetary(4e-6);
  spec.bearings[1].c_torsion = 1e7;
  const GearTrainModel model(spec);
  TrainHarmonicBalance hbm(model, planetaryHbmOptions());
  HarmonicBalancePoint point;
  point.omega = 2.0 * std::numbers::pi * 4000.0;
  point.q = hbm.startingGuess(point.omega);
  hbm.solve(point);
  ASSERT_TRUE(point.converged);
  const detail::TrainHillProblem problem = hbm.hillProblem(point, false);
  EXPECT_FALSE(detail::trainHillProjection(problem).has_value());
  const double arnoldi = detail::trainHillExponents(problem).exponents.front().real();
  HarmonicBalancePoint hill = point, monodromy = point;
  hbm.classify(hill, StabilityMethod::kHill, false);
  hbm.classify(monodromy, StabilityMethod::kMonodromy, false);
  EXPECT_EQ(hill.max_floquet_real, arnoldi);
  EXPECT_EQ(hill.stable, monodromy.stable);
}

}  // namespace
}  // namespace geardyn
