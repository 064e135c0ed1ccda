// Hill's method with more harmonics than the balance (issue 39; TrainHarmonicBalance::
// classifyHill): at a base frequency so low that the balance's H does not resolve the train's
// fastest mode (|λ| > Hω/2), the resolvent projection is run with as many harmonics as do, from
// the same samples, where that costs less than the Arnoldi run. Checked against the monodromy
// (an independent method) on the 3-planet stage at 1.0–1.7 kHz base, where the projection at
// H = 15 declines, and against Hill's eigenvalues at the same extended truncation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "geardyn/solvers/continuation.h"
#include "geardyn/solvers/detail/train_hill.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "system/nonlinear_trains.h"

namespace geardyn {
namespace {

using namespace testing::nonlinear;

/// Tolerance on max Re λ against the monodromy, 1e-4 ω: the two methods discretise differently
/// (H harmonics against N = 256 Newmark steps a period); at these points, in contact throughout,
/// they agree to 2e-6 ω (measured), where with contact loss they differ by up to 2.3e-3 ω
/// (train_hill_projection_test); 1e-4 ω is far below the exponents themselves (−0.014 to
/// −0.024 ω), so a wrong mode or a spurious exponent would show.
TEST(TrainHillExtended, ResolvesTheFastestModeWithMoreHarmonics) {
  const GearTrainModel model(planetary(4e-6));
  const TrainHarmonicBalanceOptions options = planetaryHbmOptions();
  TrainHarmonicBalance hbm(model, options);
  detail::TrainHillSolver solver;
  for (const double hz : {1000.0, 1300.0, 1700.0}) {
    HarmonicBalancePoint p;
    p.omega = 2.0 * std::numbers::pi * hz;
    p.q = hbm.startingGuess(p.omega);
    hbm.solve(p);
    ASSERT_TRUE(p.converged) << hz;
    HarmonicBalancePoint monodromy = p, hill = p;
    hbm.classify(monodromy, StabilityMethod::kMonodromy, false);
    // At the balance's H the projection declines and says how many harmonics would resolve.
    const detail::TrainHillProblem problem = hbm.hillProblem(p, false);
    EXPECT_FALSE(solver.projection(problem)) << hz;
    const int resolving = solver.resolvingHarmonics();
    EXPECT_GT(resolving, options.harmonics) << hz;
    ASSERT_LE(resolving, options.samples / 4) << hz;
    EXPECT_TRUE(detail::TrainHillSolver::extensionPays(static_cast<int>(problem.M.rows()),
                                                       static_cast<int>(problem.V.cols()),
                                                       options.harmonics, resolving));
    // With them it projects, and agrees with the monodromy.
    const detail::TrainHillProblem extended = hbm.hillProblem(p, true, resolving);
    const std::optional<detail::TrainHillResult> projected = solver.projection(extended);
    ASSERT_TRUE(projected) << hz;
    EXPECT_EQ(projected->harmonics, resolving);
    const double max_re = projected->exponents.front().real();
    EXPECT_NEAR(max_re, monodromy.max_floquet_real, 1e-4 * p.omega) << hz;
    // Hill's eigenvalues at the same truncation: the same largest exponent (the projection's
    // truncation error, 1e-3 ω at most on the 4–13 kHz sweep).
    const detail::TrainHillResult eigenvalues = detail::trainHillExponents(extended);
    EXPECT_NEAR(max_re, eigenvalues.exponents.front().real(), 1e-3 * p.omega) << hz;
    // The classification takes that path (its max Re λ is the extended projection's).
    hbm.classify(hill, StabilityMethod::kHill, false);
    EXPECT_NEAR(hill.max_floquet_real, max_re, 1e-12 * p.omega) << hz;
    EXPECT_EQ(hill.stable, monodromy.stable) << hz;
    std::printf(
        "%.0f Hz: H' = %d, max Re λ %.7f ω (monodromy %.7f ω, Hill eigenvalues %.7f ω), %d "
        "unpolished (damped by more than 0.1 ω)\n",
        hz, resolving, max_re / p.omega, monodromy.max_floquet_real / p.omega,
        eigenvalues.exponents.front().real() / p.omega, projected->unpolished);
  }
}

/// The cost model: a single mesh (a capacitance 2H + 1 wide) extends to N/4; many meshes with
/// many DOFs (r = 20, n = 40) do not double H, where the capacitance's LU grows eightfold.
TEST(TrainHillExtended, ExtendsWhereItCostsLessThanTheArnoldiRun) {
  EXPECT_TRUE(detail::TrainHillSolver::extensionPays(6, 1, 15, 64));
  EXPECT_TRUE(detail::TrainHillSolver::extensionPays(17, 6, 15, 29));
  EXPECT_FALSE(detail::TrainHillSolver::extensionPays(17, 6, 15, 60));
  EXPECT_FALSE(detail::TrainHillSolver::extensionPays(40, 20, 15, 30));
}

/// Fewer than 4H samples (allowed: N > 2H): the balance's own H is classified as its Jacobian
/// has it, and only an extension beyond N/4 is refused (the slopes' 2H harmonics would alias).
TEST(TrainHillExtended, FewSamplesClassifyAtTheBalancesHarmonics) {
  const GearTrainModel model(planetary(4e-6));
  TrainHarmonicBalanceOptions options = planetaryHbmOptions();
  options.samples = 40;  // N/4 = 10 < H = 15
  TrainHarmonicBalance hbm(model, options);
  HarmonicBalancePoint p;
  p.omega = 2.0 * std::numbers::pi * 7000.0;
  p.q = hbm.startingGuess(p.omega);
  hbm.solve(p);
  ASSERT_TRUE(p.converged);
  HarmonicBalancePoint hill = p, monodromy = p;
  EXPECT_NO_THROW(hbm.classify(hill, StabilityMethod::kHill, false));
  hbm.classify(monodromy, StabilityMethod::kMonodromy, false);
  EXPECT_EQ(hill.stable, monodromy.stable);
  EXPECT_EQ(hbm.hillProblem(p, false).harmonics, options.harmonics);
  EXPECT_THROW(hbm.hillProblem(p, false, 16), std::invalid_argument);
}

}  // namespace
}  // namespace geardyn
