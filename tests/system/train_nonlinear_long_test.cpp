// Issue 17 acceptance (long label): the planetary stage with backlash at all 6 meshes and the
// two-stage reducer with backlash at both meshes, train harmonic balance against nonlinear
// Newmark at >= 10 frequencies each, through contact loss, back-flank impacts and folds.
#include <gtest/gtest.h>

#include "system/nonlinear_trains.h"

namespace geardyn {
namespace {

using namespace testing::nonlinear;

void report(const char* name, const NewmarkCheck& check) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", check.worst);
  ::testing::Test::RecordProperty("worst_p2p_difference", text);
  std::printf("%s: %d stable (%d with contact loss) at %d frequencies, %d unstable, worst %.3g\n",
              name, check.stable, check.contact_loss, check.frequencies, check.unstable,
              check.worst);
}

/// Mesh frequencies 4–13 kHz: two softening loops with contact loss (folds at 5.56/5.73 and
/// 8.42/8.82 kHz) and back-flank impacts above; a period-doubling instability near 12.5 kHz.
TEST(TrainNonlinearLong, PlanetaryStageAgreesWithNewmark) {
  const GearTrainModel model(planetary(4e-6));
  TrainHarmonicBalance hbm(model, planetaryHbmOptions());
  const ContinuationResult sweep = continueInFrequency(hbm, planetarySweep(false));
  ASSERT_TRUE(sweep.completed) << sweep.message;
  EXPECT_EQ(sweep.folds.size(), 4u);
  std::vector<double> omegas;
  for (double f : {4200., 4500., 5300., 5650., 6000., 6500., 7200., 7600., 8000., 8600., 9300.,
                   9700., 10000., 10500., 11000., 12500.}) {
    omegas.push_back(2 * std::numbers::pi * f);
  }
  const NewmarkCheck check = checkAgainstNewmark(model, hbm, sweep, omegas);
  // Issue 17: stable branches confirmed at >= 10 frequencies. Since the ring–sun phase γ_rs is
  // derived (planet_phasing.h) some of the original 12 frequencies have only unstable solutions;
  // with 16 frequencies, 12 stable solutions at 10 of them persist under Newmark (worst 4.4e-4
  // of p2p, 9 with contact loss) and 8 unstable ones are left by it.
  EXPECT_GE(check.frequencies, 10);
  EXPECT_GE(check.stable, 12);
  EXPECT_GE(check.contact_loss, 8);
  EXPECT_GE(check.unstable, 2);
  report("planetary", check);
}

/// Base frequencies (a third of the stage-1 mesh frequency) 100–3000 Hz: stage 1 loses contact
/// around 1.4–2.0 kHz, stage 2 around 2.38–2.8 kHz (H = 30: 10 harmonics of the stage-1 mesh,
/// 30 of stage 2).
TEST(TrainNonlinearLong, TwoStageReducerAgreesWithNewmark) {
  const GearTrainModel model(twoStage(2e-5));
  TrainHarmonicBalanceOptions options;
  options.harmonics = 30;
  options.samples = 512;
  TrainHarmonicBalance hbm(model, options);
  const ContinuationResult sweep =
      continueInFrequency(hbm, baseSweep(100, 3000, options.harmonics));
  ASSERT_TRUE(sweep.completed) << sweep.message;
  std::vector<double> omegas;
  for (double f :
       {400., 750., 1200., 1420., 1500., 1700., 1900., 2200., 2400., 2500., 2700., 2900.}) {
    omegas.push_back(2 * std::numbers::pi * f);
  }
  const NewmarkCheck check = checkAgainstNewmark(model, hbm, sweep, omegas);
  // Issue 17: stable branches confirmed at >= 10 frequencies; measured 12 stable solutions at
  // all 12 (7 with contact loss), worst 3.2e-4 of p2p.
  EXPECT_GE(check.frequencies, 10);
  EXPECT_GE(check.stable, 10);
  EXPECT_GE(check.contact_loss, 6);
  report("two-stage", check);
}

}  // namespace
}  // namespace geardyn
