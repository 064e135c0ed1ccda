/// The derived number of mesh harmonics (train_truncation.h): closed forms of the rule, and the
/// hunting-tooth reducer at its derived truncation against Newmark (issue 32's acceptance; the
/// three-speed version is TrainTorusLong.DerivedTruncationAgainstNewmarkAtThreeSpeeds).

#include "geardyn/solvers/train_truncation.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <numbers>

#include "geardyn/torus/train_torus_truncation.h"
#include "system/sample_trains.h"
#include "torus/torus_newmark_comparison.h"

namespace geardyn {
namespace {

constexpr double kRpm = std::numbers::pi / 30.0;

/// The forced analysis's default speeds (0.1–1.5 × the operating speed), `points` of them.
std::vector<double> forcedSpeeds(const GearTrainModel& model, int points = 200) {
  return testing::defaultForcedSpeeds(model, {fmt::format("forced.points={}", points)});
}

// Constant stiffness: the loaded static error W/k + e has exactly the transmission error's
// orders, so the rule returns the highest order of e whose weighted line is above the fraction
// (closed form), whatever the dynamic amplification.
TEST(TrainTruncation, ConstantStiffnessKeepsTheTransmissionErrorOrders) {
  for (int order : {1, 3, 5}) {
    GearTrainSpec spec = testing::twoStageReducer();
    std::vector<double> amplitudes(order, 0.0), phases(order, 0.0);
    amplitudes[order - 1] = 2e-6;
    spec.meshes[0].transmission_error.addFourier(amplitudes, phases);
    const GearTrainModel model(spec);
    const MeshHarmonicsEstimate e = estimateMeshHarmonics(model, forcedSpeeds(model, 20));
    EXPECT_EQ(e.per_mesh[0], order);
    EXPECT_EQ(e.per_mesh[1], 1);  // no error, constant k: nothing above the mean
    EXPECT_EQ(e.harmonics, order);
    EXPECT_FALSE(e.capped);
  }
}

// A larger fraction never asks for more harmonics; the cap is reported.
TEST(TrainTruncation, MonotoneInTheFractionAndCapped) {
  const GearTrainModel model(testing::exampleGearbox("hunting_tooth_reducer.toml"));
  const std::vector<double> speeds = forcedSpeeds(model, 40);
  int previous = 1000;
  for (double fraction : {1e-5, 1e-4, 2e-4, 1e-3, 1e-2}) {
    MeshHarmonicsOptions options;
    options.fraction = fraction;
    const MeshHarmonicsEstimate e = estimateMeshHarmonics(model, speeds, options);
    EXPECT_LE(e.harmonics, previous) << fraction;
    previous = e.harmonics;
    RecordProperty(fmt::format("L_at_{:g}", fraction),
                   fmt::format("{} {}", e.per_mesh[0], e.per_mesh[1]));
  }
  MeshHarmonicsOptions few;
  few.max_harmonics = 3;
  const MeshHarmonicsEstimate capped = estimateMeshHarmonics(model, speeds, few);
  EXPECT_TRUE(capped.capped);
  EXPECT_EQ(capped.harmonics, 3);
}

/// The torus balance at the derived truncation over the forced default speeds.
TrainTorusState derivedTorus(const GearTrainModel& model, double speed) {
  const MeshHarmonicsEstimate e = estimateMeshHarmonics(model, forcedSpeeds(model));
  return TrainTorusSolver(model, torusOptionsFromEstimate(e, {}, TorusTruncation::kBox))
      .solve(speed);
}

// Issue 32's acceptance at the derived default truncation, at the operating speed: every
// mesh-force line above 1e-3 of the largest within 1e-3 of the largest against Newmark (512
// steps per stage-1 mesh period: its own period error is 6.1e-4 there, train_torus_test.cpp).
TEST(TrainTruncation, HuntingToothReducerAtTheDerivedTruncationAgainstNewmark) {
  const GearTrainModel model(testing::exampleGearbox("hunting_tooth_reducer.toml"));
  const double speed = model.inputSpeed();
  const TrainTorusState torus = derivedTorus(model, speed);
  TrainTimeOptions options;
  options.steps_per_mesh_period = 512;
  const TrainTimeResponse newmark = solveTrainTimeResponse(model, speed, options);
  ASSERT_EQ(newmark.status, "completed");
  const auto comparison = testing::compareSpectra(model, torus, newmark, 1, 1e-3);
  for (std::size_t m = 0; m < comparison.size(); ++m) {
    EXPECT_LT(comparison[m].worst, 1e-3) << model.meshes()[m].name;
    RecordProperty(model.meshes()[m].name + "_worst", fmt::format("{:.3g}", comparison[m].worst));
  }
}

}  // namespace
}  // namespace geardyn
