// Hill's method reusing the harmonic balance's factors (issue 39; detail/train_hill.h,
// TrainHillProblem::jacobian): at σ = 0 Hill's capacitance I + 𝓖𝓢 is the balance's Jacobian
// I + 𝓑𝓢, so the factors of Newton's last step are the capacitance's when that step left every
// contact state as it was. Checked: the exponents with the reused factors against those with
// the operator's own (projection and Arnoldi run), and that the factors are refused at another
// ω, at other slopes and when the condensation blocks disagree with Hill's own.
#include <gtest/gtest.h>

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

/// A converged point of the planetary stage (backlash 4 µm) at `hz` [Hz] base frequency.
HarmonicBalancePoint solved(TrainHarmonicBalance& hbm, double hz) {
  return solvedFromTheLinearGuess(hbm, 2.0 * std::numbers::pi * hz);
}

detail::TrainHillProblem withoutFactors(detail::TrainHillProblem p) {
  p.jacobian = nullptr;
  p.jacobian_blocks = nullptr;
  return p;
}

/// The same matrix by another route: the exponents agree to round-off. Tolerance 1e-9 ω: the
/// two capacitances differ by 1.6e-15 relative (their 𝓖 by two LUs), measured 3.6e-11 ω apart
/// over the 201 bench points; the projection's own truncation error is 1e-3 ω, so any real
/// difference in the matrix would show far above 1e-9.
TEST(TrainHillReuse, TheBalancesFactorsGiveTheSameExponents) {
  const GearTrainModel model(planetary(4e-6));
  TrainHarmonicBalance hbm(model, planetaryHbmOptions());
  int reused = 0;
  for (const double hz : {4500.0, 7000.0, 9500.0, 12000.0}) {
    const HarmonicBalancePoint p = solved(hbm, hz);
    ASSERT_TRUE(p.converged) << hz;
    const detail::TrainHillProblem with = hbm.hillProblem(p, true);
    if (!with.jacobian) continue;  // Newton's last step changed a contact state
    ++reused;
    const detail::TrainHillProblem own = withoutFactors(with);
    const std::optional<detail::TrainHillResult> a = detail::trainHillProjection(with);
    const std::optional<detail::TrainHillResult> b = detail::trainHillProjection(own);
    ASSERT_TRUE(a && b) << hz;
    EXPECT_TRUE(a->reused_jacobian) << hz;
    EXPECT_FALSE(b->reused_jacobian) << hz;
    ASSERT_EQ(a->exponents.size(), b->exponents.size());
    EXPECT_LT(farthestExponent(a->exponents, b->exponents, p.omega), 1e-9 * p.omega) << hz;
    EXPECT_NEAR(a->exponents.front().real(), b->exponents.front().real(), 1e-9 * p.omega) << hz;
    // The Arnoldi run (the fallback) through the single-vector path: its Ritz values of the
    // stage's near-double (cyclic) pairs are only as good as the square root of its tolerance,
    // so two runs on operators 1e-15 apart give such pairs 8e-8 ω apart (measured); 1e-6 ω.
    const detail::TrainHillResult c = detail::trainHillExponents(with);
    const detail::TrainHillResult d = detail::trainHillExponents(own);
    EXPECT_TRUE(c.reused_jacobian);
    EXPECT_LT(farthestExponent(c.exponents, d.exponents, p.omega), 1e-6 * p.omega) << hz;
    std::printf("%.0f Hz: max Re λ %.6g ω with the balance's factors, %.6g ω with its own\n", hz,
                a->exponents.front().real() / p.omega, b->exponents.front().real() / p.omega);
  }
  // Newton from the linear guess ends in the same contact states at most of these points.
  EXPECT_GE(reused, 3);
}

/// Factors of another ω, or of other slopes, are not the capacitance: refused.
TEST(TrainHillReuse, RefusesFactorsOfAnotherJacobian) {
  const GearTrainModel model(planetary(4e-6));
  TrainHarmonicBalance hbm(model, planetaryHbmOptions());
  HarmonicBalancePoint p = solved(hbm, 7000.0);
  ASSERT_TRUE(p.converged);
  ASSERT_NE(hbm.hillProblem(p, true).jacobian, nullptr);
  // Other slopes at the same ω: q = 0, no deflection at all (y = −e: the 3 and 2 µm errors
  // open contact where the loaded solution keeps it).
  HarmonicBalancePoint other = p;
  other.q.setZero();
  EXPECT_EQ(hbm.hillProblem(other, false).jacobian, nullptr);
  // The same point, its samples again: accepted again (the factors are still Newton's).
  EXPECT_NE(hbm.hillProblem(p, false).jacobian, nullptr);
  // Another ω (the condensation is refactorised there by the next Newton solve).
  const HarmonicBalancePoint q = solved(hbm, 9000.0);
  ASSERT_TRUE(q.converged);
  HarmonicBalancePoint shifted = q;
  shifted.omega = p.omega;
  EXPECT_EQ(hbm.hillProblem(shifted, false).jacobian, nullptr);
}

/// Condensation blocks that are not Hill's own 𝓖 (a train whose rigid-body modes couple to V
/// would give such): the operator factorises its own capacitance, and the exponents are its.
TEST(TrainHillReuse, RefusesBlocksThatDisagree) {
  const GearTrainModel model(planetary(4e-6));
  TrainHarmonicBalance hbm(model, planetaryHbmOptions());
  const HarmonicBalancePoint p = solved(hbm, 7000.0);
  ASSERT_TRUE(p.converged);
  detail::TrainHillProblem problem = hbm.hillProblem(p, true);
  ASSERT_NE(problem.jacobian_blocks, nullptr);
  std::vector<Eigen::MatrixXcd> blocks = *problem.jacobian_blocks;
  blocks[3](1, 1) *= 1.0 + 1e-6;  // far above round-off (kJacobianAgreement 1e-8)
  problem.jacobian_blocks = &blocks;
  const std::optional<detail::TrainHillResult> a = detail::trainHillProjection(problem);
  const std::optional<detail::TrainHillResult> b =
      detail::trainHillProjection(withoutFactors(problem));
  ASSERT_TRUE(a && b);
  EXPECT_FALSE(a->reused_jacobian);
  EXPECT_LT(farthestExponent(a->exponents, b->exponents, p.omega), 1e-12 * p.omega);
}

/// A real such train: Lin & Parker's carrier-frame terms couple the rolling mode through the
/// planets' Coriolis terms, which the balance keeps and Hill's elastic subspace leaves out
/// (6e-6 apart at h = 1): the factors are offered (same ω and slopes) and refused.
TEST(TrainHillReuse, RefusesTheFactorsOfACarrierFrameStage) {
  GearTrainSpec spec = planetary(4e-6);
  spec.stages[0].carrier_frame_terms = true;
  const GearTrainModel model(spec);
  TrainHarmonicBalance hbm(model, planetaryHbmOptions());
  const HarmonicBalancePoint p = solved(hbm, 7000.0);
  ASSERT_TRUE(p.converged);
  const detail::TrainHillProblem problem = hbm.hillProblem(p, true);
  ASSERT_NE(problem.jacobian, nullptr);
  const std::optional<detail::TrainHillResult> a = detail::trainHillProjection(problem);
  ASSERT_TRUE(a);
  EXPECT_FALSE(a->reused_jacobian);
}

}  // namespace
}  // namespace geardyn
