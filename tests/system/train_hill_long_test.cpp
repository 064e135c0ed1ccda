// Hill's method against the monodromy over the whole planetary sweep (issue 17, item 4; long
// label): both classify every point of the 4–13 kHz sweep, and report the same bifurcations.
#include <gtest/gtest.h>

#include <cstdio>

#include "system/nonlinear_trains.h"

namespace geardyn {
namespace {

using namespace testing::nonlinear;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// The planetary stage, mesh frequencies 4–13 kHz (two softening loops with 4 folds), continued
/// twice: with the monodromy and with Hill's method. The sweeps are the same (stability does
/// not steer the continuation); max Re λ agrees within 5e-3 ω₀ (the cross-check's tolerance:
/// Hill's truncation of the discontinuous contact slope; measured 3.9e-3 with the resolvent
/// projection, 3.5e-3 with the Hill eigenvalues of the Arnoldi run), hence the verdicts
/// at every point whose exponents are both farther than that from 0, and the folds are the same.
/// The one other stability change, on the upper branch of the second loop, is typed
/// differently: the monodromy's critical pair of multipliers is complex near −1 (Neimark–Sacker,
/// 9.08 kHz), Hill's exponent lies within 1e-4 ω₀ of the strip's edge (read as period doubling,
/// 9.01–9.06 kHz, crossing three times): both see a multiplier leave the unit circle near −1
/// there, within each other's accuracy.
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
    if (std::abs(a.max_floquet_real) > 5e-3 * a.omega &&
        std::abs(b.max_floquet_real) > 5e-3 * a.omega) {
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
  EXPECT_GT(compared, static_cast<int>(mono.points.size()) / 2);
  EXPECT_LT(worst, 5e-3);
  const auto folds = [](const ContinuationResult& r) {
    std::vector<double> out;
    for (const Bifurcation& b : r.bifurcations) {
      if (b.type == BifurcationType::kFold) out.push_back(b.omega);
    }
    return out;
  };
  EXPECT_EQ(folds(mono), folds(hill));
  EXPECT_EQ(folds(mono).size(), 4u);
  // The other stability changes: near −1 in both, between 8.9 and 9.2 kHz.
  for (const auto* r : {&mono, &hill}) {
    int others = 0;
    for (const Bifurcation& b : r->bifurcations) {
      if (b.type == BifurcationType::kFold) continue;
      ++others;
      EXPECT_NE(b.type, BifurcationType::kBranchPoint);
      EXPECT_GT(b.omega, kTwoPi * 8900);
      EXPECT_LT(b.omega, kTwoPi * 9200);
    }
    EXPECT_GE(others, 1);
  }
}

}  // namespace
}  // namespace geardyn
