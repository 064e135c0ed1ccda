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
  std::printf("%s: %d stable (%d with contact loss), %d unstable, worst %.3g\n", name, check.stable,
              check.contact_loss, check.unstable, check.worst);
}

/// Mesh frequencies 4–13 kHz: two softening loops with contact loss (folds at 5.56/5.73 and
/// 8.42/8.82 kHz) and back-flank impacts above; a period-doubling instability near 12.5 kHz.
TEST(TrainNonlinearLong, PlanetaryStageAgreesWithNewmark) {
  const GearTrainModel model(planetary(4e-6));
  TrainHarmonicBalanceOptions options;
  options.harmonics = 15;
  options.samples = 256;
  TrainHarmonicBalance hbm(model, options);
  ContinuationOptions c;
  c.start = 2 * std::numbers::pi * 4000;
  c.stop = 2 * std::numbers::pi * 13000;
  c.stability = false;
  c.max_step = (c.stop - c.start) / 100;
  deriveContinuationSteps(c, 0.0, 0.05, options.harmonics);
  const ContinuationResult sweep = continueInFrequency(hbm, c);
  ASSERT_TRUE(sweep.completed) << sweep.message;
  EXPECT_EQ(sweep.folds.size(), 4u);
  std::vector<double> omegas;
  for (double f :
       {4500., 5300., 5650., 6000., 6500., 7200., 8000., 8600., 9300., 10000., 11000., 12500.}) {
    omegas.push_back(2 * std::numbers::pi * f);
  }
  const NewmarkCheck check = checkAgainstNewmark(model, hbm, sweep, omegas);
  EXPECT_GE(check.stable, 12);
  EXPECT_GE(check.contact_loss, 8);
  EXPECT_GE(check.unstable, 2);
  report("planetary", check);
}

}  // namespace
}  // namespace geardyn
