// Hill's method against the monodromy over the whole planetary sweep (issue 17, item 4; long
// label): both classify every point of the 4–13 kHz sweep, and report the same bifurcations.
#include <gtest/gtest.h>

#include <cstdio>

#include "system/nonlinear_trains.h"

namespace geardyn {
namespace {

using namespace testing::nonlinear;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// The planetary stage, mesh frequencies 4–13 kHz (two softening loops with 4 folds, a period
/// doubling near 12.5 kHz), continued twice: with the monodromy and with Hill's method. The
/// sweeps are the same (stability does not steer the continuation); the verdicts agree at every
/// point whose exponents are both farther than 1e-3 ω₀ from 0, and the stability changes are
/// the same in number, type and place (within 1 % of the frequency).
TEST(TrainHillLong, PlanetarySweepBifurcationsMatchTheMonodromy) {
  const GearTrainModel model(planetary(4e-6));
  TrainHarmonicBalance hbm(model, planetaryHbmOptions());
  ContinuationOptions c = planetarySweep(true);
  const ContinuationResult mono = continueInFrequency(hbm, c);
  c.stability_method = StabilityMethod::kHill;
  const ContinuationResult hill = continueInFrequency(hbm, c);
  ASSERT_TRUE(mono.completed && hill.completed);
  ASSERT_EQ(mono.points.size(), hill.points.size());
  int compared = 0, same = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < mono.points.size(); ++i) {
    const HarmonicBalancePoint &a = mono.points[i].solution, &b = hill.points[i].solution;
    worst = std::max(worst, std::abs(a.max_floquet_real - b.max_floquet_real) / a.omega);
    if (std::abs(a.max_floquet_real) > 1e-3 * a.omega &&
        std::abs(b.max_floquet_real) > 1e-3 * a.omega) {
      ++compared;
      same += a.stable == b.stable;
    }
  }
  std::printf(
      "planetary sweep: %zu points, %d of %d compared verdicts agree, worst |Δ max Re| / "
      "ω = %.3g\n",
      mono.points.size(), same, compared, worst);
  for (const auto* r : {&mono, &hill}) {
    for (const Bifurcation& b : r->bifurcations) {
      std::printf("  %s %s at %.1f Hz\n", r == &mono ? "monodromy" : "hill",
                  toString(b.type).c_str(), b.omega / kTwoPi);
    }
  }
  EXPECT_EQ(same, compared);
  EXPECT_LT(worst, 1e-3);
  ASSERT_EQ(mono.bifurcations.size(), hill.bifurcations.size());
  for (std::size_t k = 0; k < mono.bifurcations.size(); ++k) {
    EXPECT_EQ(mono.bifurcations[k].type, hill.bifurcations[k].type) << k;
    EXPECT_NEAR(mono.bifurcations[k].omega, hill.bifurcations[k].omega,
                0.01 * mono.bifurcations[k].omega);
  }
}

}  // namespace
}  // namespace geardyn
