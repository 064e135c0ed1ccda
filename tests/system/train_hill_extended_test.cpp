// Hill's method with more harmonics than the balance (issue 39; TrainHarmonicBalance::
// classifyHill): at a base frequency so low that the balance's H does not resolve the train's
// fastest mode (|λ| > Hω/2), the resolvent projection is run with as many harmonics as do, from
// the same samples, where that costs less than the Arnoldi run. Checked against the monodromy
// (an independent method) on a pump drive at 700–820 Hz base, where the projection at H = 15
// declines, and against Hill's eigenvalues at the same extended truncation; Liouville's formula
// declining a projection that is off; the cost model; fewer than 4H samples.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "geardyn/analysis/analyses.h"
#include "geardyn/config/gearbox_config.h"
#include "geardyn/solvers/continuation.h"
#include "geardyn/solvers/detail/train_hill.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "system/nonlinear_trains.h"
#include "system/pump_drive.h"

namespace geardyn {
namespace {

using namespace testing::nonlinear;
using testing::pumpDrive;
using testing::specOf;

/// Tolerances: against the monodromy 2e-4 ω, the two methods' different discretisations (H
/// harmonics against N = 256 Newmark steps a period): 3e-5 ω apart here, as at 1800 rpm where
/// H = 15 resolves the train (1e-5 ω), far below the exponent itself (−0.04 ω); against Hill's
/// eigenvalues at the same H′ 1e-5 ω (the projection's truncation, measured below 1e-6 ω).
TEST(TrainHillExtended, ResolvesTheFastestModeWithMoreHarmonics) {
  const GearTrainModel model(pumpDrive());
  TrainHarmonicBalanceOptions options;
  options.harmonics = 15;
  options.samples = 256;
  TrainHarmonicBalance hbm(model, options);
  detail::TrainHillSolver solver;
  for (const double rpm : {1450.0, 1535.0, 1600.0, 1700.0}) {
    const HarmonicBalancePoint p =
        solvedFromTheLinearGuess(hbm, hbm.baseFrequency(rpm * std::numbers::pi / 30.0));
    ASSERT_TRUE(p.converged) << rpm;
    HarmonicBalancePoint monodromy = p, hill = p;
    hbm.classify(monodromy, StabilityMethod::kMonodromy, false);
    // At the balance's H the projection declines and says how many harmonics would resolve.
    const detail::TrainHillProblem problem = hbm.hillProblem(p, false);
    EXPECT_FALSE(solver.projection(problem)) << rpm;
    const int resolving = solver.resolvingHarmonics();
    EXPECT_GT(resolving, options.harmonics) << rpm;
    ASSERT_LE(resolving, options.samples / 4) << rpm;
    EXPECT_TRUE(detail::TrainHillSolver::extensionPays(static_cast<int>(problem.M.rows()),
                                                       static_cast<int>(problem.V.cols()),
                                                       options.harmonics, resolving));
    // With them it projects, and agrees with the monodromy and with Hill's eigenvalues.
    const detail::TrainHillProblem extended = hbm.hillProblem(p, true, resolving);
    const std::optional<detail::TrainHillResult> projected = solver.projection(extended);
    ASSERT_TRUE(projected) << rpm;
    EXPECT_EQ(projected->harmonics, resolving);
    const double max_re = projected->exponents.front().real();
    EXPECT_NEAR(max_re, monodromy.max_floquet_real, 2e-4 * p.omega) << rpm;
    const detail::TrainHillResult eigenvalues = detail::trainHillExponents(extended);
    EXPECT_NEAR(max_re, eigenvalues.exponents.front().real(), 1e-5 * p.omega) << rpm;
    // The classification takes that path (its max Re λ is the extended projection's).
    hbm.classify(hill, StabilityMethod::kHill, false);
    EXPECT_NEAR(hill.max_floquet_real, max_re, 1e-12 * p.omega) << rpm;
    EXPECT_EQ(hill.stable, monodromy.stable) << rpm;
    std::printf("%.0f rpm: H' = %d, max Re λ %.7f ω (monodromy %.7f ω, Hill eigenvalues %.7f ω)\n",
                rpm, resolving, max_re / p.omega, monodromy.max_floquet_real / p.omega,
                eigenvalues.exponents.front().real() / p.omega);
  }
}

/// Where the truncated comb cannot be trusted even with every polish converged, Liouville's
/// formula catches it (the exponents must sum to −tr(M⁻¹C)): the planetary example with 4
/// planets and the carrier-frame terms at 1450 rpm (544 Hz base) projected with the 58
/// harmonics its fastest mode asks for summed 20.6 ω off; it is declined, and the classification
/// (which would not extend so far: the flop count) gives the monodromy's verdict.
TEST(TrainHillExtended, LiouvillesFormulaDeclinesAProjectionThatIsOff) {
  std::ifstream in(std::string(GEARDYN_SOURCE_DIR) + "/examples/train_planetary_nonlinear.toml");
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  const auto replace = [&text](const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("planets = 3", "planets = 4");
  replace("carrier_frame_terms = false", "carrier_frame_terms = true");
  const GearTrainModel model(specOf(text, "geardyn_hill_four_planets.toml"));
  TrainHarmonicBalance hbm(model, planetaryHbmOptions());
  const HarmonicBalancePoint p =
      solvedFromTheLinearGuess(hbm, hbm.baseFrequency(1450.0 * std::numbers::pi / 30.0));
  ASSERT_TRUE(p.converged);
  detail::TrainHillSolver solver;
  const detail::TrainHillProblem problem = hbm.hillProblem(p, false);
  EXPECT_FALSE(solver.projection(problem));
  const int resolving = solver.resolvingHarmonics();
  ASSERT_EQ(resolving, 58);
  EXPECT_FALSE(solver.projection(hbm.hillProblem(p, true, resolving)));
  HarmonicBalancePoint hill = p, monodromy = p;
  hbm.classify(hill, StabilityMethod::kHill, false);
  hbm.classify(monodromy, StabilityMethod::kMonodromy, false);
  EXPECT_EQ(hill.stable, monodromy.stable);
  EXPECT_NEAR(hill.max_floquet_real, monodromy.max_floquet_real, 2e-4 * p.omega);
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
  const HarmonicBalancePoint p = solvedFromTheLinearGuess(hbm, 2.0 * std::numbers::pi * 7000.0);
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
